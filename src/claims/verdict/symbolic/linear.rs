//! Linear changes of variables: `let` bindings that are affine in the indeterminates
//! (the coordinates a derivative is taken in) become the ring's coordinates.

use super::cases::Role;
use crate::algebra::{AlgResult, Ring, Sym};
use crate::claims::ast::{Expr, ExprKind};
use crate::claims::catalogue::PExpr;
use crate::claims::eval::Evaluator;
use crate::claims::value::Value;
use crate::claims::verdict::context::Ctx;

/// The `let` names the claim differentiates with respect to (`d(Q, x)` with `x` a
/// `let`), in the order of the lets.
pub(super) fn differentiated_lets(ctx: Ctx<'_>) -> Vec<&crate::claims::ast::Binding> {
    let mut vars: Vec<String> = Vec::new();
    let mut look = |e: &Expr| {
        e.walk(&mut |x| {
            if let ExprKind::Deriv { var, .. } = &x.kind {
                vars.push(var.clone());
            }
        })
    };
    if let crate::claims::catalogue::Body::Identity { lhs, rhs } = &ctx.claim.body {
        look(&lhs.expr);
        look(&rhs.expr);
    }
    for b in &ctx.claim.lets {
        look(&b.body);
    }
    ctx.claim
        .lets
        .iter()
        .filter(|b| b.params.is_none() && vars.contains(&b.name))
        .collect()
}

/// A derivative with respect to a `let` that is an affine function of free variables
/// (such as `x = (φ + φ̂)/2`, `y = (φ̂ − φ)/2`) holds the other such lets fixed.  When the
/// differentiated lets are as many as the free variables they involve and independent,
/// they become the new indeterminates and those variables affine functions of them.
pub(super) fn linear_change(
    ctx: Ctx<'_>,
    ev: &mut Evaluator<'_, Sym>,
    ring: &Ring,
    roles: &[(String, Role, &PExpr)],
) -> AlgResult<Option<(Vec<String>, Vec<Sym>)>> {
    let lets = differentiated_lets(ctx);
    if lets.is_empty() {
        return Ok(None);
    }
    let free: Vec<(String, Sym)> = roles
        .iter()
        .filter(|(_, r, _)| *r == Role::Free)
        .filter_map(|(n, _, _)| match ev.lookup(n) {
            Some(Value::Real(x)) if x.as_rational().is_none() => Some((n.clone(), x.clone())),
            _ => None,
        })
        .collect();
    let (lets, rows) = match affine_lets(ctx, ev, ring, &free, &lets)? {
        Some(x) => x,
        None => return Ok(None),
    };
    let involved: Vec<usize> = (0..free.len())
        .filter(|&j| rows.iter().any(|r| r.0[j] != 0))
        .collect();
    if involved.len() != rows.len() {
        return Ok(None);
    }
    let m: Vec<Vec<rug::Rational>> = rows
        .iter()
        .map(|r| involved.iter().map(|&j| r.0[j].clone()).collect())
        .collect();
    let Some(inv) = rational_inverse(&m) else {
        return Ok(None);
    };
    let mut params = Vec::new();
    for (b, (_, c0, l)) in lets.iter().zip(&rows) {
        let p = ring.indeterminate(&ring.fresh_name(&b.name), l.shadows())?;
        params.push(p.try_sub(&ring.rational(c0))?);
    }
    let mut names = Vec::new();
    for (i, &j) in involved.iter().enumerate() {
        let mut v = ring.integer(0);
        for (k, p) in params.iter().enumerate() {
            v = v.try_add(&p.try_mul(&ring.rational(&inv[i][k]))?)?;
        }
        ev.bind(&free[j].0, Value::Real(v));
        names.push(free[j].0.clone());
    }
    ring.note(format!(
        "the differentiated lets {} are new indeterminates, and {} affine functions of them",
        lets.iter()
            .map(|b| b.name.as_str())
            .collect::<Vec<_>>()
            .join(", "),
        names.join(", ")
    ));
    let originals = params
        .iter()
        .zip(&rows)
        .map(|(p, (_, c0, _))| p.try_add(&ring.rational(c0)))
        .collect::<AlgResult<Vec<_>>>()?;
    Ok(Some((names, originals)))
}

/// One affine `let`: coefficients over the free variables, constant, value.
pub(super) type AffineRow = (Vec<rug::Rational>, rug::Rational, Sym);

/// The `let` as an affine function of the free variables, if it is one.
pub(super) fn affine(
    ring: &Ring,
    free: &[(String, Sym)],
    l: &Sym,
) -> AlgResult<Option<(Vec<rug::Rational>, rug::Rational)>> {
    let mut coef = Vec::new();
    let mut rest = l.clone();
    for (_, f) in free {
        let Some(c) = l.derivative(f)?.as_rational() else {
            return Ok(None);
        };
        rest = rest.try_sub(&f.try_mul(&ring.rational(&c))?)?;
        coef.push(c);
    }
    Ok(rest.as_rational().map(|c0| (coef, c0)))
}

