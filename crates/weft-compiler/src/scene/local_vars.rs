//! Function-local variables as the scene folder tracks them: which constant
//! each holds (`State`, kept by `locals.rs` and read by `loops.rs` when it
//! interprets a loop's first iteration) and which a block may write.

use naga::{Block, Expression, Handle, LocalVariable, Statement};
use std::collections::{BTreeSet, HashMap};

/// Local variable -> the constant it holds (a literal, constant or zero value).
pub(super) type State = HashMap<Handle<LocalVariable>, Expression>;

/// The local variable a pointer expression points into, if any.
pub(super) fn root_local(
    exprs: &naga::Arena<Expression>,
    mut h: Handle<Expression>,
) -> Option<Handle<LocalVariable>> {
    loop {
        match exprs[h] {
            Expression::Access { base, .. } | Expression::AccessIndex { base, .. } => h = base,
            Expression::LocalVariable(v) => return Some(v),
            _ => return None,
        }
    }
}

/// Every local a block may write: stored to (whole or in part) or passed to a call.
pub(super) fn stored_locals(
    exprs: &naga::Arena<Expression>,
    block: &Block,
    out: &mut BTreeSet<Handle<LocalVariable>>,
) {
    for stmt in block.iter() {
        match stmt {
            Statement::Store { pointer, .. } => out.extend(root_local(exprs, *pointer)),
            Statement::Call { arguments, .. } => {
                out.extend(arguments.iter().filter_map(|a| root_local(exprs, *a)))
            }
            Statement::Block(b) => stored_locals(exprs, b, out),
            Statement::If { accept, reject, .. } => {
                stored_locals(exprs, accept, out);
                stored_locals(exprs, reject, out);
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                stored_locals(exprs, body, out);
                stored_locals(exprs, continuing, out);
            }
            Statement::Switch { cases, .. } => cases
                .iter()
                .for_each(|c| stored_locals(exprs, &c.body, out)),
            _ => {}
        }
    }
}
