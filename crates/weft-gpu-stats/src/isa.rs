//! ACO's disassembly as basic blocks and loops. ACO lays blocks out in
//! structured order: a loop's header comes first and its body runs up to
//! the block that branches back, so a loop is the block interval
//! [header, latch] of a backward branch.

/// One basic block: its label number and weighted cost.
#[derive(Clone, Debug, PartialEq)]
pub struct BasicBlock {
    /// `n` of the label `BB<n>:`.
    pub label: u32,
    /// Σ [`weight`] of its instructions.
    pub cost: f64,
    /// Instructions in it.
    pub instructions: usize,
    /// Immediate bounds of `s_cmp_{lt,le,gt,ge}_{u32,i32} s, IMM` compares.
    pub compare_immediates: Vec<i64>,
    /// Branch targets (label numbers).
    pub targets: Vec<u32>,
}

/// A loop: blocks `header..=latch` (indices into [`Program::blocks`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Loop {
    /// Index of the first block.
    pub header: usize,
    /// Index of the block that branches back.
    pub latch: usize,
    /// Loops that contain it.
    pub depth: usize,
}

/// A parsed disassembly.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// Blocks in layout order.
    pub blocks: Vec<BasicBlock>,
    /// Loops in layout order (outer before inner).
    pub loops: Vec<Loop>,
}

/// Issue cost of one instruction, in VALU-instruction units (a deliberately
/// simple table, docs/performance.md): transcendental 4 (quarter rate on
/// RDNA), vector memory 8 and scalar memory 2 (a fixed share of latency a
/// wave does not hide), bookkeeping (`s_waitcnt`, `s_nop`, `s_clause`,
/// `s_delay_alu`, …) 0, everything else 1.
pub fn weight(mnemonic: &str) -> f64 {
    const TRANSCENDENTAL: [&str; 7] = [
        "v_exp_", "v_log_", "v_rcp_", "v_rsq_", "v_sqrt_", "v_sin_", "v_cos_",
    ];
    const VMEM: [&str; 6] = [
        "image_", "buffer_", "tbuffer_", "global_", "flat_", "scratch_",
    ];
    const FREE: [&str; 6] = [
        "s_waitcnt",
        "s_nop",
        "s_clause",
        "s_delay_alu",
        "s_inst_prefetch",
        "s_endpgm",
    ];
    if TRANSCENDENTAL.iter().any(|p| mnemonic.starts_with(p)) {
        4.0
    } else if VMEM.iter().any(|p| mnemonic.starts_with(p)) {
        8.0
    } else if mnemonic.starts_with("s_load") || mnemonic.starts_with("s_buffer_load") {
        2.0
    } else if FREE.iter().any(|p| mnemonic.starts_with(p)) {
        0.0
    } else {
        1.0
    }
}

/// Parses `BB<n>:` labels and tab-indented instructions (`; …` comments dropped).
pub fn parse(text: &str) -> Program {
    let mut blocks: Vec<BasicBlock> = Vec::new();
    for line in text.lines() {
        let code = line.split(';').next().unwrap_or("").trim();
        if code.is_empty() {
            continue;
        }
        let label = code.strip_prefix("BB").and_then(|r| r.strip_suffix(':'));
        if let Some(label) = label.and_then(|n| n.parse().ok()) {
            blocks.push(new_block(label));
            continue;
        }
        if blocks.is_empty() {
            blocks.push(new_block(0)); // code before any label
        }
        let b = blocks.last_mut().expect("pushed above");
        let mut parts = code.split_whitespace();
        let mnemonic = parts.next().unwrap_or("");
        let operands: Vec<&str> = code[mnemonic.len()..].split(',').map(str::trim).collect();
        b.instructions += 1;
        b.cost += weight(mnemonic);
        let branch = mnemonic == "s_branch" || mnemonic.starts_with("s_cbranch");
        if let Some(t) = operands[0].strip_prefix("BB").and_then(|t| t.parse().ok())
            && branch
        {
            b.targets.push(t);
        }
        if let Some(v) = operands.get(1).and_then(|o| immediate(o))
            && is_bound_compare(mnemonic)
        {
            b.compare_immediates.push(v);
        }
    }
    let loops = find_loops(&blocks);
    Program { blocks, loops }
}

