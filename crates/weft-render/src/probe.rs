//! Numerical-stability probe: evaluates a material's fragment stage for many
//! exact geometric configurations (N, T, V, L) in one small render, and
//! sweeps every variant and a parameter grid derived from the metadata
//! (`weft stability`, `tests/stability.rs`).
//!
//! # The probe scene
//!
//! Each [`GeometricCase`] is one tile of [`Probe::cell`]² pixels, drawn by
//! [`Renderer::render_tiles`] with its own frame uniforms:
//!
//! - the geometry is a 2 × 2 quad through the world origin, perpendicular to
//!   the case's view direction V and wound counter-clockwise towards it, so it
//!   is always front-facing and rasterised;
//! - the *vertex attributes* carry the case's normal and tangent (constant
//!   over the quad), so the shading normal is whatever the case asks,
//!   including back-facing, zero-length or non-orthogonal frames;
//! - the camera sits at `V * 1e6` looking at the origin, with a field of view
//!   that the quad over-fills: the shader's `camera_position - world_position`
//!   is V to within |p| / 1e6 <= 1.5e-6 rad;
//! - the main light direction is the case's L exactly.
//!
//! Outputs are read from an `Rgba32Float` target (nothing is hidden by f16
//! rounding) and every channel of every pixel is classified by [`classify`].
//! A half-precision variant (metadata `f16_files`) is drawn from its f16
//! files and from its f32 files, and the two are compared by
//! [`classify_half`]: an f16 overflow the shader's final clamp would hide,
//! and an underflow to 0 where the f32 value is visible.

use crate::environment::{EnvironmentMaps, Luts, SkyParams};
use crate::error::{Error, Result};
use crate::gpu::Gpu;
use crate::image::HdrImage;
use crate::material::{CurveValue, Material, Value};
use crate::math::{self, Vec3};
use crate::renderer::{Background, ColorFormat, RenderOptions, Renderer, ShaderLanguage, Tile};
use crate::scene::{Camera, Light, Mesh, Scene};
use std::collections::BTreeMap;
use std::fmt;
use std::path::{Path, PathBuf};
use weft_meta::{
    GradientStop, InstanceCount, KeywordMode, MaterialMetadata, ParamKind, Parameter,
    TextureDefault, VariantShader,
};

/// Largest finite f16: anything above it is "absurdly large" (it would be
/// Inf in an `Rgba16Float` target).
pub const MAX_HALF: f32 = 65504.0;

/// Distance of the probe camera along V.
const CAMERA_DISTANCE: f32 = 1.0e6;

/// One geometric configuration: world-space vectors as the shader receives them.
#[derive(Clone, Debug, PartialEq)]
pub struct GeometricCase {
    pub name: String,
    /// The vertex normal (not necessarily unit; may be zero).
    pub normal: Vec3,
    /// The vertex tangent, w = bitangent sign (not necessarily unit or orthogonal).
    pub tangent: [f32; 4],
    /// Unit direction towards the camera.
    pub view: Vec3,
    /// Unit direction towards the light.
    pub light: Vec3,
}

impl GeometricCase {
    /// N·V with the normal normalised (0 for a zero normal).
    pub fn n_dot_v(&self) -> f32 {
        math::dot(math::normalize_or(self.normal, [0.0; 3]), self.view)
    }

    /// N·L with the normal normalised (0 for a zero normal).
    pub fn n_dot_l(&self) -> f32 {
        math::dot(math::normalize_or(self.normal, [0.0; 3]), self.light)
    }
}

/// Unit vector at polar cosine `cos_theta` from +Z (may be negative: below
/// the horizon) and azimuth `phi` from +X.
fn polar(cos_theta: f32, phi: f32) -> Vec3 {
    let c = f64::from(cos_theta);
    let s = (1.0 - c * c).max(0.0).sqrt();
    let p = f64::from(phi);
    [(s * p.cos()) as f32, (s * p.sin()) as f32, c as f32]
}

fn cos_label(c: f32) -> String {
    if c == 0.0 {
        "0".into()
    } else if c.abs() < 1e-3 {
        format!("{c:e}")
    } else {
        format!("{c}")
    }
}

