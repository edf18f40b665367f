// The WebGPU preview: draws one variant from its metadata alone, the way
// weft-render draws it (docs/engine-interface.md). Group 0 is filled from the
// server's environment (the prefiltered sky cube and SH weft-render computes)
// and the build's LUT files, group 2 from the mesh's model matrix, group 1
// from the panel's values at the metadata's offsets. The picture is linear
// HDR in an rgba16float target; exposure and tone mapping happen after the
// passes, as weft-render's image.rs does them.

import * as bake from './bake.js';

const HDR_FORMAT = 'rgba16float';
// Every pass of every material draws into one attachment of this format
// (`passes[].depth_stencil.format`, weft_meta::DEPTH_STENCIL_FORMAT).
const DEPTH_FORMAT = 'depth24plus-stencil8';

// ---------------------------------------------------------------------------
// Small maths, as crates/weft-render/src/math.rs (column-major, WebGPU clip space)

export function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
export function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
export function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
export function normalize(a) {
  const l = Math.hypot(a[0], a[1], a[2]);
  return l > 0 ? [a[0] / l, a[1] / l, a[2] / l] : [0, 0, 0];
}

function lookAt(eye, target, up) {
  const f = normalize(sub(target, eye));
  let s = normalize(cross(f, up));
  if (s[0] === 0 && s[1] === 0 && s[2] === 0) s = [1, 0, 0];
  const u = cross(s, f);
  return [
    [s[0], u[0], -f[0], 0],
    [s[1], u[1], -f[1], 0],
    [s[2], u[2], -f[2], 0],
    [-dot(s, eye), -dot(u, eye), dot(f, eye), 1],
  ];
}

function perspective(fovY, aspect, near, far) {
  const h = 1 / Math.tan(0.5 * fovY);
  const w = h / aspect;
  const r = far / (near - far);
  return [[w, 0, 0, 0], [0, h, 0, 0], [0, 0, r, -1], [0, 0, r * near, 0]];
}

function mul(a, b) {
  const out = [[0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]];
  for (let c = 0; c < 4; c++) for (let r = 0; r < 4; r++) {
    let v = 0;
    for (let k = 0; k < 4; k++) v += a[k][r] * b[c][k];
    out[c][r] = v;
  }
  return out;
}

// General inverse (Gauss-Jordan, partial pivoting); identity when singular.
function inverse(m) {
  const a = [0, 1, 2, 3].map((r) => [0, 1, 2, 3].map((c) => m[c][r]));
  const inv = [0, 1, 2, 3].map((r) => [0, 1, 2, 3].map((c) => (r === c ? 1 : 0)));
  for (let c = 0; c < 4; c++) {
    let p = c;
    for (let r = c + 1; r < 4; r++) if (Math.abs(a[r][c]) > Math.abs(a[p][c])) p = r;
    if (Math.abs(a[p][c]) < 1e-12) return [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]];
    [a[c], a[p]] = [a[p], a[c]];
    [inv[c], inv[p]] = [inv[p], inv[c]];
    const d = a[c][c];
    for (let k = 0; k < 4; k++) { a[c][k] /= d; inv[c][k] /= d; }
    for (let r = 0; r < 4; r++) {
      if (r === c) continue;
      const f = a[r][c];
      for (let k = 0; k < 4; k++) { a[r][k] -= f * a[c][k]; inv[r][k] -= f * inv[c][k]; }
    }
  }
  return [0, 1, 2, 3].map((c) => [0, 1, 2, 3].map((r) => inv[r][c]));
}

function normalMatrix(m) {
  const m3 = m.map((col) => col.slice());
  m3[3] = [0, 0, 0, 1];
  for (let c = 0; c < 3; c++) m3[c][3] = 0;
  const inv = inverse(m3);
  const out = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]];
  for (let c = 0; c < 3; c++) for (let r = 0; r < 3; r++) out[c][r] = inv[r][c];
  return out;
}

const flat = (m) => m.flat();

// ---------------------------------------------------------------------------
// Metadata -> WebGPU

// Metadata enum names are WebGPU's in snake_case.
const gpuName = (s) => String(s).replace(/_/g, '-');

function visibility(stages) {
  let v = 0;
  for (const s of stages) v |= s === 'vertex' ? 1 : s === 'fragment' ? 2 : 4;
  return v;
}

function layoutEntry(b) {
  const e = { binding: b.binding, visibility: visibility(b.stages) };
  if (b.buffer) e.buffer = { type: gpuName(b.buffer.type), hasDynamicOffset: b.buffer.has_dynamic_offset, minBindingSize: b.buffer.min_binding_size };
  else if (b.texture) e.texture = { sampleType: gpuName(b.texture.sample_type), viewDimension: gpuName(b.texture.view_dimension), multisampled: b.texture.multisampled };
  else if (b.sampler) e.sampler = { type: gpuName(b.sampler.binding_type) };
  else throw new Error(`binding ${b.name} has no buffer, texture or sampler entry`);
  return e;
}

