//! The static variant space: every tier crossed with every value of every
//! `static` keyword, minus the combinations `[variants].exclude` removes.

pub use crate::model::VariantKey;

use crate::model::Material;
use weft_meta::KeywordMode;

/// The most points of the static variant space (tiers × static keyword
/// values, before `exclude`) weft enumerates; a larger space is an error
/// found by counting, without enumerating (`check.rs`).
pub const ENUMERATION_LIMIT: u128 = 1 << 16;

/// The most combinations of `constant` keyword values per variant: each is
/// emitted as SPIR-V, HLSL, MSL and GLSL files of its own.
pub const CONSTANT_COMBINATION_LIMIT: u128 = 256;

/// The size of the static variant space (tiers × values of each static
/// keyword), counted without enumerating; `None` if it overflows a u128.
pub fn space_size(m: &Material) -> Option<u128> {
    m.static_keywords()
        .try_fold(m.tiers.values.len() as u128, |n, k| {
            n.checked_mul(k.values.len() as u128)
        })
}

/// How many combinations of `constant` keyword values there are; `None` on overflow.
pub fn constant_combination_count(m: &Material) -> Option<u128> {
    m.keywords
        .iter()
        .filter(|k| k.mode == KeywordMode::Constant)
        .try_fold(1u128, |n, k| n.checked_mul(k.values.len() as u128))
}

/// Every variant before exclusion, tier outermost, then keywords in
/// declaration order. Empty for a space larger than [`ENUMERATION_LIMIT`]
/// (which the checks report), so nothing ever enumerates one.
pub fn all_variants(m: &Material) -> Vec<VariantKey> {
    if space_size(m).is_none_or(|n| n > ENUMERATION_LIMIT) {
        return Vec::new();
    }
    let statics: Vec<usize> = (0..m.keywords.len())
        .filter(|&k| m.keywords[k].mode == KeywordMode::Static)
        .collect();
    let mut out = Vec::new();
    for tier in 0..m.tiers.values.len() {
        let mut combos: Vec<Vec<(usize, usize)>> = vec![Vec::new()];
        for &k in &statics {
            let mut next = Vec::new();
            for c in &combos {
                for v in 0..m.keywords[k].values.len() {
                    let mut c2 = c.clone();
                    c2.push((k, v));
                    next.push(c2);
                }
            }
            combos = next;
        }
        out.extend(
            combos
                .into_iter()
                .map(|keywords| VariantKey { tier, keywords }),
        );
    }
    out
}

/// The variants the material compiles: all minus excluded.
pub fn variants(m: &Material) -> Vec<VariantKey> {
    all_variants(m)
        .into_iter()
        .filter(|v| !m.exclude.iter().any(|e| v.matches(m, e)))
        .collect()
}

/// The variant the inspector starts from: default tier and keyword values.
pub fn default_variant(m: &Material) -> VariantKey {
    VariantKey {
        tier: m.tiers.default,
        keywords: (0..m.keywords.len())
            .filter(|&k| m.keywords[k].mode == KeywordMode::Static)
            .map(|k| (k, m.keywords[k].default))
            .collect(),
    }
}