/// The geometric extremes every material is evaluated at. The frame is
/// N = +Z, T = +X (w = +1) unless a case says otherwise.
///
/// - N·V × N·L over {1, 1e-4, 0, -0.5}², with L at the mirror azimuth
///   (φ_L = φ_V + π), at the same azimuth (L = V when the cosines agree) and
///   at a right angle (H off the incidence plane): 48 cases;
/// - L = V and L = −V at N·V = 1, 0.5, 1e-4, 0 (and −0.5 for L = −V, light
///   from above);
/// - grazing V along T and along B;
/// - H parallel to the tangent (V, L in the T–B plane; and N·V = −N·L = 0.8)
///   and to the bitangent;
/// - tangent: zero-length, parallel to N, 1e-4 from N, 45° to N, length 5,
///   w = 0, w = −1, each at a generic, a grazing and a normal-incidence
///   configuration;
/// - a zero-length normal and a non-unit normal.
pub fn geometric_cases() -> Vec<GeometricCase> {
    use std::f32::consts::{FRAC_PI_2, PI};
    let n = [0.0, 0.0, 1.0];
    let t = [1.0, 0.0, 0.0, 1.0];
    let case =
        |name: String, normal: Vec3, tangent: [f32; 4], view: Vec3, light: Vec3| GeometricCase {
            name,
            normal,
            tangent,
            view,
            light,
        };
    let cosines = [1.0f32, 1e-4, 0.0, -0.5];
    let mut out = Vec::new();
    for (az, dphi) in [
        ("mirror", PI),
        ("same-azimuth", 0.0),
        ("right-angle", FRAC_PI_2),
    ] {
        for &cv in &cosines {
            for &cl in &cosines {
                out.push(case(
                    format!("N.V={} N.L={} {az}", cos_label(cv), cos_label(cl)),
                    n,
                    t,
                    polar(cv, 0.0),
                    polar(cl, dphi),
                ));
            }
        }
    }
    for c in [0.5f32, 1e-4, 0.0] {
        let v = polar(c, 0.3);
        out.push(case(format!("L=V N.V={}", cos_label(c)), n, t, v, v));
    }
    for c in [1.0f32, 0.5, 1e-4, 0.0, -0.5] {
        let v = polar(c, 0.3);
        out.push(case(
            format!("L=-V N.V={}", cos_label(c)),
            n,
            t,
            v,
            math::scale(v, -1.0),
        ));
    }
    let generic_l = polar(0.7, 2.5);
    out.push(case(
        "grazing V along T".into(),
        n,
        t,
        [1.0, 0.0, 0.0],
        generic_l,
    ));
    out.push(case(
        "grazing V along B".into(),
        n,
        t,
        [0.0, 1.0, 0.0],
        generic_l,
    ));
    out.push(case(
        "H parallel to T, V and L in the T-B plane".into(),
        n,
        t,
        [0.6, 0.8, 0.0],
        [0.6, -0.8, 0.0],
    ));
    out.push(case(
        "H parallel to T, N.V=0.8 N.L=-0.8".into(),
        n,
        t,
        [0.6, 0.0, 0.8],
        [0.6, 0.0, -0.8],
    ));
    out.push(case(
        "H parallel to B, N.V=0.8 N.L=-0.8".into(),
        n,
        t,
        [0.0, 0.6, 0.8],
        [0.0, 0.6, -0.8],
    ));
    let s = std::f32::consts::FRAC_1_SQRT_2;
    let tangents: [(&str, [f32; 4]); 7] = [
        ("zero-length tangent", [0.0, 0.0, 0.0, 1.0]),
        ("tangent parallel to N", [0.0, 0.0, 1.0, 1.0]),
        ("tangent 1e-4 from N", [1e-4, 0.0, 1.0, 1.0]),
        ("tangent 45deg to N (non-orthogonal)", [s, 0.0, s, 1.0]),
        ("tangent of length 5", [5.0, 0.0, 0.0, 1.0]),
        ("tangent w=0", [1.0, 0.0, 0.0, 0.0]),
        ("tangent w=-1", [1.0, 0.0, 0.0, -1.0]),
    ];
    let configs: [(&str, Vec3, Vec3); 3] = [
        ("generic", polar(0.5, 0.4), generic_l),
        ("grazing N.V=1e-4", polar(1e-4, 0.4), generic_l),
        ("N=V=L", n, n),
    ];
    for (tname, tan) in tangents {
        for (cname, v, l) in configs {
            out.push(case(format!("{tname}, {cname}"), n, tan, v, l));
        }
    }
    out.push(case(
        "zero-length normal, generic".into(),
        [0.0; 3],
        t,
        polar(0.5, 0.4),
        generic_l,
    ));
    out.push(case(
        "normal of length 3, generic".into(),
        [0.0, 0.0, 3.0],
        t,
        polar(0.5, 0.4),
        generic_l,
    ));
    out
}

