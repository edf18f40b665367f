// The inspector: material list, panel, code and preview, from
// api/library.json and each material's metadata alone.

import * as bake from './bake.js';
import { Renderer, TONEMAPS, normalize, equirectToCube, cubeFaceSize } from './render.js';
import { el, numberControl, boolControl, colorControl, vectorControl, textureControl, curveControl, gradientControl } from './panel.js';

const BASE = new URL('.', document.baseURI).href;

// UI strings; labels and tooltips of materials come from their metadata.
const ZH = {
  'Materials': '材质', 'Tier': '质量档', 'Keywords': '关键字', 'Presets': '预设', 'Reset': '重置',
  'Preview': '预览', 'Mesh': '网格', 'Tone mapping': '色调映射', 'Exposure': '曝光', 'Light azimuth': '光源方位角',
  'Light elevation': '光源仰角', 'Code': '代码', 'Copy': '复制', 'Copied': '已复制', 'Variant': '变体',
  'default': '默认', 'use the default': '使用默认',
  'tiling / offset': '平铺 / 偏移', 'time': '时间', 'value': '值', 'in': '入斜率', 'out': '出斜率', 'key': '关键帧',
  'remove key': '删除关键帧', 'stop': '色标', 'remove stop': '删除色标', 'Build failed: the last good build stays visible': '构建失败：仍显示上一次成功的构建',
  'measured': '实测', 'ms measured': '实测毫秒', '× measured': '实测倍数', 'FLIP mean vs reference': '相对参考档的 FLIP 均值', 'no measurements': '无实测数据',
  'GPU model': 'GPU 模型', 'VGPRs / waves': 'VGPR / 波数',
  'loop-aware executed cost ÷ standard fast, fragment stage': '计入循环的执行代价 ÷ standard fast，片元阶段',
  'modelled on an earlier version of this material': '模型数据来自此材质的旧版本',
  'measured on an earlier version of this material': '实测数据来自此材质的旧版本', 'not compiled': '未编译',
  'static export: no live rebuilds': '静态导出：不会实时重建', 'live': '实时', 'Reset view': '重置视角',
  'sphere': '球体', 'cloth': '布料', 'swatch': '样片', 'bust': '半身像', 'variants': '个变体', 'Warnings': '警告',
  'static export: the sky keeps the default sun': '静态导出：天空保持默认太阳方向',
  'panorama (equirectangular)': '全景图（等距柱状投影）',
};

const state = {
  lang: 'en', library: null, generation: 0, name: null, meta: null,
  values: {}, tiling: {}, textures: {}, keywords: {}, tier: null,
  mesh: 'sphere', orbit: null, variant: null, renderer: null, error: null, status: 'loading',
  codeLang: 'wgsl', pending: Promise.resolve(), renders: 0,
};

const t = (s) => (state.lang === 'zh' && ZH[s]) || s;
const text = (x) => (x ? (state.lang === 'zh' && x.zh) || x.en : '');
const $ = (id) => document.getElementById(id);

async function getJson(path) {
  const r = await fetch(BASE + path + (path.includes('?') ? '&' : '?') + 'g=' + state.generation, { cache: 'no-store' });
  if (!r.ok) throw new Error(`${path}: HTTP ${r.status}`);
  return r.json();
}
async function getText(path) {
  const r = await fetch(BASE + path, { cache: 'no-store' });
  if (!r.ok) throw new Error(`${path}: HTTP ${r.status}`);
  return r.text();
}

// Serialises work (variant swaps, renders) so tests can wait for quiet.
function queue(job) {
  state.pending = state.pending.then(job).catch((e) => showPreviewError(e));
  return state.pending;
}

// ---------------------------------------------------------------------------
// Values

function defaults(meta) {
  state.values = {};
  state.tiling = {};
  state.textures = {};
  for (const p of meta.parameters) {
    if (p.kind === 'texture2d' || p.kind === 'cube') {
      state.textures[p.name] = { kind: 'builtin', name: p.default };
      if (p.texture && p.texture.tiling_member) state.tiling[p.name] = (p.texture.tiling_default || [1, 1, 0, 0]).slice();
    } else state.values[p.name] = JSON.parse(JSON.stringify(p.default));
  }
  state.keywords = {};
  for (const k of meta.keywords) state.keywords[k.name] = k.default;
  state.tier = meta.tiers.default;
}

