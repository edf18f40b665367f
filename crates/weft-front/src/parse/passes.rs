//! `[[pass]]` tables -> [`Pass`] (entry points, blend, cull, depth, stencil,
//! queue, instance count), and the single default pass of a material without
//! any.

use super::{CONDITION_FORMS, STENCIL_KEYS, bad_condition_with};
use crate::diag::Span;
use crate::model::*;
use crate::toml_reader::{Cx, Table, Value, type_error};
use toml::de::DeValue;
use weft_meta::{BlendMode, CullMode, DepthTest, StencilOperation, StencilRenderState};

pub(super) fn default_pass(file: usize, span: Span) -> Pass {
    Pass {
        name: "forward".into(),
        vertex: "vs_main".into(),
        fragment: "fs_main".into(),
        blend: BlendMode::Opaque,
        cull: CullMode::Back,
        depth_write: true,
        depth_test: DepthTest::LessEqual,
        queue: 2000,
        stencil: None,
        instances: Instances::Fixed(1),
        when: Vec::new(),
        when_span: None,
        vertex_span: span.clone(),
        fragment_span: span.clone(),
        decl: Loc { file, span },
    }
}

/// A `[[pass]]` table (or a shared pass file's `[pass]`: `keys` differ).
pub(super) fn parse_pass(v: &Value, keys: &[&str], what: &str, cx: &mut Cx) -> Option<Pass> {
    let t = Table::new(v, what, cx)?;
    t.check_keys(keys, cx);
    let mut pass = default_pass(cx.file, v.span());
    pass.name = t.string("name", cx).unwrap_or(pass.name);
    pass.vertex = t.string("vertex", cx).unwrap_or(pass.vertex);
    pass.fragment = t.string("fragment", cx).unwrap_or(pass.fragment);
    pass.vertex_span = t.span_of("vertex");
    pass.fragment_span = t.span_of("fragment");
    if let Some(b) = t.one_of("blend", &BlendMode::ALL, BlendMode::name, cx) {
        pass.blend = b;
        if b != BlendMode::Opaque {
            pass.depth_write = false;
            pass.queue = 3000;
        }
    }
    if let Some(c) = t.one_of("cull", &CullMode::ALL, CullMode::name, cx) {
        pass.cull = c;
    }
    if let Some(d) = t.one_of("depth_test", &DepthTest::ALL, DepthTest::name, cx) {
        pass.depth_test = d;
    }
    if let Some(s) = t.get("stencil") {
        pass.stencil = parse_stencil(s, cx);
    }
    pass.depth_write = t.boolean("depth_write", cx).unwrap_or(pass.depth_write);
    pass.queue = t.integer("queue", cx).unwrap_or(pass.queue);
    if let Some(w) = t.get("when") {
        pass.when_span = Some(w.span());
        if let Some(text) = crate::toml_reader::expect_string(w, "`when`", cx) {
            match crate::condition::parse_condition_text(&text) {
                Ok(conds) => pass.when = conds,
                Err(msg) => bad_condition_with(cx, &msg, w.span(), CONDITION_FORMS),
            }
        }
    }
    if let Some(iv) = t.get("instances") {
        match iv.get_ref() {
            DeValue::Integer(_) => {
                let n = crate::toml_reader::expect_integer(iv, "`instances`", cx)?;
                if !(1..=4096).contains(&n) {
                    cx.error(
                        "out-of-range",
                        "`instances` must be between 1 and 4096",
                        iv.span(),
                        "here",
                    );
                }
                pass.instances = Instances::Fixed(n.clamp(1, 4096) as u32);
            }
            DeValue::String(s) => pass.instances = Instances::Param(s.to_string()),
            other => type_error(
                cx,
                "`instances`",
                "a count or an int parameter's name",
                other,
                iv.span(),
            ),
        }
    }
    Some(pass)
}

/// A pass's `stencil` table. Omitted keys: reference 0, compare `always`,
/// every operation `keep`, both masks 255 (an 8-bit stencil), so a table
/// that only sets what it needs reads as written.
fn parse_stencil(v: &Value, cx: &mut Cx) -> Option<StencilRenderState> {
    let t = Table::new(v, "the pass's `stencil`", cx)?;
    t.check_keys(STENCIL_KEYS, cx);
    let byte = |key: &str, default: u32, cx: &mut Cx| match t.integer(key, cx) {
        Some(n) if (0..=255).contains(&n) => n as u32,
        Some(_) => {
            cx.error_with_note(
                "out-of-range",
                format!("`stencil.{key}` must be between 0 and 255"),
                t.span_of(key),
                "here",
                "the stencil buffer holds 8 bits per pixel (depth24plus_stencil8)",
            );
            default
        }
        None => default,
    };
    let op = |key: &str, cx: &mut Cx| {
        t.one_of(key, &StencilOperation::ALL, StencilOperation::name, cx)
            .unwrap_or(StencilOperation::Keep)
    };
    Some(StencilRenderState {
        reference: byte("reference", 0, cx),
        compare: t
            .one_of("compare", &DepthTest::ALL, DepthTest::name, cx)
            .unwrap_or(DepthTest::Always),
        pass_op: op("pass_op", cx),
        fail_op: op("fail_op", cx),
        depth_fail_op: op("depth_fail_op", cx),
        read_mask: byte("read_mask", 255, cx),
        write_mask: byte("write_mask", 255, cx),
    })
}