/// A unit vector perpendicular to the unit vector `v`.
fn perpendicular(v: Vec3) -> Vec3 {
    let a = if v[0].abs() < 0.6 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    math::normalize(math::cross(v, a))
}

/// The tile of one case: a quad facing V with the case's attributes, the
/// camera far along V, the light along L.
fn case_scene(case: &GeometricCase, light_radiance: Vec3) -> Scene {
    let v = math::normalize(case.view);
    let up = perpendicular(v);
    let eye = math::scale(v, CAMERA_DISTANCE);
    // The camera's own right/up (as math::look_at computes them), so the
    // quad is counter-clockwise on screen.
    let f = math::scale(v, -1.0);
    let right = math::normalize(math::cross(f, up));
    let cam_up = math::cross(right, f);
    let corner = |a: f32, b: f32| math::add(math::scale(right, a), math::scale(cam_up, b));
    let mesh = Mesh {
        positions: vec![
            corner(-1.0, -1.0),
            corner(1.0, -1.0),
            corner(1.0, 1.0),
            corner(-1.0, 1.0),
        ],
        normals: vec![case.normal; 4],
        tangents: vec![case.tangent; 4],
        uv0: vec![[0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]],
        uv1: Vec::new(),
        colors: Vec::new(),
        indices: vec![0, 1, 2, 0, 2, 3],
    };
    // The frustum's half-height at the quad is 0.5: the 2 x 2 quad
    // over-fills the viewport even if f32 rounding of the view matrix
    // shifts it by a few tenths.
    let half = 0.5 / CAMERA_DISTANCE;
    Scene {
        mesh,
        model: math::IDENTITY,
        camera: Camera {
            eye,
            target: [0.0; 3],
            up,
            fov_y_degrees: (2.0 * f64::from(half).atan()).to_degrees() as f32,
            near: CAMERA_DISTANCE * 0.5,
            far: CAMERA_DISTANCE * 2.0,
        },
        light: Light {
            direction: case.light,
            radiance: light_radiance,
        },
    }
}

/// The probe scene: one tile per geometric case.
pub struct Probe {
    pub cases: Vec<GeometricCase>,
    /// Tile size in pixels (square).
    pub cell: u32,
    pub columns: u32,
    tiles: Vec<Tile>,
}

impl Probe {
    /// Tiles of `cell` x `cell` pixels, `columns` per row.
    pub fn new(cases: Vec<GeometricCase>, light_radiance: Vec3, cell: u32, columns: u32) -> Probe {
        let cell = cell.max(1);
        let columns = columns.max(1);
        let tiles = cases
            .iter()
            .enumerate()
            .map(|(i, c)| {
                let i = i as u32;
                Tile {
                    scene: case_scene(c, light_radiance),
                    viewport: [(i % columns) * cell, (i / columns) * cell, cell, cell],
                }
            })
            .collect();
        Probe {
            cases,
            cell,
            columns,
            tiles,
        }
    }

    /// [`geometric_cases`] lit by a light of radiance `light_radiance`, 2 x 2 pixels per case.
    pub fn stability(light_radiance: Vec3) -> Probe {
        Probe::new(geometric_cases(), light_radiance, 2, 16)
    }

    pub fn width(&self) -> u32 {
        self.columns.min(self.cases.len().max(1) as u32) * self.cell
    }

    pub fn height(&self) -> u32 {
        (self.cases.len().max(1) as u32).div_ceil(self.columns) * self.cell
    }

    /// Options for preparing and rendering: the probe's size, `Rgba32Float`,
    /// WGSL, a transparent black background.
    pub fn render_options(&self) -> RenderOptions {
        RenderOptions {
            width: self.width(),
            height: self.height(),
            format: ColorFormat::Rgba32Float,
            language: ShaderLanguage::Wgsl,
            background: Background::Color([0.0; 4]),
            ..RenderOptions::default()
        }
    }