function samplerDescriptor(s) {
  const d = {
    magFilter: s.mag_filter, minFilter: s.min_filter, mipmapFilter: s.mipmap_filter,
    addressModeU: gpuName(s.address_mode_u), addressModeV: gpuName(s.address_mode_v), addressModeW: gpuName(s.address_mode_w),
    lodMinClamp: s.lod_min_clamp, lodMaxClamp: s.lod_max_clamp, maxAnisotropy: s.anisotropy_clamp || 1,
  };
  if (s.compare) d.compare = gpuName(s.compare);
  return d;
}

function blendComponent(c) {
  return { operation: gpuName(c.operation), srcFactor: gpuName(c.src_factor), dstFactor: gpuName(c.dst_factor) };
}

function colorTargets(pass) {
  const targets = [];
  for (const t of pass.color_targets) {
    let mask = 0;
    for (const c of t.write_mask) mask |= { red: 1, green: 2, blue: 4, alpha: 8 }[c];
    // The preview's target is rgba16float, what the metadata asks for.
    const target = { format: HDR_FORMAT, writeMask: mask };
    if (t.blend) target.blend = { color: blendComponent(t.blend.color), alpha: blendComponent(t.blend.alpha) };
    targets[t.location] = target;
  }
  return targets;
}

function vertexFormatFloats(format) {
  const m = /x(\d)$/.exec(format);
  return m ? Number(m[1]) : 1;
}

function halfToFloat(h) {
  const s = (h & 0x8000) ? -1 : 1;
  const e = (h >> 10) & 0x1f;
  const f = h & 0x3ff;
  if (e === 0) return s * Math.pow(2, -14) * (f / 1024);
  if (e === 31) return f ? NaN : s * Infinity;
  return s * Math.pow(2, e - 15) * (1 + f / 1024);
}

const TONEMAP_WGSL = `
struct Params { exposure: f32, op: u32, pad0: u32, pad1: u32 }
@group(0) @binding(0) var hdr: texture_2d<f32>;
@group(0) @binding(1) var<uniform> params: Params;
@vertex fn vs(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
  let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
  return vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0);
}
fn aces(x: f32) -> f32 { return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0); }
fn neutral(c0: vec3<f32>) -> vec3<f32> {
  let start = 0.8 - 0.04; let desat = 0.15;
  var c = c0;
  let x = min(c.r, min(c.g, c.b));
  var offset = 0.04; if (x < 0.08) { offset = x - 6.25 * x * x; }
  c = c - vec3<f32>(offset);
  let peak = max(c.r, max(c.g, c.b));
  if (peak < start) { return clamp(c, vec3<f32>(0.0), vec3<f32>(1.0)); }
  let d = 1.0 - start;
  let new_peak = 1.0 - d * d / (peak + d - start);
  c = c * (new_peak / peak);
  let g = 1.0 - 1.0 / (desat * (peak - new_peak) + 1.0);
  return clamp(mix(c, vec3<f32>(new_peak), g), vec3<f32>(0.0), vec3<f32>(1.0));
}
fn encode(x: f32) -> f32 { if (x <= 0.0031308) { return x * 12.92; } return 1.055 * pow(x, 1.0 / 2.4) - 0.055; }
@fragment fn fs(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
  let t = textureLoad(hdr, vec2<i32>(p.xy), 0);
  var c = max(t.rgb * params.exposure, vec3<f32>(0.0));
  if (params.op == 0u) { c = vec3<f32>(aces(c.r), aces(c.g), aces(c.b)); }
  else if (params.op == 1u) { c = neutral(c); }
  else { c = clamp(c, vec3<f32>(0.0), vec3<f32>(1.0)); }
  return vec4<f32>(encode(c.r), encode(c.g), encode(c.b), 1.0);
}`;

export const TONEMAPS = ['aces', 'neutral', 'clamp'];

// ---------------------------------------------------------------------------
// Equirectangular panorama -> cube faces

// The engine's cube faces (crates/weft-render/src/environment.rs
// `cube_direction`, the WebGPU/D3D/Vulkan convention): layers +X, −X, +Y,
// −Y, +Z, −Z; texel (x, y) of an n×n face, rows top first, looks along
// cubeDirection(face, (x + 0.5) / n * 2 − 1, (y + 0.5) / n * 2 − 1).
export function cubeDirection(face, u, v) {
  const d = [[1, -v, -u], [-1, -v, u], [u, 1, v], [u, -1, -v], [u, -v, 1], [-u, -v, -1]][face];
  return normalize(d);
}

// Where a direction lands on an equirectangular panorama, in [0, 1]²: the
// top row looks up (+Y), the bottom row down; the centre column looks
// along −Z, a quarter to its right +X, a quarter to its left −X (the
// panorama is seen unmirrored from inside, facing −Z); the side edges
// meet at +Z.
export function equirectUv(d) {
  const u = 0.5 + Math.atan2(d[0], -d[2]) / (2 * Math.PI);
  const v = Math.acos(Math.min(1, Math.max(-1, d[1]))) / Math.PI;
  return [u, v];
}