// The value a condition's subject has now ("on"/"off" for bools and toggles).
function subjectValue(subject) {
  if (subject === 'tier') return state.tier;
  if (subject in state.keywords) return state.keywords[subject];
  if (subject in state.values && typeof state.values[subject] === 'boolean') return state.values[subject] ? 'on' : 'off';
  return null;
}
function holds(cond) {
  if (!cond) return true;
  if (Array.isArray(cond)) return cond.every(holds);
  const v = subjectValue(cond.subject);
  return v !== null && (v === cond.value) === (cond.op === 'equal');
}

// The compiled variant of the current tier and static keywords (aliases followed).
function findVariant(meta, tier, keywords) {
  const v = meta.variants.find((x) => x.tier === tier && Object.entries(x.keywords).every(([k, val]) => keywords[k] === val));
  if (!v) return null;
  return v.alias_of ? meta.variants.find((x) => x.id === v.alias_of) : v;
}
function compiled(tier, keywords) { return !!findVariant(state.meta, tier, keywords); }

// The material uniform's bytes, member by member at the layout's offsets.
function materialBytes(layout) {
  const buf = new ArrayBuffer(Math.ceil(layout.size / 16) * 16);
  const f32 = new Float32Array(buf);
  const i32 = new Int32Array(buf);
  const u32 = new Uint32Array(buf);
  const params = Object.fromEntries(state.meta.parameters.map((p) => [p.name, p]));
  for (const m of layout.members) {
    const p = params[m.parameter];
    const o = m.offset / 4;
    const v = state.values[m.parameter];
    switch (m.encoding) {
      case 'f32': f32[o] = Number(v); break;
      case 'i32': i32[o] = Math.round(Number(v)); break;
      case 'bool_u32': u32[o] = v ? 1 : 0; break;
      case 'vector': f32.set(v.slice(0, m.size / 4), o); break;
      case 'color': {
        const hdr = p && p.color && p.color.hdr;
        f32.set([0, 1, 2].map((i) => (hdr ? v[i] : bake.srgbToLinear(v[i]))).concat([v[3]]), o);
        break;
      }
      case 'curve': f32.set(bake.packCurve(bake.sampleCurve(v, p.curve.samples), m.size / 4), o); break;
      case 'tiling_offset': f32.set(state.tiling[m.parameter] || [1, 1, 0, 0], o); break;
      default: throw new Error(`uniform member ${m.name}: encoding ${m.encoding} is not one the page writes`);
    }
  }
  return new Uint8Array(buf);
}

function instances() {
  const out = {};
  for (const pass of state.meta.passes) {
    const i = pass.instances;
    out[pass.name] = i.fixed !== undefined ? i.fixed : i.parameter !== undefined ? Math.max(0, Math.round(Number(state.values[i.parameter]))) : 1;
  }
  return out;
}

// Pipeline constants of the current keyword values (WebGPU takes numbers).
function constants(variant) {
  const c = {};
  for (const pc of variant.shader.pipeline_constants) {
    const value = state.keywords[pc.name] !== undefined ? state.keywords[pc.name] : pc.default;
    const i = pc.values.indexOf(value);
    c[pc.name] = i >= 0 ? i : 0;
  }
  return c;
}

// ---------------------------------------------------------------------------
// Preview

function camera() {
  const o = state.orbit;
  if (!o.moved) return o.base;
  const d = [Math.cos(o.pitch) * Math.sin(o.yaw), Math.sin(o.pitch), Math.cos(o.pitch) * Math.cos(o.yaw)];
  return { ...o.base, eye: [0, 1, 2].map((i) => o.base.target[i] + d[i] * o.dist) };
}

async function resetOrbit() {
  const r = state.renderer;
  const mesh = await r.mesh(state.mesh);
  const base = mesh.info.camera;
  const off = [0, 1, 2].map((i) => base.eye[i] - base.target[i]);
  const dist = Math.hypot(...off);
  state.orbit = { base, dist, yaw: Math.atan2(off[0], off[2]), pitch: Math.asin(off[1] / dist), moved: false };
}

function showPreviewError(e) {
  $('preview-error').textContent = String((e && e.message) || e);
  $('preview-error').hidden = false;
}

