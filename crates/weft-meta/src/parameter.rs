//! Inspector parameters: their kinds, defaults and the colour, texture,
//! curve and gradient details each kind carries.

use crate::{Condition, ResourceFile, Text, bake};
#[cfg(feature = "schema")]
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// The value kinds a parameter can have.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum ParamKind {
    /// A number: uniform member `f32` (encoding `f32`).
    Float,
    /// An integer: uniform member `i32` (encoding `i32`).
    Int,
    /// A run-time switch: uniform member `u32`, 0 or 1 (encoding `bool_u32`).
    Bool,
    /// Two numbers: uniform member `vec2<f32>` (encoding `vector`).
    Vec2,
    /// Three numbers: uniform member `vec3<f32>` (encoding `vector`; 12 bytes at 16-byte
    /// alignment).
    Vec3,
    /// Four numbers: uniform member `vec4<f32>` (encoding `vector`).
    Vec4,
    /// An RGBA colour edited in sRGB (linear when `color.hdr`): uniform member `vec4<f32>`
    /// (encoding `color`).
    Color,
    /// A 2-D texture (`texture_2d<f32>`) at its own group-1 `binding`; no uniform member unless
    /// tiled (`texture.tiling_member`).
    Texture2d,
    /// A cube texture (`texture_cube<f32>`) at its own group-1 `binding`.
    Cube,
    /// A keyframed curve baked into uniform samples (encoding `curve`; see `curve`).
    Curve,
    /// A colour ramp baked into a `width` × 1 `rgba8unorm_srgb` texture at its own group-1
    /// `binding` (see `gradient`).
    Gradient,
}

impl ParamKind {
    pub const ALL: [ParamKind; 11] = [
        ParamKind::Float,
        ParamKind::Int,
        ParamKind::Bool,
        ParamKind::Vec2,
        ParamKind::Vec3,
        ParamKind::Vec4,
        ParamKind::Color,
        ParamKind::Texture2d,
        ParamKind::Cube,
        ParamKind::Curve,
        ParamKind::Gradient,
    ];

    pub fn name(self) -> &'static str {
        match self {
            ParamKind::Float => "float",
            ParamKind::Int => "int",
            ParamKind::Bool => "bool",
            ParamKind::Vec2 => "vec2",
            ParamKind::Vec3 => "vec3",
            ParamKind::Vec4 => "vec4",
            ParamKind::Color => "color",
            ParamKind::Texture2d => "texture2d",
            ParamKind::Cube => "cube",
            ParamKind::Curve => "curve",
            ParamKind::Gradient => "gradient",
        }
    }

    /// Number of scalar components of a numeric parameter (None for resources).
    pub fn components(self) -> Option<usize> {
        match self {
            ParamKind::Float | ParamKind::Int | ParamKind::Bool => Some(1),
            ParamKind::Vec2 => Some(2),
            ParamKind::Vec3 => Some(3),
            ParamKind::Vec4 | ParamKind::Color => Some(4),
            _ => None,
        }
    }
}

