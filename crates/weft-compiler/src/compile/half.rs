//! Half precision: a material's code may compute in `weft_half` (f16).
//!
//! Every material is composed with `enable f16; alias weft_half = f16;`
//! (compose::compose). A variant whose specialised module still holds an f16
//! type needs the device feature `shader-f16` for its WGSL, SPIR-V and MSL.
//! Two languages cannot carry it — naga's GLSL writer has no 16-bit float,
//! and HLSL SM 5.1 has none (`half` is 32-bit there) — so those files, and a
//! WGSL/SPIR-V fallback for devices without the feature, are written from a
//! second composition with `alias weft_half = f32;`: the same code, in f32.
//! Materials that never name `weft_half` or `f16` get no second parse.

use crate::compile::compose::{self, HalfAs};
use crate::compile::prelude::Prelude;
use crate::compile::source_map::Composed;
use naga::{Module, Scalar, TypeInner};
use weft_front::model::Material;
use weft_front::{Diagnostics, SourceDb};

/// The WebGPU feature name a half-precision variant needs.
pub const SHADER_F16: &str = "shader-f16";

/// True when the module keeps any f16 value (after specialisation and
/// compaction only live code's types remain). Besides the type arena, the
/// functions' expressions are scanned: an f16 scalar or vector made by a
/// conversion (`weft_half(x)`, `vec3<weft_half>(v)` of an f32 value) or an
/// f16 literal needs no type handle, so code whose only f16 values are such
/// has no f16 type in the arena.
pub fn uses_f16(module: &Module) -> bool {
    let f16_type = module.types.iter().any(|(_, ty)| match ty.inner {
        TypeInner::Scalar(s) | TypeInner::Vector { scalar: s, .. } => s == Scalar::F16,
        TypeInner::Matrix { scalar, .. } => scalar == Scalar::F16,
        _ => false,
    });
    f16_type
        || module
            .functions
            .iter()
            .map(|(_, f)| f)
            .chain(module.entry_points.iter().map(|e| &e.function))
            .any(|f| f.expressions.iter().any(|(_, e)| is_f16_expression(e)))
}

/// Adds the f16 scalar type to the arena of a module that computes in f16
/// but has none there (its f16 values all come from conversions or
/// literals: `uses_f16`). naga's writers decide from the arena alone whether
/// a module needs `enable f16;` (WGSL) and the `SPV_KHR_16bit_storage`
/// extension that declares the 16-bit capabilities (SPIR-V); without the
/// type, such a module's WGSL does not parse and its SPIR-V fails
/// `spirv-val --target-env vulkan1.0`. Call after compaction (which would
/// drop the unused type again), before validation.
pub fn declare_f16(module: &mut Module) {
    let in_arena = module
        .types
        .iter()
        .any(|(_, ty)| matches!(ty.inner, TypeInner::Scalar(Scalar::F16)));
    if !in_arena && uses_f16(module) {
        module.types.insert(
            naga::Type {
                name: None,
                inner: TypeInner::Scalar(Scalar::F16),
            },
            naga::Span::UNDEFINED,
        );
    }
}

fn is_f16_expression(e: &naga::Expression) -> bool {
    matches!(
        *e,
        naga::Expression::As {
            kind: naga::ScalarKind::Float,
            convert: Some(2),
            ..
        } | naga::Expression::Literal(naga::Literal::F16(_))
    )
}

/// True when the material's own sources (not the prelude) name `weft_half`
/// or `f16`: only then can a variant hold half-precision values.
pub fn mentions_half(m: &Material, db: &SourceDb) -> bool {
    m.sources
        .iter()
        .any(|src| has_identifier(db.text(src.file), &["weft_half", "f16"]))
}

fn has_identifier(text: &str, names: &[&str]) -> bool {
    let is_ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    names.iter().any(|name| {
        text.match_indices(name).any(|(at, _)| {
            let before = text[..at].chars().next_back();
            let after = text[at + name.len()..].chars().next();
            !before.is_some_and(is_ident) && !after.is_some_and(is_ident)
        })
    })
}

/// The f32 fallback module of a material whose sources name half precision:
/// composed with `weft_half = f32`, parsed and validated. Its errors point
/// into the user's files with a hint (the usual cause: code that spells
/// `f16` or an `h` literal where `weft_half` keeps it portable).
pub fn fallback_module(
    m: &Material,
    prelude: &Prelude,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<Option<(Composed, Module)>> {
    if !mentions_half(m, db) {
        return Some(None);
    }
    let composed = compose::compose_with(m, prelude, db, HalfAs::F32);
    let mark = diags.len();
    match compose::parse_and_validate(&composed, m, diags) {
        Some((module, _)) => Some(Some((composed, module))),
        None => {
            for d in diags.since_mut(mark) {
                d.message = format!("in the f32 fallback of half-precision code: {}", d.message);
                // naga's advice to add `enable f16;` is wrong here: weft adds it.
                d.notes.retain(|n| !n.contains("enable f16"));
                d.notes.push(
                    "HLSL (SM 5.1) and GLSL have no 16-bit float, so weft also compiles the material with `weft_half` = f32 for them and for devices without `shader-f16`".into(),
                );
                d.notes.push(
                    "write half-precision code with the type `weft_half` (e.g. `vec3<weft_half>`, `weft_half(0.5)`), not `f16` or `h` literals, so it compiles both ways".into(),
                );
            }
            None
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{has_identifier, uses_f16};

    fn parse(src: &str) -> naga::Module {
        naga::front::wgsl::parse_str(src).expect("test WGSL parses")
    }

    #[test]
    fn f16_values_made_by_conversions_alone_count() {
        // No f16 type in the arena: the only f16 values are conversions.
        let half = parse(
            "enable f16;\n@fragment fn main(@location(0) x: f32) -> @location(0) vec4<f32> {\n\
             let h = f16(x) * f16(x);\n    return vec4<f32>(f32(h));\n}\n",
        );
        assert!(uses_f16(&half));
        let single = parse(
            "@fragment fn main(@location(0) x: f32) -> @location(0) vec4<f32> {\n\
             let h = x * x;\n    return vec4<f32>(h);\n}\n",
        );
        assert!(!uses_f16(&single));
    }

    #[test]
    fn declared_f16_reaches_the_writers() {
        let mut half = parse(
            "enable f16;\n@fragment fn main(@location(0) x: f32) -> @location(0) vec4<f32> {\n\
             let h = f16(x) * f16(x);\n    return vec4<f32>(f32(h));\n}\n",
        );
        super::declare_f16(&mut half);
        let info = naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::all(),
        )
        .validate(&half)
        .expect("valid");
        let text =
            naga::back::wgsl::write_string(&half, &info, naga::back::wgsl::WriterFlags::empty())
                .expect("WGSL");
        assert!(text.starts_with("enable f16;"), "{text}");
    }

    #[test]
    fn identifiers_are_whole_words() {
        assert!(has_identifier("let x: weft_half = 1.0;", &["weft_half"]));
        assert!(has_identifier("vec3<f16>(x)", &["f16"]));
        assert!(!has_identifier("let f16x = 1; let af16 = 2;", &["f16"]));
        assert!(!has_identifier("weft_half_max", &["weft_half"]));
    }
}
