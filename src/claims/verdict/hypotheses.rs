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
use crate::claims::value::Value;

/// Gives the ring of `ev` the sign hypotheses the claim states.
pub(super) fn state_signs(ctx: Ctx<'_>, ev: &Evaluator<'_, Sym>) -> AlgResult<()> {
    for h in ctx.cat.hypotheses_of(ctx.claim) {
        let HypothesisKind::Sign { condition, sign } = &h.kind else {
            continue;
        };
        let ExprKind::Binary(_, a, b) = &condition.expr.kind else {
            continue;
        };
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
