//! `[tables.<name>]`: lookup tables the toolchain bakes at build time, as it
//! bakes the split-sum LUT, from parameters written here (the bake itself is
//! weft-compiler's `bake/`). Each becomes a group-1 texture of the material
//! and a file beside its variants (docs/material-format.md, `[tables]`).

use super::{TABLE_KEYS, is_snake_ident};
use crate::diag::Span;
use crate::model::*;
use crate::toml_reader::{Cx, Table, Value};

/// Recipes: the name, what it is for (the hint of an unknown recipe) and
/// its own keys besides `recipe` and `size` (`TABLE_KEYS` lists them all).
pub const RECIPES: &[(&str, &str, &[&str])] = &[
    (
        "preintegrated_skin",
        "Penner & Borshukov's pre-integrated skin diffuse over the Burley profile",
        &["shape", "ring"],
    ),
    (
        "thin_film_sensitivity",
        "the spectral sensitivity of thin-film interference over the optical path difference",
        &["opd_max"],
    ),
];

/// `ring` values of `preintegrated_skin` and whether each is the half ring.
pub const RINGS: &[(&str, bool)] = &[("full", false), ("half", true)];

/// Texels per axis a table may have (a one-dimensional function such as
/// the film's oscillating sensitivity needs thousands along u; WebGPU
/// guarantees 8192).
pub const TABLE_SIZE_RANGE: [u32; 2] = [2, 4096];

/// The longest optical path difference (nm) a `thin_film_sensitivity`
/// table may cover: the sensitivity has decayed to nothing long before.
pub const MAX_OPD_NM: f64 = 100_000.0;

/// The most texels a material's tables may have in all (256²): baking
/// integrates thousands of points per texel, and this keeps a build with
/// the largest tables to seconds (the shipped skin table is 64²).
pub const MAX_TABLE_TEXELS: u64 = 256 * 256;

pub(super) fn parse_tables(top: &Table, material: &mut Material, cx: &mut Cx) {
    let Some(tables) = top
        .get("tables")
        .and_then(|v| Table::new(v, "[tables]", cx))
    else {
        return;
    };
    for (name, span, v) in tables.entries() {
        if let Some(table) = parse_table(name, span, v, &material.tables, cx) {
            material.tables.push(table);
        }
    }
}

/// One `[tables.<name>]` entry, checked against the texel budget of the
/// material's tables so far (`earlier`).
fn parse_table(
    name: &str,
    span: Span,
    v: &Value,
    earlier: &[BakedTable],
    cx: &mut Cx,
) -> Option<BakedTable> {
    let t = Table::new(v, format!("table `{name}`"), cx)?;
    if !is_snake_ident(name) {
        cx.error_with_note(
            "bad-name",
            format!("table name `{name}` is not a lower-case identifier"),
            span.clone(),
            "used as a WGSL name and a file name",
            "use lower_snake_case letters, digits and underscores",
        );
        return None;
    }
    let recipe_name = t.string("recipe", cx);
    check_table_keys(&t, recipe_name.as_deref(), cx);
    let size = table_size(&t, name, &span, cx)?;
    let recipe = table_recipe(&t, recipe_name.as_deref(), name, &span, cx)?;
    let texels: u64 = earlier
        .iter()
        .chain(std::iter::once(&BakedTable {
            name: String::new(),
            recipe: recipe.clone(),
            size,
            decl: Loc {
                file: cx.file,
                span: span.clone(),
            },
        }))
        .map(|t| u64::from(t.size[0]) * u64::from(t.size[1]))
        .sum();
    if texels > MAX_TABLE_TEXELS {
        cx.error_with_note(
            "too-large",
            format!(
                "the material's tables would have {texels} texels in all; at most {MAX_TABLE_TEXELS} (256²) are baked"
            ),
            t.span_of("size"),
            "this table passes the budget",
            "each texel integrates thousands of points at build time: use smaller tables (filtering interpolates between texels)",
        );
        return None;
    }
    Some(BakedTable {
        name: name.to_string(),
        recipe,
        size,
        decl: Loc {
            file: cx.file,
            span: span.clone(),
        },
    })
}

/// `size`: two whole numbers of texels, each in [`TABLE_SIZE_RANGE`].
fn table_size(t: &Table, name: &str, span: &Span, cx: &mut Cx) -> Option<[u32; 2]> {
    Some(match t.numbers("size", cx) {
        Some(s) if s.len() == 2 && s.iter().all(|n| n.fract() == 0.0) => {
            let ok = |n: f64| {
                (f64::from(TABLE_SIZE_RANGE[0])..=f64::from(TABLE_SIZE_RANGE[1])).contains(&n)
            };
            if !ok(s[0]) || !ok(s[1]) {
                cx.error(
                    "out-of-range",
                    format!(
                        "a table has {} to {} texels per axis",
                        TABLE_SIZE_RANGE[0], TABLE_SIZE_RANGE[1]
                    ),
                    t.span_of("size"),
                    "here",
                );
                return None;
            }
            [s[0] as u32, s[1] as u32]
        }
        Some(_) => {
            cx.error(
                "wrong-type",
                "`size` is two whole numbers: texels along u and v",
                t.span_of("size"),
                "here",
            );
            return None;
        }
        None => {
            cx.error_with_note(
                "missing-key",
                format!("table `{name}` has no `size`"),
                span.clone(),
                "in this table",
                "add `size = [64, 64]` (texels along u and v)",
            );
            return None;
        }
    })
}

