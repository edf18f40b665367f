//! Compile-time switches and named values: show-if conditions, keywords,
//! quality tiers and presets.

use crate::Text;
#[cfg(feature = "schema")]
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A show-if condition on a keyword or a bool parameter.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Condition {
    /// A keyword, `tier`, or a bool parameter.
    pub subject: String,
    /// The comparison of the subject's current value with `value`.
    pub op: ConditionOp,
    /// Keyword value, tier name, or "on"/"off" for toggles and bool parameters.
    pub value: String,
}

/// How a condition compares its subject's current value with `value`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum ConditionOp {
    /// Holds when the subject's value is `value`.
    Equal,
    /// Holds when the subject's value is not `value`.
    NotEqual,
}

/// The values a keyword has.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum KeywordKind {
    /// Unity's Toggle: values "off", "on".
    Toggle,
    /// Unity's KeywordEnum.
    Enum,
}

value_names!(KeywordKind {
    Toggle => "toggle",
    Enum => "enum",
});

/// How a keyword's values become compiled code.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum KeywordMode {
    /// One compiled variant per value.
    Static,
    /// Kept as a WGSL `override` (a pipeline constant) in the WGSL output; the
    /// other languages, which naga cannot give specialisation constants, get
    /// one file per value.
    Constant,
}

value_names!(KeywordMode {
    Static => "static",
    Constant => "constant",
});

/// A keyword: a compile-time switch shown in the inspector.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Keyword {
    /// The WGSL `override` name (UPPER_SNAKE).
    pub name: String,
    /// Toggle (values `off`, `on`) or enum (values as listed).
    pub kind: KeywordKind,
    /// `static`: a variant per value; `constant`: one variant, the value set as a pipeline
    /// constant (WGSL) or by choosing a file (other languages).
    pub mode: KeywordMode,
    /// Values in order; the WGSL constant `<NAME>_<VALUE>` equals the index.
    pub values: Vec<String>,
    /// The value (one of `values`) the inspector starts from.
    pub default: String,
    /// Display name.
    pub label: Text,
    /// Hover help; absent when none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tooltip: Option<Text>,
    /// The `groups[].name` of the section the keyword is shown in.
    pub group: String,
    /// Show the keyword only while this condition holds; absent: always shown.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub show_if: Option<Condition>,
}

/// The material's quality tiers: the same material at different cost, each tier its own
/// variant.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Tiers {
    /// Tier names; the WGSL constant `TIER_<NAME>` equals the index.
    pub values: Vec<String>,
    /// The tier (one of `values`) the inspector starts from.
    pub default: String,
    /// The most accurate tier every other tier is measured against.
    pub reference: String,
    /// Per tier: what it changes, for people choosing one.
    pub descriptions: BTreeMap<String, Text>,
    /// Per tier that approximates another: the tier it approximates (its
    /// error is measured against that one; `reference` unless the material
    /// says otherwise). The reference and the looks are not listed.
    #[serde(default)]
    pub approximates: BTreeMap<String, String>,
    /// Tiers that are a different model, not an approximation (e.g. `seed`:
    /// a source document's formula kept for its look). Their difference from
    /// the reference is reported apart, never as an error, and automatic
    /// tier choice never picks them.
    #[serde(default)]
    pub looks: Vec<String>,
    /// The material declares itself stylised (no physical ground truth,
    /// `[material] stylised = true`). With a single tier, that tier is
    /// `reference` here and nothing is measured against it.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub stylised: bool,
}

/// A named set of values for the inspector.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Preset {
    /// Preset id (lower_snake_case), as scene manifests name it.
    pub name: String,
    /// Display name.
    pub label: Text,
    /// Values by name: parameters (as in `Parameter::default`), keywords (a
    /// value name) and `tier` (a tier name).
    pub values: BTreeMap<String, serde_json::Value>,
}