    /// Renders the prepared material (prepared with [`Probe::render_options`])
    /// at every case; returns each case's pixels.
    pub fn evaluate(
        &self,
        renderer: &mut Renderer,
        prepared: &crate::renderer::PreparedMaterial,
    ) -> Result<Vec<Vec<[f32; 4]>>> {
        let image = renderer.render_tiles(prepared, &self.tiles, &self.render_options())?;
        Ok(self.split(&image))
    }

    /// The pixels of each case's tile.
    pub fn split(&self, image: &HdrImage) -> Vec<Vec<[f32; 4]>> {
        self.tiles
            .iter()
            .map(|t| {
                let [x0, y0, w, h] = t.viewport;
                let mut px = Vec::with_capacity((w * h) as usize);
                for y in y0..y0 + h {
                    for x in x0..x0 + w {
                        px.push(image.pixels[(y * image.width + x) as usize]);
                    }
                }
                px
            })
            .collect()
    }
}

/// Why an output value is bad.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum BadKind {
    NaN,
    Inf,
    Negative,
    /// Finite but above [`MAX_HALF`].
    Huge,
    /// A half-precision variant saturates at the f16 maximum (or overflows to
    /// Inf) where its f32 fallback stays below it.
    HalfOverflow,
    /// A half-precision variant gives 0 where its f32 fallback is visible
    /// (at least [`VISIBLE`]): an f16 underflow that changes the picture.
    HalfUnderflow,
}

/// The smallest linear value an 8-bit sRGB display shows as non-black (1/255
/// after the sRGB curve): below it an underflow to 0 cannot be seen.
pub const VISIBLE: f32 = 1.0 / 255.0 / 12.92;

/// Compares a half-precision render's channel with its f32 fallback's.
pub fn classify_half(half: f32, full: f32) -> Option<BadKind> {
    if (half >= MAX_HALF || half.is_infinite()) && full < MAX_HALF {
        Some(BadKind::HalfOverflow)
    } else if half == 0.0 && full >= VISIBLE {
        Some(BadKind::HalfUnderflow)
    } else {
        None
    }
}

impl fmt::Display for BadKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            BadKind::NaN => "NaN",
            BadKind::Inf => "Inf",
            BadKind::Negative => "negative",
            BadKind::Huge => "> 65504",
            BadKind::HalfOverflow => "f16 overflow (the f32 fallback stays below 65504)",
            BadKind::HalfUnderflow => "f16 underflow to 0 (the f32 fallback is visible)",
        })
    }
}

/// NaN, ±Inf, negative (< 0; -0.0 is fine) or above 65504.
pub fn classify(x: f32) -> Option<BadKind> {
    if x.is_nan() {
        Some(BadKind::NaN)
    } else if x.is_infinite() {
        Some(BadKind::Inf)
    } else if x < 0.0 {
        Some(BadKind::Negative)
    } else if x > MAX_HALF {
        Some(BadKind::Huge)
    } else {
        None
    }
}

// ------------------------------------------------------------------ grid

/// One point of the parameter grid: values set on top of the defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct Setting {
    /// e.g. `defaults`, `roughness=0 (min)`, `all-max`.
    pub label: String,
    pub values: Vec<(String, Value)>,
}

/// Which end of a parameter's domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum End {
    Min,
    Mid,
    Max,
}

fn numeric_domain(p: &Parameter) -> (f64, f64) {
    if let Some([lo, hi]) = p.range {
        return (lo, hi);
    }
    if let Some([lo, hi]) = p.soft_range {
        return (lo, hi);
    }
    match p.kind {
        ParamKind::Color => (0.0, 1.0),
        _ => {
            // Unbounded: from min(0, default) to max(1, 2 default).
            let d = p
                .default
                .as_f64()
                .or_else(|| p.default.as_array().and_then(|a| a.first()?.as_f64()))
                .unwrap_or(0.0);
            (d.min(0.0), (2.0 * d).max(1.0))
        }
    }
}

fn fmt_num(x: f64) -> String {
    let s = format!("{x}");
    if s.len() > 10 { format!("{x:.4}") } else { s }
}

