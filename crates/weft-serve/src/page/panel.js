// Controls of the panel, one per parameter kind, built from a parameter's
// metadata alone. Each control calls `onChange(value)` with the parameter's
// value in the metadata's own form (sRGB-edited colours as [r, g, b, a],
// HDR colours linear, curves as keyframes, gradients as stops).

import * as bake from './bake.js';

export function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null || v === false) continue;
    if (k === 'class') e.className = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else if (k === 'text') e.textContent = v;
    else e.setAttribute(k, v === true ? '' : v);
  }
  for (const c of children.flat()) if (c !== null && c !== undefined) e.append(c);
  return e;
}

const clamp = (x, lo, hi) => Math.min(Math.max(x, lo), hi);
const fmt = (x, step) => {
  if (!Number.isFinite(x)) return String(x);
  const digits = step && step < 1 ? Math.min(6, Math.max(0, Math.ceil(-Math.log10(step)))) : (Number.isInteger(x) ? 0 : 3);
  return Number(x.toFixed(digits)).toString();
};

// Slider position (0..1) <-> value, with Unity's PowerSlider mapping.
function toValue(pos, lo, hi, power) { return lo + (hi - lo) * Math.pow(pos, power); }
function toPos(v, lo, hi, power) { return hi > lo ? Math.pow(clamp((v - lo) / (hi - lo), 0, 1), 1 / power) : 0; }

// float / int: slider over the soft range (else the range), number field
// over the full range; step and power honoured.
export function numberControl(p, value, onChange) {
  const isInt = p.kind === 'int';
  const range = p.range || null;
  const span = p.soft_range || p.range || null;
  const step = p.step || (isInt ? 1 : null);
  const power = p.power || 1;
  const wrap = el('div', { class: 'number' });
  const snap = (x) => {
    if (range) x = clamp(x, range[0], range[1]);
    if (step) {
      const origin = range ? range[0] : 0;
      x = origin + Math.round((x - origin) / step) * step;
      x = Number(x.toFixed(10));
    }
    if (isInt) x = Math.round(x);
    return x;
  };
  const field = el('input', { type: 'number', step: step || 'any', min: range ? range[0] : undefined, max: range ? range[1] : undefined, value: fmt(value, step) });
  let slider = null;
  if (span) {
    slider = el('input', { type: 'range', min: 0, max: 1000, step: 1, value: Math.round(toPos(value, span[0], span[1], power) * 1000) });
    slider.addEventListener('input', () => {
      const v = snap(toValue(Number(slider.value) / 1000, span[0], span[1], power));
      field.value = fmt(v, step);
      onChange(v);
    });
    wrap.append(slider);
  }
  field.addEventListener('change', () => {
    const raw = Number(field.value);
    if (!Number.isFinite(raw)) { field.value = fmt(value, step); return; }
    const v = snap(raw);
    field.value = fmt(v, step);
    if (slider) slider.value = Math.round(toPos(v, span[0], span[1], power) * 1000);
    value = v;
    onChange(v);
  });
  wrap.append(field);
  return wrap;
}

export function boolControl(p, value, onChange) {
  const box = el('input', { type: 'checkbox' });
  box.checked = !!value;
  box.addEventListener('change', () => onChange(box.checked));
  return box;
}

const hex2 = (x) => Math.round(clamp(x, 0, 1) * 255).toString(16).padStart(2, '0');
const toHex = (rgb) => '#' + rgb.slice(0, 3).map(hex2).join('');
const fromHex = (h) => [1, 3, 5].map((i) => parseInt(h.slice(i, i + 2), 16) / 255);

