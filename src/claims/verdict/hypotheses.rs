//! The hypotheses a claim states (`hypotheses = ["NAME", …]`, each a
//! `[hypothesis.NAME]` table that quotes the paper), as a proof uses them.
//!
//! A proof may rest on a stated hypothesis, never on one it invents:
//! - a **sign** hypothesis (`when = "a > b"`) is given to the ring, which decides by it
//!   the sign of any value that is `a − b` times a factor of proved sign;
//! - a **branch** hypothesis (`branch = "step_gamma1"`) covers the solution branch of an
//!   implicit map that the proof's parametrization of the map takes.  A proof that
//!   takes a branch the claim does not state is not a proof.

use super::context::Ctx;
use super::proof_info::HypothesisUse;
use crate::algebra::{AlgResult, AlgebraError, Assumption, AssumptionKind, Sym};
use crate::claims::ast::ExprKind;
use crate::claims::catalogue::claim::HypothesisKind;
use crate::claims::eval::Evaluator;
use crate::claims::sampler::Stream;
use crate::claims::value::Value;

/// Gives the ring of `ev` the sign hypotheses the claim states that are not in
/// `stated` yet and whose condition names no `let` of the claim still unbound (a
/// condition on `Mh` is stated once the `let` of `Mh` is bound); adds their names to
/// `stated`.
pub(crate) fn state_signs(
    ctx: Ctx<'_>,
    ev: &Evaluator<'_, Sym>,
    stated: &mut Vec<String>,
) -> AlgResult<()> {
    for h in ctx.cat.hypotheses_of(ctx.claim) {
        let HypothesisKind::Sign { condition, sign } = &h.kind else {
            continue;
        };
        let ExprKind::Binary(_, a, b) = &condition.expr.kind else {
            continue;
        };
        if stated.contains(&h.name) || names_unbound_let(ctx, ev, &condition.expr) {
            continue;
        }
        stated.push(h.name.clone());
        let side = |e: &crate::claims::ast::Expr| -> AlgResult<Sym> {
            match ev.eval(e) {
                Ok(Value::Real(x)) => Ok(x),
                Ok(_) => Err(AlgebraError::Domain(format!(
                    "hypothesis {}: a side of '{}' is not a real number",
                    h.name, condition.text
                ))),
                Err(e) => Err(AlgebraError::Domain(format!(
                    "hypothesis {}: {}",
                    h.name, e.message
                ))),
            }
        };
        let value = side(a)?.try_sub(&side(b)?)?;
        ev.like()
            .ring()
            .state_hypothesis(&value, *sign, format!("hypothesis.{}", h.name));
    }
    Ok(())
}

/// Checks the claim's sign hypotheses at its sample points (the sampling stream of its
/// numerical verdict, at 128 bits): `Err` names the first that fails and at how many
/// of the points.  A proof resting on a hypothesis that fails on the claim's domain
/// would prove nothing there, so such a claim is not proved.
///
/// A condition that cannot be evaluated at a point counts as failing there.
pub(super) fn check_at_samples(ctx: Ctx<'_>) -> Result<(), String> {
    let signs: Vec<_> = (ctx.cat.hypotheses_of(ctx.claim).into_iter())
        .filter_map(|h| match &h.kind {
            HypothesisKind::Sign { condition, .. } => Some((h.name.clone(), condition)),
            HypothesisKind::Branch(_) => None,
        })
        .collect();
    if signs.is_empty() {
        return Ok(());
    }
    let mut sampler = ctx.sampler(Stream::Samples).map_err(|c| c.to_string())?;
    let n = ctx.claim.samples.max(1);
    let mut failed = vec![0usize; signs.len()];
    for _ in 0..n {
        let p = sampler.draw()?;
        let ev = ctx.setup(&p, rug::Float::with_val(128, 0));
        for (i, (_, condition)) in signs.iter().enumerate() {
            let holds = match &ev {
                Ok(ev) => matches!(ev.eval(&condition.expr), Ok(Value::Bool(true))),
                Err(_) => false,
            };
            failed[i] += usize::from(!holds);
        }
    }
    match (failed.iter().zip(&signs)).find(|(k, _)| **k > 0) {
        Some((k, (name, condition))) => Err(format!(
            "hypothesis {name} ('{}') fails at {k} of {n} domain points",
            condition.text
        )),
        None => Ok(()),
    }
}

/// Whether `e` names a `let` of the claim that `ev` has not bound yet.
fn names_unbound_let(ctx: Ctx<'_>, ev: &Evaluator<'_, Sym>, e: &crate::claims::ast::Expr) -> bool {
    let mut unbound = false;
    e.walk(&mut |x| {
        if let ExprKind::Name(n) = &x.kind {
            unbound |= ev.lookup(n).is_none() && ctx.claim.lets.iter().any(|b| b.name == *n);
        }
    });
    unbound
}

/// The facts a proof rests on, as reported; `Err` with the reason when one of them is
/// a solution branch the claim does not state.
pub(super) fn uses(ctx: Ctx<'_>, assumptions: &[Assumption]) -> Result<Vec<HypothesisUse>, String> {
    let stated = ctx.cat.hypotheses_of(ctx.claim);
    let mut out = Vec::new();
    for a in assumptions {
        let u = match &a.kind {
            AssumptionKind::Lemma(id) => HypothesisUse {
                kind: "lemma",
                statement: a.statement.clone(),
                source: id.clone(),
            },
            AssumptionKind::Hypothesis(label) => {
                let name = label.trim_start_matches("hypothesis.");
                let statement = (stated.iter())
                    .find(|h| h.name == name)
                    .map_or_else(|| a.statement.clone(), |h| h.statement.clone());
                HypothesisUse {
                    kind: "sign",
                    statement,
                    source: label.clone(),
                }
            }
            AssumptionKind::Branch(map) => {
                let Some(h) = (stated.iter())
                    .find(|h| matches!(&h.kind, HypothesisKind::Branch(m) if m == map))
                else {
                    return Err(format!(
                        "the proof takes the solution branch of {map} ({}), which the claim does not state as a hypothesis",
                        a.statement
                    ));
                };
                HypothesisUse {
                    kind: "branch",
                    statement: h.statement.clone(),
                    source: format!("hypothesis.{}", h.name),
                }
            }
        };
        if !out.contains(&u) {
            out.push(u);
        }
    }
    Ok(out)
}
