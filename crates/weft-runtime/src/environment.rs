//! The lighting environment of the engine interface, computed on the CPU:
//! a procedural HDR sky cube (gradient, sun disc, ground), its GGX-prefiltered
//! mip chain and its L2 SH irradiance (the toolchain's LUTs: `luts.rs`).
//!
//! Everything is deterministic: fixed sample sets (Hammersley), f64
//! accumulation, no threads.
//!
//! Cube faces follow the Vulkan/WebGPU convention (+X, -X, +Y, -Y, +Z, -Z;
//! texel row 0 at the top of each face). World +Y is up.

use crate::math::Vec3;
use std::f64::consts::PI;
// The probe (probe.rs) takes the tables from here with the environment.
pub use crate::luts::Luts;

/// One mip level of a cube: 6 faces of `size * size` linear RGB texels.
#[derive(Clone, Debug, PartialEq)]
pub struct CubeLevel {
    pub size: u32,
    /// Face-major, then row-major: `data[(face * size + y) * size + x]`.
    pub data: Vec<[f32; 3]>,
}

/// Which perceptual roughness each prefiltered mip holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum MipRoughness {
    /// Mip m holds the roughness r with r (1.7 - 0.7 r) = m / (count - 1):
    /// the inverse of `weft_specular_mip` in materials/lib/lighting.wgsl, so
    /// the lookup `textureSampleLevel(.., weft_specular_mip(r))` returns
    /// radiance prefiltered at r itself.
    #[default]
    ShaderMapping,
    /// Mip m holds roughness m / (count - 1) (the literal reading of the
    /// engine-interface comment).
    Linear,
}

impl MipRoughness {
    /// Roughness of mip `m` of `count`.
    pub fn roughness(self, m: u32, count: u32) -> f64 {
        if count <= 1 {
            return 0.0;
        }
        let x = f64::from(m) / f64::from(count - 1);
        match self {
            MipRoughness::Linear => x,
            // 0.7 r^2 - 1.7 r + x = 0, the root in [0, 1].
            MipRoughness::ShaderMapping => {
                ((1.7 - (2.89 - 2.8 * x).max(0.0).sqrt()) / 1.4).clamp(0.0, 1.0)
            }
        }
    }
}

/// Parameters of the procedural sky.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SkyParams {
    /// Direction towards the sun (normalised on use); usually the main light's.
    pub sun_direction: Vec3,
    /// Radiance of the sun disc.
    pub sun_radiance: Vec3,
    /// Angular radius of the sun disc in degrees.
    pub sun_radius_degrees: f32,
    pub zenith: Vec3,
    pub horizon: Vec3,
    pub ground: Vec3,
    /// Face size of mip 0 (a power of two).
    pub size: u32,
    /// GGX importance samples per prefiltered texel.
    pub samples: u32,
    pub mip_roughness: MipRoughness,
}

impl Default for SkyParams {
    fn default() -> Self {
        SkyParams {
            sun_direction: weft_meta::scene::DEFAULT_LIGHT_DIRECTION.map(|c| c as f32),
            sun_radiance: [60.0, 55.0, 46.0],
            sun_radius_degrees: 2.5,
            zenith: [0.11, 0.24, 0.62],
            horizon: [0.55, 0.62, 0.74],
            ground: [0.13, 0.115, 0.1],
            size: 64,
            samples: 64,
            mip_roughness: MipRoughness::ShaderMapping,
        }
    }
}

impl SkyParams {
    /// Radiance of the sky along the unit direction `d`.
    pub fn radiance(&self, d: [f64; 3]) -> [f64; 3] {
        SkyEval::new(self).radiance(d)
    }
}

/// [`SkyParams`] with the per-direction constants precomputed.
struct SkyEval {
    sun: [f64; 3],
    sun_radiance: [f64; 3],
    zenith: [f64; 3],
    horizon: [f64; 3],
    ground: [f64; 3],
    cos_outer: f64,
    cos_inner: f64,
}