/// The differentiated lets with the other affine lets of the same variables, when every
/// differentiated let is affine and the variables they involve are used by the sides
/// and later lets only through these lets (so that holding the others fixed is what
/// the derivative means).
pub(super) fn affine_lets<'c>(
    ctx: Ctx<'c>,
    ev: &Evaluator<'_, Sym>,
    ring: &Ring,
    free: &[(String, Sym)],
    wanted: &[&'c crate::claims::ast::Binding],
) -> AlgResult<Option<(Vec<&'c crate::claims::ast::Binding>, Vec<AffineRow>)>> {
    let mut chosen = Vec::new();
    let mut rows: Vec<AffineRow> = Vec::new();
    for b in ctx.claim.lets.iter().filter(|b| b.params.is_none()) {
        let Ok(Value::Real(l)) = ev.eval(&b.body) else {
            continue;
        };
        match affine(ring, free, &l)? {
            Some((c, c0)) if c.iter().any(|q| *q != 0) => {
                chosen.push(b);
                rows.push((c, c0, l));
            }
            _ => {}
        }
    }
    if wanted
        .iter()
        .any(|w| !chosen.iter().any(|b| b.name == w.name))
    {
        return Ok(None);
    }
    let involved: Vec<&String> = free
        .iter()
        .enumerate()
        .filter(|(j, _)| rows.iter().any(|r| r.0[*j] != 0))
        .map(|(_, (n, _))| n)
        .collect();
    let mut direct = false;
    let mut look = |e: &Expr| {
        e.walk(&mut |x| {
            if let ExprKind::Name(n) = &x.kind {
                direct |= involved.contains(&n);
            }
        })
    };
    if let crate::claims::catalogue::Body::Identity { lhs, rhs } = &ctx.claim.body {
        look(&lhs.expr);
        look(&rhs.expr);
    }
    for b in ctx
        .claim
        .lets
        .iter()
        .filter(|b| !chosen.iter().any(|c| c.name == b.name))
    {
        look(&b.body);
    }
    Ok((!direct).then_some((chosen, rows)))
}

/// The inverse of a square rational matrix, if it is invertible.
pub(super) fn rational_inverse(m: &[Vec<rug::Rational>]) -> Option<Vec<Vec<rug::Rational>>> {
    let n = m.len();
    let mut a: Vec<Vec<rug::Rational>> = m
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let mut row = r.clone();
            row.extend((0..n).map(|j| rug::Rational::from(i32::from(i == j))));
            row
        })
        .collect();
    for col in 0..n {
        let piv = (col..n).find(|&r| a[r][col] != 0)?;
        a.swap(col, piv);
        let p = a[col][col].clone();
        for x in a[col].iter_mut() {
            *x /= &p;
        }
        for r in 0..n {
            if r != col && a[r][col] != 0 {
                let f = a[r][col].clone();
                let prow = a[col].clone();
                for (x, y) in a[r].iter_mut().zip(&prow) {
                    *x -= rug::Rational::from(&f * y);
                }
            }
        }
    }
    Some(a.into_iter().map(|r| r[n..].to_vec()).collect())
}

/// After parametrizations, the claim's free variables as functions of the remaining
/// indeterminates and the new parameters (for derivatives by the chain rule).
pub(super) fn declare_coordinates(
    ev: &Evaluator<'_, Sym>,
    ring: &Ring,
    roles: &[(String, Role, &PExpr)],
    replaced: &[String],
    new_params: Vec<Sym>,
) -> AlgResult<()> {
    let symbolic = |v: &Value<Sym>| -> Vec<Sym> {
        v.components()
            .into_iter()
            .filter(|c| c.as_rational().is_none())
            .collect()
    };
    let (mut coords, mut params, mut names) = (Vec::new(), Vec::new(), Vec::new());
    for (name, role, _) in roles {
        if *role != Role::Free {
            continue;
        }
        let Some(v) = ev.lookup(name) else { continue };
        let comps = v.components();
        for (i, c) in comps.iter().enumerate() {
            if c.as_rational().is_none() {
                names.push(if comps.len() == 1 {
                    name.clone()
                } else {
                    format!("{name}[{}]", i + 1)
                });
            }
        }
        coords.extend(symbolic(v));
        if !replaced.contains(name) {
            params.extend(symbolic(v));
        }
    }
    params.extend(new_params);
    ring.set_named_coordinates(coords, names, params)
}
