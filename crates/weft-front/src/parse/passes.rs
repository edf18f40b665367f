//! `[[pass]]` tables -> [`Pass`] (entry points, blend, cull, depth, queue,
//! instance count), and the single default pass of a material without any.

use super::{CONDITION_FORMS, bad_condition_with};
use crate::diag::Span;
use crate::model::*;
use crate::toml_reader::{Cx, Table, Value, type_error};
use toml::de::DeValue;
use weft_meta::{BlendMode, CullMode, DepthTest};

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
        instances: Instances::Fixed(1),
        when: Vec::new(),
        when_span: None,
        vertex_span: span.clone(),
        fragment_span: span.clone(),
        decl: Loc { file, span },
    }
}

fn pick<T: Copy>(t: &Table, key: &str, options: &[(&str, T)], cx: &mut Cx) -> Option<T> {
    let s = t.string(key, cx)?;
    match options.iter().find(|(n, _)| *n == s) {
        Some((_, v)) => Some(*v),
        None => {
            let names: Vec<&str> = options.iter().map(|(n, _)| *n).collect();
            let hint = crate::diag::did_you_mean(&s, names.iter().copied()).map_or_else(
                || format!("expected one of: {}", names.join(", ")),
                |x| format!("did you mean `{x}`?"),
            );
            cx.error_with_note(
                "unknown-value",
                format!("unknown `{key}` value `{s}` in {}", t.what),
                t.span_of(key),
                "unknown",
                hint,
            );
            None
        }
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
    use BlendMode as B;
    if let Some(b) = pick(
        &t,
        "blend",
        &[
            ("opaque", B::Opaque),
            ("alpha", B::Alpha),
            ("premultiplied", B::Premultiplied),
            ("additive", B::Additive),
            ("multiply", B::Multiply),
        ],
        cx,
    ) {
        pass.blend = b;
        if b != B::Opaque {
            pass.depth_write = false;
            pass.queue = 3000;
        }
    }
    if let Some(c) = pick(
        &t,
        "cull",
        &[
            ("none", CullMode::None),
            ("front", CullMode::Front),
            ("back", CullMode::Back),
        ],
        cx,
    ) {
        pass.cull = c;
    }
    use DepthTest as D;
    if let Some(d) = pick(
        &t,
        "depth_test",
        &[
            ("always", D::Always),
            ("never", D::Never),
            ("less", D::Less),
            ("less_equal", D::LessEqual),
            ("equal", D::Equal),
            ("greater", D::Greater),
            ("greater_equal", D::GreaterEqual),
        ],
        cx,
    ) {
        pass.depth_test = d;
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
