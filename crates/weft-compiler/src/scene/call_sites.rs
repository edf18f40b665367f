//! Constants across function calls: per-call-site specialisation of helpers.
//!
//! naga keeps calls opaque, so a scene constant passed to a helper (a
//! thread's offset list, a roughness) stayed a run-time argument inside it.
//! A call with constant arguments now calls a clone of the helper in which
//! those parameters are replaced by the constants (and dropped from its
//! signature); the folder's next round evaluates, prunes and unrolls inside
//! the clone as in an entry point. Clones are shared by every call with the
//! same helper and the same constant values (`Memo`, kept across rounds, by
//! name: handles change when functions are reordered). A pure helper whose
//! every path returns one constant is then no call at all: the call goes and
//! its result becomes the constant.
//!
//! The driver (`ACO`/NIR on AMD, every other GPU compiler too) inlines each
//! call and folds literals itself; what this buys on the GPU is what the
//! driver cannot do after inlining: loops it will not unroll (`loops.rs`) and
//! identities it does not know (`identities.rs`) see the constants. For the
//! other languages the helpers also come out simpler.

use super::dead_calls::pure_functions;
use super::evaluate::{const_key, is_constant};
use crate::compile::specialise::map_child_blocks;
use naga::{Arena, Block, Expression, Function, Handle, Module, Span, Statement};
use std::collections::{BTreeMap, HashMap, HashSet};

/// (helper name, [(parameter index, constant value key)]) -> the clone's name.
pub(super) type Memo = BTreeMap<(String, Vec<(u32, String)>), String>;

/// Points every call with constant arguments at a clone of its callee bound
/// to them. Returns how many calls were redirected.
pub(super) fn specialise_calls(module: &mut Module, memo: &mut Memo) -> usize {
    let mut fns = std::mem::take(&mut module.functions);
    let mut redirected = 0;
    let callers: Vec<Handle<Function>> = fns.iter().map(|(h, _)| h).collect();
    for h in callers {
        let mut f = std::mem::take(&mut fns[h]);
        redirected += specialise_in(module, &mut fns, &mut f, memo);
        fns[h] = f;
    }
    let mut eps = std::mem::take(&mut module.entry_points);
    for ep in eps.iter_mut() {
        redirected += specialise_in(module, &mut fns, &mut ep.function, memo);
    }
    module.entry_points = eps;
    module.functions = fns;
    if redirected > 0 {
        reorder_functions(module);
    }
    redirected
}

fn specialise_in(
    module: &Module,
    fns: &mut Arena<Function>,
    f: &mut Function,
    memo: &mut Memo,
) -> usize {
    let mut redirected = 0;
    let body = std::mem::take(&mut f.body);
    f.body = rewrite_calls(body, &mut |stmt| {
        let Statement::Call {
            function,
            arguments,
            result,
        } = stmt
        else {
            return;
        };
        let bound: BTreeMap<u32, (String, Expression)> = arguments
            .iter()
            .enumerate()
            .filter_map(|(i, a)| {
                let e = &f.expressions[*a];
                Some((i as u32, (const_key(module, e)?, e.clone())))
            })
            .collect();
        let Some(callee_name) = fns[*function].name.clone() else {
            return;
        };
        if bound.is_empty() {
            return;
        }
        let key = (
            callee_name.clone(),
            bound.iter().map(|(i, (k, _))| (*i, k.clone())).collect(),
        );
        let existing = memo
            .get(&key)
            .and_then(|name| fns.iter().find(|(_, g)| g.name.as_ref() == Some(name)))
            .map(|(h, _)| h);
        let clone = match existing {
            Some(h) => h,
            None => {
                let name = memo
                    .get(&key)
                    .cloned()
                    .unwrap_or_else(|| clone_name(fns, &callee_name, memo.len()));
                memo.insert(key, name.clone());
                let values = bound.iter().map(|(i, (_, e))| (*i, e.clone())).collect();
                let mut g = bind(fns[*function].clone(), &values);
                g.name = Some(name);
                fns.append(g, Span::UNDEFINED)
            }
        };
        *function = clone;
        let kept = std::mem::take(arguments)
            .into_iter()
            .enumerate()
            .filter(|(i, _)| !bound.contains_key(&(*i as u32)))
            .map(|(_, a)| a);
        arguments.extend(kept);
        if let Some(r) = result {
            f.expressions[*r] = Expression::CallResult(clone);
        }
        redirected += 1;
    });
    redirected
}