/// Keys every table has.
const COMMON_KEYS: [&str; 2] = ["recipe", "size"];

/// The common keys and the recipe's own; a key of another recipe is
/// unknown here (every recipe's keys when the recipe is not known).
fn check_table_keys(t: &Table, recipe: Option<&str>, cx: &mut Cx) {
    let own = RECIPES
        .iter()
        .find(|(name, _, _)| Some(*name) == recipe)
        .map_or(&TABLE_KEYS[COMMON_KEYS.len()..], |(_, _, keys)| *keys);
    let allowed: Vec<&str> = COMMON_KEYS.iter().chain(own).copied().collect();
    t.check_keys(&allowed, cx);
}

/// The recipe named `recipe` with its own keys.
fn table_recipe(
    t: &Table,
    recipe: Option<&str>,
    name: &str,
    span: &Span,
    cx: &mut Cx,
) -> Option<TableRecipe> {
    Some(match recipe {
        Some("preintegrated_skin") => {
            let shape = skin_shape(t, cx)?;
            let ring = t.string("ring", cx);
            let half_ring = match ring.as_deref() {
                None => false,
                Some(name) if RINGS.iter().any(|(n, _)| *n == name) => {
                    RINGS.iter().any(|(n, half)| *n == name && *half)
                }
                Some(other) => {
                    cx.error_with_note(
                        "unknown-value",
                        format!("unknown `ring` value `{other}`"),
                        t.span_of("ring"),
                        "unknown",
                        "`full` (Penner & Borshukov: the whole ring) or `half` (the seed: ±π/2)",
                    );
                    return None;
                }
            };
            TableRecipe::PreintegratedSkin { shape, half_ring }
        }
        Some("thin_film_sensitivity") => TableRecipe::ThinFilmSensitivity {
            opd_max_nm: film_opd_max(t, cx)?,
        },
        Some(other) => {
            let names: Vec<&str> = RECIPES.iter().map(|(n, _, _)| *n).collect();
            let hint = crate::diag::did_you_mean(other, names.iter().copied()).map_or_else(
                || {
                    let list: Vec<String> = RECIPES
                        .iter()
                        .map(|(n, w, _)| format!("`{n}` ({w})"))
                        .collect();
                    format!("known recipes: {}", list.join(", "))
                },
                |s| format!("did you mean `{s}`?"),
            );
            cx.error_with_note(
                "unknown-value",
                format!("unknown table recipe `{other}`"),
                t.span_of("recipe"),
                "unknown",
                hint,
            );
            return None;
        }
        None => {
            cx.error_with_note(
                "missing-key",
                format!("table `{name}` has no `recipe`"),
                span.clone(),
                "in this table",
                "add `recipe = \"preintegrated_skin\"`",
            );
            return None;
        }
    })
}

/// The Burley shape s per channel: three positive numbers (1 / the
/// scattering distance, in the units of the curvature radius).
fn skin_shape(t: &Table, cx: &mut Cx) -> Option<[f64; 3]> {
    let Some(s) = t.numbers("shape", cx) else {
        cx.error_with_note(
            "missing-key",
            "a `preintegrated_skin` table needs `shape`",
            t.span.clone(),
            "in this table",
            "add `shape = [r, g, b]`: the Burley profile's s per channel (1 / scattering distance), e.g. [1.0, 2.5, 4.0]",
        );
        return None;
    };
    if s.len() != 3 || s.iter().any(|x| !(x.is_finite() && *x > 0.0 && *x <= 1e4)) {
        cx.error(
            "out-of-range",
            "`shape` is three numbers in (0, 10000]: s per RGB channel",
            t.span_of("shape"),
            "here",
        );
        return None;
    }
    Some([s[0], s[1], s[2]])
}

/// The film table's `opd_max`: the longest optical path difference (nm) it
/// covers, u = 1.
fn film_opd_max(t: &Table, cx: &mut Cx) -> Option<f64> {
    let Some(x) = t.number("opd_max", cx) else {
        cx.error_with_note(
            "missing-key",
            "a `thin_film_sensitivity` table needs `opd_max`",
            t.span.clone(),
            "in this table",
            "add `opd_max = 16000.0`: the longest optical path difference (nm) it covers, e.g. four Airy orders of a 1000 nm film of IOR 2",
        );
        return None;
    };
    if !(x.is_finite() && x > 0.0 && x <= MAX_OPD_NM) {
        cx.error(
            "out-of-range",
            format!("`opd_max` is a path difference in nm in (0, {MAX_OPD_NM}]"),
            t.span_of("opd_max"),
            "here",
        );
        return None;
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_keys_are_the_common_ones_then_every_recipes_own() {
        let mut all: Vec<&str> = COMMON_KEYS.to_vec();
        for (_, _, own) in RECIPES {
            all.extend(own.iter().copied());
        }
        assert_eq!(TABLE_KEYS, &all[..]);
    }
}