// Swaps the pipeline for the current tier/keywords (compiles only when the
// variant or its constants change), then uploads every value and renders.
async function applyVariant() {
  const r = state.renderer;
  if (!r || !state.meta) return;
  const v = findVariant(state.meta, state.tier, state.keywords);
  if (!v) throw new Error(`no compiled variant for tier ${state.tier} and ${JSON.stringify(state.keywords)}`);
  const consts = constants(v);
  const key = `${state.name}|${state.generation}|${v.id}|${JSON.stringify(consts)}`;
  if (state.variantKey !== key) {
    const file = v.shader.files.wgsl[0].path;
    const code = await getText(`api/files/${state.name}/${file}`);
    await r.setVariant(state.meta, v, code, consts);
    state.variantKey = key;
    state.variant = v;
    state.pipelineSwaps = (state.pipelineSwaps || 0) + 1;
    await uploadTextures();
    renderCode();
  }
  $('variant-id').textContent = v.id;
  uploadUniform();
  await render();
}

function uploadUniform() {
  const layout = state.variant && state.variant.shader.material_uniform;
  if (layout) state.renderer.writeMaterial(materialBytes(layout));
  state.uniformWrites = (state.uniformWrites || 0) + 1;
}

async function uploadTextures() {
  const r = state.renderer;
  for (const b of r.variant.textureSlots) {
    const p = state.meta.parameters.find((x) => x.name === b.parameter);
    if (p && p.kind === 'gradient') {
      r.setTexture(b.binding, r.rampTexture(bake.bakeGradient(state.values[p.name], p.gradient.width), b.texture.format));
    } else if (p && state.textures[p.name] && state.textures[p.name].kind === 'image' && b.texture.view_dimension === 'cube') {
      r.setTexture(b.binding, await panoramaCube(r, state.textures[p.name], b.texture.format));
    } else if (p && state.textures[p.name] && state.textures[p.name].kind === 'image') {
      r.setTexture(b.binding, await r.imageTexture(state.textures[p.name].bitmap, b.texture.format));
    } else if (b.texture.file && !(p && state.textures[p.name] && state.textures[p.name].set)) {
      // Unset, a texture that ships an image binds its file (`texture.file`).
      r.setTexture(b.binding, await r.fileTexture(b.texture.file));
    } else {
      r.setTexture(b.binding, r.builtinTexture(b.texture.default || 'white', b.texture.format, b.texture.view_dimension === 'cube'));
    }
  }
}

// A cube parameter's panorama as the engine's six faces, converted once per
// image and encoding (kept on the value: a variant swap re-binds it as is).
async function panoramaCube(r, value, format) {
  const srgb = /_srgb$/.test(format);
  if (!value.cube || value.cube.srgb !== srgb) {
    if (!value.pixels) value.pixels = await r.imagePixels(value.bitmap);
    const size = cubeFaceSize(value.bitmap.width, Math.min(1024, r.device.limits.maxTextureDimension2D));
    value.cube = { srgb, size, faces: equirectToCube(value.pixels, value.bitmap.width, value.bitmap.height, size, srgb) };
  }
  return r.cubeTexture(value.cube.faces, value.cube.size, format);
}

async function render() {
  const r = state.renderer;
  if (!r) return;
  await r.render(state.mesh, camera(), instances());
  state.renders += 1;
  $('preview-error').hidden = r.errors.length === 0;
  if (r.errors.length) $('preview-error').textContent = r.errors.join('\n');
}

// A parameter changed: only the uniform is rewritten (gradients re-upload their ramp).
function paramChanged(p, value) {
  state.values[p.name] = value;
  queue(async () => {
    if (p.kind === 'gradient') await uploadTextures();
    uploadUniform();
    await render();
  });
  if (p.kind === 'bool' || p.kind === 'int') refreshVisibility();
}

// ---------------------------------------------------------------------------
// Panel

function renderLibrary() {
  const list = $('materials');
  list.replaceChildren();
  for (const m of state.library.materials) {
    list.append(el('li', {}, el('button', {
      type: 'button', class: m.name === state.name ? 'active' : '', 'data-material': m.name,
      title: text(m.description), onclick: () => selectMaterial(m.name),
    }, el('span', { class: 'mname', text: text(m.label) }), el('span', { class: 'mid', text: `${m.name} · ${m.variants} ${t('variants')}` }))));
  }
  const banner = $('diagnostics');
  if (state.library.error) {
    banner.hidden = false;
    $('diagnostics-title').textContent = t('Build failed: the last good build stays visible');
    $('diagnostics-text').textContent = state.library.error;
  } else banner.hidden = true;
  $('mode').textContent = state.library.live ? `${t('live')} · #${state.library.generation}` : t('static export: no live rebuilds');
}

