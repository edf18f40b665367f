//! Conditions used by `show_if`, `default_when` and `[variants].exclude`:
//! `NAME`, `!NAME`, `NAME == value`, `NAME != value`, joined with `&&`.
//! `NAME` is a keyword, `tier`, or a bool parameter; bare `NAME` means `NAME == on`.
//! Which names each use may take is checked in `check.rs`.

use weft_meta::{Condition, ConditionOp};

pub fn parse_condition_text(text: &str) -> Result<Vec<Condition>, String> {
    let mut out = Vec::new();
    for atom in text.split("&&") {
        let atom = atom.trim();
        if atom.is_empty() {
            return Err(format!("empty condition in `{text}`"));
        }
        let (subject, op, value) = if let Some((l, r)) = atom.split_once("==") {
            (l.trim(), ConditionOp::Equal, r.trim())
        } else if let Some((l, r)) = atom.split_once("!=") {
            (l.trim(), ConditionOp::NotEqual, r.trim())
        } else if let Some(rest) = atom.strip_prefix('!') {
            (rest.trim(), ConditionOp::NotEqual, "on")
        } else {
            (atom, ConditionOp::Equal, "on")
        };
        let value = match value {
            "true" => "on",
            "false" => "off",
            v => v,
        };
        let ident = |s: &str| {
            !s.is_empty()
                && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
                && !s.starts_with(|c: char| c.is_ascii_digit())
        };
        if !ident(subject) {
            return Err(format!("`{subject}` is not a name"));
        }
        if !ident(value) {
            return Err(format!("`{value}` is not a value name"));
        }
        out.push(Condition {
            subject: subject.to_string(),
            op,
            value: value.to_string(),
        });
    }
    Ok(out)
}

/// Whether `c` holds where its subject has the value `value` (`None`: the
/// subject has no value there, and no condition on it holds).
pub fn holds(c: &Condition, value: Option<&str>) -> bool {
    value.is_some_and(|v| (v == c.value) == (c.op == ConditionOp::Equal))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_forms() {
        let c = parse_condition_text("NORMAL_MAP && SPHERE_MAP != off && tier == fast && !USE")
            .unwrap();
        assert_eq!(c.len(), 4);
        assert_eq!(c[0].value, "on");
        assert_eq!(c[1].op, ConditionOp::NotEqual);
        assert_eq!(c[3].subject, "USE");
        assert_eq!(c[3].op, ConditionOp::NotEqual);
        assert!(parse_condition_text("A && ").is_err());
        assert!(parse_condition_text("A == b c").is_err());
    }
}