// Colours: LDR colours are edited in sRGB (the value is sRGB; the uniform
// gets linear); HDR colours are linear: a picker for the hue (display
// encoded) and an intensity, plus the exact linear components.
export function colorControl(p, value, onChange) {
  const hdr = p.color && p.color.hdr;
  const v = value.slice();
  const wrap = el('div', { class: 'color' });
  const picker = el('input', { type: 'color' });
  const alpha = el('input', { type: 'number', step: 0.01, min: 0, max: 1, value: fmt(v[3], 0.01), title: 'alpha' });
  const comps = [0, 1, 2].map((i) => el('input', { type: 'number', step: 'any', value: fmt(v[i], 0.001), title: 'rgb'[i] + (hdr ? ' (linear)' : ' (sRGB)') }));
  const intensity = () => Math.max(v[0], v[1], v[2], 1e-6);
  const sync = () => {
    if (hdr) {
      const k = Math.max(1, intensity());
      picker.value = toHex([0, 1, 2].map((i) => bake.linearToSrgb(clamp(v[i] / k, 0, 1))));
    } else picker.value = toHex(v);
    comps.forEach((c, i) => { c.value = fmt(v[i], 0.001); });
  };
  sync();
  picker.addEventListener('input', () => {
    const rgb = fromHex(picker.value);
    if (hdr) {
      const k = Math.max(1, intensity());
      for (let i = 0; i < 3; i++) v[i] = bake.srgbToLinear(rgb[i]) * k;
    } else for (let i = 0; i < 3; i++) v[i] = rgb[i];
    comps.forEach((c, i) => { c.value = fmt(v[i], 0.001); });
    onChange(v.slice());
  });
  comps.forEach((c, i) => c.addEventListener('change', () => {
    const x = Number(c.value);
    if (!Number.isFinite(x)) return sync();
    v[i] = hdr ? Math.max(0, x) : clamp(x, 0, 1);
    sync();
    onChange(v.slice());
  }));
  alpha.addEventListener('change', () => {
    const x = Number(alpha.value);
    if (Number.isFinite(x)) v[3] = clamp(x, 0, 1);
    alpha.value = fmt(v[3], 0.01);
    onChange(v.slice());
  });
  wrap.append(picker, ...comps, el('span', { class: 'unit', text: 'α' }), alpha);
  if (hdr) wrap.append(el('span', { class: 'unit', text: 'HDR, linear' }));
  return wrap;
}

export function vectorControl(p, value, onChange) {
  const v = value.slice();
  const wrap = el('div', { class: 'vector' });
  v.forEach((x, i) => {
    const f = el('input', { type: 'number', step: p.step || 'any', value: fmt(x, 0.001) });
    f.addEventListener('change', () => {
      const n = Number(f.value);
      if (!Number.isFinite(n)) { f.value = fmt(v[i], 0.001); return; }
      v[i] = p.range ? clamp(n, p.range[0], p.range[1]) : n;
      f.value = fmt(v[i], 0.001);
      onChange(v.slice());
    });
    wrap.append(f);
  });
  return wrap;
}