function tierPanel() {
  const meta = state.meta;
  const wrap = el('section', { class: 'group', id: 'tier-panel' }, el('h3', { text: t('Tier') }));
  const select = el('select', { 'data-tier': '' });
  for (const tier of meta.tiers.values) {
    const opt = el('option', { value: tier, text: tier + (tier === meta.tiers.reference ? ' ★' : '') });
    if (!compiled(tier, state.keywords)) { opt.disabled = true; opt.textContent += ` (${t('not compiled')})`; }
    select.append(opt);
  }
  select.value = state.tier;
  select.addEventListener('change', () => { state.tier = select.value; rebuildPanel(); queue(applyVariant); });
  wrap.append(select);
  // Measured (a rasteriser's timings, lavapipe unless measured elsewhere) and
  // the GPU model (AMD's compiler, per family) side by side, never mixed.
  const m = meta.measurements;
  const families = (meta.gpu_model && meta.gpu_model.families) || [];
  const modelTip = `${t('GPU model')}: ${t('loop-aware executed cost ÷ standard fast, fragment stage')}`;
  const table = el('table', { class: 'tiers' });
  table.append(el('tr', {}, el('th', { text: t('Tier') }), el('th', { text: t('ms measured') }), el('th', { text: t('× measured') }),
    ...families.map((f) => el('th', { text: `${f.family} ×`, title: `${modelTip} (${f.device}, ${f.driver})` })),
    ...(families.length ? [el('th', { text: t('VGPRs / waves'), title: `${families[0].device}` })] : []),
    el('th', { text: t('FLIP mean vs reference') })));
  for (const tier of meta.tiers.values) {
    const row = m && m.tiers.find((x) => x.tier === tier);
    const modelled = families.map((f) => f.tiers.find((x) => x.tier === tier));
    const first = modelled[0];
    table.append(el('tr', { class: tier === state.tier ? 'current' : '' },
      el('td', { text: tier, title: text(meta.tiers.descriptions[tier]) }),
      el('td', { text: row ? row.gpu_ms.toFixed(1) : '—' }),
      el('td', { text: row && row.ratio_to_standard_fast ? row.ratio_to_standard_fast.toFixed(2) : '—' }),
      ...modelled.map((c) => el('td', { text: c ? c.executed_ratio.toFixed(2) : '—' })),
      ...(families.length ? [el('td', { text: first ? `${first.vgprs} / ${first.waves}` : '—' })] : []),
      el('td', { text: row ? row.flip_mean.toFixed(3) : '—' })));
  }
  wrap.append(table);
  // What the chosen tier computes (each tier's in its cell's tooltip).
  wrap.append(el('p', { class: 'desc', text: text(meta.tiers.descriptions[state.tier]) }));
  if (m) {
    wrap.append(el('p', { class: 'note', text: `${t('measured')}: ${m.adapter}, ${m.width}×${m.height} ${m.scene}` + (m.inputs_hash !== meta.inputs_hash ? ` — ${t('measured on an earlier version of this material')}` : '') }));
  } else wrap.append(el('p', { class: 'note', text: t('no measurements') }));
  if (families.length) {
    const stale = meta.gpu_model.inputs_hash && meta.gpu_model.inputs_hash !== meta.inputs_hash;
    wrap.append(el('p', { class: 'note', text: `${modelTip}: ${families.map((f) => `${f.family} (${f.device}, ${f.driver})`).join(', ')}` + (stale ? ` — ${t('modelled on an earlier version of this material')}` : '') }));
  }
  return wrap;
}

