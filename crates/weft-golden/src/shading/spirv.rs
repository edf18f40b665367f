//! SPIR-V instruction counts: the module's and those of the functions the
//! fragment entry point reaches.

use weft_render::Material;

/// Instruction counts of a SPIR-V module: all instructions, and those in
/// the functions a fragment entry point reaches (its function and callees,
/// `OpFunction` to `OpFunctionEnd`; module-level types, constants and
/// decorations are not included).
pub fn spirv_instruction_counts(bytes: &[u8]) -> Result<(u32, u32), String> {
    if !bytes.len().is_multiple_of(4) || bytes.len() < 20 {
        return Err("not a SPIR-V module (length)".into());
    }
    let words: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    if words[0] != 0x0723_0203 {
        return Err("not a little-endian SPIR-V module (magic)".into());
    }
    const OP_ENTRY_POINT: u32 = 15;
    const OP_FUNCTION: u32 = 54;
    const OP_FUNCTION_END: u32 = 56;
    const OP_FUNCTION_CALL: u32 = 57;
    const FRAGMENT: u32 = 4;
    let mut total = 0u32;
    let mut fragment_roots = Vec::new();
    // Per function id: instruction count and callees.
    let mut functions: std::collections::HashMap<u32, (u32, Vec<u32>)> = Default::default();
    let mut current: Option<u32> = None;
    let mut i = 5;
    while i < words.len() {
        let count = (words[i] >> 16) as usize;
        let op = words[i] & 0xffff;
        if count == 0 || i + count > words.len() {
            return Err(format!("malformed instruction at word {i}"));
        }
        let w = &words[i..i + count];
        total += 1;
        match op {
            OP_ENTRY_POINT if count > 2 && w[1] == FRAGMENT => fragment_roots.push(w[2]),
            OP_FUNCTION if count > 2 => {
                current = Some(w[2]);
                functions.entry(w[2]).or_default();
            }
            _ => {}
        }
        if let Some(f) = current {
            let entry = functions.entry(f).or_default();
            entry.0 += 1;
            if op == OP_FUNCTION_CALL && count > 3 {
                entry.1.push(w[3]);
            }
        }
        if op == OP_FUNCTION_END {
            current = None;
        }
        i += count;
    }
    let mut seen = std::collections::HashSet::new();
    let mut stack = fragment_roots;
    let mut fragment = 0;
    while let Some(f) = stack.pop() {
        if !seen.insert(f) {
            continue;
        }
        if let Some((n, callees)) = functions.get(&f) {
            fragment += n;
            stack.extend(callees);
        }
    }
    Ok((total, fragment))
}

/// The SPIR-V file of the material's current variant (the one whose baked
/// constant-mode keyword values match the material's) and its counts.
pub(super) fn spirv_counts_for(material: &Material) -> Result<(u32, u32), String> {
    let name = material.name().to_string();
    let v = material
        .current_variant()
        .map_err(|e| format!("{name}: {e}"))?;
    let file = v
        .shader
        .files
        .get("spirv")
        .and_then(|files| {
            files.iter().find(|f| {
                f.constants
                    .iter()
                    .all(|(k, val)| material.keyword(k) == Some(val.as_str()))
            })
        })
        .ok_or_else(|| format!("{name}: variant `{}` has no SPIR-V file", v.canonical.id))?;
    let path = material.dir().join(&file.path);
    let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    spirv_instruction_counts(&bytes).map_err(|e| format!("{}: {e}", path.display()))
}
