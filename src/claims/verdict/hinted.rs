//! Proofs that follow a catalogue hint: ideal membership with the paper's multipliers.
//!
//! A claim's [`Hint`] names the `let` that holds an implicit call (`M̂ = step(M, h, …)`)
//! and gives one multiplier `qⱼ` per component of `lhs − rhs`.  The prover then leaves
//! the call's value unknown: `M̂` becomes new indeterminates, `R(M, M̂, h)` are the
//! function's own equations ([`Implicit::residual`](crate::claims::implicit::Implicit)),
//! and component `j` is proved when `(lhs − rhs)ⱼ − ⟨qⱼ, R⟩` has the normal form 0.
//! That is an identity in the unknowns, so it holds at every solution of `R = 0`
//! where the multipliers are finite.  Proposition 4's proof reads this way: multiply
//! (impl spec) by `M + M̂` and by `Ω(M + M̂)`.
//!
//! A hint is only a suggestion: a wrong multiplier leaves a remainder, and the claim
//! is not proved (the other routes are not tried behind it).

use super::context::{Ctx, eval};
use crate::algebra::{AlgResult, AlgebraError, Ring, Sym};
use crate::claims::ast::{Binding, ExprKind};
use crate::claims::catalogue::{Hint, PExpr};
use crate::claims::eval::Evaluator;
use crate::claims::sampler::Point;
use crate::claims::value::Value;
use crate::linalg::Vec3;
use crate::numbers::Scalar;
use rug::Complex;

/// The `let` the hint names.
fn binding<'c>(ctx: Ctx<'c>, hint: &Hint) -> AlgResult<&'c Binding> {
    ctx.claim
        .lets
        .iter()
        .find(|b| b.name == hint.value)
        .ok_or_else(|| AlgebraError::Domain(format!("hint: no let '{}'", hint.value)))
}

/// The value of the hinted `let` at each point, in f64 (the numerical solution the
/// unknowns' shadows take, so that decisions are made at solutions).
fn values_at(ctx: Ctx<'_>, hint: &Hint, points: &[Point]) -> AlgResult<Vec<Value<f64>>> {
    let fail = |m: String| AlgebraError::Domain(format!("hint: {m}"));
    points
        .iter()
        .map(|p| {
            let mut ev = Evaluator::new(&ctx.cat.registry, 0.0f64);
            for (name, v) in &p.vars {
                ev.bind(name, v.clone());
            }
            for b in &ctx.claim.lets {
                if b.name == hint.value {
                    return ev.eval(&b.body).map_err(|e| fail(e.message));
                }
                ev.bind_let(b).map_err(|e| fail(e.message))?;
            }
            Err(fail(format!("no let '{}'", hint.value)))
        })
        .collect()
}

/// The unknown value of the hinted call: one new indeterminate per component, named
/// after the `let`, with the numerical solution at the points as its values.
pub(super) fn unknown(
    ctx: Ctx<'_>,
    ring: &Ring,
    hint: &Hint,
    points: &[Point],
) -> AlgResult<Value<Sym>> {
    let vals = values_at(ctx, hint, points)?;
    let comp = |j: usize| -> Vec<Complex> {
        vals.iter()
            .map(|v| Complex::with_val(256, v.components().get(j).copied().unwrap_or(f64::NAN)))
            .collect()
    };
    let name = |j: usize| ring.fresh_name(&format!("{}{}", hint.value, j + 1));
    Ok(match vals.first() {
        Some(Value::Real(_)) => {
            Value::Real(ring.indeterminate(&ring.fresh_name(&hint.value), &comp(0))?)
        }
        Some(Value::Vec3(_)) => {
            let c = |j: usize| ring.indeterminate(&name(j), &comp(j));
            Value::Vec3(Vec3::new(c(0)?, c(1)?, c(2)?))
        }
        other => {
            return Err(AlgebraError::Domain(format!(
                "hint: the value of '{}' is a {:?}, not a real or a vector",
                hint.value,
                other.map(|v| v.type_name())
            )));
        }
    })
}

/// The pairs `((lhs − rhs)ⱼ − ⟨qⱼ, R⟩, 0)` of a hinted proof, with `value` bound to the
/// hinted `let` in `ev`.
pub(super) fn sides(
    ctx: Ctx<'_>,
    ev: &Evaluator<'_, Sym>,
    hint: &Hint,
    value: &Value<Sym>,
    (lhs, rhs): (&PExpr, &PExpr),
) -> AlgResult<Vec<(Sym, Sym)>> {
    let fail = |m: String| AlgebraError::Domain(format!("hint: {m}"));
    let b = binding(ctx, hint)?;
    let ExprKind::Call(name, args) = &b.body.kind else {
        return Err(fail(format!("'{}' is not a call", hint.value)));
    };
    let imp = ev
        .registry()
        .ext(name)
        .and_then(|r| r.f.implicit())
        .ok_or_else(|| fail(format!("{name} is not an implicit function")))?;
    let vals: Vec<Value<Sym>> = args
        .iter()
        .map(|a| ev.eval(a).map_err(|e| fail(e.message)))
        .collect::<AlgResult<_>>()?;
    let eqs = imp
        .residual(&vals, value)
        .map_err(|m| fail(format!("{name}: {m}")))?;
    let l = eval(ev, lhs).map_err(AlgebraError::Domain)?;
    let r = eval(ev, rhs).map_err(AlgebraError::Domain)?;
    let diff = l.sub(&r).map_err(fail)?.components();
    if diff.len() != hint.multipliers.len() {
        return Err(fail(format!(
            "{} multipliers for {} components of lhs − rhs",
            hint.multipliers.len(),
            diff.len()
        )));
    }
    let zero = ev.like().zero();
    let mut pairs = Vec::with_capacity(diff.len());
    for (d, q) in diff.into_iter().zip(&hint.multipliers) {
        let q = eval(ev, q).map_err(AlgebraError::Domain)?.components();
        if q.len() != eqs.len() {
            return Err(fail(format!(
                "a multiplier with {} components for {} equations",
                q.len(),
                eqs.len()
            )));
        }
        let combo = q
            .iter()
            .zip(&eqs)
            .fold(zero.clone(), |acc, (qi, ri)| acc + qi.clone() * ri.clone());
        pairs.push((d - combo, zero.clone()));
    }
    let ring = ev.like().ring().clone();
    ring.note(format!(
        "ideal membership with the hint's multipliers: each component of lhs − rhs minus Σ qᵢ·Rᵢ is 0, where R = {} at the unknown value {} of {name}",
        imp.stated_equations(),
        hint.value
    ));
    ring.note(format!(
        "the identity holds at every solution of the equations of {name}: no solution branch is assumed"
    ));
    Ok(pairs)
}