function keywordControl(k) {
  const row = el('div', { class: 'row keyword', 'data-keyword': k.name, title: text(k.tooltip) });
  row.append(el('label', { class: 'label', text: text(k.label), title: text(k.tooltip) }));
  // Only values with a compiled variant (given the other keywords and the tier) are offered.
  const ok = (value) => compiled(state.tier, { ...state.keywords, [k.name]: value }) || k.mode === 'constant';
  let control;
  if (k.kind === 'toggle') {
    control = el('input', { type: 'checkbox' });
    control.checked = state.keywords[k.name] === 'on';
    control.disabled = !ok(control.checked ? 'off' : 'on');
    control.addEventListener('change', () => { state.keywords[k.name] = control.checked ? 'on' : 'off'; rebuildPanel(); queue(applyVariant); });
  } else {
    control = el('select');
    for (const v of k.values) {
      const opt = el('option', { value: v, text: v });
      if (!ok(v)) { opt.disabled = true; opt.textContent += ` (${t('not compiled')})`; }
      control.append(opt);
    }
    control.value = state.keywords[k.name];
    control.addEventListener('change', () => { state.keywords[k.name] = control.value; rebuildPanel(); queue(applyVariant); });
  }
  row.append(control, el('span', { class: 'kwmode', text: k.mode }));
  return row;
}

function paramControl(p) {
  const row = el('div', { class: 'row param', 'data-param': p.name, 'data-kind': p.kind });
  row.append(el('label', { class: 'label', text: text(p.label), title: text(p.tooltip) }));
  const v = state.values[p.name];
  let c;
  switch (p.kind) {
    case 'float': case 'int': c = numberControl(p, v, (x) => paramChanged(p, x)); break;
    case 'bool': c = boolControl(p, v, (x) => paramChanged(p, x)); break;
    case 'color': c = colorControl(p, v, (x) => paramChanged(p, x)); break;
    case 'vec2': case 'vec3': case 'vec4': c = vectorControl(p, v, (x) => paramChanged(p, x)); break;
    case 'texture2d': case 'cube': {
      const b = state.variant && state.variant.shader.bindings.find((x) => x.group === 1 && x.parameter === p.name);
      const shipped = b && b.texture ? (b.texture.file ? b.texture.file.path : b.texture.default) : null;
      c = textureControl(p, state.textures[p.name], shipped, state.tiling[p.name], t,
        (x) => { state.textures[p.name] = x; queue(async () => { await uploadTextures(); await render(); }); },
        (x) => { state.tiling[p.name] = x; queue(async () => { uploadUniform(); await render(); }); });
      break;
    }
    case 'curve': c = curveControl(p, v, t, (x) => paramChanged(p, x)); break;
    case 'gradient': c = gradientControl(p, v, t, (x) => paramChanged(p, x)); break;
    default: c = el('span', { class: 'unit', text: `${p.kind}: ${JSON.stringify(v)}` });
  }
  row.append(c);
  if (p.tooltip) row.append(el('div', { class: 'tooltip', text: text(p.tooltip) }));
  return row;
}

function refreshVisibility() {
  for (const row of document.querySelectorAll('#panel [data-param]')) {
    const p = state.meta.parameters.find((x) => x.name === row.dataset.param);
    row.hidden = !holds(p.show_if);
  }
  for (const row of document.querySelectorAll('#panel [data-keyword]')) {
    const k = state.meta.keywords.find((x) => x.name === row.dataset.keyword);
    row.hidden = !holds(k.show_if);
  }
  for (const g of document.querySelectorAll('#panel section[data-group]')) {
    g.hidden = [...g.querySelectorAll('.row')].every((r) => r.hidden);
  }
}

function rebuildPanel() {
  const meta = state.meta;
  $('title').textContent = text(meta.label);
  $('description').textContent = text(meta.description);
  const panel = $('panel');
  panel.replaceChildren(tierPanel());
  // Presets.
  const presets = el('section', { class: 'group', id: 'presets' }, el('h3', { text: t('Presets') }));
  for (const pr of meta.presets) presets.append(el('button', { type: 'button', 'data-preset': pr.name, text: text(pr.label), title: pr.name, onclick: () => applyPreset(pr.name) }));
  presets.append(el('button', { type: 'button', class: 'reset', text: t('Reset'), onclick: () => { defaults(meta); rebuildPanel(); queue(applyVariant); } }));
  panel.append(presets);
  // Groups in order, keywords then parameters (by `order`).
  for (const g of meta.groups) {
    const sec = el('section', { class: 'group', 'data-group': g.name }, el('h3', { text: text(g.label) }));
    for (const k of meta.keywords.filter((x) => x.group === g.name)) sec.append(keywordControl(k));
    const ps = meta.parameters.map((p, i) => ({ p, i })).filter((x) => x.p.group === g.name).sort((a, b) => a.p.order - b.p.order || a.i - b.i);
    for (const { p } of ps) sec.append(paramControl(p));
    panel.append(sec);
  }
  const stray = meta.keywords.filter((k) => !meta.groups.some((g) => g.name === k.group));
  if (stray.length) panel.append(el('section', { class: 'group', 'data-group': '' }, el('h3', { text: t('Keywords') }), ...stray.map(keywordControl)));
  refreshVisibility();
}

