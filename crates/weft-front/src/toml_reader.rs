//! Typed access to a spanned TOML tree that reports, rather than stops at, mistakes.
//!
//! The parser (`parse.rs`) reads every table through [`Table`]: unknown keys
//! get a "did you mean" hint, wrong types say what was expected, and reading
//! continues so that one run shows every error.

use crate::diag::{Diagnostics, FileId, Span, did_you_mean, with_note};
use toml::Spanned;
use toml::de::{DeTable, DeValue};

pub type Value<'i> = Spanned<DeValue<'i>>;

/// The file being read and the diagnostics being collected.
pub struct Cx<'d> {
    pub file: FileId,
    pub diags: &'d mut Diagnostics,
}

impl Cx<'_> {
    pub fn error(
        &mut self,
        code: &str,
        msg: impl Into<String>,
        span: Span,
        label: impl Into<String>,
    ) {
        self.diags.error(code, msg, self.file, span, label);
    }
    pub fn error_with_note(
        &mut self,
        code: &str,
        msg: impl Into<String>,
        span: Span,
        label: impl Into<String>,
        note: impl Into<String>,
    ) {
        let d = self.diags.error(code, msg, self.file, span, label);
        with_note(d, note);
    }
}

/// A TOML table plus a description of what it is ("parameter `roughness`").
pub struct Table<'a, 'i> {
    pub map: &'a DeTable<'i>,
    pub span: Span,
    pub what: String,
}

impl<'a, 'i> Table<'a, 'i> {
    pub fn new(value: &'a Value<'i>, what: impl Into<String>, cx: &mut Cx) -> Option<Self> {
        let what = what.into();
        match value.get_ref() {
            DeValue::Table(map) => Some(Table {
                map,
                span: value.span(),
                what,
            }),
            other => {
                type_error(cx, &what, "a table", other, value.span());
                None
            }
        }
    }

    /// Reports every key not in `allowed`, with the closest allowed key as a hint.
    pub fn check_keys(&self, allowed: &[&str], cx: &mut Cx) {
        for key in self.map.keys() {
            let name: &str = key.get_ref();
            if !allowed.contains(&name) {
                let hint = match did_you_mean(name, allowed.iter().copied()) {
                    Some(s) => format!("did you mean `{s}`?"),
                    None => format!("expected one of: {}", allowed.join(", ")),
                };
                cx.error_with_note(
                    "unknown-key",
                    format!("unknown key `{name}` in {}", self.what),
                    key.span(),
                    "unknown key",
                    hint,
                );
            }
        }
    }

    pub fn get(&self, key: &str) -> Option<&'a Value<'i>> {
        self.map.get(key)
    }

    pub fn key_span(&self, key: &str) -> Option<Span> {
        self.map.get_key_value(key).map(|(k, _)| k.span())
    }

    /// The span of `key = value`, or of the table header when absent.
    pub fn span_of(&self, key: &str) -> Span {
        self.get(key)
            .map_or_else(|| self.span.clone(), |v| v.span())
    }

    /// Entries in file order.
    pub fn entries(&self) -> impl Iterator<Item = (&'a str, Span, &'a Value<'i>)> + '_ {
        self.map
            .iter()
            .map(|(k, v)| (k.get_ref().as_ref(), k.span(), v))
    }

    pub fn string(&self, key: &str, cx: &mut Cx) -> Option<String> {
        let v = self.get(key)?;
        expect_string(v, &format!("`{key}` of {}", self.what), cx)
    }

    /// The value of `key` among a metadata enum's values (`ALL`, spelled by
    /// `name`); an unknown value is an `unknown-value` error with a hint.
    pub fn one_of<T: Copy>(
        &self,
        key: &str,
        options: &[T],
        name: fn(T) -> &'static str,
        cx: &mut Cx,
    ) -> Option<T> {
        let s = self.string(key, cx)?;
        match options.iter().find(|v| name(**v) == s) {
            Some(v) => Some(*v),
            None => {
                let names: Vec<&str> = options.iter().map(|v| name(*v)).collect();
                let hint = crate::diag::did_you_mean(&s, names.iter().copied()).map_or_else(
                    || format!("expected one of: {}", names.join(", ")),
                    |x| format!("did you mean `{x}`?"),
                );
                cx.error_with_note(
                    "unknown-value",
                    format!("unknown `{key}` value `{s}` in {}", self.what),
                    self.span_of(key),
                    "unknown",
                    hint,
                );
                None
            }
        }
    }

    pub fn number(&self, key: &str, cx: &mut Cx) -> Option<f64> {
        let v = self.get(key)?;
        expect_number(v, &format!("`{key}` of {}", self.what), cx)
    }

    pub fn integer(&self, key: &str, cx: &mut Cx) -> Option<i64> {
        let v = self.get(key)?;
        expect_integer(v, &format!("`{key}` of {}", self.what), cx)
    }

    pub fn boolean(&self, key: &str, cx: &mut Cx) -> Option<bool> {
        let v = self.get(key)?;
        expect_bool(v, &format!("`{key}` of {}", self.what), cx)
    }

    pub fn numbers(&self, key: &str, cx: &mut Cx) -> Option<Vec<f64>> {
        let v = self.get(key)?;
        expect_numbers(v, &format!("`{key}` of {}", self.what), cx)
    }

    pub fn strings(&self, key: &str, cx: &mut Cx) -> Option<Vec<(String, Span)>> {
        let v = self.get(key)?;
        let what = format!("`{key}` of {}", self.what);
        let items = expect_array(v, &what, cx)?;
        let mut out = Vec::new();
        for item in items {
            out.push((expect_string(item, &what, cx)?, item.span()));
        }
        Some(out)
    }

    /// A `[min, max]` pair; reports min > max.
    pub fn range(&self, key: &str, cx: &mut Cx) -> Option<[f64; 2]> {
        let v = self.get(key)?;
        let nums = self.numbers(key, cx)?;
        if nums.len() != 2 {
            cx.error(
                "wrong-type",
                format!("`{key}` of {} must be [min, max]", self.what),
                v.span(),
                format!("{} numbers here", nums.len()),
            );
            return None;
        }
        if nums[0] > nums[1] {
            cx.error_with_note(
                "min-above-max",
                format!("`{key}` of {} has min > max", self.what),
                v.span(),
                format!("min {} is greater than max {}", nums[0], nums[1]),
                "write the smaller bound first: [min, max]",
            );
            return None;
        }
        Some([nums[0], nums[1]])
    }
}

pub fn type_name(v: &DeValue) -> &'static str {
    match v {
        DeValue::String(_) => "a string",
        DeValue::Integer(_) => "an integer",
        DeValue::Float(_) => "a float",
        DeValue::Boolean(_) => "a boolean",
        DeValue::Datetime(_) => "a date-time",
        DeValue::Array(_) => "an array",
        DeValue::Table(_) => "a table",
    }
}

