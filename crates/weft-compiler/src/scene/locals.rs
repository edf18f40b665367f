//! Constant stores forwarded to the loads of function-local variables.
//!
//! naga's WGSL front end turns every `var` into a local variable read through
//! `Load`s, and constant evaluation (`evaluate.rs`) stops at a load: after
//! `var k = 0; … f(k)` the call still sees a run-time value. This pass walks
//! each body in order, tracking which locals hold a known constant (from
//! their initialiser or a whole-variable store of a constant), and replaces a
//! load by that constant. Knowledge is dropped where it could be wrong: a
//! store through a component or a pointer passed to a call forgets the
//! variable, branches keep only what both sides agree on, and a loop forgets
//! everything it stores before its body is walked.
//!
//! Loops that provably run once (or never) are replaced here by their body
//! (or by nothing): see `loops.rs`. Their body is then walked with the state
//! before the loop, so its induction variables become constants.

use super::evaluate::{filter_emits, is_constant};
use super::local_vars::{State, root_local, stored_locals};
use super::loops::{Trip, single_trip};
use naga::{Block, Expression, Function, Handle, LocalVariable, Module, Statement};
use std::collections::BTreeSet;

/// Forwards constants in every function and entry point; returns how many
/// loads became constants and loops were resolved.
pub(super) fn forward_locals(module: &mut Module) -> usize {
    let mut changed = 0;
    let mut fns = std::mem::take(&mut module.functions);
    for (_, f) in fns.iter_mut() {
        changed += forward_in_function(module, f);
    }
    module.functions = fns;
    let mut eps = std::mem::take(&mut module.entry_points);
    for ep in eps.iter_mut() {
        changed += forward_in_function(module, &mut ep.function);
    }
    module.entry_points = eps;
    changed
}

fn forward_in_function(module: &Module, f: &mut Function) -> usize {
    let mut state = State::new();
    for (v, var) in f.local_variables.iter() {
        if let Some(init) = var.init
            && is_constant(&f.expressions[init])
        {
            state.insert(v, f.expressions[init].clone());
        }
    }
    let mut walker = Walker {
        module,
        exprs: &mut f.expressions,
        changed: 0,
    };
    let body = std::mem::take(&mut f.body);
    let body = walker.block(body, &mut state);
    let mut changed = walker.changed;
    let body = if changed > 0 {
        filter_emits(body, &f.expressions)
    } else {
        body
    };
    // Stores to locals nothing reads any more (a counter of a loop that is
    // gone, a variable every load of which became a constant) go too.
    let read: BTreeSet<Handle<LocalVariable>> = f
        .expressions
        .iter()
        .filter_map(|(_, e)| match *e {
            Expression::Load { pointer } => root_local(&f.expressions, pointer),
            _ => None,
        })
        .collect();
    let mut passed = BTreeSet::new();
    collect_passed(&f.expressions, &body, &mut passed);
    let exprs = &f.expressions;
    f.body = drop_stores(body, &mut |pointer| {
        let dead =
            root_local(exprs, pointer).is_some_and(|v| !read.contains(&v) && !passed.contains(&v));
        changed += usize::from(dead);
        dead
    });
    changed
}

/// Locals whose pointer a call receives (it may read them).
fn collect_passed(
    exprs: &naga::Arena<Expression>,
    block: &Block,
    out: &mut BTreeSet<Handle<LocalVariable>>,
) {
    for stmt in block.iter() {
        match stmt {
            Statement::Call { arguments, .. } => {
                out.extend(arguments.iter().filter_map(|a| root_local(exprs, *a)))
            }
            Statement::Block(b) => collect_passed(exprs, b, out),
            Statement::If { accept, reject, .. } => {
                collect_passed(exprs, accept, out);
                collect_passed(exprs, reject, out);
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                collect_passed(exprs, body, out);
                collect_passed(exprs, continuing, out);
            }
            Statement::Switch { cases, .. } => cases
                .iter()
                .for_each(|c| collect_passed(exprs, &c.body, out)),
            _ => {}
        }
    }
}

/// Removes the stores whose pointer `dead` accepts, recursively.
fn drop_stores(block: Block, dead: &mut dyn FnMut(Handle<Expression>) -> bool) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        if let Statement::Store { pointer, .. } = stmt
            && dead(pointer)
        {
            continue;
        }
        let stmt =
            crate::compile::specialise::map_child_blocks(stmt, &mut |b| drop_stores(b, dead));
        out.push(stmt, span);
    }
    out
}

struct Walker<'a> {
    module: &'a Module,
    exprs: &'a mut naga::Arena<Expression>,
    changed: usize,
}