async function applyPreset(name) {
  const pr = state.meta.presets.find((x) => x.name === name);
  if (!pr) return;
  for (const [key, v] of Object.entries(pr.values)) {
    if (key === 'tier') state.tier = String(v);
    else if (key in state.keywords) state.keywords[key] = typeof v === 'boolean' ? (v ? 'on' : 'off') : String(v);
    else if (key in state.textures) state.textures[key] = { kind: 'builtin', name: String(v), set: true };
    else state.values[key] = JSON.parse(JSON.stringify(v));
  }
  rebuildPanel();
  await queue(applyVariant);
}

// ---------------------------------------------------------------------------
// Code

const LANGS = [['wgsl', 'WGSL'], ['hlsl', 'HLSL'], ['glsl', 'GLSL'], ['msl', 'MSL'], ['spirv', 'SPIR-V']];

async function renderCode() {
  const v = state.variant;
  const box = $('code-files');
  box.replaceChildren();
  const tabs = $('code-tabs');
  tabs.replaceChildren(...LANGS.map(([id, label]) => el('button', { type: 'button', class: id === state.codeLang ? 'active' : '', 'data-lang': id, text: label, onclick: () => { state.codeLang = id; renderCode(); } })));
  if (!v) return;
  for (const f of v.shader.files[state.codeLang] || []) {
    const path = state.codeLang === 'spirv' ? `api/spirv/${state.name}/${f.path}.txt` : `api/files/${state.name}/${f.path}`;
    const pre = el('pre', { class: 'code', text: '…' });
    const copy = el('button', { type: 'button', class: 'copy', text: t('Copy'), onclick: async () => {
      try { await navigator.clipboard.writeText(pre.textContent); copy.textContent = t('Copied'); } catch (e) {
        const range = document.createRange(); range.selectNodeContents(pre);
        const sel = getSelection(); sel.removeAllRanges(); sel.addRange(range); document.execCommand('copy');
        copy.textContent = t('Copied');
      }
      setTimeout(() => { copy.textContent = t('Copy'); }, 1200);
    } });
    const consts = Object.entries(f.constants || {}).map(([k, val]) => `${k}=${val}`).join(' ');
    box.append(el('div', { class: 'file' }, el('div', { class: 'filehead' }, el('span', { text: f.path + (state.codeLang === 'spirv' ? ' (disassembly)' : '') + (consts ? `  [${consts}]` : '') }), el('span', { class: 'sha', text: f.sha256.slice(0, 12) }), copy), pre));
    getText(path).then((s) => { pre.textContent = s; }).catch((e) => { pre.textContent = String(e); });
  }
}

// ---------------------------------------------------------------------------
// Loading and live updates

async function selectMaterial(name, keep) {
  const meta = await getJson(`api/materials/${name}.json`);
  const old = state.name === name ? { values: state.values, keywords: state.keywords, tier: state.tier, textures: state.textures, tiling: state.tiling } : null;
  state.name = name;
  state.meta = meta;
  defaults(meta);
  if (keep && old) {
    // A rebuild of the same material keeps what the user set where it still fits.
    for (const p of meta.parameters) {
      const prev = p.kind === 'texture2d' || p.kind === 'cube' ? old.textures[p.name] : old.values[p.name];
      if (prev === undefined) continue;
      if (p.kind === 'texture2d' || p.kind === 'cube') state.textures[p.name] = prev;
      else if (typeof prev === typeof p.default && Array.isArray(prev) === Array.isArray(p.default)) state.values[p.name] = prev;
      if (old.tiling[p.name] && state.tiling[p.name]) state.tiling[p.name] = old.tiling[p.name];
    }
    for (const k of meta.keywords) if (k.values.includes(old.keywords[k.name])) state.keywords[k.name] = old.keywords[k.name];
    if (meta.tiers.values.includes(old.tier)) state.tier = old.tier;
    if (!findVariant(meta, state.tier, state.keywords)) { state.tier = meta.tiers.default; for (const k of meta.keywords) state.keywords[k.name] = k.default; }
  }
  state.variantKey = null;
  renderLibrary();
  rebuildPanel();
  await queue(applyVariant);
  rebuildPanel();
}