// The face size for a panorama `width` texels wide: a face spans a quarter
// of the longitudes, so width / 4, as a power of two in [8, max].
export function cubeFaceSize(width, max = 1024) {
  let n = 8;
  while (n * 2 <= width / 4 && n * 2 <= max) n *= 2;
  return n;
}

const SRGB_TO_LINEAR = Array.from({ length: 256 }, (_, i) => {
  const c = i / 255;
  return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
});
function linearToSrgb8(x) {
  const c = x <= 0.0031308 ? x * 12.92 : 1.055 * Math.pow(x, 1 / 2.4) - 0.055;
  return Math.round(Math.min(1, Math.max(0, c)) * 255);
}

// RGBA8 texels of a `w`×`h` panorama (rows top first) resampled onto six
// `size`² faces (face-major, rows top first: ready for one writeTexture of
// a 6-layer texture), bilinear, wrapping in longitude and clamped in
// latitude. `srgb`: the texels are sRGB-encoded (the parameter's `srgb`,
// bound as rgba8unorm_srgb), so colour is filtered in linear and encoded
// again, as sampling a 2D sRGB texture filters; alpha is always linear.
export function equirectToCube(src, w, h, size, srgb) {
  const out = new Uint8Array(size * size * 4 * 6);
  const val = new Float64Array(w * h * 4);
  for (let i = 0; i < w * h * 4; i++) val[i] = srgb && (i & 3) !== 3 ? SRGB_TO_LINEAR[src[i]] : src[i] / 255;
  let o = 0;
  for (let face = 0; face < 6; face++) {
    for (let y = 0; y < size; y++) {
      for (let x = 0; x < size; x++) {
        const d = cubeDirection(face, (x + 0.5) / size * 2 - 1, (y + 0.5) / size * 2 - 1);
        const [u, v] = equirectUv(d);
        const fx = u * w - 0.5;
        const fy = Math.min(h - 1, Math.max(0, v * h - 0.5));
        const x0 = Math.floor(fx);
        const y0 = Math.floor(fy);
        const tx = fx - x0;
        const ty = fy - y0;
        const xa = ((x0 % w) + w) % w;
        const xb = (xa + 1) % w;
        const ya = y0;
        const yb = Math.min(h - 1, y0 + 1);
        for (let c = 0; c < 4; c++) {
          const a = val[(ya * w + xa) * 4 + c] * (1 - tx) + val[(ya * w + xb) * 4 + c] * tx;
          const b = val[(yb * w + xa) * 4 + c] * (1 - tx) + val[(yb * w + xb) * 4 + c] * tx;
          const m = a * (1 - ty) + b * ty;
          out[o + c] = srgb && c !== 3 ? linearToSrgb8(m) : Math.round(Math.min(1, Math.max(0, m)) * 255);
        }
        o += 4;
      }
    }
  }
  return out;
}

async function fetchOk(url, kind) {
  const r = await fetch(url, { cache: 'no-store' });
  if (!r.ok) throw new Error(`${url}: HTTP ${r.status}`);
  return kind === 'json' ? r.json() : kind === 'text' ? r.text() : r.arrayBuffer();
}