impl SkyEval {
    fn new(p: &SkyParams) -> SkyEval {
        let r = f64::from(p.sun_radius_degrees).to_radians();
        SkyEval {
            sun: normalize64(p.sun_direction.map(f64::from)),
            sun_radiance: p.sun_radiance.map(f64::from),
            zenith: p.zenith.map(f64::from),
            horizon: p.horizon.map(f64::from),
            ground: p.ground.map(f64::from),
            cos_outer: r.cos(),
            cos_inner: (r * 0.8).cos(),
        }
    }

    fn radiance(&self, d: [f64; 3]) -> [f64; 3] {
        let e = d[1];
        let (from, to, t) = if e >= 0.0 {
            (self.horizon, self.zenith, e.powf(0.6))
        } else {
            (self.horizon, self.ground, smoothstep(0.0, 0.12, -e))
        };
        let cos_sun = dot64(d, self.sun);
        // A soft glow around the sun above the horizon, and the disc.
        let c = cos_sun.max(0.0);
        let c2 = c * c;
        let c6 = c2 * c2 * c2;
        let c48 = {
            let c12 = c6 * c6;
            let c24 = c12 * c12;
            c24 * c24
        };
        let glow = smoothstep(-0.05, 0.05, e) * (0.5 * c48 + 0.12 * c6) * 0.05;
        let disc = smoothstep(self.cos_outer, self.cos_inner, cos_sun);
        let mut out = [0.0; 3];
        for i in 0..3 {
            out[i] = from[i] + (to[i] - from[i]) * t + (glow + disc) * self.sun_radiance[i];
        }
        out
    }
}

fn smoothstep(e0: f64, e1: f64, x: f64) -> f64 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

fn dot64(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn normalize64(a: [f64; 3]) -> [f64; 3] {
    let l = dot64(a, a).sqrt();
    if l > 0.0 {
        a.map(|x| x / l)
    } else {
        [0.0, 1.0, 0.0]
    }
}

/// Unit direction through face coordinates `u, v` in [-1, 1] (v down).
pub fn cube_direction(face: u32, u: f64, v: f64) -> [f64; 3] {
    let d = match face {
        0 => [1.0, -v, -u],
        1 => [-1.0, -v, u],
        2 => [u, 1.0, v],
        3 => [u, -1.0, -v],
        4 => [u, -v, 1.0],
        _ => [-u, -v, -1.0],
    };
    normalize64(d)
}

/// Face and face coordinates (u, v in [-1, 1], v down) of a direction.
pub fn cube_face_uv(d: [f64; 3]) -> (u32, f64, f64) {
    let [x, y, z] = d;
    let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
    let (face, ma, sc, tc) = if ax >= ay && ax >= az {
        if x > 0.0 {
            (0, ax, -z, -y)
        } else {
            (1, ax, z, -y)
        }
    } else if ay >= az {
        if y > 0.0 {
            (2, ay, x, z)
        } else {
            (3, ay, x, -z)
        }
    } else if z > 0.0 {
        (4, az, x, -y)
    } else {
        (5, az, -x, -y)
    };
    let ma = ma.max(1e-30);
    (face, sc / ma, tc / ma)
}

/// Exact solid angle of the texel `(x, y)` of a `size`-texel face.
pub fn texel_solid_angle(x: u32, y: u32, size: u32) -> f64 {
    let inv = 2.0 / f64::from(size);
    let (x0, y0) = (f64::from(x) * inv - 1.0, f64::from(y) * inv - 1.0);
    let (x1, y1) = (x0 + inv, y0 + inv);
    let area = |a: f64, b: f64| (a * b).atan2((a * a + b * b + 1.0).sqrt());
    area(x0, y0) - area(x0, y1) - area(x1, y0) + area(x1, y1)
}

impl CubeLevel {
    fn texel(&self, face: u32, x: u32, y: u32) -> [f32; 3] {
        self.data[((face * self.size + y) * self.size + x) as usize]
    }

    /// Bilinear lookup inside the face the direction hits (clamped at face edges).
    pub fn sample(&self, d: [f64; 3]) -> [f64; 3] {
        let (face, u, v) = cube_face_uv(d);
        let n = f64::from(self.size);
        let fx = ((u + 1.0) * 0.5 * n - 0.5).clamp(0.0, n - 1.0);
        let fy = ((v + 1.0) * 0.5 * n - 0.5).clamp(0.0, n - 1.0);
        let (x0, y0) = (fx as u32, fy as u32);
        let x1 = (x0 + 1).min(self.size - 1);
        let y1 = (y0 + 1).min(self.size - 1);
        let (tx, ty) = (fx - f64::from(x0), fy - f64::from(y0));
        let row0 = ((face * self.size + y0) * self.size) as usize;
        let row1 = ((face * self.size + y1) * self.size) as usize;
        let a = &self.data[row0 + x0 as usize];
        let b = &self.data[row0 + x1 as usize];
        let c = &self.data[row1 + x0 as usize];
        let e = &self.data[row1 + x1 as usize];
        let (wa, wb) = ((1.0 - tx) * (1.0 - ty), tx * (1.0 - ty));
        let (wc, we) = ((1.0 - tx) * ty, tx * ty);
        let mut out = [0.0; 3];
        for i in 0..3 {
            out[i] = wa * f64::from(a[i])
                + wb * f64::from(b[i])
                + wc * f64::from(c[i])
                + we * f64::from(e[i]);
        }
        out
    }

    /// 2x2 box average (a face of size 1 stays 1).
    fn downsample(&self) -> CubeLevel {
        let size = (self.size / 2).max(1);
        let mut data = Vec::with_capacity((size * size * 6) as usize);
        for face in 0..6 {
            for y in 0..size {
                for x in 0..size {
                    let mut acc = [0.0f64; 3];
                    let (sx, sy) = (x * 2, y * 2);
                    for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                        let t = self.texel(
                            face,
                            (sx + dx).min(self.size - 1),
                            (sy + dy).min(self.size - 1),
                        );
                        for c in 0..3 {
                            acc[c] += f64::from(t[c]);
                        }
                    }
                    data.push(acc.map(|a| (a * 0.25) as f32));
                }
            }
        }
        CubeLevel { size, data }
    }
}