/// `<helper>_k<n>`, `<helper>` without an earlier clone's suffix, `n` the first free number.
fn clone_name(fns: &Arena<Function>, callee: &str, mut n: usize) -> String {
    let base = match callee.rsplit_once("_k") {
        Some((b, digits)) if !digits.is_empty() && digits.bytes().all(|c| c.is_ascii_digit()) => b,
        _ => callee,
    };
    loop {
        n += 1;
        let name = format!("{base}_k{n}");
        if !fns.iter().any(|(_, g)| g.name.as_deref() == Some(&name)) {
            return name;
        }
    }
}

/// `f` with parameter `i` replaced by `values[i]` and removed from its signature.
fn bind(mut f: Function, values: &BTreeMap<u32, Expression>) -> Function {
    let mut next = 0;
    let renumber: Vec<Option<u32>> = (0..f.arguments.len() as u32)
        .map(|i| {
            (!values.contains_key(&i)).then(|| {
                next += 1;
                next - 1
            })
        })
        .collect();
    for (_, e) in f.expressions.iter_mut() {
        if let Expression::FunctionArgument(i) = *e {
            *e = match renumber[i as usize] {
                Some(j) => Expression::FunctionArgument(j),
                None => values[&i].clone(),
            };
        }
    }
    f.arguments = std::mem::take(&mut f.arguments)
        .into_iter()
        .enumerate()
        .filter(|(i, _)| renumber[*i].is_some())
        .map(|(_, a)| a)
        .collect();
    f
}

/// Calls to pure functions whose only `return` (their last statement)
/// returns a constant: the call goes, its result becomes the constant.
pub(super) fn fold_constant_returns(module: &mut Module) -> usize {
    let pure = pure_functions(module);
    let returns: HashMap<Handle<Function>, Expression> = module
        .functions
        .iter()
        .filter(|(h, _)| pure.contains(h))
        .filter_map(|(h, f)| Some((h, constant_return(f)?)))
        .collect();
    if returns.is_empty() {
        return 0;
    }
    let mut folded = 0;
    let mut fold_in = |f: &mut Function| {
        let mut values = Vec::new();
        let body = std::mem::take(&mut f.body);
        f.body = filter_block(body, &mut |stmt| match stmt {
            Statement::Call {
                function,
                result: Some(r),
                ..
            } if returns.contains_key(function) => {
                values.push((*r, returns[function].clone()));
                false
            }
            _ => true,
        });
        folded += values.len();
        for (r, value) in values {
            f.expressions[r] = value;
        }
    };
    for (_, f) in module.functions.iter_mut() {
        fold_in(f);
    }
    for ep in module.entry_points.iter_mut() {
        fold_in(&mut ep.function);
    }
    folded
}

fn constant_return(f: &Function) -> Option<Expression> {
    let Some(Statement::Return { value: Some(v) }) = f.body.last() else {
        return None;
    };
    let value = &f.expressions[*v];
    (is_constant(value) && count_returns(&f.body) == 1).then(|| value.clone())
}

fn count_returns(block: &Block) -> usize {
    block
        .iter()
        .map(|s| match s {
            Statement::Return { .. } => 1,
            Statement::Block(b) => count_returns(b),
            Statement::If { accept, reject, .. } => count_returns(accept) + count_returns(reject),
            Statement::Loop {
                body, continuing, ..
            } => count_returns(body) + count_returns(continuing),
            Statement::Switch { cases, .. } => cases.iter().map(|c| count_returns(&c.body)).sum(),
            _ => 0,
        })
        .sum()
}

/// Keeps the statements `keep` accepts, recursively.
fn filter_block(block: Block, keep: &mut dyn FnMut(&Statement) -> bool) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        if !keep(&stmt) {
            continue;
        }
        out.push(map_child_blocks(stmt, &mut |b| filter_block(b, keep)), span);
    }
    out
}

/// Applies `edit` to every call statement, recursively.
fn rewrite_calls(block: Block, edit: &mut dyn FnMut(&mut Statement)) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (mut stmt, span) in block.span_into_iter() {
        if matches!(stmt, Statement::Call { .. }) {
            edit(&mut stmt);
        }
        out.push(
            map_child_blocks(stmt, &mut |b| rewrite_calls(b, edit)),
            span,
        );
    }
    out
}