export class Renderer {
  static async create(canvas, base) {
    if (!navigator.gpu) throw new Error('this browser has no WebGPU (navigator.gpu is undefined): use a current Chrome/Chromium, or start it with --enable-unsafe-webgpu');
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter) throw new Error('navigator.gpu.requestAdapter() returned null: no WebGPU adapter');
    const device = await adapter.requestDevice();
    const r = new Renderer(canvas, device, adapter, base);
    await r.init();
    return r;
  }

  constructor(canvas, device, adapter, base) {
    this.canvas = canvas;
    this.device = device;
    // Held for the page's lifetime: Chromium drops the WebGPU instance (and
    // destroys the device) once the adapter is garbage-collected.
    this.adapter = adapter;
    const info = adapter.info || {};
    this.adapterInfo = [info.vendor, info.architecture, info.device, info.description].filter(Boolean).join(' ');
    this.base = base;
    this.errors = [];
    device.addEventListener('uncapturederror', (e) => {
      this.errors.push(String(e.error && e.error.message));
      if (this.onError) this.onError(String(e.error && e.error.message));
    });
    device.lost.then((info) => {
      this.lost = `the WebGPU device was lost (${info.reason}): ${info.message}`;
      if (this.onError) this.onError(this.lost);
    });
    // The tone-mapped picture is read back and put into a 2D canvas: no
    // WebGPU canvas presentation (headless Chromium's SwiftShader loses the
    // device when a page's WebGPU canvas is composited), and what is shown
    // is exactly the bytes a screenshot or a test reads.
    this.context = canvas.getContext('2d');
    this.format = 'rgba8unorm';
    this.meshes = {};
    this.luts = {};
    this.exposure = 1.0;
    this.tonemap = 'aces';
    this.time = 0;
    this.variant = null;
  }

  async init() {
    const d = this.device;
    const env = await fetchOk(this.base + 'api/environment.json', 'json');
    const bin = await fetchOk(this.base + 'api/environment.bin', 'bin');
    this.light = { direction: env.light.direction.slice(), radiance: env.light.radiance.slice() };
    this.uploadEnvironment(env, bin);
    this.frameBuffers = new Map();
    // Background: weft-render's sky shader.
    const skyCode = await fetchOk(this.base + 'sky.wgsl', 'text');
    const skyModule = d.createShaderModule({ code: skyCode, label: 'sky' });
    this.skyUniform = d.createBuffer({ size: 96, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
    this.skyPipeline = d.createRenderPipeline({
      layout: 'auto', vertex: { module: skyModule, entryPoint: 'vs_sky' },
      fragment: { module: skyModule, entryPoint: 'fs_sky', targets: [{ format: HDR_FORMAT }] },
      primitive: { topology: 'triangle-list' },
      depthStencil: { format: DEPTH_FORMAT, depthWriteEnabled: false, depthCompare: 'always' },
    });
    this.skySampler = d.createSampler({ magFilter: 'linear', minFilter: 'linear', mipmapFilter: 'linear' });
    this.rebindSky();
    const tm = d.createShaderModule({ code: TONEMAP_WGSL, label: 'tonemap' });
    this.tonemapUniform = d.createBuffer({ size: 16, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
    this.tonemapPipeline = d.createRenderPipeline({ layout: 'auto', vertex: { module: tm, entryPoint: 'vs' }, fragment: { module: tm, entryPoint: 'fs', targets: [{ format: this.format }] }, primitive: { topology: 'triangle-list' } });
  }

  // Uploads an environment (api/environment.json and .bin) into a new cube;
  // the variant's group 0 and the background are rebound to it.
  uploadEnvironment(env, bin) {
    const d = this.device;
    const cube = d.createTexture({ label: 'weft_environment', size: [env.size, env.size, 6], mipLevelCount: env.mip_count, format: 'rgba16float', usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    env.mips.forEach((m, level) => {
      for (let face = 0; face < 6; face++) {
        d.queue.writeTexture({ texture: cube, mipLevel: level, origin: [0, 0, face] }, bin, { offset: m.offset + face * m.face_bytes, bytesPerRow: m.size * 8, rowsPerImage: m.size }, [m.size, m.size, 1]);
      }
    });
    const old = this.envView;
    this.env = env;
    this.envView = cube.createView({ dimension: 'cube' });
    this.envSun = env.sky.sun_direction.slice();
    if (!old) return;
    this.rebindSky();
    const v = this.variant;
    if (v) {
      for (const b of v.variant.shader.bindings) {
        if (b.resource && b.resource.id === 'environment') {
          const e = v.groupEntries[b.group].find((x) => x.binding === b.binding);
          if (e) e.resource = this.envView;
        }
      }
      this.rebindGroups();
    }
  }

  rebindSky() {
    this.skyGroup = this.device.createBindGroup({ layout: this.skyPipeline.getBindGroupLayout(0), entries: [
      { binding: 0, resource: { buffer: this.skyUniform } }, { binding: 1, resource: this.envView }, { binding: 2, resource: this.skySampler }] });
  }

  // Fetches the environment with the sky's sun along `direction` (what
  // `weft preview --light` renders under). Returns it (not yet uploaded),
  // or null when the server ignored the request (a static export answers
  // every query with the default sky).
  async fetchEnvironment(direction) {
    const n = normalize(direction);
    const q = `?sun=${n.map((x) => x.toPrecision(9)).join(',')}`;
    const env = await fetchOk(this.base + 'api/environment.json' + q, 'json');
    const s = normalize(env.sky.sun_direction);
    if (dot(s, n) < 0.99999) return null;
    const bin = await fetchOk(this.base + 'api/environment.bin' + q, 'bin');
    return { env, bin };
  }

  async mesh(name) {
    if (this.meshes[name]) return this.meshes[name];
    const info = await fetchOk(this.base + `api/meshes/${name}.json`, 'json');
    const bin = await fetchOk(this.base + `api/meshes/${name}.bin`, 'bin');
    const d = this.device;
    const streams = {};
    for (const [key, s] of Object.entries(info.streams)) {
      const bytes = info.vertex_count * s.components * 4;
      const buf = d.createBuffer({ label: key, size: Math.max(16, bytes), usage: GPUBufferUsage.VERTEX | GPUBufferUsage.COPY_DST });
      d.queue.writeBuffer(buf, 0, bin, s.offset, bytes);
      streams[key] = { buffer: buf, components: s.components };
    }
    const ib = d.createBuffer({ label: 'indices', size: Math.max(4, info.indices.count * 4), usage: GPUBufferUsage.INDEX | GPUBufferUsage.COPY_DST });
    d.queue.writeBuffer(ib, 0, bin, info.indices.offset, info.indices.count * 4);
    const m = { info, streams, indexBuffer: ib, indexCount: info.indices.count };
    this.meshes[name] = m;
    return m;
  }

  async lut(file) {
    if (this.luts[file.path]) return this.luts[file.path];
    const bytes = await fetchOk(this.base + 'api/files/' + file.path, 'bin');
    const bpp = file.format === 'rg16float' ? 4 : file.format === 'r16float' ? 2 : file.format === 'rgba16float' ? 8 : 0;
    if (!bpp) throw new Error(`LUT ${file.path}: format ${file.format} is not one the page knows`);
    const t = this.device.createTexture({ label: file.path, size: [file.width, file.height], format: file.format, usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    this.device.queue.writeTexture({ texture: t }, bytes, { bytesPerRow: file.width * bpp, rowsPerImage: file.height }, [file.width, file.height]);
    this.luts[file.path] = t.createView();
    return this.luts[file.path];
  }

  // A texture parameter's image (`texture.file`: RGBA8 texels, rows top
  // first, under the library root), uploaded once per file.
  async fileTexture(file) {
    const key = `${file.path}|${file.format}|${file.sha256}`;
    if (this.luts[key]) return this.luts[key];
    if (file.format !== 'rgba8unorm' && file.format !== 'rgba8unorm_srgb') throw new Error(`image ${file.path}: format ${file.format} is not one the page knows`);
    const bytes = await fetchOk(this.base + 'api/files/' + file.path, 'bin');
    // Level 0 only: build the chain the file's `mip_chain` states.
    this.luts[key] = this.mippedTexture(file.path, file.width, file.height, new Uint8Array(bytes), file.format);
    return this.luts[key];
  }

  // An RGBA8 image with its full mip chain (bake.mipChain: box 2x2, in
  // linear light for sRGB), as weft-render binds a texture parameter's image.
  mippedTexture(label, width, height, level0, format) {
    const levels = bake.mipChain(width, height, level0, format === 'rgba8unorm_srgb');
    const t = this.device.createTexture({ label, size: [width, height], mipLevelCount: levels.length, format: gpuName(format), usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    levels.forEach((data, m) => {
      const w = Math.max(1, width >> m);
      const h = Math.max(1, height >> m);
      this.device.queue.writeTexture({ texture: t, mipLevel: m }, data, { bytesPerRow: w * 4, rowsPerImage: h }, [w, h]);
    });
    return t.createView();
  }

  // A 1x1 (or 1x1x6) RGBA8 texture of a built-in default.
  builtinTexture(name, format, cube) {
    const texel = { white: [255, 255, 255, 255], black: [0, 0, 0, 255], gray: [128, 128, 128, 255], normal: [128, 128, 255, 255] }[name] || [255, 0, 255, 255];
    const layers = cube ? 6 : 1;
    const t = this.device.createTexture({ label: `default ${name}`, size: [1, 1, layers], format: gpuName(format), usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    for (let l = 0; l < layers; l++) this.device.queue.writeTexture({ texture: t, origin: [0, 0, l] }, new Uint8Array(texel), { bytesPerRow: 4 }, [1, 1, 1]);
    return t.createView({ dimension: cube ? 'cube' : '2d' });
  }

  async imageTexture(bitmap, format) {
    const pixels = await this.imagePixels(bitmap);
    return this.mippedTexture('user image', bitmap.width, bitmap.height, pixels, format);
  }

  // The RGBA8 texels of an image (rows top first), exactly as the 2D path
  // uploads them (copyExternalImageToTexture of the same bitmap).
  async imagePixels(bitmap) {
    const d = this.device;
    const w = bitmap.width;
    const h = bitmap.height;
    const t = d.createTexture({ label: 'panorama', size: [w, h], format: 'rgba8unorm', usage: GPUTextureUsage.COPY_SRC | GPUTextureUsage.COPY_DST | GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.TEXTURE_BINDING });
    d.queue.copyExternalImageToTexture({ source: bitmap }, { texture: t }, [w, h]);
    const row = Math.ceil(w * 4 / 256) * 256;
    const buf = d.createBuffer({ size: row * h, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
    const enc = d.createCommandEncoder();
    enc.copyTextureToBuffer({ texture: t }, { buffer: buf, bytesPerRow: row, rowsPerImage: h }, [w, h]);
    d.queue.submit([enc.finish()]);
    await buf.mapAsync(GPUMapMode.READ);
    const src = new Uint8Array(buf.getMappedRange());
    const out = new Uint8Array(w * h * 4);
    for (let y = 0; y < h; y++) out.set(src.subarray(y * row, y * row + w * 4), y * w * 4);
    buf.unmap();
    buf.destroy();
    t.destroy();
    return out;
  }

  // A cube of six size² faces of RGBA8 texels (face-major, as
  // equirectToCube returns them) in the binding's format.
  cubeTexture(faces, size, format) {
    const t = this.device.createTexture({ label: 'user cube', size: [size, size, 6], format: gpuName(format), usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    this.device.queue.writeTexture({ texture: t }, faces, { bytesPerRow: size * 4, rowsPerImage: size }, [size, size, 6]);
    return t.createView({ dimension: 'cube' });
  }

  rampTexture(rgba8, format) {
    const width = rgba8.length / 4;
    const t = this.device.createTexture({ label: 'gradient ramp', size: [width, 1], format: gpuName(format), usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    this.device.queue.writeTexture({ texture: t }, rgba8, { bytesPerRow: width * 4 }, [width, 1]);
    return t.createView();
  }

  // Prepares a variant: shader module, explicit layouts from `bindings`,
  // one pipeline per pass (per constant set), group 0 and 2 bind groups.
  // `constants`: pipeline constants (name -> number). Swapping keywords or
  // tiers calls this again; parameter edits only call writeMaterial.
  async setVariant(meta, variant, code, constants) {
    const d = this.device;
    const shader = variant.shader;
    d.pushErrorScope('validation');
    const module = d.createShaderModule({ code, label: variant.id });
    const info = await module.getCompilationInfo();
    const errors = info.messages.filter((m) => m.type === 'error');
    if (errors.length) {
      await d.popErrorScope();
      throw new Error(`${variant.id}.wgsl: ` + errors.map((m) => `${m.lineNum}:${m.linePos} ${m.message}`).join('\n'));
    }
    const groups = Math.max(0, ...shader.bindings.map((b) => b.group + 1));
    const entries = Array.from({ length: groups }, () => []);
    for (const b of shader.bindings) entries[b.group].push(layoutEntry(b));
    const bgls = entries.map((e, g) => d.createBindGroupLayout({ label: `group ${g}`, entries: e }));
    const layout = d.createPipelineLayout({ bindGroupLayouts: bgls });
    const buffers = shader.vertex_inputs.map((vi) => {
      const n = ['position', 'normal'].includes(vi.name) ? 3 : ['uv0', 'uv1'].includes(vi.name) ? 2 : 4;
      return { arrayStride: n * 4, attributes: [{ shaderLocation: vi.location, offset: 0, format: vi.format }] };
    });
    // The variant's own passes (`variant.passes`: a pass with `when` exists only where it holds).
    const passes = meta.passes.filter((p) => variant.passes.includes(p.name)).map((p, i) => ({ p, i })).sort((a, b) => a.p.render_state.queue - b.p.render_state.queue || a.i - b.i).map((x) => x.p);
    const pipelines = [];
    for (const pass of passes) {
      const desc = {
        label: `${variant.id} ${pass.name}`, layout,
        vertex: { module, entryPoint: pass.vertex_entry, buffers, constants },
        fragment: { module, entryPoint: pass.fragment_entry, targets: colorTargets(pass), constants },
        primitive: { topology: gpuName(pass.primitive.topology), frontFace: gpuName(pass.primitive.front_face), cullMode: gpuName(pass.primitive.cull_mode) },
      };
      // The metadata's depth-stencil state as it is; the reference is set per draw.
      const ds = pass.depth_stencil;
      if (gpuName(ds.format) !== DEPTH_FORMAT) throw new Error(`pass ${pass.name} asks for a ${ds.format} attachment; the page draws into ${DEPTH_FORMAT}`);
      const face = (f) => ({ compare: gpuName(f.compare), failOp: gpuName(f.fail_op), depthFailOp: gpuName(f.depth_fail_op), passOp: gpuName(f.pass_op) });
      desc.depthStencil = {
        format: DEPTH_FORMAT, depthWriteEnabled: ds.depth_write_enabled, depthCompare: gpuName(ds.depth_compare),
        stencilFront: face(ds.stencil_front), stencilBack: face(ds.stencil_back),
        stencilReadMask: ds.stencil_read_mask, stencilWriteMask: ds.stencil_write_mask,
      };
      pipelines.push({ pass, pipeline: await d.createRenderPipelineAsync(desc) });
    }
    // Uniform buffers and engine resources.
    const blocks = [];
    const groupEntries = Array.from({ length: groups }, () => []);
    let material = null;
    const textureSlots = [];
    for (const b of shader.bindings) {
      let resource;
      if (b.buffer) {
        const size = Math.max(b.buffer.min_binding_size, b.buffer.layout ? b.buffer.layout.size : 0);
        const buffer = d.createBuffer({ label: b.name, size: Math.ceil(size / 16) * 16, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
        const block = { binding: b, buffer, size: Math.ceil(size / 16) * 16, layout: b.buffer.layout };
        if (b.resource && b.resource.id === 'frame') block.kind = 'frame';
        else if (b.resource && b.resource.id === 'object') block.kind = 'object';
        else if (b.group === 1) { block.kind = 'material'; material = block; }
        else throw new Error(`uniform ${b.name} (group ${b.group}) carries ${b.resource ? b.resource.id : 'nothing'} the page knows`);
        blocks.push(block);
        resource = { buffer };
      } else if (b.sampler) {
        resource = d.createSampler(samplerDescriptor(b.sampler));
      } else if (b.resource) {
        const id = b.resource.id;
        if (id === 'environment') resource = this.envView;
        else if (b.resource.file) resource = await this.lut(b.resource.file);
        else throw new Error(`engine resource ${id} (${b.name}) is not one the page binds`);
      } else {
        // A material texture: filled by the panel (default until then).
        const cube = b.texture.view_dimension === 'cube';
        resource = this.builtinTexture(b.texture.default || 'white', b.texture.format, cube);
        textureSlots.push(b);
      }
      groupEntries[b.group].push({ binding: b.binding, resource });
    }
    this.variant = { meta, variant, pipelines, bgls, groupEntries, blocks, material, textureSlots, bindGroups: null };
    this.rebindGroups();
    const err = await d.popErrorScope();
    if (err) throw new Error(`${variant.id}: ${err.message}`);
  }

  rebindGroups() {
    const v = this.variant;
    v.bindGroups = v.groupEntries.map((entries, g) => (entries.length ? this.device.createBindGroup({ layout: v.bgls[g], entries }) : this.device.createBindGroup({ layout: v.bgls[g], entries: [] })));
  }

  // Replaces the view bound at a group-1 texture binding.
  setTexture(binding, view) {
    const v = this.variant;
    if (!v) return;
    const e = v.groupEntries[1].find((x) => x.binding === binding);
    if (e) { e.resource = view; this.rebindGroups(); }
  }

  // The material uniform's bytes (from the panel): one writeBuffer.
  writeMaterial(bytes) {
    const v = this.variant;
    if (!v || !v.material) return;
    const out = new Uint8Array(v.material.size);
    out.set(bytes.subarray(0, Math.min(bytes.length, out.length)));
    this.device.queue.writeBuffer(v.material.buffer, 0, out);
  }

  frameBytes(block, camera, w, h) {
    const aspect = w / h;
    const f = new Float32Array(block.size / 4);
    const view = lookAt(camera.eye, camera.target, camera.up);
    const proj = perspective(camera.fov_y_degrees * Math.PI / 180, aspect, camera.near, camera.far);
    for (const m of block.layout.members) {
      let vals;
      switch (m.name) {
        case 'view_proj': vals = flat(mul(proj, view)); break;
        case 'view': vals = flat(view); break;
        case 'camera_position': vals = [...camera.eye, 1]; break;
        case 'light_direction': vals = [...normalize(this.light.direction), 0]; break;
        case 'light_color': vals = [...this.light.radiance, 0]; break;
        case 'sh': vals = this.env.sh.flatMap((c) => [...c, 0]); break;
        case 'params': vals = [this.env.mip_count, this.exposure, this.time, 0]; break;
        case 'viewport': vals = [w, h, 1 / w, 1 / h]; break;
        default: throw new Error(`weft_frame member ${m.name} is not one the page fills`);
      }
      f.set(vals, m.offset / 4);
    }
    return f;
  }

  objectBytes(block, model) {
    const f = new Float32Array(block.size / 4);
    for (const m of block.layout.members) {
      if (m.name === 'model') f.set(flat(model), m.offset / 4);
      else if (m.name === 'normal_matrix') f.set(flat(normalMatrix(model)), m.offset / 4);
      else throw new Error(`weft_object member ${m.name} is not one the page fills`);
    }
    return f;
  }

  // Draws the variant on `meshName` into an HDR target of w x h. `instances`
  // maps pass name -> count. Returns the HDR texture.
  async drawHdr(meshName, camera, w, h, instances) {
    const d = this.device;
    const mesh = await this.mesh(meshName);
    const v = this.variant;
    const aspect = w / h;
    const hdr = d.createTexture({ size: [w, h], format: HDR_FORMAT, usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_SRC });
    const depth = d.createTexture({ size: [w, h], format: DEPTH_FORMAT, usage: GPUTextureUsage.RENDER_ATTACHMENT });
    const view = lookAt(camera.eye, camera.target, camera.up);
    const proj = perspective(camera.fov_y_degrees * Math.PI / 180, aspect, camera.near, camera.far);
    const sky = new Float32Array(24);
    sky.set(flat(inverse(mul(proj, view))), 0);
    sky.set([...camera.eye, 1], 16);
    sky.set([0, 0, 0, 0], 20);
    d.queue.writeBuffer(this.skyUniform, 0, sky);
    if (v) {
      for (const b of v.blocks) {
        if (b.kind === 'frame') d.queue.writeBuffer(b.buffer, 0, this.frameBytes(b, camera, w, h));
        if (b.kind === 'object') d.queue.writeBuffer(b.buffer, 0, this.objectBytes(b, mesh.info.model));
      }
    }
    const enc = d.createCommandEncoder();
    const rp = enc.beginRenderPass({
      colorAttachments: [{ view: hdr.createView(), loadOp: 'clear', storeOp: 'store', clearValue: [0, 0, 0, 0] }],
      depthStencilAttachment: {
        view: depth.createView(), depthLoadOp: 'clear', depthClearValue: 1.0, depthStoreOp: 'discard',
        stencilLoadOp: 'clear', stencilClearValue: 0, stencilStoreOp: 'discard',
      },
    });
    rp.setPipeline(this.skyPipeline);
    rp.setBindGroup(0, this.skyGroup);
    rp.draw(3);
    if (v) {
      const inputs = v.variant.shader.vertex_inputs;
      inputs.forEach((vi, i) => {
        const s = mesh.streams[vi.name];
        if (!s) throw new Error(`vertex input ${vi.name} is not a mesh stream the page has`);
        rp.setVertexBuffer(i, s.buffer);
      });
      rp.setIndexBuffer(mesh.indexBuffer, 'uint32');
      v.bindGroups.forEach((bg, g) => rp.setBindGroup(g, bg));
      for (const { pass, pipeline } of v.pipelines) {
        const n = instances && pass.name in instances ? instances[pass.name] : 1;
        if (n <= 0 || mesh.indexCount === 0) continue;
        rp.setPipeline(pipeline);
        rp.setStencilReference(pass.depth_stencil.stencil_reference);
        rp.drawIndexed(mesh.indexCount, n);
      }
    }
    rp.end();
    d.queue.submit([enc.finish()]);
    depth.destroy();
    return hdr;
  }

  // Draws into the canvas (tone-mapped).
  async render(meshName, camera, instances) {
    const w = this.canvas.width;
    const h = this.canvas.height;
    const hdr = await this.drawHdr(meshName, camera, w, h, instances);
    const d = this.device;
    const u = new ArrayBuffer(16);
    new Float32Array(u, 0, 1)[0] = this.exposure;
    new Uint32Array(u, 4, 1)[0] = Math.max(0, TONEMAPS.indexOf(this.tonemap));
    d.queue.writeBuffer(this.tonemapUniform, 0, u);
    const bg = d.createBindGroup({ layout: this.tonemapPipeline.getBindGroupLayout(0), entries: [{ binding: 0, resource: hdr.createView() }, { binding: 1, resource: { buffer: this.tonemapUniform } }] });
    const ldr = d.createTexture({ size: [w, h], format: this.format, usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC });
    const row = Math.ceil(w * 4 / 256) * 256;
    const buf = d.createBuffer({ size: row * h, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
    const enc = d.createCommandEncoder();
    const rp = enc.beginRenderPass({ colorAttachments: [{ view: ldr.createView(), loadOp: 'clear', storeOp: 'store', clearValue: [0, 0, 0, 1] }] });
    rp.setPipeline(this.tonemapPipeline);
    rp.setBindGroup(0, bg);
    rp.draw(3);
    rp.end();
    enc.copyTextureToBuffer({ texture: ldr }, { buffer: buf, bytesPerRow: row, rowsPerImage: h }, [w, h]);
    d.queue.submit([enc.finish()]);
    await buf.mapAsync(GPUMapMode.READ);
    const src = new Uint8Array(buf.getMappedRange());
    const img = new ImageData(w, h);
    for (let y = 0; y < h; y++) img.data.set(src.subarray(y * row, y * row + w * 4), y * w * 4);
    buf.unmap();
    buf.destroy();
    ldr.destroy();
    this.context.putImageData(img, 0, 0);
    await d.queue.onSubmittedWorkDone();
    hdr.destroy();
  }

  // Linear HDR pixels (rows top first) of the variant drawn at w x h, as
  // base64 of little-endian RGBA f16 — what weft-render reads back.
  async captureHdr(meshName, camera, w, h, instances) {
    const d = this.device;
    const hdr = await this.drawHdr(meshName, camera, w, h, instances);
    const row = Math.ceil(w * 8 / 256) * 256;
    const buf = d.createBuffer({ size: row * h, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
    const enc = d.createCommandEncoder();
    enc.copyTextureToBuffer({ texture: hdr }, { buffer: buf, bytesPerRow: row, rowsPerImage: h }, [w, h]);
    d.queue.submit([enc.finish()]);
    await buf.mapAsync(GPUMapMode.READ);
    const src = new Uint8Array(buf.getMappedRange());
    const out = new Uint8Array(w * h * 8);
    for (let y = 0; y < h; y++) out.set(src.subarray(y * row, y * row + w * 8), y * w * 8);
    buf.unmap();
    buf.destroy();
    hdr.destroy();
    let s = '';
    for (let i = 0; i < out.length; i += 0x8000) s += String.fromCharCode.apply(null, out.subarray(i, i + 0x8000));
    return btoa(s);
  }
}

export { halfToFloat, vertexFormatFloats, bake };