fn new_block(label: u32) -> BasicBlock {
    BasicBlock {
        label,
        cost: 0.0,
        instructions: 0,
        compare_immediates: Vec::new(),
        targets: Vec::new(),
    }
}

/// Ordered compares only: `s_cmp_eq/lg` also test naga's loop-bounding guard counters.
fn is_bound_compare(m: &str) -> bool {
    ["s_cmp_lt_", "s_cmp_le_", "s_cmp_gt_", "s_cmp_ge_"]
        .iter()
        .any(|p| m.starts_with(p))
}

fn immediate(op: &str) -> Option<i64> {
    match op.strip_prefix("0x") {
        Some(hex) => i64::from_str_radix(hex, 16).ok(),
        None => op.parse().ok(),
    }
}

/// One loop per header: the interval up to its last backward branch.
fn find_loops(blocks: &[BasicBlock]) -> Vec<Loop> {
    let index = |label: u32| blocks.iter().position(|b| b.label == label);
    let mut loops: Vec<Loop> = Vec::new();
    for (i, b) in blocks.iter().enumerate() {
        for &t in &b.targets {
            let Some(h) = index(t).filter(|&h| h <= i) else {
                continue;
            };
            match loops.iter_mut().find(|l| l.header == h) {
                Some(l) => l.latch = l.latch.max(i),
                None => loops.push(Loop {
                    header: h,
                    latch: i,
                    depth: 0,
                }),
            }
        }
    }
    loops.sort_by_key(|l| (l.header, std::cmp::Reverse(l.latch)));
    let spans: Vec<(usize, usize)> = loops.iter().map(|l| (l.header, l.latch)).collect();
    for l in &mut loops {
        l.depth = spans
            .iter()
            .filter(|&&(h, e)| (h, e) != (l.header, l.latch) && h <= l.header && l.latch <= e)
            .count();
    }
    loops
}

#[cfg(test)]
mod tests {
    use super::*;

    const SNIPPET: &str = "BB0:
\ts_mov_b32 s5, 0                                             ; be850380
\tv_mov_b32_e32 v1, 0                                         ; 7e020280
BB1:
\ts_cmp_ge_u32 s5, 12                                         ; bf098c05
\ts_cbranch_scc1 BB4                                          ; bf8501e1
BB2:
\tv_sin_f32_e32 v40, v40                                      ; 7e506b28
\timage_sample v[4:7], v[4:5], s[16:23], s[12:15] dmask:0xf   ; f0800f08
\ts_waitcnt vmcnt(0)                                          ; bf8c3f70
\tv_add_f32_e32 v1, v1, v4                                    ; 06020901
\ts_add_u32 s5, s5, 1                                         ; 80058105
\ts_branch BB1                                                ; bf82fe14
BB4:
\texp mrt0 v1, v1, v1, v1 done vm                             ; f800180f
\ts_endpgm                                                    ; bf810000
";

    #[test]
    fn blocks_costs_and_the_loop_of_a_snippet() {
        let p = parse(SNIPPET);
        let labels: Vec<u32> = p.blocks.iter().map(|b| b.label).collect();
        assert_eq!(labels, [0, 1, 2, 4]);
        let costs: Vec<f64> = p.blocks.iter().map(|b| b.cost).collect();
        // BB2: sin 4 + image 8 + waitcnt 0 + add 1 + s_add 1 + branch 1.
        assert_eq!(costs, [2.0, 2.0, 15.0, 1.0]);
        assert_eq!(p.blocks[1].compare_immediates, [12]);
        assert_eq!(p.blocks[1].targets, [4]);
        assert_eq!(
            p.loops,
            [Loop {
                header: 1,
                latch: 2,
                depth: 0
            }]
        );
    }
}
