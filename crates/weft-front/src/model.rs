//! The checked material model: what the front end hands the compiler.
//!
//! Every value here has passed the checks in `check.rs`; spans are kept so the
//! compiler can still point back into the TOML (e.g. for a prelude error).

use crate::diag::{FileId, Span};
use std::path::PathBuf;
use weft_meta::{
    BlendMode, Condition, CullMode, DepthTest, GradientStop, Keyframe, KeywordKind, KeywordMode,
    ParamKind, TextureDefault,
};

/// Where something was declared: file and byte range.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Loc {
    pub file: FileId,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct Material {
    pub name: String,
    pub label: String,
    pub label_zh: Option<String>,
    pub description: Option<String>,
    pub description_zh: Option<String>,
    /// The TOML file.
    pub file: FileId,
    pub path: PathBuf,
    /// The materials root (`materials/`), against which includes resolve.
    pub root: PathBuf,
    /// WGSL files in composition order: includes (dependencies first), then the material source.
    pub sources: Vec<SourceFile>,
    pub requires: Vec<VertexAttribute>,
    /// Where `requires` is written (or [material] when absent).
    pub requires_span: Span,
    pub groups: Vec<Group>,
    pub params: Vec<Param>,
    pub keywords: Vec<Keyword>,
    pub tiers: Tiers,
    pub max_variants: usize,
    /// Span of `max_variants` when set (budget errors point there).
    pub max_variants_span: Option<Span>,
    /// Excluded combinations: a variant matching every condition of one entry is dropped.
    pub exclude: Vec<Vec<Condition>>,
    /// Where each entry of `exclude` is written (the filter string), in `file`.
    pub exclude_spans: Vec<Span>,
    pub presets: Vec<Preset>,
    pub passes: Vec<Pass>,
    pub decl: Loc,
}

#[derive(Clone, Debug)]
pub struct SourceFile {
    pub file: FileId,
    /// Path relative to the materials root, with `/` separators.
    pub rel_path: String,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum VertexAttribute {
    Position,
    Normal,
    Tangent,
    Uv0,
    Uv1,
    Color,
}

impl VertexAttribute {
    pub const ALL: [VertexAttribute; 6] = [
        VertexAttribute::Position,
        VertexAttribute::Normal,
        VertexAttribute::Tangent,
        VertexAttribute::Uv0,
        VertexAttribute::Uv1,
        VertexAttribute::Color,
    ];
    pub fn name(self) -> &'static str {
        match self {
            VertexAttribute::Position => "position",
            VertexAttribute::Normal => "normal",
            VertexAttribute::Tangent => "tangent",
            VertexAttribute::Uv0 => "uv0",
            VertexAttribute::Uv1 => "uv1",
            VertexAttribute::Color => "color",
        }
    }
    /// The engine interface's fixed shader location.
    pub fn location(self) -> u32 {
        self as u32
    }
    /// WebGPU vertex format.
    pub fn format(self) -> &'static str {
        match self {
            VertexAttribute::Position | VertexAttribute::Normal => "float32x3",
            VertexAttribute::Tangent | VertexAttribute::Color => "float32x4",
            VertexAttribute::Uv0 | VertexAttribute::Uv1 => "float32x2",
        }
    }
}

#[derive(Clone, Debug)]
pub struct Group {
    pub name: String,
    pub label: String,
    pub label_zh: Option<String>,
}

#[derive(Clone, Debug)]
pub struct Param {
    pub name: String,
    pub kind: ParamKind,
    pub label: String,
    pub label_zh: Option<String>,
    pub tooltip: Option<String>,
    pub tooltip_zh: Option<String>,
    pub group: String,
    pub order: i64,
    pub default: ParamValue,
    pub range: Option<[f64; 2]>,
    pub soft_range: Option<[f64; 2]>,
    pub step: Option<f64>,
    pub power: Option<f64>,
    pub show_if: Option<Condition>,
    /// Colours: HDR (edited linear, may exceed 1).
    pub hdr: bool,
    /// Textures.
    pub srgb: bool,
    pub tiling: bool,
    /// Curves: samples baked into the uniform; gradients: ramp width.
    pub samples: u32,
    pub decl: Loc,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ParamValue {
    Float(f64),
    Int(i64),
    Bool(bool),
    Vector(Vec<f64>),
    Texture(TextureDefault),
    Curve(Vec<Keyframe>),
    Gradient(Vec<GradientStop>),
}

#[derive(Clone, Debug)]
pub struct Keyword {
    pub name: String,
    pub kind: KeywordKind,
    pub mode: KeywordMode,
    pub values: Vec<String>,
    pub default: usize,
    pub label: String,
    pub label_zh: Option<String>,
    pub tooltip: Option<String>,
    pub tooltip_zh: Option<String>,
    pub group: String,
    pub show_if: Option<Condition>,
    pub decl: Loc,
}

#[derive(Clone, Debug)]
pub struct Tiers {
    pub values: Vec<String>,
    pub default: usize,
    pub reference: usize,
    /// (tier, English, Chinese) descriptions.
    pub descriptions: Vec<(String, String, Option<String>)>,
}

#[derive(Clone, Debug)]
pub struct Preset {
    pub name: String,
    pub label: String,
    pub label_zh: Option<String>,
    pub values: Vec<(String, PresetValue)>,
    pub decl: Loc,
}

#[derive(Clone, Debug, PartialEq)]
pub enum PresetValue {
    Param(ParamValue),
    Keyword(String),
}

#[derive(Clone, Debug)]
pub struct Pass {
    pub name: String,
    pub vertex: String,
    pub fragment: String,
    pub blend: BlendMode,
    pub cull: CullMode,
    pub depth_write: bool,
    pub depth_test: DepthTest,
    pub queue: i64,
    pub instances: Instances,
    pub decl: Loc,
    /// Where `vertex` / `fragment` are written (the pass itself when absent).
    pub vertex_span: Span,
    pub fragment_span: Span,
}

#[derive(Clone, Debug)]
pub enum Instances {
    Fixed(u32),
    Param(String),
}

impl Material {
    pub fn param(&self, name: &str) -> Option<&Param> {
        self.params.iter().find(|p| p.name == name)
    }
    pub fn keyword(&self, name: &str) -> Option<&Keyword> {
        self.keywords.iter().find(|k| k.name == name)
    }
    /// Keywords that multiply the static variant count.
    pub fn static_keywords(&self) -> impl Iterator<Item = &Keyword> {
        self.keywords
            .iter()
            .filter(|k| k.mode == KeywordMode::Static)
    }
}
