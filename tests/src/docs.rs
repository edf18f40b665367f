//! Blocks of the documentation that tests keep current, and the value lists
//! the docs write out (tables and prose), so the tests that hold the parsers,
//! the schemas and the docs to one list can compare them. Shared by the test
//! binaries through `weft_tests::docs`.

/// Text between `<!-- begin NAME -->` and `<!-- end NAME -->`, inside its code fence.
pub fn doc_block(doc: &str, name: &str) -> String {
    let begin = format!("<!-- begin {name} -->");
    let end = format!("<!-- end {name} -->");
    let start = doc.find(&begin).unwrap_or_else(|| panic!("no {begin}")) + begin.len();
    let stop = doc[start..]
        .find(&end)
        .unwrap_or_else(|| panic!("no {end}"))
        + start;
    // A block inside a list item is indented like the fence before it.
    let indent = doc[..start]
        .lines()
        .last()
        .map_or(0, |l| l.len() - l.trim_start().len());
    let dedented: String = doc[start..stop]
        .lines()
        .map(|l| &l[l.len().min(indent).min(l.len() - l.trim_start().len())..])
        .collect::<Vec<_>>()
        .join("\n");
    let block = dedented.trim();
    let block = ["```wgsl", "```toml", "```rust"]
        .iter()
        .find_map(|fence| block.strip_prefix(fence))
        .expect("fenced block");
    let block = block.strip_suffix("```").expect("closing fence");
    let mut block = block.trim_start_matches('\n').to_string();
    if indent > 0 && !block.ends_with('\n') {
        block.push('\n');
    }
    block
}

use std::collections::BTreeSet;
use std::path::Path;

pub fn load(path: impl AsRef<Path>) -> String {
    let path = path.as_ref();
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The lines of the section under the first heading whose text contains
/// `heading` (outside code blocks), up to the next heading of the same or a
/// higher level.
pub fn section<'a>(doc: &'a str, heading: &str) -> Vec<&'a str> {
    let mut fenced = false;
    let mut level = None;
    let mut out = Vec::new();
    for line in doc.lines() {
        if line.starts_with("```") {
            fenced = !fenced;
        }
        let hashes = line.chars().take_while(|&c| c == '#').count();
        let is_heading = !fenced && hashes > 0 && line[hashes..].starts_with(' ');
        match level {
            None if is_heading && line.contains(heading) => level = Some(hashes),
            None => {}
            Some(l) if is_heading && hashes <= l => break,
            Some(_) => out.push(line),
        }
    }
    assert!(level.is_some(), "no heading containing {heading:?}");
    out
}

/// The cells of a Markdown table row (`\|` inside a cell is a literal bar).
pub fn cells(row: &str) -> Vec<String> {
    let row = row.trim().trim_start_matches('|').trim_end_matches('|');
    row.replace("\\|", "\u{0}")
        .split('|')
        .map(|c| c.replace('\u{0}', "|").trim().to_string())
        .collect()
}

/// The cells of the first table row in `heading`'s section whose first cell
/// is `` `key` ``.
pub fn row(doc: &str, heading: &str, key: &str) -> Vec<String> {
    let first = format!("`{key}`");
    section(doc, heading)
        .into_iter()
        .filter(|l| l.trim_start().starts_with('|'))
        .map(cells)
        .find(|c| c.first() == Some(&first))
        .unwrap_or_else(|| panic!("no table row for `{key}` under {heading:?}"))
}

/// Every `` `code` `` span of `text`, a quoted string (`` `"auto"` ``) without its quotes.
pub fn backticked(text: &str) -> Vec<String> {
    text.split('`')
        .skip(1)
        .step_by(2)
        .map(|s| s.trim_matches('"').to_string())
        .collect()
}

/// The distinct `` `code` `` spans of `text`.
pub fn backticked_set(text: &str) -> BTreeSet<String> {
    backticked(text).into_iter().collect()
}

pub fn set<'a>(names: impl IntoIterator<Item = &'a str>) -> BTreeSet<String> {
    names.into_iter().map(str::to_string).collect()
}