/// One inspector parameter.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Parameter {
    /// Parameter name (lower_snake_case): the key in presets and scene values, and the uniform
    /// member's name for uniform-backed kinds.
    pub name: String,
    /// Value kind: decides how the value is stored and which of `color`, `texture`, `curve` and
    /// `gradient` is present.
    pub kind: ParamKind,
    /// Display name.
    pub label: Text,
    /// Hover help; absent when none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tooltip: Option<Text>,
    /// The `groups[].name` of the section the parameter is shown in.
    pub group: String,
    /// Sort key within the group, ascending (default 0).
    pub order: i64,
    /// Default value as the inspector shows it: a number, bool, array of
    /// numbers (vectors; colours in sRGB-encoded space unless `hdr`), or a
    /// texture default name.
    pub default: serde_json::Value,
    /// Hard limits [min, max], inclusive: values outside are invalid and the inspector clamps
    /// to them. Per component for vectors and colours, keyframe values for curves. Non-HDR
    /// colours get [0, 1]; absent: unbounded.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub range: Option<[f64; 2]>,
    /// The slider's span [min, max], inside `range`; values outside it (but inside `range`) may
    /// still be typed in. Absent: the slider spans `range`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub soft_range: Option<[f64; 2]>,
    /// Slider increment (> 0); absent: the inspector chooses.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub step: Option<f64>,
    /// Power-slider exponent: slider position p maps to value min + (max-min) p^power.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub power: Option<f64>,
    /// Show the parameter only while this condition holds; absent: always shown.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub show_if: Option<Condition>,
    /// Present for `color` parameters: the HDR flag and the linear default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<ColorInfo>,
    /// Present for `texture2d` and `cube` parameters: defaults, sRGB flag and tiling.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub texture: Option<TextureInfo>,
    /// Present for `curve` parameters: keyframes and how they are baked into the uniform.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub curve: Option<CurveInfo>,
    /// Present for `gradient` parameters: stops and how they are baked into the ramp texture.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gradient: Option<GradientInfo>,
    /// Where the value lives in the material uniform (numeric kinds, curves, texture tiling).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub uniform_member: Option<String>,
    /// The binding (group 1) of a texture, cube or gradient ramp.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub binding: Option<u32>,
}

/// Colour details of a `color` parameter.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct ColorInfo {
    /// HDR colours may exceed 1 and are edited in linear space.
    pub hdr: bool,
    /// The default converted to the linear value written into the uniform.
    pub linear_default: [f64; 4],
}

/// Built-in 1x1 textures an engine binds when a texture parameter is unset.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum TextureDefault {
    /// (1,1,1,1)
    White,
    /// (0,0,0,1)
    Black,
    /// (0.5,0.5,0.5,1) in the texture's own encoding: bytes (128, 128, 128, 255).
    Gray,
    /// Flat tangent-space normal (0.5,0.5,1,1): bytes (128, 128, 255, 255).
    Normal,
}

impl TextureDefault {
    pub const ALL: [TextureDefault; 4] = [
        TextureDefault::White,
        TextureDefault::Black,
        TextureDefault::Gray,
        TextureDefault::Normal,
    ];
    pub fn name(self) -> &'static str {
        match self {
            TextureDefault::White => "white",
            TextureDefault::Black => "black",
            TextureDefault::Gray => "gray",
            TextureDefault::Normal => "normal",
        }
    }
    /// The RGBA8 bytes of the built-in 1x1 texture: what weft's renderer
    /// uploads and metadata states (`conventions.builtin_textures`). 0.5 is
    /// 128 (0.5 × 255 = 127.5, rounded half away from zero).
    pub const fn rgba8(self) -> [u8; 4] {
        match self {
            TextureDefault::White => [255, 255, 255, 255],
            TextureDefault::Black => [0, 0, 0, 255],
            TextureDefault::Gray => [128, 128, 128, 255],
            TextureDefault::Normal => [128, 128, 255, 255],
        }
    }
    /// What sampling the built-in texture returns: its RGBA8 bytes decoded,
    /// through the sRGB curve (RGB only) when the texture is sRGB. Scene
    /// builds fold a texture left at its default to this constant.
    pub fn sampled(self, srgb: bool) -> [f32; 4] {
        let b = self.rgba8();
        std::array::from_fn(|i| {
            let unorm = f64::from(b[i]) / 255.0;
            if srgb && i < 3 {
                bake::srgb_to_linear(unorm) as f32
            } else {
                unorm as f32
            }
        })
    }
    /// The texel value as stored (before any sRGB decode): the
    /// [`TextureDefault::rgba8`] bytes / 255 (`gray` is 128/255, not 0.5).
    pub fn texel(self) -> [f32; 4] {
        self.rgba8().map(|b| f32::from(b) / 255.0)
    }
}