async function refresh() {
  const lib = await getJson('api/library.json');
  const changed = lib.generation !== (state.library && state.library.generation);
  state.library = lib;
  state.generation = lib.generation;
  if (state.name && !lib.materials.some((m) => m.name === state.name)) state.name = null;
  const name = state.name || (lib.materials[0] && lib.materials[0].name);
  renderLibrary();
  if (name && (changed || !state.meta)) await selectMaterial(name, true);
}

function subscribe() {
  if (!state.library.live || !window.EventSource) return;
  const es = new EventSource(BASE + 'api/events');
  es.addEventListener('build', (e) => {
    const ev = JSON.parse(e.data);
    if (ev.generation !== state.generation) refresh().catch(showPreviewError);
  });
}

function setLanguage(lang) {
  state.lang = lang;
  document.documentElement.lang = lang === 'zh' ? 'zh-CN' : 'en';
  for (const b of document.querySelectorAll('[data-lang-switch]')) b.classList.toggle('active', b.dataset.langSwitch === lang);
  for (const n of document.querySelectorAll('[data-t]')) n.textContent = t(n.dataset.t);
  previewControls();
  if (state.library) renderLibrary();
  if (state.meta) { rebuildPanel(); renderCode(); }
}

function previewControls() {
  const box = $('preview-controls');
  box.replaceChildren();
  const mesh = el('select', { id: 'mesh' }, ...['sphere', 'cloth', 'swatch', 'bust'].map((m) => el('option', { value: m, text: t(m) })));
  mesh.value = state.mesh;
  mesh.addEventListener('change', () => queue(async () => { state.mesh = mesh.value; await resetOrbit(); await render(); }));
  const tm = el('select', { id: 'tonemap' }, ...TONEMAPS.map((x) => el('option', { value: x, text: x })));
  tm.value = state.renderer ? state.renderer.tonemap : 'aces';
  tm.addEventListener('change', () => { state.renderer.tonemap = tm.value; queue(render); });
  const r = state.renderer;
  const exposure = numberControl({ kind: 'float', range: [0, 16], soft_range: [0, 4], step: 0.01 }, r ? r.exposure : 1, (x) => { r.exposure = x; queue(render); });
  const dir = r ? normalize(r.light.direction) : [0, 1, 0];
  const az = numberControl({ kind: 'float', range: [-180, 180], step: 1 }, Math.round(Math.atan2(dir[0], dir[2]) * 180 / Math.PI), (x) => setLight(x, null));
  const elev = numberControl({ kind: 'float', range: [-89, 89], step: 1 }, Math.round(Math.asin(dir[1]) * 180 / Math.PI), (x) => setLight(null, x));
  az.dataset.light = 'azimuth';
  elev.dataset.light = 'elevation';
  box.append(
    el('label', {}, t('Mesh'), mesh), el('label', {}, t('Tone mapping'), tm),
    el('label', {}, t('Exposure'), exposure), el('label', {}, t('Light azimuth'), az), el('label', {}, t('Light elevation'), elev),
    el('button', { type: 'button', text: t('Reset view'), onclick: () => queue(async () => { await resetOrbit(); await render(); }) }));
}

let lightAngles = null;
function setLight(az, elev) {
  const r = state.renderer;
  if (!lightAngles) {
    const d = normalize(r.light.direction);
    lightAngles = [Math.atan2(d[0], d[2]) * 180 / Math.PI, Math.asin(d[1]) * 180 / Math.PI];
  }
  if (az !== null) lightAngles[0] = az;
  if (elev !== null) lightAngles[1] = elev;
  const [a, e] = lightAngles.map((x) => x * Math.PI / 180);
  r.light.direction = [Math.cos(e) * Math.sin(a), Math.sin(e), Math.cos(e) * Math.cos(a)];
  queue(render);
  refreshEnvironment();
}