/// The value of `p` at one end of its domain, with its label; None when the
/// kind has no such value (e.g. the middle of a texture).
fn param_value(p: &Parameter, end: End) -> Option<(Value, String)> {
    let (lo, hi) = numeric_domain(p);
    let x = match end {
        End::Min => lo,
        End::Max => hi,
        End::Mid => 0.5 * (lo + hi),
    };
    let tag = match end {
        End::Min => "min",
        End::Mid => "mid",
        End::Max => "max",
    };
    match p.kind {
        ParamKind::Float => Some((Value::Float(x), fmt_num(x))),
        ParamKind::Int => {
            let i = match end {
                End::Mid => x.round(),
                End::Min => x.ceil(),
                End::Max => x.floor(),
            };
            Some((Value::Int(i as i64), format!("{i}")))
        }
        ParamKind::Bool => match end {
            End::Min => Some((Value::Bool(false), "false".into())),
            End::Max => Some((Value::Bool(true), "true".into())),
            End::Mid => None,
        },
        ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4 => {
            let n = p.kind.components().unwrap_or(4);
            Some((Value::Vector(vec![x; n]), format!("all {}", fmt_num(x))))
        }
        ParamKind::Color => {
            if end == End::Mid {
                return None;
            }
            // rgb at the end of the range, alpha 0 or 1 (clamped into the range).
            let a: f64 = if end == End::Min { 0.0 } else { 1.0 };
            let a = a.clamp(lo, hi);
            Some((
                Value::Vector(vec![x, x, x, a]),
                format!("[{0}, {0}, {0}, {1}]", fmt_num(x), fmt_num(a)),
            ))
        }
        ParamKind::Curve => {
            let n = p.curve.as_ref()?.samples as usize;
            let samples: Vec<f64> = match end {
                End::Min => vec![lo; n],
                End::Max => vec![hi; n],
                // The steepest curve: samples alternate between the ends.
                End::Mid => (0..n).map(|i| if i % 2 == 0 { lo } else { hi }).collect(),
            };
            let label = match end {
                End::Mid => format!("zigzag {}/{}", fmt_num(lo), fmt_num(hi)),
                _ => format!("flat {}", fmt_num(x)),
            };
            Some((Value::Curve(CurveValue::Samples(samples)), label))
        }
        ParamKind::Gradient => {
            let c = match end {
                End::Min => 0.0,
                End::Max => 1.0,
                End::Mid => return None,
            };
            let stop = |position| GradientStop {
                position,
                color: [c, c, c, c],
            };
            Some((
                Value::Gradient(vec![stop(0.0), stop(1.0)]),
                format!("flat [{c}, {c}, {c}, {c}]"),
            ))
        }
        ParamKind::Texture2d | ParamKind::Cube => {
            let t = match end {
                End::Min => TextureDefault::Black,
                End::Max => TextureDefault::White,
                End::Mid => TextureDefault::Normal,
            };
            if p.kind == ParamKind::Cube && end == End::Mid {
                return None;
            }
            Some((Value::from(t), t.name().to_string()))
        }
    }
    .map(|(v, label)| (v, format!("{label} ({tag})")))
}

/// Whether the variant reads the parameter: its uniform member or tiling
/// member is in the variant's uniform layout, a binding carries it, or a
/// pass takes its instance count from it.
pub fn variant_reads(meta: &MaterialMetadata, shader: &VariantShader, p: &Parameter) -> bool {
    let member = |m: &String| {
        shader
            .material_uniform
            .as_ref()
            .is_some_and(|u| u.members.iter().any(|x| &x.name == m))
    };
    p.uniform_member.as_ref().is_some_and(member)
        || p.texture
            .as_ref()
            .and_then(|t| t.tiling_member.as_ref())
            .is_some_and(member)
        || shader
            .bindings
            .iter()
            .any(|b| b.parameter.as_deref() == Some(p.name.as_str()))
        || meta
            .passes
            .iter()
            .any(|pass| matches!(&pass.instances, InstanceCount::Parameter(n) if *n == p.name))
}