/// Details of a `texture2d` or `cube` parameter.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct TextureInfo {
    /// The built-in texture bound while the parameter is unset, unless an
    /// entry of `default_when` holds for the variant.
    pub default: TextureDefault,
    /// Keyword-dependent defaults, tried in order; each variant's binding
    /// states the resolved one (`bindings[].texture.default`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub default_when: Vec<ConditionalTextureDefault>,
    /// Colour data: bind an `*Srgb` format so sampling returns linear values.
    pub srgb: bool,
    /// `texture2d` parameters that ship an image (`file` in the material's
    /// TOML): the texels weft wrote beside the variants. An engine binds this
    /// file while the parameter is unset; `default` is what it binds where it
    /// cannot load the file. Absent for parameters without one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<ResourceFile>,
    /// Uniform member (vec4: xy tiling, zw offset) when the texture has tiling/offset.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tiling_member: Option<String>,
    /// Default of `tiling_member`, [tiling x, tiling y, offset x, offset y] = [1, 1, 0, 0];
    /// present exactly when `tiling_member` is.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tiling_default: Option<[f64; 4]>,
}

/// `default` replaces the texture default in variants where `condition` holds.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct ConditionalTextureDefault {
    /// On a static keyword or `tier`.
    pub condition: Condition,
    /// The built-in texture bound in variants where `condition` holds.
    pub default: TextureDefault,
}

/// A curve keyframe: cubic Hermite between keys, slopes per unit time.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Keyframe {
    /// Position on the curve's axis; strictly increasing along `keyframes`.
    pub time: f64,
    /// Curve value at `time` (inside the parameter's `range`, when it has one).
    pub value: f64,
    /// Slope (value per unit time) entering the key, from the previous key.
    pub in_slope: f64,
    /// Slope (value per unit time) leaving the key, towards the next key.
    pub out_slope: f64,
}

/// How a `curve` parameter is edited and baked into the material uniform.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct CurveInfo {
    /// The default curve's keys, times strictly increasing; the curve is constant before the
    /// first and after the last (`weft_meta::bake::eval_curve` evaluates it).
    pub keyframes: Vec<Keyframe>,
    /// Number of samples the toolchain bakes into the uniform array.
    pub samples: u32,
    /// The default curve sampled at `time_min + i (time_max - time_min)/(samples-1)`.
    pub baked_default: Vec<f64>,
    /// [time_min, time_max]: the span the shader maps its argument onto.
    /// Fixed at build time: a re-baked curve must be sampled over this span.
    pub time_range: [f64; 2],
    /// How the samples are laid out in the uniform member.
    pub encoding: CurveEncoding,
}

/// The uniform encoding of a curve: `samples` f32 values packed four per
/// `vec4<f32>` (sample i in element i / 4, component i % 4), the last
/// element's unused components zero. The shader interpolates linearly
/// between neighbouring samples and clamps outside `time_range`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum CurveEncoding {
    /// Named and versioned: a different packing gets a new name.
    F32x4PackedV1,
}

/// One stop of a gradient.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct GradientStop {
    /// Where the stop sits, in [0, 1]; positions never decrease along `stops`.
    pub position: f64,
    /// sRGB-encoded colour as edited.
    pub color: [f64; 4],
}

/// How a `gradient` parameter is edited and baked into its ramp texture.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct GradientInfo {
    /// The default gradient's stops, positions non-decreasing; the colour is constant before
    /// the first and after the last.
    pub stops: Vec<GradientStop>,
    /// Width in texels of the 1-D ramp (a `width` x 1 Rgba8UnormSrgb texture).
    pub width: u32,
    /// How the ramp's texels are made from the stops.
    pub encoding: GradientEncoding,
    /// The default ramp, sRGB8 RGBA texels, `width` * 4 bytes as numbers.
    pub baked_default: Vec<u8>,
}

/// The texel encoding of a gradient ramp.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum GradientEncoding {
    /// Texel i holds the gradient at x = (i + 0.5) / width (texel centres):
    /// the stops' colours decoded from sRGB to linear, interpolated linearly
    /// between neighbouring stops (alpha linearly too; constant outside the
    /// first and last stop), then sRGB-encoded and rounded to 8 bits. Bound
    /// as `rgba8unorm_srgb`, width × 1, and sampled with the clamp sampler.
    /// `weft_meta::bake::bake_gradient` is the reference implementation.
    Rgba8SrgbRampV1,
}
