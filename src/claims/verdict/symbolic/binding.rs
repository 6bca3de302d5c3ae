//! The claim's variables bound to the prover's symbols: indeterminates, cases, sign
//! symbols and computed values, and the sides of the identity evaluated in the ring.

use super::cases::Role;
use super::linear::{declare_coordinates, linear_change};
use crate::algebra::{AlgResult, AlgebraError, AssumptionKind, Ring, Sym};
use crate::claims::ast::{Expr, ExprKind};
use crate::claims::catalogue::{Hint, PExpr};
use crate::claims::eval::Evaluator;
use crate::claims::sampler::Point;
use crate::claims::value::Value;
use crate::claims::verdict::context::{Ctx, eval};
use crate::linalg::Vec3;
use crate::numbers::Cplx;
use crate::numbers::Scalar;
use rug::Complex;

/// The shadow values of one scalar component across the points.
pub(super) fn shadows(points: &[Point], name: &str, comp: Option<usize>) -> Vec<Complex> {
    points
        .iter()
        .map(|p| {
            let x = match (p.get(name), comp) {
                (Some(Value::Real(x)), None) => *x,
                (Some(Value::Vec3(v)), Some(j)) => v.0[j],
                _ => f64::NAN,
            };
            Complex::with_val(256, x)
        })
        .collect()
}

/// The complex shadow values of a complex variable across the points.
pub(super) fn complex_shadows(points: &[Point], name: &str) -> Vec<Complex> {
    points
        .iter()
        .map(|p| match p.get(name) {
            Some(Value::Complex(z)) => Complex::with_val(256, (z.re, z.im)),
            _ => Complex::with_val(256, f64::NAN),
        })
        .collect()
}

/// An implicit call whose eliminated arguments are free variables of the claim: the
/// prover replaces them by the function's parametrization.
pub(super) struct Plan<'e> {
    name: String,
    args: &'e [Expr],
    vars: Vec<String>,
}

/// The implicit calls of the claim's own formulas that can be parametrized, in order;
/// each free variable is eliminated at most once.
pub(super) fn plans<'e>(
    ctx: Ctx<'e>,
    roles: &[(String, Role, &PExpr)],
    exprs: &[&'e Expr],
) -> Vec<Plan<'e>> {
    let free = |n: &str| roles.iter().any(|(v, r, _)| v == n && *r == Role::Free);
    let mut out: Vec<Plan<'e>> = Vec::new();
    for e in exprs {
        e.walk(&mut |x: &'e Expr| {
            let ExprKind::Call(name, args) = &x.kind else {
                return;
            };
            let Some(imp) = ctx.cat.registry.ext(name).and_then(|r| r.f.implicit()) else {
                return;
            };
            let vars: Option<Vec<String>> = imp
                .eliminates()
                .iter()
                .map(|&j| match args.get(j).map(|a| &a.kind) {
                    Some(ExprKind::Name(v)) if free(v) => Some(v.clone()),
                    _ => None,
                })
                .collect();
            let Some(vars) = vars else { return };
            let taken = out.iter().any(|p| p.vars.iter().any(|v| vars.contains(v)));
            if !taken {
                out.push(Plan {
                    name: name.clone(),
                    args,
                    vars,
                });
            }
        });
    }
    out
}

