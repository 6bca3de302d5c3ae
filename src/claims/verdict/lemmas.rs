//! Lemmas: a proved identity that states the value of an implicit call supplies that
//! value to the proofs of the claims that use it.
//!
//! An identity `f(args) = rhs` whose left side calls an implicit function `f` (a step of
//! a map) and which a claim lists in `uses` is a *lemma* of that claim when it expects
//! `proved`, samples the same domain, adds no variables the claim does not sample with
//! the same definition, and has no `let`s of its own.  Its variables are then the
//! claim's variables, so at every point of the claim's domain it states
//! `f(args) = rhs`.  The prover evaluates `args` and `rhs` at the claim's symbols and
//! remembers `rhs` as the value of the call (where `rhs` calls a phase step, the step's
//! parametrization is planned as for the claim's own calls).  A proof that uses a lemma
//! is accepted only when the lemma itself is proved symbolically: [`check`] proves it
//! (once per catalogue) and the claim is not proved otherwise.

use super::context::{Ctx, eval};
use crate::algebra::{AlgResult, AlgebraError, Sym};
use crate::claims::ast::{Expr, ExprKind};
use crate::claims::catalogue::{Body, Claim, PExpr};
use crate::claims::eval::Evaluator;
use crate::claims::implicit::{recall, remember};
use crate::claims::kind::Verdict;
use crate::claims::verdict::ProofInfo;

/// A lemma of a claim: `name(args) = rhs`.
pub(super) struct Lemma<'c> {
    /// The lemma's claim.
    pub claim: &'c Claim,
    /// The implicit function.
    pub name: &'c str,
    /// Its arguments as written in the lemma.
    pub args: &'c [Expr],
    /// The value the lemma states.
    pub rhs: &'c PExpr,
}

/// The lemmas of the claim, in the order of its `uses`.
pub(super) fn lemmas<'c>(ctx: Ctx<'c>) -> Vec<Lemma<'c>> {
    let claim = ctx.claim;
    let domain = |c: &Claim| c.domain.as_ref().map(|d| d.value.clone());
    let sampled_alike = |c: &Claim| {
        c.vars.iter().all(|(n, p)| {
            claim
                .vars
                .iter()
                .any(|(m, q)| m == n && q.text.trim() == p.text.trim())
        })
    };
    claim
        .uses
        .iter()
        .filter_map(|u| ctx.cat.claims.iter().find(|c| c.id == u.value))
        .filter(|c| c.expect == Some(Verdict::Proved) && c.lets.is_empty())
        .filter(|c| domain(c) == domain(claim) && c.wheres.is_empty() && sampled_alike(c))
        .filter_map(|c| {
            let Body::Identity { lhs, rhs } = &c.body else {
                return None;
            };
            let ExprKind::Call(name, args) = &lhs.expr.kind else {
                return None;
            };
            ctx.cat.registry.ext(name)?.f.implicit()?;
            calls(claim, name).then_some(())?;
            Some(Lemma {
                claim: c,
                name,
                args,
                rhs,
            })
        })
        .collect()
}

/// Remembers the value each lemma states, at the claim's symbols.
pub(super) fn apply(ev: &Evaluator<'_, Sym>, lemmas: &[Lemma<'_>]) -> AlgResult<()> {
    for l in lemmas {
        let fail = |m: String| AlgebraError::Domain(format!("lemma {}: {m}", l.claim.id));
        let args = l
            .args
            .iter()
            .map(|a| ev.eval(a).map_err(|e| fail(e.message)))
            .collect::<AlgResult<Vec<_>>>()?;
        if recall(l.name, &args).is_some() {
            continue;
        }
        let value = eval(ev, l.rhs).map_err(fail)?;
        remember(l.name, &args, &value).map_err(fail)?;
        let ring = ev.like().ring().clone();
        ring.assume(
            crate::algebra::AssumptionKind::Lemma(l.claim.id.clone()),
            format!(
                "{}(…) = {}: by {}, proved separately (under its own hypotheses)",
                l.name,
                l.rhs.text.trim(),
                l.claim.id
            ),
        );
    }
    Ok(())
}

/// The prover of identities, passed in by its module (which uses this one).
pub(super) type Prover = fn(Ctx<'_>, &PExpr, &PExpr, bool) -> ProofInfo;

/// Checks that every lemma is proved symbolically by `prove` (memoised per catalogue).
pub(super) fn check(ctx: Ctx<'_>, lemmas: &[Lemma<'_>], prove: Prover) -> Result<(), String> {
    for l in lemmas {
        let Body::Identity { lhs, rhs } = &l.claim.body else {
            continue;
        };
        let sub = Ctx {
            cat: ctx.cat,
            claim: l.claim,
        };
        let p = proof_of(sub, lhs, rhs, prove);
        if !p.is_proved() {
            return Err(format!(
                "rests on {}, which is not proved: {}",
                l.claim.id,
                p.reason.clone().unwrap_or_default()
            ));
        }
    }
    Ok(())
}

