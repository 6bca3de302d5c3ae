//! What a symbolic proof does not attempt: claims that state a condition, formulas
//! that are not analytic in the variables, and deep self-iteration.

use crate::claims::ast::{Expr, ExprKind};
use crate::claims::catalogue::PExpr;
use crate::claims::verdict::context::Ctx;

/// Why the claim's own formulas state a condition rather than an identity, if they do.
pub(super) fn states_condition(ctx: Ctx<'_>, sides: &[&PExpr]) -> Option<String> {
    let mut found: Option<String> = None;
    let mut look = |e: &Expr| {
        e.walk(&mut |x| {
            let what = match &x.kind {
                ExprKind::If(_, a, b) if is_literal(a) || is_literal(b) => Some("if".to_string()),
                ExprKind::Call(n, _) if ["min", "max", "floor"].contains(&n.as_str()) => {
                    Some(n.clone())
                }
                _ => None,
            };
            if found.is_none() {
                found = what;
            }
        })
    };
    for s in sides {
        look(&s.expr);
    }
    for b in &ctx.claim.lets {
        look(&b.body);
    }
    found.map(|w| {
        format!("the claim's own formulas use '{w}': it states a condition, which a normal form does not prove")
    })
}

/// Why the claim is not an analytic function of its complex variables, if it is not
/// (then an indeterminate does not stand for every complex value).
pub(super) fn not_analytic(
    ctx: Ctx<'_>,
    vars: &[(String, &PExpr)],
    sides: &[&PExpr],
) -> Option<String> {
    if !vars.iter().any(|(_, p)| p.text.contains("cplx(")) {
        return None;
    }
    let mut found = None;
    let mut look = |e: &Expr| {
        e.walk(&mut |x| {
            if let ExprKind::Call(n, _) = &x.kind
                && ["re", "im", "conj", "arg"].contains(&n.as_str())
                && found.is_none()
            {
                found = Some(n.clone());
            }
        })
    };
    for s in sides {
        look(&s.expr);
    }
    for b in &ctx.claim.lets {
        look(&b.body);
    }
    found.map(|n| format!("'{n}' of a complex variable is not analytic: an indeterminate does not stand for every complex value"))
}

/// Nested applications of one catalogue function to its own result, this deep or
/// deeper, are an iteration (such as Newton's method written out).
pub(super) const ITERATION_DEPTH: usize = 3;

/// Why no proof is attempted when the claim evaluates an iteration: a catalogue
/// function applied to its own result [`ITERATION_DEPTH`] times, in the claim's
/// formulas or in a catalogue function they call.  Its exact value is a rational
/// function whose size multiplies with every step, far beyond the prover's bound.
pub(super) fn iteration(ctx: Ctx<'_>, sides: &[&PExpr]) -> Option<String> {
    let reg = &ctx.cat.registry;
    let mut seen = std::collections::BTreeSet::new();
    let mut stack: Vec<(&Expr, Option<&str>)> = sides.iter().map(|s| (&s.expr, None)).collect();
    stack.extend(ctx.claim.lets.iter().map(|b| (&b.body, None)));
    while let Some((e, inside)) = stack.pop() {
        let mut found = None;
        e.walk(&mut |x| {
            let ExprKind::Call(name, _) = &x.kind else {
                return;
            };
            if found.is_none() && self_nesting(x, name) >= ITERATION_DEPTH {
                found = Some(name.clone());
            }
            if let Some(f) = reg.user(name)
                && seen.insert(name.clone())
            {
                stack.push((&f.def.body, Some(name.as_str())));
            }
        });
        if let Some(n) = found {
            let place = inside.map_or(String::new(), |f| format!(" in the catalogue function {f}"));
            return Some(format!(
                "the claim evaluates an iteration ({n} applied to its own result{place}): its exact value grows with every step beyond the prover's bound, so no proof is attempted"
            ));
        }
    }
    None
}

/// How many times `name` is applied in a chain `name(name(…))` starting at `e`
/// (through the first argument).
pub(super) fn self_nesting(e: &Expr, name: &str) -> usize {
    match &e.kind {
        ExprKind::Call(n, args) if n == name => {
            1 + args.first().map_or(0, |a| self_nesting(a, name))
        }
        _ => 0,
    }
}

/// A numeric literal, possibly negated: the branch of an indicator `if c then 1 else 0`.
pub(super) fn is_literal(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Num(_) => true,
        ExprKind::Unary(_, x) => is_literal(x),
        _ => false,
    }
}

/// Why no proof is attempted when the claim's formulas evaluate `pi` whatever the
/// point: π is not algebraic, so the attempt would fail when it reaches it, after all
/// the work before it.  Occurrences in an `if` branch, a `sum` body or a derivative may
/// never be evaluated and are not counted; neither is a `pi` the claim binds itself.
pub(super) fn evaluates_pi(ctx: Ctx<'_>, sides: &[&PExpr]) -> Option<String> {
    let claim = ctx.claim;
    let bound = claim.vars.iter().any(|(n, _)| n == "pi")
        || claim.lets.iter().any(|b| {
            b.name == "pi"
                || b.params
                    .as_ref()
                    .is_some_and(|p| p.iter().any(|n| n == "pi"))
        });
    if bound {
        return None;
    }
    let forced = sides.iter().any(|s| forces_pi(&s.expr))
        || claim
            .lets
            .iter()
            .any(|b| b.params.is_none() && forces_pi(&b.body));
    forced.then(|| "pi is not algebraic: the symbolic prover cannot expand it".to_string())
}

/// Whether evaluating `e` evaluates the constant `pi` at every point.
fn forces_pi(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Name(n) => n == "pi",
        ExprKind::Num(_) | ExprKind::Deriv { .. } | ExprKind::Grad { .. } => false,
        ExprKind::Call(_, a) | ExprKind::List(a) => a.iter().any(forces_pi),
        ExprKind::Unary(_, a) => forces_pi(a),
        ExprKind::Binary(_, a, b) => forces_pi(a) || forces_pi(b),
        ExprKind::If(c, _, _) => forces_pi(c),
        ExprKind::Index(a, ix) => forces_pi(a) || ix.iter().any(forces_pi),
        ExprKind::Sum { from, to, .. } => forces_pi(from) || forces_pi(to),
    }
}
