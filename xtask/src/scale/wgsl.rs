//! The WGSL rewrite: the shipped fragment entry point renamed and wrapped
//! by a new one that applies the added keywords.

use std::fmt::Write as _;

/// The byte range of the parenthesised list starting at `open` (`(`).
fn matching_paren(s: &str, open: usize) -> Option<usize> {
    let mut depth = 0i32;
    for (i, ch) in s[open..].char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(open + i);
                }
            }
            _ => {}
        }
    }
    None
}

/// Splits a parameter list at top-level commas.
fn split_params(list: &str) -> Vec<String> {
    let (mut out, mut cur, mut depth) = (Vec::new(), String::new(), 0i32);
    for ch in list.chars() {
        match ch {
            '(' | '<' => depth += 1,
            ')' | '>' => depth -= 1,
            ',' if depth == 0 => {
                out.push(std::mem::take(&mut cur));
                continue;
            }
            _ => {}
        }
        cur.push(ch);
    }
    out.push(cur);
    out.into_iter()
        .map(|p| p.trim().to_string())
        .filter(|p| !p.is_empty())
        .collect()
}

/// A parameter without its attributes (`@builtin(x) name: T` -> `name: T`).
pub(super) fn strip_attributes(p: &str) -> String {
    let mut s = p.trim_start();
    while let Some(rest) = s.strip_prefix('@') {
        let end = rest
            .find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(rest.len());
        let mut after = rest[end..].trim_start();
        if after.starts_with('(') {
            let close = matching_paren(after, 0).unwrap_or(after.len() - 1);
            after = &after[close + 1..];
        }
        s = after.trim_start();
    }
    s.to_string()
}

/// Renames the `@fragment fn <entry>` of `wgsl` to `weft_syn_base_<entry>`
/// (a plain function) and appends a new `@fragment fn <entry>` with the same
/// signature that calls it and then runs `body`.
pub(super) fn wrap_fragment(wgsl: &str, entry: &str, body: &str) -> Result<String, String> {
    let needle = format!("fn {entry}(");
    let at = wgsl
        .match_indices(&needle)
        .map(|(i, _)| i)
        .find(|&i| wgsl[..i].trim_end().ends_with("@fragment"))
        .ok_or_else(|| format!("no `@fragment fn {entry}(`"))?;
    let attr = wgsl[..at].trim_end().len() - "@fragment".len();
    let open = at + needle.len() - 1;
    let close = matching_paren(wgsl, open).ok_or("unbalanced parameter list")?;
    let params = split_params(&wgsl[open + 1..close]);
    let brace = close + wgsl[close..].find('{').ok_or("no function body")?;
    let ret = wgsl[close + 1..brace].trim();
    if ret != "-> @location(0) vec4<f32>" {
        return Err(format!(
            "`{entry}` returns `{ret}`, not `@location(0) vec4<f32>`"
        ));
    }
    let stripped: Vec<String> = params.iter().map(|p| strip_attributes(p)).collect();
    let names: Vec<&str> = stripped
        .iter()
        .map(|p| p.split(':').next().unwrap_or("").trim())
        .collect();
    let varyings = stripped
        .iter()
        .zip(&names)
        .find(|(p, _)| p.split(':').nth(1).map(str::trim) == Some("WeftVaryings"))
        .map(|(_, n)| *n)
        .ok_or_else(|| format!("`{entry}` takes no WeftVaryings"))?;
    let base = format!("weft_syn_base_{entry}");
    let mut out = String::with_capacity(wgsl.len() + body.len() + 1024);
    out.push_str(&wgsl[..attr]);
    let _ = write!(out, "fn {base}({}) -> vec4<f32> ", stripped.join(", "));
    out.push_str(&wgsl[brace..]);
    if !out.ends_with('\n') {
        out.push('\n');
    }
    let _ = write!(
        out,
        "
// ---- synthetic keywords (cargo xtask bench scale) ----
@fragment
fn {entry}({}) -> @location(0) vec4<f32> {{
    var c = {base}({});
    let vin = {varyings};
    let surface = weft_surface(vin.world_position, vin.world_normal);
    let v = surface.v;
    let n = surface.n;
    let lit = weft_main_light_geometry(n, v);
    let n_dot_v = lit.n_dot_v;
    let l = lit.l;
{body}    return c;
}}
",
        params.join(", "),
        names.join(", ")
    );
    Ok(out)
}
