//! How deeply the user's WGSL nests, located in the user's files. naga's
//! WGSL parser stops at a recursion depth of 200 without saying where: the
//! deepest bracket is found here instead. naga's writers recurse once per
//! level of an expression tree, so an expression nested deeper than
//! [`MAX_EXPRESSION_DEPTH`] (long chains like `a + b + c + …` included) is an
//! error at that expression rather than a stack overflow in a backend.

use crate::compile::source_map::Composed;
use naga::{Expression, Handle, SampleLevel};
use std::ops::Range;
use weft_front::FileId;

/// The deepest expression tree weft hands naga's backends. A `let` ends a
/// level: the backends write a named expression once and then use its name.
/// (Shipped materials nest about 10 deep.)
pub const MAX_EXPRESSION_DEPTH: usize = 64;

/// Stack size of the threads that compile: naga's writers take tens of
/// kilobytes per level of nesting in unoptimised builds, so the
/// [`MAX_EXPRESSION_DEPTH`] levels and naga's 127 nested blocks need more
/// than a thread's default 2 MiB.
pub const COMPILER_STACK_SIZE: usize = 64 << 20;

/// A thread pool for compiling: `jobs` threads (None: rayon's default) with
/// [`COMPILER_STACK_SIZE`] stacks.
pub fn compiler_pool(jobs: Option<usize>) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(jobs.unwrap_or(0))
        .stack_size(COMPILER_STACK_SIZE)
        .build()
        .expect("thread pool")
}

/// naga's WGSL parser's recursion limit (`Parser::track_recursion`).
pub const NAGA_PARSER_RECURSION_LIMIT: usize = 200;

/// The operands of an expression (what a writer recurses into).
fn operands(e: &Expression) -> Vec<Handle<Expression>> {
    use Expression as E;
    let mut out = Vec::new();
    let opt = |h: &Option<Handle<Expression>>, out: &mut Vec<_>| out.extend(*h);
    match e {
        E::Compose { components, .. } => out.extend(components.iter().copied()),
        E::Access { base, index } => out.extend([*base, *index]),
        E::AccessIndex { base, .. } => out.push(*base),
        E::Splat { value, .. } => out.push(*value),
        E::Swizzle { vector, .. } => out.push(*vector),
        E::Load { pointer } => out.push(*pointer),
        E::ImageSample {
            image,
            sampler,
            coordinate,
            array_index,
            offset,
            level,
            depth_ref,
            ..
        } => {
            out.extend([*image, *sampler, *coordinate]);
            opt(array_index, &mut out);
            opt(offset, &mut out);
            opt(depth_ref, &mut out);
            match level {
                SampleLevel::Exact(h) | SampleLevel::Bias(h) => out.push(*h),
                SampleLevel::Gradient { x, y } => out.extend([*x, *y]),
                _ => {}
            }
        }
        E::ImageLoad {
            image,
            coordinate,
            array_index,
            sample,
            level,
        } => {
            out.extend([*image, *coordinate]);
            opt(array_index, &mut out);
            opt(sample, &mut out);
            opt(level, &mut out);
        }
        E::ImageQuery { image, query } => {
            out.push(*image);
            if let naga::ImageQuery::Size { level } = query {
                opt(level, &mut out);
            }
        }
        E::Unary { expr, .. } | E::Derivative { expr, .. } | E::As { expr, .. } => out.push(*expr),
        E::Binary { left, right, .. } => out.extend([*left, *right]),
        E::Select {
            condition,
            accept,
            reject,
        } => out.extend([*condition, *accept, *reject]),
        E::Relational { argument, .. } => out.push(*argument),
        E::Math {
            arg,
            arg1,
            arg2,
            arg3,
            ..
        } => {
            out.push(*arg);
            opt(arg1, &mut out);
            opt(arg2, &mut out);
            opt(arg3, &mut out);
        }
        E::ArrayLength(h) => out.push(*h),
        _ => {}
    }
    out
}

/// The deepest expression of an arena (operands always come before their
/// users, so one forward pass suffices): its depth and handle. Expressions
/// in `named` count as one level where they are used.
fn deepest(
    arena: &naga::Arena<Expression>,
    named: impl Fn(Handle<Expression>) -> bool,
) -> Option<(usize, Handle<Expression>)> {
    let mut depth = vec![0usize; arena.len()];
    let mut worst: Option<(usize, Handle<Expression>)> = None;
    for (h, e) in arena.iter() {
        let d = 1 + operands(e)
            .into_iter()
            .map(|o| if named(o) { 1 } else { depth[o.index()] })
            .max()
            .unwrap_or(0);
        depth[h.index()] = d;
        if worst.is_none_or(|(w, _)| d > w) {
            worst = Some((d, h));
        }
    }
    worst
}

/// The first expression of the module nested deeper than
/// [`MAX_EXPRESSION_DEPTH`]: its depth and where it is in the composed text.
pub fn too_deep(module: &naga::Module) -> Option<(usize, naga::Span)> {
    let functions = module
        .functions
        .iter()
        .map(|(_, f)| f)
        .chain(module.entry_points.iter().map(|ep| &ep.function));
    let mut found = deepest(&module.global_expressions, |_| false)
        .map(|(d, h)| (d, module.global_expressions.get_span(h)));
    for f in functions {
        let candidate = deepest(&f.expressions, |h| f.named_expressions.contains_key(&h))
            .map(|(d, h)| (d, f.expressions.get_span(h)));
        if let Some((d, _)) = candidate
            && found.is_none_or(|(w, _)| d > w)
        {
            found = candidate;
        }
    }
    found.filter(|(d, _)| *d > MAX_EXPRESSION_DEPTH)
}

/// The most deeply nested bracket of the composed text outside comments:
/// where naga's parser most likely ran out of recursion. Mapped to the user's file.
pub fn deepest_bracket(composed: &Composed) -> Option<(FileId, Range<usize>, usize)> {
    let bytes = composed.text.as_bytes();
    let (mut depth, mut best, mut at) = (0usize, 0usize, None);
    let mut i = 0;
    let mut block_comment = 0usize;
    while i < bytes.len() {
        let (c, next) = (bytes[i], bytes.get(i + 1).copied());
        if block_comment > 0 {
            match (c, next) {
                (b'*', Some(b'/')) => {
                    block_comment -= 1;
                    i += 1;
                }
                (b'/', Some(b'*')) => {
                    block_comment += 1;
                    i += 1;
                }
                _ => {}
            }
        } else {
            match (c, next) {
                (b'/', Some(b'/')) => {
                    while i < bytes.len() && bytes[i] != b'\n' {
                        i += 1;
                    }
                }
                (b'/', Some(b'*')) => {
                    block_comment = 1;
                    i += 1;
                }
                (b'(' | b'[' | b'{', _) => {
                    depth += 1;
                    if depth > best {
                        best = depth;
                        at = Some(i);
                    }
                }
                (b')' | b']' | b'}', _) => depth = depth.saturating_sub(1),
                _ => {}
            }
        }
        i += 1;
    }
    let (file, range) = composed.map.map(at?..at? + 1)?;
    Some((file, range, best))
}
