//! The query string of a request (`a=1&b=x%2Cy`): split into decoded
//! parameters, every malformed one refused with a short message (a 400).
//! Parameters the server does not read (the page's `g=` cache buster) are
//! accepted and ignored.

/// Longest number accepted in a parameter: more digits than any f64 has
/// are refused before parsing, with a message that says so.
const MAX_NUMBER: usize = 64;

/// How much of a refused value a message shows.
const SHOWN: usize = 40;

/// A request's decoded parameters, in order.
#[derive(Debug, Default)]
pub struct Query {
    pairs: Vec<(String, String)>,
}

impl Query {
    /// Decodes `query` (the part after `?`, empty when none): `&`-separated
    /// `key=value` (or `key`), `%XX` escapes (`+` stays a plus: the page
    /// writes no spaces, and numbers may carry a sign). Errors:
    /// a `%` not followed by two hex digits, bytes that are not UTF-8.
    pub fn parse(query: &str) -> Result<Query, String> {
        let mut pairs = Vec::new();
        for kv in query.split('&').filter(|kv| !kv.is_empty()) {
            let (k, v) = kv.split_once('=').unwrap_or((kv, ""));
            pairs.push((decode(k)?, decode(v)?));
        }
        Ok(Query { pairs })
    }

    /// The value of `key`: None when absent; an error when it is given more
    /// than once (which one was meant is ambiguous).
    pub fn unique(&self, key: &str) -> Result<Option<&str>, String> {
        let mut values = self.pairs.iter().filter(|(k, _)| k == key);
        let first = values.next().map(|(_, v)| v.as_str());
        if values.next().is_some() {
            return Err(format!("the query gives `{key}` more than once"));
        }
        Ok(first)
    }

    /// The `sun` parameter (`sun=x,y,z`): None when absent, else the
    /// direction normalised. Errors name what is wrong: not three numbers,
    /// a number too long, not finite, zero length.
    pub fn sun(&self) -> Result<Option<[f32; 3]>, String> {
        self.unique("sun")?.map(parse_sun).transpose()
    }
}

/// `%XX` decoded.
fn decode(s: &str) -> Result<String, String> {
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'%' => {
                let hex = |j: usize| bytes.get(j).and_then(|&b| (b as char).to_digit(16));
                let (Some(hi), Some(lo)) = (hex(i + 1), hex(i + 2)) else {
                    return Err(format!(
                        "malformed query `{}`: `%` must be followed by two hex digits",
                        shown(s)
                    ));
                };
                out.push((hi * 16 + lo) as u8);
                i += 3;
            }
            b => {
                out.push(b);
                i += 1;
            }
        }
    }
    String::from_utf8(out).map_err(|_| format!("malformed query `{}`: not UTF-8", shown(s)))
}

/// The start of `s`, control characters escaped, for a message.
fn shown(s: &str) -> String {
    let mut out: String = s.chars().take(SHOWN).flat_map(char::escape_debug).collect();
    if s.chars().nth(SHOWN).is_some() {
        out.push('…');
    }
    out
}

/// `x,y,z` as a unit vector.
fn parse_sun(value: &str) -> Result<[f32; 3], String> {
    let bad = |why: &str| {
        format!(
            "bad sun direction `{}`: {why}; expected sun=x,y,z, three finite numbers not all zero (the direction towards the sun, as `weft preview --light x,y,z`)",
            shown(value)
        )
    };
    let parts: Vec<&str> = value.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(bad("not three numbers"));
    }
    let mut d = [0f64; 3];
    for (i, p) in parts.iter().enumerate() {
        if p.len() > MAX_NUMBER {
            return Err(bad(&format!(
                "a number longer than {MAX_NUMBER} characters"
            )));
        }
        let v: f64 = p.parse().map_err(|_| bad("not a number"))?;
        if !v.is_finite() {
            return Err(bad("not finite"));
        }
        d[i] = v;
    }
    // Scale first so huge components do not overflow the length.
    let m = d.iter().fold(0f64, |m, v| m.max(v.abs()));
    if m <= 0.0 {
        return Err(bad("zero length"));
    }
    let d = d.map(|v| v / m);
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let unit = d.map(|v| (v / len) as f32);
    if unit.iter().any(|v| !v.is_finite()) {
        return Err(bad("not finite"));
    }
    Ok(unit)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sun(q: &str) -> Result<Option<[f32; 3]>, String> {
        Query::parse(q)?.sun()
    }

    #[test]
    fn decodes_and_refuses_malformed_queries() {
        assert_eq!(sun("g=2&sun=0%2C2%2c0").unwrap(), Some([0.0, 1.0, 0.0]));
        assert_eq!(sun("sun=+0,-3e+0,0e0").unwrap(), Some([0.0, -1.0, 0.0]));
        assert_eq!(sun("g=1&&x").unwrap(), None);
        let long = format!("sun=1{},0,0", "0".repeat(MAX_NUMBER));
        for (q, why) in [
            ("sun=1,0,0&sun=0,1,0", "more than once"),
            ("sun=%zz,0,0", "two hex digits"),
            ("sun=1%2", "two hex digits"),
            ("sun=%ff,0,0", "not UTF-8"),
            ("sun=%00,1,1", "not a number"),
            ("sun=NaN,1,0", "not finite"),
            ("sun=1e999,1,0", "not finite"),
            ("sun=0,0,0", "zero length"),
            ("sun=1,2", "not three numbers"),
            (long.as_str(), "longer than 64"),
        ] {
            let e = sun(q).unwrap_err();
            assert!(e.contains(why), "{q}: {e}");
            assert!(e.len() < 300, "{q}: a short message: {e}");
        }
        assert!(sun("sun=%00,1,1").unwrap_err().contains("`\\0,1,1`"));
    }
}
