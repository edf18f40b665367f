// How weft bakes parameter values, as crates/weft-meta/src/bake.rs does it,
// operation for operation in f64, so the page's curve samples and gradient
// ramps are byte-identical to the toolchain's (tests/inspector.rs compares).

export function srgbToLinear(c) {
  if (c <= 0.04045) return c / 12.92;
  return Math.pow((c + 0.055) / 1.055, 2.4);
}

export function linearToSrgb(c) {
  if (c <= 0.0031308) return c * 12.92;
  return 1.055 * Math.pow(c, 1.0 / 2.4) - 0.055;
}

// Keyframes: [{time, value, in_slope, out_slope}], sorted by time.
// Cubic Hermite (Unity's AnimationCurve), clamped at the ends.
export function evalCurve(keys, t) {
  const first = keys[0];
  const last = keys[keys.length - 1];
  if (t <= first.time) return first.value;
  if (t >= last.time) return last.value;
  let i = 0;
  for (let w = 0; w + 1 < keys.length; w++) {
    if (t >= keys[w].time && t <= keys[w + 1].time) { i = w; break; }
  }
  const k0 = keys[i];
  const k1 = keys[i + 1];
  const dt = k1.time - k0.time;
  const s = (t - k0.time) / dt;
  const s2 = s * s;
  const s3 = s * s * s;
  const h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
  const h10 = s3 - 2.0 * s2 + s;
  const h01 = -2.0 * s3 + 3.0 * s2;
  const h11 = s3 - s2;
  return h00 * k0.value + h10 * dt * k0.out_slope + h01 * k1.value + h11 * dt * k1.in_slope;
}

export function curveTimeRange(keys) {
  return [keys[0].time, keys[keys.length - 1].time];
}

// `n` samples at evenly spaced times over the keyframes' span.
export function sampleCurve(keys, n) {
  const [t0, t1] = curveTimeRange(keys);
  const out = [];
  for (let i = 0; i < n; i++) {
    const t = n > 1 ? t0 + (t1 - t0) * i / (n - 1) : t0;
    out.push(evalCurve(keys, t));
  }
  return out;
}

// The `f32x4_packed_v1` encoding: sample i in element i / 4, component
// i % 4, unused tail zero; `floats` is the member's size in f32s.
export function packCurve(samples, floats) {
  const out = new Float32Array(floats);
  for (let i = 0; i < samples.length && i < floats; i++) out[i] = samples[i];
  return out;
}

// Linear-light colour of a gradient at x. Stops: [{position, color: [r,g,b,a] sRGB}].
export function gradientAt(stops, x) {
  const lin = (s) => [srgbToLinear(s.color[0]), srgbToLinear(s.color[1]), srgbToLinear(s.color[2]), s.color[3]];
  const first = stops[0];
  const last = stops[stops.length - 1];
  if (x <= first.position) return lin(first);
  if (x >= last.position) return lin(last);
  let i = 0;
  for (let w = 0; w + 1 < stops.length; w++) {
    if (x >= stops[w].position && x <= stops[w + 1].position) { i = w; break; }
  }
  const a = lin(stops[i]);
  const b = lin(stops[i + 1]);
  const span = stops[i + 1].position - stops[i].position;
  const t = span > 0.0 ? (x - stops[i].position) / span : 0.0;
  return [0, 1, 2, 3].map((c) => a[c] + (b[c] - a[c]) * t);
}

// `width` sRGB8 RGBA texels (the `rgba8_srgb_ramp_v1` encoding).
export function bakeGradient(stops, width) {
  const out = new Uint8Array(width * 4);
  for (let i = 0; i < width; i++) {
    const x = (i + 0.5) / width;
    const c = gradientAt(stops, x);
    for (let ch = 0; ch < 4; ch++) {
      const enc = ch < 3 ? linearToSrgb(c[ch]) : c[ch];
      // Rust's f64::round rounds half away from zero, Math.round half up:
      // the same for values >= 0 (both exact, no intermediate addition).
      out[i * 4 + ch] = Math.round(Math.min(Math.max(enc, 0.0), 1.0) * 255.0);
    }
  }
  return out;
}

// The mip chain of an RGBA8 texture (rows top first), as weft_meta's
// bake::rgba8_mip_chain builds it (docs/engine-interface.md, "Texture
// files: mip chains"): level n + 1 halves each side (never below 1); each
// texel is the mean of the 2x2 texels above it, clamped to the level's
// edge; RGB in linear light for sRGB formats (decoded, averaged, encoded,
// rounded), otherwise (and alpha) bytes averaged and rounded half up.
export function mipLevelCount(width, height) {
  return Math.floor(Math.log2(Math.max(width, height, 1))) + 1;
}

export function mipChain(width, height, level0, srgb) {
  const decode = new Float64Array(256);
  for (let b = 0; b < 256; b++) decode[b] = srgbToLinear(b / 255);
  const levels = [level0];
  let w = width;
  let h = height;
  for (let n = 1; n < mipLevelCount(width, height); n++) {
    const src = levels[levels.length - 1];
    const nw = Math.max(1, w >> 1);
    const nh = Math.max(1, h >> 1);
    const dst = new Uint8Array(nw * nh * 4);
    for (let y = 0; y < nh; y++) {
      for (let x = 0; x < nw; x++) {
        const x0 = Math.min(2 * x, w - 1), x1 = Math.min(2 * x + 1, w - 1);
        const y0 = Math.min(2 * y, h - 1), y1 = Math.min(2 * y + 1, h - 1);
        const t = [(y0 * w + x0) * 4, (y0 * w + x1) * 4, (y1 * w + x0) * 4, (y1 * w + x1) * 4];
        for (let c = 0; c < 4; c++) {
          const o = (y * nw + x) * 4 + c;
          if (srgb && c < 3) {
            const mean = (decode[src[t[0] + c]] + decode[src[t[1] + c]] + decode[src[t[2] + c]] + decode[src[t[3] + c]]) / 4;
            dst[o] = Math.min(255, Math.max(0, Math.round(linearToSrgb(mean) * 255)));
          } else {
            dst[o] = (src[t[0] + c] + src[t[1] + c] + src[t[2] + c] + src[t[3] + c] + 2) >> 2;
          }
        }
      }
    }
    levels.push(dst);
    w = nw;
    h = nh;
  }
  return levels;
}