/// The symbolic proof of an identity that serves as a lemma, memoised per catalogue.
pub(super) fn proof_of(ctx: Ctx<'_>, lhs: &PExpr, rhs: &PExpr, prove: Prover) -> ProofInfo {
    memoised(ctx, &ctx.claim.id, || prove(ctx, lhs, rhs, false))
}

/// A proof memoised per catalogue under `key`.  The first caller computes it; a caller
/// that finds it under way waits for it (a panic in the computation is recorded as a
/// failed proof).
pub(super) fn memoised(ctx: Ctx<'_>, key: &str, run: impl FnOnce() -> ProofInfo) -> ProofInfo {
    use std::sync::atomic::Ordering;
    let slot = ctx.cat.lemma_memo.slot(key);
    let read = |r: &crate::claims::catalogue::claim::LemmaRecord| {
        r.downcast_ref::<ProofInfo>()
            .cloned()
            .unwrap_or_else(|| ProofInfo::none("a memoised proof of another type"))
    };
    if !slot.started.swap(true, Ordering::AcqRel) {
        let p = std::panic::catch_unwind(std::panic::AssertUnwindSafe(run))
            .unwrap_or_else(|_| ProofInfo::none("the proof panicked"));
        let _ = slot.value.set(std::sync::Arc::new(p.clone()));
        return p;
    }
    // wait without running other work meanwhile: a task run here could wait in turn for
    // a proof that is waiting for this one.  The computing caller only ever waits for
    // its own lemmas (the `uses` graph has no cycles), so the waits end.
    loop {
        if let Some(r) = slot.value.get() {
            return read(r);
        }
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
}

/// What a proof of `sides` for the claim depends on: its domain, variables, constraints,
/// `let`s, lemmas and the sides, as written (two claims that agree in all of these have
/// the same proof).
pub(super) fn content_key(ctx: Ctx<'_>, sides: &[&PExpr]) -> String {
    let claim = ctx.claim;
    let lemma_ids: Vec<String> = lemmas(ctx).iter().map(|l| l.claim.id.clone()).collect();
    let texts = |v: &[PExpr]| {
        v.iter()
            .map(|p| p.text.trim().to_string())
            .collect::<Vec<_>>()
    };
    format!(
        "content|{:?}|{:?}|{:?}|{:?}|{:?}|{:?}",
        claim.domain.as_ref().map(|d| &d.value),
        claim
            .vars
            .iter()
            .map(|(n, p)| (n, p.text.trim()))
            .collect::<Vec<_>>(),
        texts(&claim.wheres),
        claim
            .lets
            .iter()
            .map(crate::claims::latex::binding_to_latex)
            .collect::<Vec<_>>(),
        lemma_ids,
        sides.iter().map(|p| p.text.trim()).collect::<Vec<_>>()
    )
}

/// Is the claim a lemma of some claim (an identity stating an implicit call's value)?
pub(super) fn is_lemma(ctx: Ctx<'_>) -> bool {
    let Body::Identity { lhs, .. } = &ctx.claim.body else {
        return false;
    };
    let ExprKind::Call(name, _) = &lhs.expr.kind else {
        return false;
    };
    ctx.claim.lets.is_empty()
        && ctx
            .cat
            .registry
            .ext(name)
            .and_then(|r| r.f.implicit())
            .is_some()
}

/// Do the claim's own formulas call `name`?
fn calls(claim: &Claim, name: &str) -> bool {
    calls_where(claim, |n| n == name)
}

/// Do the claim's own formulas (sides or expression, and `let`s) call a function whose
/// name satisfies `pred`?
pub(super) fn calls_where(claim: &Claim, pred: impl Fn(&str) -> bool) -> bool {
    let mut found = false;
    let mut look = |e: &Expr| {
        e.walk(&mut |x| {
            if let ExprKind::Call(n, _) = &x.kind {
                found |= pred(n);
            }
        })
    };
    match &claim.body {
        Body::Identity { lhs, rhs } => {
            look(&lhs.expr);
            look(&rhs.expr);
        }
        Body::Independence { expr, .. } => look(&expr.expr),
        _ => {}
    }
    for b in &claim.lets {
        look(&b.body);
    }
    found
}