/// A chain of levels sampled trilinearly by level of detail.
struct CubeChain(Vec<CubeLevel>);

impl CubeChain {
    fn sample_lod(&self, d: [f64; 3], lod: f64) -> [f64; 3] {
        let max = (self.0.len() - 1) as f64;
        let lod = lod.clamp(0.0, max);
        let l0 = lod.floor() as usize;
        let l1 = (l0 + 1).min(self.0.len() - 1);
        let t = lod - l0 as f64;
        let a = self.0[l0].sample(d);
        if t == 0.0 || l0 == l1 {
            return a;
        }
        let b = self.0[l1].sample(d);
        [
            a[0] + (b[0] - a[0]) * t,
            a[1] + (b[1] - a[1]) * t,
            a[2] + (b[2] - a[2]) * t,
        ]
    }
}

/// The prefiltered environment and its SH irradiance.
#[derive(Clone, Debug, PartialEq)]
pub struct EnvironmentMaps {
    /// Mip 0 is the sky itself (roughness 0); mip m is GGX-prefiltered at `mip_roughness[m]`.
    pub mips: Vec<CubeLevel>,
    pub mip_roughness: Vec<f64>,
    /// L2 SH of the irradiance, cosine-convolved and divided by pi (engine-interface order).
    pub sh: [[f32; 3]; 9],
}

impl EnvironmentMaps {
    /// The procedural sky of `params`, prefiltered.
    pub fn sky(params: &SkyParams) -> EnvironmentMaps {
        let size = params.size.max(1).next_power_of_two();
        let base = sky_level(params, size);
        let sh = project_sh(&base);
        let count = size.trailing_zeros() + 1;
        let mut chain = vec![base.clone()];
        for _ in 1..count {
            let next = chain.last().expect("non-empty").downsample();
            chain.push(next);
        }
        let chain = CubeChain(chain);
        let mip_roughness: Vec<f64> = (0..count)
            .map(|m| params.mip_roughness.roughness(m, count))
            .collect();
        let mut mips = vec![base];
        for m in 1..count {
            mips.push(prefilter_level(
                &chain,
                size >> m,
                mip_roughness[m as usize],
                params.samples.max(1),
                size,
            ));
        }
        EnvironmentMaps {
            mips,
            mip_roughness,
            sh,
        }
    }

