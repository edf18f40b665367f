//! Dropping calls whose result nothing uses, to functions without side
//! effects. naga keeps every call statement, so after folding a helper whose
//! only consumer was pruned (e.g. a UV transform for a texture that became a
//! constant) would still run; compaction then drops the helper itself.

use crate::compile::specialise::map_child_blocks;
use naga::{Block, Expression, Function, Handle, Module, Statement};
use std::collections::HashSet;

/// Removes dead pure calls until none is left. Returns the module unchanged
/// when the result would not validate (it always should).
pub(super) fn remove_dead_calls(module: &mut Module) {
    for _ in 0..8 {
        let Ok(info) = crate::compile::compose::validator().validate(module) else {
            return;
        };
        let pure = pure_functions(module);
        let mut candidate = module.clone();
        let mut removed = 0;
        for (h, f) in candidate.functions.iter_mut() {
            removed += remove_in_function(f, &info[h], &pure);
        }
        for (i, ep) in candidate.entry_points.iter_mut().enumerate() {
            removed += remove_in_function(&mut ep.function, info.get_entry_point(i), &pure);
        }
        if removed == 0 {
            return;
        }
        naga::compact::compact(&mut candidate, naga::compact::KeepUnused::No);
        if crate::compile::compose::validator()
            .validate(&candidate)
            .is_err()
        {
            return;
        }
        *module = candidate;
    }
}

fn remove_in_function(
    f: &mut Function,
    info: &naga::valid::FunctionInfo,
    pure: &HashSet<Handle<Function>>,
) -> usize {
    let mut removed = Vec::new();
    let body = std::mem::take(&mut f.body);
    f.body = filter_block(body, &mut |stmt| match stmt {
        Statement::Call {
            function, result, ..
        } if pure.contains(function) => match result {
            Some(r) if info[*r].ref_count == 0 => {
                removed.push(*r);
                false
            }
            None => true, // a pure call without a result is harmless; keep the IR simple
            _ => true,
        },
        _ => true,
    });
    for r in &removed {
        f.named_expressions.shift_remove(r);
    }
    removed.len()
}

/// Keeps the statements `keep` accepts, recursively.
fn filter_block(block: Block, keep: &mut dyn FnMut(&Statement) -> bool) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        if !keep(&stmt) {
            continue;
        }
        let stmt = map_child_blocks(stmt, &mut |b| filter_block(b, keep));
        out.push(stmt, span);
    }
    out
}

/// Functions that write nothing outside their own locals and stop nothing:
/// no stores through globals or arguments, no image stores, atomics,
/// barriers, `discard` or calls to impure functions.
pub(super) fn pure_functions(module: &Module) -> HashSet<Handle<Function>> {
    let mut pure = HashSet::new();
    // Functions only call functions declared before them.
    for (h, f) in module.functions.iter() {
        if block_is_pure(&f.body, f, &pure) {
            pure.insert(h);
        }
    }
    pure
}

fn root_is_local(f: &Function, mut h: Handle<Expression>) -> bool {
    loop {
        match f.expressions[h] {
            Expression::Access { base, .. } | Expression::AccessIndex { base, .. } => h = base,
            Expression::LocalVariable(_) => return true,
            _ => return false,
        }
    }
}

fn block_is_pure(block: &Block, f: &Function, pure: &HashSet<Handle<Function>>) -> bool {
    block.iter().all(|stmt| match stmt {
        Statement::Emit(_) | Statement::Return { .. } | Statement::Break | Statement::Continue => {
            true
        }
        Statement::Store { pointer, .. } => root_is_local(f, *pointer),
        Statement::Call { function, .. } => pure.contains(function),
        Statement::Block(b) => block_is_pure(b, f, pure),
        Statement::If { accept, reject, .. } => {
            block_is_pure(accept, f, pure) && block_is_pure(reject, f, pure)
        }
        Statement::Loop {
            body, continuing, ..
        } => block_is_pure(body, f, pure) && block_is_pure(continuing, f, pure),
        Statement::Switch { cases, .. } => cases.iter().all(|c| block_is_pure(&c.body, f, pure)),
        _ => false,
    })
}