/// The parameter grid of one variant: the defaults; each parameter the
/// variant reads at its min, mid and max (colours at 0 and 1, bools false and
/// true, textures black / white / flat normal, curves flat at their range's
/// ends and zigzag, gradients black and white) with every other parameter
/// at its default; and the corners all-min and all-max (every parameter).
pub fn parameter_settings(meta: &MaterialMetadata, shader: &VariantShader) -> Vec<Setting> {
    let mut out = vec![Setting {
        label: "defaults".into(),
        values: Vec::new(),
    }];
    for p in &meta.parameters {
        if !variant_reads(meta, shader, p) {
            continue;
        }
        for end in [End::Min, End::Mid, End::Max] {
            if let Some((v, label)) = param_value(p, end) {
                out.push(Setting {
                    label: format!("{}={label}", p.name),
                    values: vec![(p.name.clone(), v)],
                });
            }
        }
    }
    for (end, label) in [(End::Min, "all-min"), (End::Max, "all-max")] {
        out.push(Setting {
            label: label.into(),
            values: meta
                .parameters
                .iter()
                .filter_map(|p| Some((p.name.clone(), param_value(p, end)?.0)))
                .collect(),
        });
    }
    out
}

// ------------------------------------------------------------------ sweep

/// Where a bad output happened.
#[derive(Clone, Debug, PartialEq)]
pub struct Failure {
    pub material: String,
    /// Variant id, plus `+KEYWORD=value` for constant-mode keywords.
    pub variant: String,
    /// The parameter setting's label.
    pub setting: String,
    /// The geometric case's name (with its N·V and N·L).
    pub case: String,
    pub n_dot_v: f32,
    pub n_dot_l: f32,
    /// The first bad pixel of the tile (RGBA) and its kind.
    pub value: [f32; 4],
    pub kind: BadKind,
    /// Bad channels in the tile.
    pub count: usize,
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} {} [{}] at `{}` (N.V={}, N.L={}): {} ({} channel{}), rgba = {:?}",
            self.material,
            self.variant,
            self.setting,
            self.case,
            cos_label(self.n_dot_v),
            cos_label(self.n_dot_l),
            self.kind,
            self.count,
            if self.count == 1 { "" } else { "s" },
            self.value
        )
    }
}

/// Counts of one material's sweep.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MaterialSweep {
    pub material: String,
    /// Canonical variants swept (times constant-keyword combinations).
    pub variants: usize,
    /// Variants skipped because they alias a swept one (identical WGSL).
    pub aliases: usize,
    /// Renders: (variant, parameter setting) pairs.
    pub renders: usize,
    /// Tiles drawn: renders x geometric cases.
    pub draws: usize,
    /// Channels checked.
    pub outputs: u64,
    /// Bad channels.
    pub bad: u64,
    /// Renders of half-precision variants compared with their f32 fallback.
    pub half_compared: usize,
    /// Renders of half-precision variants that could not be compared: the
    /// device has no `shader-f16`, so only the f32 files were drawn.
    pub half_unchecked: usize,
}

/// The result of a sweep over one or more materials.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SweepReport {
    pub cases: usize,
    pub materials: Vec<MaterialSweep>,
    /// One entry per (variant, setting, case) with bad outputs, at most
    /// [`SweepReport::MAX_RECORDED`].
    pub failures: Vec<Failure>,
}

impl SweepReport {
    pub const MAX_RECORDED: usize = 100_000;

    pub fn bad(&self) -> u64 {
        self.materials.iter().map(|m| m.bad).sum()
    }

    pub fn outputs(&self) -> u64 {
        self.materials.iter().map(|m| m.outputs).sum()
    }

    pub fn renders(&self) -> usize {
        self.materials.iter().map(|m| m.renders).sum()
    }

    pub fn draws(&self) -> usize {
        self.materials.iter().map(|m| m.draws).sum()
    }

    /// One line of totals.
    pub fn summary(&self) -> String {
        let compared: usize = self.materials.iter().map(|m| m.half_compared).sum();
        let unchecked: usize = self.materials.iter().map(|m| m.half_unchecked).sum();
        let half = match (compared, unchecked) {
            (0, 0) => String::new(),
            (c, 0) => format!("; {c} half-precision renders compared with their f32 fallback"),
            (c, u) => format!(
                "; {c} half-precision renders compared with their f32 fallback, {u} NOT compared (the device has no shader-f16)"
            ),
        };
        format!(
            "{} material(s), {} variant(s) ({} aliases skipped), {} parameter settings x {} geometric cases = {} draws, {} outputs checked: {} bad{half}",
            self.materials.len(),
            self.materials.iter().map(|m| m.variants).sum::<usize>(),
            self.materials.iter().map(|m| m.aliases).sum::<usize>(),
            self.renders(),
            self.cases,
            self.draws(),
            self.outputs(),
            self.bad()
        )
    }
}

