//! Blocks of the documentation that tests keep current. Shared by the test
//! files with `#[path = "support/docs.rs"] mod docs;`.

/// Text between `<!-- begin NAME -->` and `<!-- end NAME -->`, inside its code fence.
pub fn doc_block(doc: &str, name: &str) -> String {
    let begin = format!("<!-- begin {name} -->");
    let end = format!("<!-- end {name} -->");
    let start = doc.find(&begin).unwrap_or_else(|| panic!("no {begin}")) + begin.len();
    let stop = doc[start..]
        .find(&end)
        .unwrap_or_else(|| panic!("no {end}"))
        + start;
    let block = doc[start..stop].trim();
    let block = block
        .strip_prefix("```wgsl")
        .or_else(|| block.strip_prefix("```toml"))
        .expect("fenced block");
    let block = block.strip_suffix("```").expect("closing fence");
    block.trim_start_matches('\n').to_string()
}