// Texture slots: the built-in default the variant binds (a texture's
// default can depend on keywords: the binding's `texture.default` says
// which, `defaultName` passes it; or the image it ships, `texture.file`), a file picker for the user's own image
// (2D textures: the image; cubes: an equirectangular panorama, converted to
// the six faces when bound), and tiling/offset when the metadata has a
// member for it.
export function textureControl(p, value, defaultName, tiling, t, onChange, onTiling) {
  const wrap = el('div', { class: 'texture' });
  const label = el('span', { class: 'texname' });
  const show = () => {
    label.textContent = value && value.kind === 'image' ? value.file : `${t('default')}: ${defaultName || value.name}`;
  };
  show();
  wrap.append(label);
  const cube = p.kind === 'cube';
  const input = el('input', { type: 'file', accept: 'image/*', title: cube ? t('panorama (equirectangular)') : undefined });
  input.addEventListener('change', async () => {
    const f = input.files && input.files[0];
    if (!f) return;
    try {
      let bitmap = await createImageBitmap(f, { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
      const k = 8192 / Math.max(bitmap.width, bitmap.height);
      if (cube && k < 1) {
        // More than a 1024² face needs; keeps the copy within WebGPU's limits.
        bitmap = await createImageBitmap(bitmap, { resizeWidth: Math.max(1, Math.round(bitmap.width * k)), resizeHeight: Math.max(1, Math.round(bitmap.height * k)), resizeQuality: 'high', colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
      }
      value = { kind: 'image', bitmap, file: f.name };
      show();
      onChange(value);
    } catch (e) {
      label.textContent = `${f.name}: ${e.message}`;
    }
  });
  const reset = el('button', { type: 'button', text: '×', title: t('use the default'), onclick: () => { value = { kind: 'builtin', name: p.default }; input.value = ''; show(); onChange(value); } });
  wrap.append(input, reset);
  if (cube) wrap.append(el('span', { class: 'unit', text: t('panorama (equirectangular)') }));
  if (tiling) {
    wrap.append(el('span', { class: 'unit', text: t('tiling / offset') }), vectorControl({ step: null }, tiling, onTiling));
  }
  return wrap;
}

// Curve editor: the curve drawn from the keyframes with the toolchain's
// evaluation, draggable keys, and the keys as numbers (time, value, slopes).
export function curveControl(p, value, t, onChange) {
  let keys = value.map((k) => ({ ...k }));
  const wrap = el('div', { class: 'curve' });
  const W = 260;
  const H = 110;
  const canvas = el('canvas', { width: W, height: H });
  const table = el('div', { class: 'keys' });
  const range = p.range || null;
  const bounds = () => {
    const samples = bake.sampleCurve(keys, 64);
    let lo = Math.min(...samples, ...keys.map((k) => k.value));
    let hi = Math.max(...samples, ...keys.map((k) => k.value));
    if (range) { lo = Math.min(lo, range[0]); hi = Math.max(hi, range[1]); }
    if (hi - lo < 1e-6) { lo -= 0.5; hi += 0.5; }
    const [t0, t1] = bake.curveTimeRange(keys);
    return { t0, t1: t1 > t0 ? t1 : t0 + 1, lo, hi };
  };
  let b = bounds();
  const X = (time) => 6 + (W - 12) * (time - b.t0) / (b.t1 - b.t0);
  const Y = (v) => H - 6 - (H - 12) * (v - b.lo) / (b.hi - b.lo);
  const draw = () => {
    const g = canvas.getContext('2d');
    g.clearRect(0, 0, W, H);
    g.strokeStyle = '#555'; g.strokeRect(0.5, 0.5, W - 1, H - 1);
    g.strokeStyle = '#6cf'; g.beginPath();
    for (let i = 0; i <= 100; i++) {
      const time = b.t0 + (b.t1 - b.t0) * i / 100;
      const y = Y(bake.evalCurve(keys, time));
      if (i) g.lineTo(X(time), y); else g.moveTo(X(time), y);
    }
    g.stroke();
    // The samples the uniform gets.
    g.fillStyle = '#888';
    bake.sampleCurve(keys, p.curve.samples).forEach((v, i, all) => {
      const time = b.t0 + (b.t1 - b.t0) * (all.length > 1 ? i / (all.length - 1) : 0);
      g.fillRect(X(time) - 1, Y(v) - 1, 2, 2);
    });
    g.fillStyle = '#fc6';
    for (const k of keys) { g.beginPath(); g.arc(X(k.time), Y(k.value), 4, 0, 7); g.fill(); }
  };
  const emit = () => { draw(); onChange(keys.map((k) => ({ ...k }))); };
  const rows = () => {
    table.replaceChildren(el('div', { class: 'keyhead' }, ...['time', 'value', 'in', 'out', ''].map((h) => el('span', { text: t(h) }))));
    keys.forEach((k, i) => {
      const field = (name) => {
        const f = el('input', { type: 'number', step: 'any', value: fmt(k[name], 0.001) });
        f.addEventListener('change', () => {
          const n = Number(f.value);
          if (!Number.isFinite(n)) { f.value = fmt(k[name], 0.001); return; }
          k[name] = n;
          if (name === 'time') { keys.sort((a, c) => a.time - c.time); b = bounds(); rows(); }
          b = bounds();
          emit();
        });
        return f;
      };
      const del = el('button', { type: 'button', text: '−', title: t('remove key'), disabled: keys.length <= 1, onclick: () => { keys.splice(i, 1); b = bounds(); rows(); emit(); } });
      table.append(el('div', { class: 'keyrow' }, field('time'), field('value'), field('in_slope'), field('out_slope'), del));
    });
    table.append(el('button', { type: 'button', text: '+ ' + t('key'), onclick: () => {
      const last = keys[keys.length - 1];
      const prev = keys.length > 1 ? keys[keys.length - 2] : { time: last.time - 1 };
      const time = (last.time + prev.time) / 2;
      keys.push({ time, value: bake.evalCurve(keys, time), in_slope: 0, out_slope: 0 });
      keys.sort((a, c) => a.time - c.time);
      b = bounds(); rows(); emit();
    } }));
  };
  let drag = -1;
  canvas.addEventListener('pointerdown', (e) => {
    const r = canvas.getBoundingClientRect();
    const x = e.clientX - r.left;
    const y = e.clientY - r.top;
    drag = keys.findIndex((k) => Math.hypot(X(k.time) - x, Y(k.value) - y) < 8);
    if (drag >= 0) canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointermove', (e) => {
    if (drag < 0) return;
    const r = canvas.getBoundingClientRect();
    const y = e.clientY - r.top;
    let v = b.lo + (H - 6 - y) / (H - 12) * (b.hi - b.lo);
    if (range) v = clamp(v, range[0], range[1]);
    // Inner keys move in time too, between their neighbours.
    if (drag > 0 && drag < keys.length - 1) {
      const x = e.clientX - r.left;
      const time = b.t0 + (x - 6) / (W - 12) * (b.t1 - b.t0);
      keys[drag].time = clamp(time, keys[drag - 1].time + 1e-3, keys[drag + 1].time - 1e-3);
    }
    keys[drag].value = v;
    draw();
  });
  canvas.addEventListener('pointerup', () => { if (drag >= 0) { drag = -1; b = bounds(); rows(); emit(); } });
  draw();
  rows();
  wrap.append(canvas, table);
  return wrap;
}

// Gradient editor: the ramp drawn from the toolchain's bake (what is
// uploaded), stops with position, sRGB colour and alpha.
export function gradientControl(p, value, t, onChange) {
  let stops = value.map((s) => ({ position: s.position, color: s.color.slice() }));
  const wrap = el('div', { class: 'gradient' });
  const bar = el('canvas', { width: p.gradient.width, height: 1, class: 'ramp' });
  const list = el('div', { class: 'stops' });
  const draw = () => {
    const rgba = bake.bakeGradient(stops, p.gradient.width);
    const g = bar.getContext('2d');
    g.putImageData(new ImageData(new Uint8ClampedArray(rgba), p.gradient.width, 1), 0, 0);
  };
  const emit = () => { draw(); onChange(stops.map((s) => ({ position: s.position, color: s.color.slice() }))); };
  const rows = () => {
    list.replaceChildren();
    stops.forEach((s, i) => {
      const pos = el('input', { type: 'number', step: 0.01, min: 0, max: 1, value: fmt(s.position, 0.001) });
      pos.addEventListener('change', () => {
        const n = Number(pos.value);
        if (Number.isFinite(n)) s.position = clamp(n, 0, 1);
        stops.sort((a, c) => a.position - c.position);
        rows(); emit();
      });
      const color = colorControl({ color: { hdr: false } }, s.color, (c) => { s.color = c; emit(); });
      const del = el('button', { type: 'button', text: '−', title: t('remove stop'), disabled: stops.length <= 1, onclick: () => { stops.splice(i, 1); rows(); emit(); } });
      list.append(el('div', { class: 'stop' }, pos, color, del));
    });
    list.append(el('button', { type: 'button', text: '+ ' + t('stop'), onclick: () => {
      const x = 0.5;
      const c = bake.gradientAt(stops, x);
      stops.push({ position: x, color: [bake.linearToSrgb(c[0]), bake.linearToSrgb(c[1]), bake.linearToSrgb(c[2]), c[3]].map((v) => Number(v.toFixed(4))) });
      stops.sort((a, b2) => a.position - b2.position);
      rows(); emit();
    } }));
  };
  draw();
  rows();
  wrap.append(bar, list);
  return wrap;
}