// The sky's sun follows the light, as `weft preview --light` does: the
// server computes the environment (cube, SH) for the new sun. While the
// light is dragged, at most one request is in flight and only the latest
// direction is fetched next; the direct light moves at once.
let envWanted = null;
function refreshEnvironment() {
  const r = state.renderer;
  if (!r || !state.library || !state.library.live) {
    // A static export has only the default sky: the direct light moves alone.
    $('env-note').hidden = !(r && state.library && !state.library.live);
    return;
  }
  envWanted = r.light.direction.slice();
  if (state.envBusy) return;
  state.envBusy = (async () => {
    try {
      while (envWanted) {
        const d = envWanted;
        envWanted = null;
        const got = await r.fetchEnvironment(d);
        if (!got) { $('env-note').hidden = false; break; }
        if (envWanted) continue; // already stale: fetch the latest instead
        await queue(async () => { r.uploadEnvironment(got.env, got.bin); state.envLoads = (state.envLoads || 0) + 1; await render(); });
      }
    } catch (e) {
      showPreviewError(e);
    } finally {
      state.envBusy = null;
    }
  })();
}

function orbitControls(canvas) {
  let last = null;
  canvas.addEventListener('pointerdown', (e) => { last = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
  canvas.addEventListener('pointermove', (e) => {
    if (!last || !state.orbit) return;
    const o = state.orbit;
    o.yaw -= (e.clientX - last[0]) * 0.01;
    o.pitch = Math.min(1.5, Math.max(-1.5, o.pitch + (e.clientY - last[1]) * 0.01));
    o.moved = true;
    last = [e.clientX, e.clientY];
    queue(render);
  });
  canvas.addEventListener('pointerup', () => { last = null; });
  canvas.addEventListener('wheel', (e) => {
    if (!state.orbit) return;
    e.preventDefault();
    state.orbit.dist = Math.min(20, Math.max(1.2, state.orbit.dist * Math.exp(e.deltaY * 0.001)));
    state.orbit.moved = true;
    queue(render);
  }, { passive: false });
}

async function main() {
  for (const b of document.querySelectorAll('[data-lang-switch]')) b.addEventListener('click', () => setLanguage(b.dataset.langSwitch));
  const canvas = $('preview');
  try {
    state.renderer = await Renderer.create(canvas, BASE);
    $('adapter').textContent = state.renderer.adapterInfo;
    await resetOrbit();
    orbitControls(canvas);
  } catch (e) {
    state.webgpuError = String(e.message || e);
    showPreviewError(e);
  }
  previewControls();
  setLanguage(state.lang);
  await refresh();
  subscribe();
  await state.pending;
  state.status = state.webgpuError ? 'no-webgpu' : 'ready';
  document.body.dataset.status = state.status;
}

// What tests and scripts drive (the UI itself is plain DOM).
window.weftInspector = {
  state,
  ready: main().catch((e) => { state.status = 'error'; state.error = String((e && e.stack) || e); document.body.dataset.status = 'error'; }),
  idle: async () => {
    let p;
    do { p = state.pending; await p; if (state.envBusy) await state.envBusy; } while (p !== state.pending || state.envBusy);
    return state.renders;
  },
  select: (name) => selectMaterial(name),
  setLanguage,
  applyPreset,
  variantId: () => (state.variant ? state.variant.id : null),
  capture: async (w, h, mesh) => { await window.weftInspector.idle(); const c = camera(); return state.renderer.captureHdr(mesh || state.mesh, mesh ? (await state.renderer.mesh(mesh)).info.camera : c, w, h, instances()); },
  materialBytes: () => Array.from(materialBytes(state.variant.shader.material_uniform)),
  bakeCurve: (keys, n, floats) => Array.from(new Uint8Array(bake.packCurve(bake.sampleCurve(keys, n), floats).buffer)),
  bakeGradient: (stops, width) => Array.from(bake.bakeGradient(stops, width)),
  equirectToCube: (rgba, w, h, size, srgb) => Array.from(equirectToCube(Uint8Array.from(rgba), w, h, size, srgb)),
  // The six faces a cube parameter's panorama was converted to: { size, srgb, faces (base64) }.
  cubeFaces: (name) => {
    const c = state.textures[name] && state.textures[name].cube;
    if (!c) return null;
    let s = '';
    for (let i = 0; i < c.faces.length; i += 0x8000) s += String.fromCharCode.apply(null, c.faces.subarray(i, i + 0x8000));
    return { size: c.size, srgb: c.srgb, faces: btoa(s) };
  },
};