/// Orders the functions so that each comes after every function it calls
/// (naga's rule), depth first in the present order: clones are appended
/// after their callers and move up before them.
pub(super) fn reorder_functions(module: &mut Module) {
    fn visit(
        h: Handle<Function>,
        fns: &Arena<Function>,
        seen: &mut HashSet<Handle<Function>>,
        order: &mut Vec<Handle<Function>>,
    ) {
        if !seen.insert(h) {
            return;
        }
        for c in callees(&fns[h].body) {
            visit(c, fns, seen, order);
        }
        order.push(h);
    }
    let handles: Vec<Handle<Function>> = module.functions.iter().map(|(h, _)| h).collect();
    let mut order = Vec::with_capacity(handles.len());
    let mut seen = HashSet::new();
    for &h in &handles {
        visit(h, &module.functions, &mut seen, &mut order);
    }
    if order == handles {
        return;
    }
    let mut slots: Vec<Option<(Function, Span)>> = std::mem::take(&mut module.functions)
        .drain()
        .map(|(_, f, span)| Some((f, span)))
        .collect();
    let mut functions = Arena::new();
    let mut map = HashMap::new();
    for h in order {
        let (f, span) = slots[h.index()].take().expect("each function once");
        map.insert(h, functions.append(f, span));
    }
    for (_, f) in functions.iter_mut() {
        remap_calls(f, &map);
    }
    for ep in module.entry_points.iter_mut() {
        remap_calls(&mut ep.function, &map);
    }
    module.functions = functions;
}

fn callees(block: &Block) -> Vec<Handle<Function>> {
    let mut out = Vec::new();
    for s in block.iter() {
        match s {
            Statement::Call { function, .. } => out.push(*function),
            Statement::Block(b) => out.extend(callees(b)),
            Statement::If { accept, reject, .. } => {
                out.extend(callees(accept));
                out.extend(callees(reject));
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                out.extend(callees(body));
                out.extend(callees(continuing));
            }
            Statement::Switch { cases, .. } => {
                cases.iter().for_each(|c| out.extend(callees(&c.body)))
            }
            _ => {}
        }
    }
    out
}

fn remap_calls(f: &mut Function, map: &HashMap<Handle<Function>, Handle<Function>>) {
    for (_, e) in f.expressions.iter_mut() {
        if let Expression::CallResult(c) = e {
            *c = map[c];
        }
    }
    let body = std::mem::take(&mut f.body);
    f.body = rewrite_calls(body, &mut |stmt| {
        if let Statement::Call { function, .. } = stmt {
            *function = map[function];
        }
    });
}

#[cfg(test)]
mod tests {
    use crate::scene::fold::test_support::folded;

    #[test]
    fn a_constant_argument_reaches_inside_the_helper() {
        let wgsl = folded(
            "
fn pick(k: i32) -> f32 { return select(1.0, 2.0, k > 1); }
fn scale(x: f32, k: f32) -> f32 { return x * k; }
@fragment fn fs(@location(0) v: f32) -> @location(0) vec4<f32> {
    return vec4<f32>(scale(v, pick(3)), scale(v + 1.0, pick(3)), scale(v, 3.0), 1.0);
}",
        );
        // pick(3) returns a constant: no call, no function left.
        assert!(!wgsl.contains("pick"), "{wgsl}");
        // One clone per distinct constant, shared by the calls that pass it;
        // the generic helper is gone with its last call.
        assert_eq!(wgsl.matches("fn scale").count(), 2, "{wgsl}");
        assert_eq!(wgsl.matches(" * 2f);").count(), 1, "{wgsl}");
        assert_eq!(wgsl.matches(" * 3f);").count(), 1, "{wgsl}");
        assert_eq!(wgsl.matches("scale_k").count(), 5, "{wgsl}");
    }

    #[test]
    fn a_helper_with_side_effects_keeps_its_call() {
        let wgsl = folded(
            "
var<private> counter: f32;
fn bump(k: f32) -> f32 { counter += k; return 1.0; }
@fragment fn fs() -> @location(0) vec4<f32> {
    let one = bump(2.0);
    return vec4<f32>(one, counter, 0.0, 1.0);
}",
        );
        assert!(wgsl.contains("counter = (_e"), "{wgsl}");
        assert!(wgsl.contains("bump"), "{wgsl}");
    }
}