/// Binds the sampled variables as symbols in a fresh evaluator on `ring`; implicit
/// calls with free arguments are parametrized, and the equations the parametrization
/// must satisfy are returned with the evaluator.
pub(super) fn bind_variables<'c>(
    ctx: Ctx<'c>,
    ring: &Ring,
    roles: &[(String, Role, &PExpr)],
    points: &[Point],
    (plans, lemmas): (&[Plan<'c>], &[crate::claims::verdict::lemmas::Lemma<'_>]),
    hint: Option<&Hint>,
) -> AlgResult<Bound<'c>> {
    let mut ev = Evaluator::new(&ctx.cat.registry, ring.integer(0));
    let fail = |m: String| AlgebraError::Domain(m);
    for (name, role, def) in roles {
        let value = bind_one(&ev, ring, name, role, def, points)?;
        ev.bind(name, value);
    }
    let mut checks = Vec::new();
    let mut params = Vec::new();
    for plan in plans {
        let (c, p) = parametrize(ctx, &mut ev, plan)?;
        checks.extend(c);
        params.extend(p);
        recompute(&mut ev, roles)?;
    }
    let mut replaced: Vec<String> = plans.iter().flat_map(|p| p.vars.clone()).collect();
    if let Some((vars, p)) = linear_change(ctx, &mut ev, ring, roles)? {
        replaced.extend(vars);
        params.extend(p);
    }
    if !replaced.is_empty() {
        recompute(&mut ev, roles)?;
        declare_coordinates(&ev, ring, roles, &replaced, params)?;
    }
    crate::claims::verdict::lemmas::apply(&ev, lemmas)?;
    let unknown = match hint {
        Some(h) => Some(crate::claims::verdict::hinted::unknown(
            ctx, ring, h, points,
        )?),
        None => None,
    };
    // the stated sign hypotheses, in the variables as bound (a chart's, where a map is
    // parametrized), before the `let`s that may need them
    let mut stated = Vec::new();
    crate::claims::verdict::hypotheses::state_signs(ctx, &ev, &mut stated)?;
    for b in &ctx.claim.lets {
        match (hint, &unknown) {
            (Some(h), Some(v)) if h.value == b.name => ev.bind(&b.name, v.clone()),
            _ => ev
                .bind_let(b)
                .map_err(|e| fail(format!("let {}: {}", b.name, e.message)))?,
        }
        crate::claims::verdict::hypotheses::state_signs(ctx, &ev, &mut stated)?;
    }
    Ok(Bound {
        ev,
        checks,
        unknown,
    })
}

/// The claim's variables bound in the prover: the evaluator, the equations the
/// parametrizations must satisfy, and the unknown value of a hinted call.
pub(super) struct Bound<'c> {
    pub(super) ev: Evaluator<'c, Sym>,
    pub(super) checks: Vec<Sym>,
    pub(super) unknown: Option<Value<Sym>>,
}

/// Re-evaluates the computed variables after free ones were replaced.
pub(super) fn recompute(
    ev: &mut Evaluator<'_, Sym>,
    roles: &[(String, Role, &PExpr)],
) -> AlgResult<()> {
    for (name, role, def) in roles {
        if *role == Role::Computed {
            let v = eval(ev, def).map_err(AlgebraError::Domain)?;
            ev.bind(name, v);
        }
    }
    Ok(())
}

/// The symbolic value of one sampled variable.
pub(super) fn bind_one(
    ev: &Evaluator<'_, Sym>,
    ring: &Ring,
    name: &str,
    role: &Role,
    def: &PExpr,
    points: &[Point],
) -> AlgResult<Value<Sym>> {
    let fail = |m: String| AlgebraError::Domain(m);
    let first = points[0].get(name).cloned();
    Ok(match (role, first) {
        (Role::Free, Some(Value::Real(_))) => {
            Value::Real(ring.indeterminate(name, &shadows(points, name, None))?)
        }
        (Role::Free, Some(Value::Complex(_))) => {
            // an analytic identity in a complex variable holds for all complex values
            // once it holds for an indeterminate (the claim may not use re/im/conj)
            let z = ring.indeterminate(name, &complex_shadows(points, name))?;
            Value::Complex(Cplx::new(z, ring.integer(0)))
        }
        (Role::Free, Some(Value::Vec3(_))) => {
            let c = |j: usize| {
                ring.indeterminate(&format!("{name}{}", j + 1), &shadows(points, name, Some(j)))
            };
            Value::Vec3(Vec3::new(c(0)?, c(1)?, c(2)?))
        }
        (Role::Sign, Some(Value::Real(_))) => {
            Value::Real(ring.sign_symbol(name, &shadows(points, name, None))?)
        }
        (Role::Case, Some(v)) => v.map(&mut |x: &f64| {
            let q = rug::Rational::from_f64(*x).unwrap_or_default();
            ring.rational(&q)
        }),
        (Role::Computed, _) => eval(ev, def).map_err(fail)?,
        (_, other) => {
            return Err(fail(format!(
                "variable '{name}' of type {:?} cannot be a symbol",
                other.map(|v| v.type_name())
            )));
        }
    })
}