pub fn type_error(cx: &mut Cx, what: &str, expected: &str, found: &DeValue, span: Span) {
    cx.error(
        "wrong-type",
        format!("{what} must be {expected}, found {}", type_name(found)),
        span,
        format!("expected {expected}"),
    );
}

pub fn expect_string(v: &Value, what: &str, cx: &mut Cx) -> Option<String> {
    match v.get_ref() {
        DeValue::String(s) => Some(s.to_string()),
        other => {
            type_error(cx, what, "a string", other, v.span());
            None
        }
    }
}

pub fn expect_bool(v: &Value, what: &str, cx: &mut Cx) -> Option<bool> {
    match v.get_ref() {
        DeValue::Boolean(b) => Some(*b),
        other => {
            type_error(cx, what, "a boolean (true or false)", other, v.span());
            None
        }
    }
}

pub fn expect_integer(v: &Value, what: &str, cx: &mut Cx) -> Option<i64> {
    match v.get_ref() {
        DeValue::Integer(i) => match i64::from_str_radix(i.as_str(), i.radix()) {
            Ok(n) => Some(n),
            Err(_) => {
                cx.error(
                    "wrong-type",
                    format!("{what} is out of range"),
                    v.span(),
                    "too large",
                );
                None
            }
        },
        other => {
            type_error(cx, what, "an integer", other, v.span());
            None
        }
    }
}

/// The range of an f32 as messages state it: every number read is bound for
/// a GPU type (`gpu_numbers` checks the others).
pub const F32_RANGE: &str = "finite values within ±3.4028235e38";

/// A float or an integer, as f64; NaN and infinities are rejected.
pub fn expect_number(v: &Value, what: &str, cx: &mut Cx) -> Option<f64> {
    let n = match v.get_ref() {
        DeValue::Integer(i) => i64::from_str_radix(i.as_str(), i.radix())
            .ok()
            .map(|n| n as f64),
        DeValue::Float(f) => f.as_str().parse::<f64>().ok(),
        other => {
            type_error(cx, what, "a number", other, v.span());
            return None;
        }
    };
    match n {
        Some(n) if n.is_finite() => Some(n),
        _ => {
            cx.error_with_note(
                "type-range",
                format!("{what} must be a finite number"),
                v.span(),
                "not finite",
                format!(
                    "numbers are stored on the GPU as f32 or i32, which hold no infinities or NaN (an f32: {F32_RANGE})",
                ),
            );
            None
        }
    }
}

pub fn expect_array<'a, 'i>(v: &'a Value<'i>, what: &str, cx: &mut Cx) -> Option<&'a [Value<'i>]> {
    match v.get_ref() {
        DeValue::Array(a) => Some(a.as_ref()),
        other => {
            type_error(cx, what, "an array", other, v.span());
            None
        }
    }
}

pub fn expect_numbers(v: &Value, what: &str, cx: &mut Cx) -> Option<Vec<f64>> {
    let items = expect_array(v, what, cx)?;
    let mut out = Vec::with_capacity(items.len());
    let mut ok = true;
    for item in items {
        match expect_number(item, what, cx) {
            Some(n) => out.push(n),
            None => ok = false,
        }
    }
    ok.then_some(out)
}