/// A renderer for sweeps: a small procedural sky (16² faces; the sweep
/// checks finiteness, not appearance) and the LUTs of a generated folder.
pub fn sweep_renderer(luts: &Luts) -> Result<Renderer> {
    let sky = SkyParams {
        size: 16,
        samples: 16,
        ..SkyParams::default()
    };
    Renderer::new(Gpu::new()?, &EnvironmentMaps::sky(&sky), luts)
}

/// Every `<dir>/<name>/<name>.meta.json` of a generated folder, sorted.
pub fn generated_materials(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    let entries = std::fs::read_dir(dir).map_err(|e| Error::Io {
        path: dir.to_path_buf(),
        source: e,
    })?;
    for entry in entries.flatten() {
        let path = entry.path();
        let Some(name) = path.file_name().map(|n| n.to_string_lossy().into_owned()) else {
            continue;
        };
        let meta = path.join(format!("{name}.meta.json"));
        if meta.is_file() {
            out.push(meta);
        }
    }
    out.sort();
    Ok(out)
}

/// Every combination of the constant-mode keywords' values.
fn constant_combinations(meta: &MaterialMetadata) -> Vec<Vec<(String, String)>> {
    let mut combos: Vec<Vec<(String, String)>> = vec![Vec::new()];
    for k in meta
        .keywords
        .iter()
        .filter(|k| k.mode == KeywordMode::Constant)
    {
        combos = combos
            .into_iter()
            .flat_map(|c| {
                k.values.iter().map(move |v| {
                    let mut c = c.clone();
                    c.push((k.name.clone(), v.clone()));
                    c
                })
            })
            .collect();
    }
    combos
}