    pub fn mip_count(&self) -> u32 {
        self.mips.len() as u32
    }

    /// E(n)/pi from the SH coefficients, as `weft_sh_irradiance` computes it.
    pub fn sh_irradiance(&self, n: Vec3) -> [f32; 3] {
        let b = sh_basis(n.map(f64::from));
        let mut out = [0.0f32; 3];
        for (i, c) in self.sh.iter().enumerate() {
            for ch in 0..3 {
                out[ch] += c[ch] * b[i] as f32;
            }
        }
        out.map(|x| x.max(0.0))
    }

    /// The sky (mip 0) as a linear RGBA cube, e.g. for a material's cube parameter.
    pub fn sky_cube_rgba(&self) -> (u32, Vec<[f32; 4]>) {
        let base = &self.mips[0];
        (
            base.size,
            base.data.iter().map(|c| [c[0], c[1], c[2], 1.0]).collect(),
        )
    }
}

fn sky_level(params: &SkyParams, size: u32) -> CubeLevel {
    // 2x2 supersampling per texel keeps the sun disc's edge smooth.
    const SS: u32 = 2;
    let sky = SkyEval::new(params);
    let mut data = Vec::with_capacity((size * size * 6) as usize);
    let n = f64::from(size * SS);
    for face in 0..6 {
        for y in 0..size {
            for x in 0..size {
                let mut acc = [0.0f64; 3];
                for sy in 0..SS {
                    for sx in 0..SS {
                        let u = (f64::from(x * SS + sx) + 0.5) / n * 2.0 - 1.0;
                        let v = (f64::from(y * SS + sy) + 0.5) / n * 2.0 - 1.0;
                        let l = sky.radiance(cube_direction(face, u, v));
                        for c in 0..3 {
                            acc[c] += l[c];
                        }
                    }
                }
                let k = 1.0 / f64::from(SS * SS);
                data.push(acc.map(|a| (a * k) as f32));
            }
        }
    }
    CubeLevel { size, data }
}

/// The engine interface's real SH basis (order Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22).
pub fn sh_basis(d: [f64; 3]) -> [f64; 9] {
    let [x, y, z] = d;
    [
        0.282095,
        0.488603 * y,
        0.488603 * z,
        0.488603 * x,
        1.092548 * x * y,
        1.092548 * y * z,
        0.315392 * (3.0 * z * z - 1.0),
        1.092548 * x * z,
        0.546274 * (x * x - y * y),
    ]
}

/// Projects a cube onto L2 SH (exact texel solid angles), then applies the
/// clamped-cosine convolution A_l / pi = (1, 2/3, 1/4).
pub fn project_sh(level: &CubeLevel) -> [[f32; 3]; 9] {
    let mut acc = [[0.0f64; 3]; 9];
    let n = level.size;
    for face in 0..6 {
        for y in 0..n {
            for x in 0..n {
                let u = (f64::from(x) + 0.5) / f64::from(n) * 2.0 - 1.0;
                let v = (f64::from(y) + 0.5) / f64::from(n) * 2.0 - 1.0;
                let d = cube_direction(face, u, v);
                let w = texel_solid_angle(x, y, n);
                let b = sh_basis(d);
                let l = level.texel(face, x, y);
                for i in 0..9 {
                    for c in 0..3 {
                        acc[i][c] += f64::from(l[c]) * b[i] * w;
                    }
                }
            }
        }
    }
    let band = [
        1.0,
        2.0 / 3.0,
        2.0 / 3.0,
        2.0 / 3.0,
        0.25,
        0.25,
        0.25,
        0.25,
        0.25,
    ];
    let mut out = [[0.0f32; 3]; 9];
    for i in 0..9 {
        for c in 0..3 {
            out[i][c] = (acc[i][c] * band[i]) as f32;
        }
    }
    out
}