impl Walker<'_> {
    fn block(&mut self, block: Block, state: &mut State) -> Block {
        let mut out = Block::with_capacity(block.len());
        for (stmt, span) in block.span_into_iter() {
            let stmt = match stmt {
                Statement::Emit(range) => {
                    for h in range.clone() {
                        if let Expression::Load { pointer } = self.exprs[h]
                            && let Expression::LocalVariable(v) = self.exprs[pointer]
                            && let Some(value) = state.get(&v)
                        {
                            self.exprs[h] = value.clone();
                            self.changed += 1;
                        }
                    }
                    Statement::Emit(range)
                }
                Statement::Store { pointer, value } => {
                    match self.exprs[pointer] {
                        Expression::LocalVariable(v) if is_constant(&self.exprs[value]) => {
                            state.insert(v, self.exprs[value].clone());
                        }
                        _ => {
                            if let Some(v) = root_local(self.exprs, pointer) {
                                state.remove(&v);
                            }
                        }
                    }
                    Statement::Store { pointer, value }
                }
                Statement::Call {
                    function,
                    arguments,
                    result,
                } => {
                    for a in &arguments {
                        if let Some(v) = root_local(self.exprs, *a) {
                            state.remove(&v);
                        }
                    }
                    Statement::Call {
                        function,
                        arguments,
                        result,
                    }
                }
                Statement::Block(b) => Statement::Block(self.block(b, state)),
                Statement::If {
                    condition,
                    accept,
                    reject,
                } => {
                    let mut a_state = state.clone();
                    let accept = self.block(accept, &mut a_state);
                    let mut r_state = state.clone();
                    let reject = self.block(reject, &mut r_state);
                    // A branch that leaves (return, break, continue) does not reach the join.
                    *state = match (ends(&accept), ends(&reject)) {
                        (true, false) => r_state,
                        (false, true) => a_state,
                        _ => meet(&a_state, &r_state),
                    };
                    Statement::If {
                        condition,
                        accept,
                        reject,
                    }
                }
                Statement::Switch { selector, cases } => {
                    let mut stored = BTreeSet::new();
                    for c in &cases {
                        stored_locals(self.exprs, &c.body, &mut stored);
                    }
                    stored.iter().for_each(|v| {
                        state.remove(v);
                    });
                    let cases = cases
                        .into_iter()
                        .map(|mut c| {
                            c.body = self.block(c.body, &mut state.clone());
                            c
                        })
                        .collect();
                    Statement::Switch { selector, cases }
                }
                Statement::Loop {
                    body,
                    continuing,
                    break_if,
                } => {
                    match single_trip(self.module, self.exprs, &body, &continuing, break_if, state)
                    {
                        Some(Trip::Never) => {
                            self.changed += 1;
                            continue;
                        }
                        Some(Trip::Once) => {
                            self.changed += 1;
                            let once = super::loops::unrolled(body, continuing);
                            Statement::Block(self.block(once, state))
                        }
                        None => {
                            let mut stored = BTreeSet::new();
                            stored_locals(self.exprs, &body, &mut stored);
                            stored_locals(self.exprs, &continuing, &mut stored);
                            stored.iter().for_each(|v| {
                                state.remove(v);
                            });
                            let body = self.block(body, &mut state.clone());
                            let continuing = self.block(continuing, &mut state.clone());
                            Statement::Loop {
                                body,
                                continuing,
                                break_if,
                            }
                        }
                    }
                }
                other => other,
            };
            out.push(stmt, span);
        }
        out
    }
}

/// What both states agree on (bit for bit: `0.0` is not `-0.0`).
fn meet(a: &State, b: &State) -> State {
    let same = |x: &Expression, y: &Expression| match (x, y) {
        (Expression::Literal(p), Expression::Literal(q)) => literal_bits(p) == literal_bits(q),
        _ => x == y,
    };
    a.iter()
        .filter(|(v, e)| b.get(*v).is_some_and(|o| same(e, o)))
        .map(|(v, e)| (*v, e.clone()))
        .collect()
}

fn literal_bits(l: &naga::Literal) -> (u8, u64) {
    use naga::Literal as L;
    match *l {
        L::F64(x) => (0, x.to_bits()),
        L::F32(x) => (1, x.to_bits() as u64),
        L::F16(x) => (2, x.to_bits() as u64),
        L::U16(x) => (10, x as u64),
        L::I16(x) => (11, x as u16 as u64),
        L::U32(x) => (3, x as u64),
        L::I32(x) => (4, x as u32 as u64),
        L::U64(x) => (5, x),
        L::I64(x) => (6, x as u64),
        L::Bool(x) => (7, x as u64),
        L::AbstractInt(x) => (8, x as u64),
        L::AbstractFloat(x) => (9, x.to_bits()),
    }
}

/// Whether a block never falls through its end.
fn ends(block: &Block) -> bool {
    match block.last() {
        Some(
            Statement::Return { .. } | Statement::Kill | Statement::Break | Statement::Continue,
        ) => true,
        Some(Statement::Block(b)) => ends(b),
        Some(Statement::If { accept, reject, .. }) => ends(accept) && ends(reject),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use crate::scene::fold::test_support::folded;

    #[test]
    fn a_local_holding_a_constant_is_read_as_the_constant() {
        let wgsl = folded(
            "
@fragment fn fs(@location(0) v: f32) -> @location(0) vec4<f32> {
    var agreed = 2;
    if v > 0.5 { agreed = 3; } else { agreed = 3; }
    var disputed = 1;
    if v > 0.5 { disputed = 4; }
    var partial = vec2<f32>(1.0, 2.0);
    partial.x = v;
    return vec4<f32>(f32(agreed), f32(disputed), partial.x + partial.y, 1.0);
}",
        );
        // Both branches store 3: the read is the constant.
        assert!(wgsl.contains("vec4<f32>(3f, f32("), "{wgsl}");
        // One branch stores 4, the other keeps 1; a component store forgets the vector.
        assert!(wgsl.contains("disputed"), "{wgsl}");
        assert!(wgsl.contains("partial"), "{wgsl}");
    }
}
