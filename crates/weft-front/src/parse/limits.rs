//! The `[limits]` table: WebGPU device limits a material raises above the
//! defaults (keys named after WebGPU's limits, values that may only raise
//! them). The compiler checks every variant against the limits in force.

use super::LIMITS_KEYS;
use crate::model::Material;
use crate::toml_reader::{Cx, Table};
use weft_meta::limits::limit_spec;

pub(super) fn parse_limits(top: &Table, material: &mut Material, cx: &mut Cx) {
    let Some(t) = top
        .get("limits")
        .and_then(|v| Table::new(v, "[limits]", cx))
    else {
        return;
    };
    t.check_keys(LIMITS_KEYS, cx);
    for key in LIMITS_KEYS {
        let Some(spec) = limit_spec(key) else {
            continue;
        };
        let Some(n) = t.integer(key, cx) else {
            continue;
        };
        let span = t.span_of(key);
        if n < 0 || (n as u64) < spec.default {
            cx.error_with_note(
                "out-of-range",
                format!(
                    "`{key}` may only raise WebGPU's default {} ({})",
                    spec.default, spec.webgpu
                ),
                span,
                format!("{n} is below the default"),
                "every WebGPU device supports the defaults; leave the key out to keep it",
            );
            continue;
        }
        if n as u64 > spec.max {
            cx.error_with_note(
                "type-range",
                format!("`{key}` does not fit in a u32"),
                span,
                format!("{n} is outside u32's range [0, 4294967295]"),
                format!("WebGPU's {} is a GPUSize32", spec.webgpu),
            );
            continue;
        }
        material.limits.declare(key, n as u64);
        material.limit_spans.push((spec.key, span));
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn keys_are_the_checked_limits() {
        let keys: Vec<&str> = weft_meta::limits::LIMITS.iter().map(|l| l.key).collect();
        assert_eq!(super::LIMITS_KEYS, keys.as_slice());
    }
}
