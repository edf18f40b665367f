//! Executed cost of one stage: Σ over ACO's blocks of (weighted cost ×
//! executions), a block's executions being the product of the trip counts
//! of the loops around it. Trip counts come from the specialised WGSL
//! ([`crate::trips`]); see [`match_loops`] for how source loops are paired
//! with ACO's.

use crate::isa::{self, Program};
use crate::trips::SourceLoop;

/// A loop as the model counted it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ModelLoop {
    /// Label of its header block (`BB<n>`).
    pub header_label: u32,
    /// Loops around it.
    pub depth: usize,
    /// Iterations per execution; `None`: unknown, counted once.
    pub trips: Option<u64>,
}

/// The modelled cost of one executable.
#[derive(Clone, Debug, PartialEq)]
pub struct StageModel {
    /// Σ block cost, each block once (the static view).
    pub static_cost: f64,
    /// Σ block cost × executions.
    pub executed_cost: f64,
    /// ACO's loops with the trip counts used.
    pub loops: Vec<ModelLoop>,
}

impl StageModel {
    /// Loops counted once because no trip count was found.
    pub fn unknown_loops(&self) -> usize {
        self.loops.iter().filter(|l| l.trips.is_none()).count()
    }
}

/// Models a disassembly given the source loops of its entry point (`None`:
/// source unknown, every loop counted once).
pub fn model(disassembly: &str, source: Option<&[SourceLoop]>) -> StageModel {
    model_at(disassembly, source, None)
}

/// [`model`], where a loop the shader's own source leaves without a trip
/// count takes the one `instance` gives it: the generic variant drawing a
/// scene instance runs its loops as many times as the instance's specialised
/// shader, whose source has the count where the generic's reads a uniform
/// (loops paired as [`match_loops`] pairs them; a loop the specialisation
/// removed ran at most once and stays counted once).
pub fn model_at(
    disassembly: &str,
    source: Option<&[SourceLoop]>,
    instance: Option<&[SourceLoop]>,
) -> StageModel {
    let program = isa::parse(disassembly);
    let own = match source {
        Some(s) => match_loops(&program, s),
        None => vec![None; program.loops.len()],
    };
    let trips: Vec<Option<u64>> = match instance {
        Some(i) => own
            .iter()
            .zip(match_loops(&program, i))
            .map(|(o, i)| o.or(i))
            .collect(),
        None => own,
    };
    let mut static_cost = 0.0;
    let mut executed_cost = 0.0;
    for (i, b) in program.blocks.iter().enumerate() {
        let executions: f64 = program
            .loops
            .iter()
            .zip(&trips)
            .filter(|(l, _)| l.header <= i && i <= l.latch)
            .map(|(_, t)| t.map_or(1.0, |t| t as f64))
            .product();
        static_cost += b.cost;
        executed_cost += b.cost * executions;
    }
    let loops = program
        .loops
        .iter()
        .zip(&trips)
        .map(|(l, t)| ModelLoop {
            header_label: program.blocks[l.header].label,
            depth: l.depth,
            trips: *t,
        })
        .collect();
    StageModel {
        static_cost,
        executed_cost,
        loops,
    }
}

/// Pairs ACO's loops (layout order) with the source's (program order, calls
/// inlined) walking both forwards. The driver unrolls some loops (small
/// bodies, few iterations), so source loops may be skipped, never ACO's.
/// An ACO loop whose exit compares against an immediate takes the next
/// source loop with that bound; otherwise the next source loop at its
/// nesting depth. A loop left without a source loop has an unknown count.
pub fn match_loops(program: &Program, source: &[SourceLoop]) -> Vec<Option<u64>> {
    let mut cursor = 0;
    program
        .loops
        .iter()
        .map(|l| {
            let immediates: Vec<i64> = program.blocks[l.header..=l.latch]
                .iter()
                .flat_map(|b| b.compare_immediates.iter().copied())
                .collect();
            let rest = source.get(cursor..).unwrap_or(&[]);
            let by_bound = rest
                .iter()
                .position(|s| s.bound.is_some_and(|b| immediates.contains(&b)));
            let by_depth = || rest.iter().position(|s| s.depth == l.depth);
            let found = by_bound.or_else(by_depth)?;
            cursor += found + 1;
            rest[found].trips
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn src(depth: usize, trips: u64) -> SourceLoop {
        SourceLoop {
            depth,
            trips: Some(trips),
            bound: Some(trips as i64),
        }
    }

    const TWO_LOOPS: &str = "BB0:
\tv_mov_b32 v0, 0
BB1:
\ts_cmp_ge_u32 s5, 12
\ts_cbranch_scc1 BB3
BB2:
\tv_add_f32 v0, v0, v1
\ts_branch BB1
BB3:
\tv_mov_b32 v1, 0
BB4:
\ts_cmp_ge_u32 s6, s0
\ts_cbranch_scc1 BB6
BB5:
\tv_add_f32 v0, v0, v1
\ts_branch BB4
BB6:
\ts_endpgm
";

    #[test]
    fn unrolled_source_loops_are_skipped_and_counts_multiply_blocks() {
        // Source: a 4-iteration loop the driver unrolled, then 12, then 101.
        let source = [src(0, 4), src(0, 12), src(0, 101)];
        let m = model(TWO_LOOPS, Some(&source));
        let trips: Vec<_> = m.loops.iter().map(|l| l.trips).collect();
        assert_eq!(trips, [Some(12), Some(101)]);
        // BB0 1, BB1 2 ×12, BB2 2 ×12, BB3 1, BB4 2 ×101, BB5 2 ×101, BB6 0.
        assert_eq!(m.static_cost, 10.0);
        assert_eq!(m.executed_cost, 1.0 + 48.0 + 1.0 + 404.0);
        let unknown = model(TWO_LOOPS, None);
        assert_eq!(unknown.executed_cost, unknown.static_cost);
        assert_eq!(unknown.unknown_loops(), 2);
    }

    #[test]
    fn an_instance_gives_the_counts_the_generic_source_lacks() {
        // The generic's second loop reads its bound from a uniform (no count);
        // the instance's shader has 7 there. The first loop keeps its own 12.
        let own = [
            src(0, 12),
            SourceLoop {
                depth: 0,
                trips: None,
                bound: None,
            },
        ];
        let instance = [src(0, 3), src(0, 7)];
        let m = model_at(TWO_LOOPS, Some(&own), Some(&instance));
        let trips: Vec<_> = m.loops.iter().map(|l| l.trips).collect();
        assert_eq!(trips, [Some(12), Some(7)]);
        // An instance whose shader lost the loop (it ran once) leaves it counted once.
        let m = model_at(TWO_LOOPS, Some(&own), Some(&instance[..1]));
        assert_eq!(m.unknown_loops(), 1);
    }
}
