//! Sampler-heap aliases in naga's HLSL that Slang accepts.
//!
//! naga binds every sampler through its sampler heap and names each WGSL
//! sampler with a global
//! `static const SamplerState s = nagaSamplerHeap[nagaGroup1SamplerIndexArray[2]];`
//! (`SamplerComparisonState` / `nagaComparisonSamplerHeap` for comparison
//! samplers). DXC and FXC take that, but Slang rejects it ("static const
//! global initializer must be a compile-time constant"), and naga 30 has no
//! option to leave the heap out. A macro names the same heap element in
//! every compiler: `#define s (nagaSamplerHeap[nagaGroup1SamplerIndexArray[2]])`.
//! The registers do not change: the heap and index-buffer declarations stay.

/// `hlsl` with every sampler-heap alias turned into a macro. Fails rather
/// than write HLSL a macro would corrupt: a macro replaces every token of
/// its name, so the name must appear nowhere but as a plain identifier
/// (never after `.`, i.e. as a struct member, and never declared again).
pub fn sampler_heap_macros(hlsl: &str) -> Result<String, String> {
    let mut out = String::with_capacity(hlsl.len());
    let mut names = Vec::new();
    for line in hlsl.split_inclusive('\n') {
        match alias(line) {
            Some((name, element)) => {
                out.push_str(&format!("#define {name} ({element})\n"));
                names.push(name);
            }
            None => out.push_str(line),
        }
    }
    for name in &names {
        check_uses(&out, name)?;
    }
    Ok(out)
}

/// `(name, heap element)` of a line naga writes for a sampler global.
fn alias(line: &str) -> Option<(String, String)> {
    let rest = line.trim_end().strip_prefix("static const ")?;
    let rest = rest
        .strip_prefix("SamplerState ")
        .or_else(|| rest.strip_prefix("SamplerComparisonState "))?;
    let (name, element) = rest.split_once(" = ")?;
    let element = element.strip_suffix(';')?;
    let heap_ok = element.starts_with("nagaSamplerHeap[")
        || element.starts_with("nagaComparisonSamplerHeap[");
    let name_ok = !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    (heap_ok && name_ok && element.ends_with(']')).then(|| (name.to_string(), element.to_string()))
}

/// Every whole-word occurrence of `name` but the `#define` itself must be a
/// use as a value: not a member (`x.name`) and not a declaration (`T name`).
fn check_uses(hlsl: &str, name: &str) -> Result<(), String> {
    let define = format!("#define {name} ");
    for line in hlsl.lines().filter(|l| !l.starts_with(&define)) {
        for (at, _) in line.match_indices(name) {
            let before = &line[..at];
            let after = &line[at + name.len()..];
            let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
            if before.ends_with(ident) || after.starts_with(ident) {
                continue;
            }
            let prev = before.trim_end();
            let member = prev.ends_with('.');
            // `Type name` (a declaration): the previous token is an identifier.
            let declared = prev.ends_with(ident) && !prev.ends_with("return");
            if member || declared {
                return Err(format!(
                    "HLSL: sampler `{name}` also names a member or declaration (`{}`): it \
                     cannot become a macro",
                    line.trim()
                ));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    const NAGA: &str = "SamplerState nagaSamplerHeap[2048]: register(s0, space8);\n\
        SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);\n\
        StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);\n\
        static const SamplerState samp = nagaSamplerHeap[nagaGroup1SamplerIndexArray[2]];\n\
        static const SamplerComparisonState shadow = nagaComparisonSamplerHeap[nagaGroup1SamplerIndexArray[3]];\n\
        float4 f(float2 uv) { return t.Sample(samp, uv) * t2.SampleCmp(shadow, uv, 0.5); }\n";

    #[test]
    fn aliases_become_macros_and_the_heaps_stay() {
        let out = sampler_heap_macros(NAGA).unwrap();
        assert!(!out.contains("static const Sampler"), "{out}");
        assert!(out.contains("#define samp (nagaSamplerHeap[nagaGroup1SamplerIndexArray[2]])\n"));
        assert!(out.contains(
            "#define shadow (nagaComparisonSamplerHeap[nagaGroup1SamplerIndexArray[3]])\n"
        ));
        assert!(out.contains("SamplerState nagaSamplerHeap[2048]: register(s0, space8);"));
        assert!(out.contains("t.Sample(samp, uv)"));
    }

    #[test]
    fn a_name_a_macro_would_corrupt_is_an_error() {
        let member = format!("{NAGA}struct S {{ float x; }};\nfloat g(S s) {{ return s.samp; }}\n");
        let e = sampler_heap_macros(&member).unwrap_err();
        assert!(e.contains("`samp`"), "{e}");
        let declared = format!("{NAGA}float g() {{ float shadow = 1.0; return shadow; }}\n");
        assert!(sampler_heap_macros(&declared).is_err());
        // A longer identifier that contains the name is not a use.
        let longer = format!("{NAGA}float g() {{ float samp_1 = 1.0; return samp_1; }}\n");
        assert!(sampler_heap_macros(&longer).is_ok());
    }
}