fn hammersley(i: u32, n: u32) -> (f64, f64) {
    (
        (f64::from(i) + 0.5) / f64::from(n),
        f64::from(i.reverse_bits()) * (1.0 / 4_294_967_296.0),
    )
}

/// GGX-prefiltered level (Karis 2013 with n = v = r) using filtered importance
/// sampling (Krivanek & Colbert 2008): each sample reads the source chain at
/// the level whose texels match the sample's solid angle, so few samples
/// give a smooth result.
fn prefilter_level(
    chain: &CubeChain,
    size: u32,
    roughness: f64,
    samples: u32,
    base_size: u32,
) -> CubeLevel {
    let alpha = (roughness * roughness).max(1e-4);
    let a2 = alpha * alpha;
    // Per-sample data independent of the texel: tangent-space H, n.l, lod.
    let omega_p = 4.0 * PI / (6.0 * f64::from(base_size) * f64::from(base_size));
    let mut set = Vec::with_capacity(samples as usize);
    for i in 0..samples {
        let (e1, e2) = hammersley(i, samples);
        let phi = 2.0 * PI * e1;
        let cos_t = ((1.0 - e2) / (1.0 + (a2 - 1.0) * e2)).sqrt();
        let sin_t = (1.0 - cos_t * cos_t).max(0.0).sqrt();
        let h = [sin_t * phi.cos(), sin_t * phi.sin(), cos_t];
        // v = n = +z: l = 2 (v.h) h - v.
        let n_dot_l = 2.0 * cos_t * cos_t - 1.0;
        if n_dot_l <= 0.0 {
            continue;
        }
        let l = [2.0 * cos_t * h[0], 2.0 * cos_t * h[1], n_dot_l];
        let dd = cos_t * cos_t * (a2 - 1.0) + 1.0;
        let d = a2 / (PI * dd * dd);
        let pdf = d * 0.25; // D n.h / (4 v.h) with v.h = n.h
        let omega_s = 1.0 / (f64::from(samples) * pdf + 1e-12);
        let lod = (0.5 * (omega_s / omega_p).log2() + 1.0).max(0.0);
        set.push((l, n_dot_l, lod));
    }
    // Faces are independent: computed on scoped threads, stitched in order,
    // so the bytes do not depend on the thread count.
    let face_data = |face: u32| -> Vec<[f32; 3]> {
        let mut data = Vec::with_capacity((size * size) as usize);
        for y in 0..size {
            for x in 0..size {
                let u = (f64::from(x) + 0.5) / f64::from(size) * 2.0 - 1.0;
                let v = (f64::from(y) + 0.5) / f64::from(size) * 2.0 - 1.0;
                let n = cube_direction(face, u, v);
                let up = if n[1].abs() < 0.999 {
                    [0.0, 1.0, 0.0]
                } else {
                    [1.0, 0.0, 0.0]
                };
                let t = normalize64(cross64(up, n));
                let b = cross64(n, t);
                let mut acc = [0.0f64; 3];
                let mut wsum = 0.0;
                for &(l, w, lod) in &set {
                    let dir = [
                        t[0] * l[0] + b[0] * l[1] + n[0] * l[2],
                        t[1] * l[0] + b[1] * l[1] + n[1] * l[2],
                        t[2] * l[0] + b[2] * l[1] + n[2] * l[2],
                    ];
                    let s = chain.sample_lod(dir, lod);
                    acc[0] += s[0] * w;
                    acc[1] += s[1] * w;
                    acc[2] += s[2] * w;
                    wsum += w;
                }
                let k = if wsum > 0.0 { 1.0 / wsum } else { 0.0 };
                data.push([
                    (acc[0] * k) as f32,
                    (acc[1] * k) as f32,
                    (acc[2] * k) as f32,
                ]);
            }
        }
        data
    };
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .clamp(1, 6);
    let mut faces: Vec<Vec<[f32; 3]>> = vec![Vec::new(); 6];
    if threads == 1 || size <= 4 {
        for (f, out) in faces.iter_mut().enumerate() {
            *out = face_data(f as u32);
        }
    } else {
        std::thread::scope(|scope| {
            let face_data = &face_data;
            let handles: Vec<_> = (0..threads)
                .map(|t| {
                    scope.spawn(move || {
                        (0..6u32)
                            .filter(|f| *f as usize % threads == t)
                            .map(|f| (f, face_data(f)))
                            .collect::<Vec<_>>()
                    })
                })
                .collect();
            for h in handles {
                for (f, d) in h.join().expect("prefilter thread") {
                    faces[f as usize] = d;
                }
            }
        });
    }
    CubeLevel {
        size,
        data: faces.concat(),
    }
}