/// Sweeps one material (`<name>.meta.json`): every canonical variant x every
/// constant-keyword combination x [`parameter_settings`], each rendered at
/// every case of `probe`. `progress(done, total)` is called after each render.
pub fn sweep_material(
    renderer: &mut Renderer,
    probe: &Probe,
    meta_path: &Path,
    report: &mut SweepReport,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<()> {
    let mut material = Material::load(meta_path)?;
    let meta = material.metadata().clone();
    let options = probe.render_options();
    report.cases = probe.cases.len();
    let mut summary = MaterialSweep {
        material: meta.name.clone(),
        ..MaterialSweep::default()
    };
    let mut jobs = Vec::new();
    for v in &meta.variants {
        if v.alias_of.is_some() {
            summary.aliases += 1;
            continue;
        }
        let Some(shader) = &v.shader else { continue };
        let settings = parameter_settings(&meta, shader);
        let half = !shader.f16_files.is_empty();
        for combo in constant_combinations(&meta) {
            jobs.push((v.id.clone(), combo, settings.clone(), half));
        }
    }
    summary.variants = jobs.len();
    let total: usize = jobs.iter().map(|j| j.2.len()).sum();
    let has_f16 = renderer
        .gpu()
        .device
        .features()
        .contains(wgpu::Features::SHADER_F16);
    for (id, combo, settings, half) in jobs {
        let variant_label = std::iter::once(id.clone())
            .chain(combo.iter().map(|(k, v)| format!("+{k}={v}")))
            .collect::<String>();
        for setting in settings {
            material.reset()?;
            material.select_variant(&id)?;
            for (k, v) in &combo {
                material.set_keyword(k, v)?;
            }
            for (name, value) in &setting.values {
                material
                    .set(name, value.clone())
                    .map_err(|e| Error::InvalidValue {
                        name: name.clone(),
                        message: format!("probe setting `{}`: {e}", setting.label),
                    })?;
            }
            let prepared = renderer.prepare(&material, &options)?;
            let tiles = probe.evaluate(renderer, &prepared)?;
            // A half-precision variant is also drawn in f32 (its fallback):
            // where they disagree by an overflow or a visible underflow, f16
            // changed the picture.
            let fallback_tiles = match half && has_f16 {
                true => {
                    let options = RenderOptions {
                        f32_fallback: true,
                        ..options
                    };
                    let prepared = renderer.prepare(&material, &options)?;
                    summary.half_compared += 1;
                    Some(probe.evaluate(renderer, &prepared)?)
                }
                false => {
                    summary.half_unchecked += half as usize;
                    None
                }
            };
            summary.renders += 1;
            summary.draws += tiles.len();
            for (i, (case, pixels)) in probe.cases.iter().zip(&tiles).enumerate() {
                let mut first: Option<([f32; 4], BadKind)> = None;
                let mut count = 0;
                let full = fallback_tiles.as_ref().map(|t| &t[i]);
                for (j, px) in pixels.iter().enumerate() {
                    summary.outputs += 4;
                    for (c, &x) in px.iter().enumerate() {
                        let kind =
                            classify(x).or_else(|| full.and_then(|f| classify_half(x, f[j][c])));
                        if let Some(kind) = kind {
                            count += 1;
                            first.get_or_insert((*px, kind));
                        }
                    }
                }
                if let Some((value, kind)) = first {
                    summary.bad += count as u64;
                    if report.failures.len() < SweepReport::MAX_RECORDED {
                        report.failures.push(Failure {
                            material: meta.name.clone(),
                            variant: variant_label.clone(),
                            setting: setting.label.clone(),
                            case: case.name.clone(),
                            n_dot_v: case.n_dot_v(),
                            n_dot_l: case.n_dot_l(),
                            value,
                            kind,
                            count,
                        });
                    }
                }
            }
            progress(summary.renders, total);
        }
    }
    report.materials.push(summary);
    Ok(())
}

/// Failures grouped by geometric case: case -> (count of (variant, setting)
/// pairs, kinds seen).
pub fn failures_by_case(failures: &[Failure]) -> BTreeMap<String, (usize, Vec<BadKind>)> {
    let mut out: BTreeMap<String, (usize, Vec<BadKind>)> = BTreeMap::new();
    for f in failures {
        let e = out.entry(f.case.clone()).or_default();
        e.0 += 1;
        if !e.1.contains(&f.kind) {
            e.1.push(f.kind);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_precision_outputs_are_held_against_their_f32_fallback() {
        use super::{BadKind, VISIBLE, classify_half};
        assert_eq!(classify_half(65504.0, 7e4), None); // both saturate
        assert_eq!(classify_half(65504.0, 1.2e3), Some(BadKind::HalfOverflow));
        assert_eq!(
            classify_half(f32::INFINITY, 10.0),
            Some(BadKind::HalfOverflow)
        );
        assert_eq!(classify_half(0.0, VISIBLE), Some(BadKind::HalfUnderflow));
        assert_eq!(classify_half(0.0, VISIBLE * 0.5), None); // invisible either way
        assert_eq!(classify_half(0.2, 0.2001), None); // rounding is not a failure
    }

    #[test]
    fn cases_have_the_cosines_they_are_named_after() {
        let cases = geometric_cases();
        let find = |name: &str| cases.iter().find(|c| c.name == name).unwrap();
        let c = find("N.V=1e-4 N.L=-0.5 mirror");
        assert!((c.n_dot_v() - 1e-4).abs() < 1e-7);
        assert!((c.n_dot_l() + 0.5).abs() < 1e-6);
        let c = find("L=-V N.V=0");
        assert_eq!(math::add(c.view, c.light), [0.0; 3]);
        let c = find("H parallel to T, V and L in the T-B plane");
        let h = math::normalize(math::add(c.view, c.light));
        assert_eq!(h, [1.0, 0.0, 0.0]);
        for c in &cases {
            assert!((math::length(c.view) - 1.0).abs() < 1e-6, "{}", c.name);
            assert!((math::length(c.light) - 1.0).abs() < 1e-6, "{}", c.name);
        }
    }

    #[test]
    fn quads_face_the_camera_counter_clockwise() {
        for c in geometric_cases() {
            let s = case_scene(&c, [1.0; 3]);
            let vp = s.camera.view_proj(1.0);
            let ndc: Vec<[f32; 2]> = s.mesh.positions[..3]
                .iter()
                .map(|p| {
                    let q = math::transform_point(&vp, *p);
                    [q[0] / q[3], q[1] / q[3]]
                })
                .collect();
            let (a, b, d) = (ndc[0], ndc[1], ndc[2]);
            let area = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
            assert!(area > 0.0, "{}: clockwise", c.name);
            // The quad over-fills the viewport ([-1, 1]) on every side.
            assert!(
                a[0] < -1.2 && a[1] < -1.2 && d[0] > 1.2 && d[1] > 1.2,
                "{}: {ndc:?}",
                c.name
            );
        }
    }
}