/// Replaces the free arguments of one implicit call by its parametrization, and
/// remembers the call's value at the new arguments.
pub(super) fn parametrize(
    ctx: Ctx<'_>,
    ev: &mut Evaluator<'_, Sym>,
    plan: &Plan<'_>,
) -> AlgResult<(Vec<Sym>, Vec<Sym>)> {
    let fail = |m: String| AlgebraError::Domain(format!("{}: {m}", plan.name));
    let imp = ctx
        .cat
        .registry
        .ext(&plan.name)
        .and_then(|r| r.f.implicit())
        .ok_or_else(|| fail("not an implicit function".into()))?;
    let args_now = |ev: &Evaluator<'_, Sym>| -> AlgResult<Vec<Value<Sym>>> {
        plan.args
            .iter()
            .map(|a| ev.eval(a).map_err(|e| fail(e.message)))
            .collect()
    };
    let p = imp.parametrize(&args_now(ev)?).map_err(fail)?;
    for (var, v) in plan.vars.iter().zip(p.replace) {
        ev.bind(var, v);
    }
    let args = args_now(ev)?;
    crate::claims::implicit::remember(&plan.name, &args, &p.value).map_err(fail)?;
    for (name, v) in &p.also {
        crate::claims::implicit::remember(name, &args, v).map_err(fail)?;
    }
    let ring = ev.like().ring().clone();
    ring.note(p.note);
    ring.note(format!(
        "the equations {} at the parametrization are proved to vanish together with the claim",
        imp.equations()
    ));
    ring.assume(
        AssumptionKind::Branch(plan.name.clone()),
        format!("{}: {}", plan.name, imp.branch()),
    );
    Ok((p.checks, p.params))
}

/// Both sides as pairs of scalar components (every component of lhs − rhs against 0).
/// When one side is an implicit call the parametrizations did not cover, the other side
/// is its stated value and is substituted into the function's equations instead.
pub(super) fn sides(
    ev: &Evaluator<'_, Sym>,
    lhs: &PExpr,
    rhs: &PExpr,
) -> AlgResult<Vec<(Sym, Sym)>> {
    let fail = AlgebraError::Domain;
    let zero = ev.like().zero();
    for (call, other) in [(lhs, rhs), (rhs, lhs)] {
        if let Some(comps) = stated_value(ev, call, other)? {
            return Ok(comps.into_iter().map(|c| (c, zero.clone())).collect());
        }
    }
    let l = eval(ev, lhs).map_err(fail)?;
    let r = eval(ev, rhs).map_err(fail)?;
    let d = l
        .sub(&r)
        .map_err(|m| fail(format!("lhs and rhs have different types: {m}")))?;
    Ok(d.components()
        .into_iter()
        .map(|c| (c, zero.clone()))
        .collect())
}

/// If `call` is a call of an implicit function whose value is not known, the
/// components of its equations with `other` as the value.
pub(super) fn stated_value(
    ev: &Evaluator<'_, Sym>,
    call: &PExpr,
    other: &PExpr,
) -> AlgResult<Option<Vec<Sym>>> {
    let ExprKind::Call(name, args) = &call.expr.kind else {
        return Ok(None);
    };
    let Some(imp) = ev.registry().ext(name).and_then(|r| r.f.implicit()) else {
        return Ok(None);
    };
    let fail = |m: String| AlgebraError::Domain(format!("{name}: {m}"));
    let vals: Vec<Value<Sym>> = args
        .iter()
        .map(|a| ev.eval(a).map_err(|e| fail(e.message)))
        .collect::<AlgResult<_>>()?;
    if crate::claims::implicit::recall(name, &vals).is_some() {
        return Ok(None);
    }
    let value = eval(ev, other).map_err(AlgebraError::Domain)?;
    let (comps, factor) = imp.stated_residual(&vals, &value).map_err(fail)?;
    let ring = ev.like().ring().clone();
    if let Some(d) = factor {
        // the equations were multiplied by d: they hold where d ≠ 0, decided on the domain
        if d.sign()? == 0 {
            return Err(fail("the equations' factor vanishes".into()));
        }
        ring.note(format!(
            "the equations of {name} are multiplied through by the denominator of γ, which is nonzero on the domain"
        ));
    }
    ring.note(format!(
        "the claim states the value of {name}: the other side is substituted into {}, and every component vanishes",
        imp.stated_equations()
    ));
    ring.assume(
        AssumptionKind::Branch(name.to_string()),
        format!("{name}: {}", imp.branch()),
    );
    Ok(Some(comps))
}