fn cross64(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn face_uv_round_trips() {
        for face in 0..6 {
            for (u, v) in [(-0.5, 0.25), (0.9, -0.9), (0.0, 0.0)] {
                let d = cube_direction(face, u, v);
                let (f, uu, vv) = cube_face_uv(d);
                assert_eq!(f, face);
                assert!((uu - u).abs() < 1e-9 && (vv - v).abs() < 1e-9);
            }
        }
    }

    #[test]
    fn solid_angles_sum_to_sphere() {
        let n = 16;
        let s: f64 = (0..n)
            .flat_map(|y| (0..n).map(move |x| texel_solid_angle(x, y, n)))
            .sum();
        assert!((s * 6.0 - 4.0 * PI).abs() < 1e-9);
    }

    #[test]
    fn constant_environment_has_unit_irradiance() {
        let level = CubeLevel {
            size: 8,
            data: vec![[1.0, 1.0, 1.0]; 8 * 8 * 6],
        };
        let env = EnvironmentMaps {
            sh: project_sh(&level),
            mips: vec![level],
            mip_roughness: vec![0.0],
        };
        for n in [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]] {
            let e = env.sh_irradiance(n);
            assert!((e[0] - 1.0).abs() < 1e-4, "{e:?}");
        }
    }

    #[test]
    fn sh_matches_direct_cosine_integral() {
        // E(n)/pi of the sky, brute force over the cube, vs the SH estimate.
        let params = SkyParams {
            size: 16,
            ..SkyParams::default()
        };
        let level = sky_level(&params, 16);
        let sh = project_sh(&level);
        let env = EnvironmentMaps {
            sh,
            mips: vec![level.clone()],
            mip_roughness: vec![0.0],
        };
        for n in [[0.0f32, 1.0, 0.0], [0.0, -1.0, 0.0], [0.6, 0.0, 0.8]] {
            let nn = n.map(f64::from);
            let mut e = [0.0f64; 3];
            for face in 0..6 {
                for y in 0..16 {
                    for x in 0..16 {
                        let u = (f64::from(x) + 0.5) / 16.0 * 2.0 - 1.0;
                        let v = (f64::from(y) + 0.5) / 16.0 * 2.0 - 1.0;
                        let d = cube_direction(face, u, v);
                        let c = dot64(d, nn).max(0.0) * texel_solid_angle(x, y, 16) / PI;
                        let l = level.texel(face, x, y);
                        for ch in 0..3 {
                            e[ch] += f64::from(l[ch]) * c;
                        }
                    }
                }
            }
            let s = env.sh_irradiance(n);
            // L2 captures irradiance to within a few percent (plus the sun's ringing).
            for ch in 0..3 {
                assert!(
                    (f64::from(s[ch]) - e[ch]).abs() < 0.08 * e[ch] + 0.02,
                    "n={n:?} sh={s:?} direct={e:?}"
                );
            }
        }
    }

    #[test]
    fn mip_mapping_inverts_the_shader_formula() {
        for m in 0..7 {
            let r = MipRoughness::ShaderMapping.roughness(m, 7);
            let mip = r * (1.7 - 0.7 * r) * 6.0;
            assert!((mip - f64::from(m)).abs() < 1e-9);
        }
    }
}
