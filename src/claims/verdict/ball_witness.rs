//! Certified refutations in ball arithmetic: a sampled domain point at which lhs − rhs,
//! evaluated in Arb balls, excludes 0.
//!
//! The prover's witnesses (module `crate::algebra::witness`) need the claim in its
//! field.  A claim outside it (an iteration such as Newton's method written out, an
//! implicit map, functions the prover does not expand) may still be evaluated in balls
//! ([`crate::numbers::Ball`]): every operation encloses its exact result, a comparison
//! the balls cannot decide voids the evaluation, functions whose numerical algorithms do
//! not enclose are refused, an implicit map's value is certified by the Krawczyk test,
//! and an iteration stands for its limit, a fixed point certified in the same way.  At
//! a point of the domain (the sampler's values, exact binary numbers) where a
//! component of lhs − rhs is a ball excluding 0, the claim fails: a certified witness.
//!
//! The search walks the claim's sample stream: for a refuted or inconclusive claim the
//! points the ladder saw and three times as many more; for a claim that holds at its
//! samples as many points past them, so that a refutation does not depend on the few
//! points one seed draws.  It stops at the first refusal (the same function is
//! refused at every point).  A claim that states hypotheses (sign conditions, solution
//! branches) is not searched: its domain is narrower than the sampler's.

use super::context::{Ctx, eval, named, render};
use super::proof_info::{ProofInfo, ProofMethod};
use super::result::{Counterexample, Evidence};
use crate::claims::catalogue::PExpr;
use crate::claims::kind::Verdict;
use crate::claims::sampler::{Point, Stream};
use crate::numbers::{Ball, Decisions};

/// The working precision of the search, in bits.
const BITS: u32 = 128;

/// What one point gave.
enum AtPoint {
    /// lhs − rhs excludes 0 there: the witness and the counterexample.
    Witness(String, Counterexample),
    /// The balls do not decide (they contain 0, or a comparison was undecided).
    Undecided,
}

/// The point as `name = value` pairs, each value the exact binary number sampled
/// (shortest decimal that reads back to it).
fn show_point(p: &Point) -> String {
    (p.vars.iter())
        .map(|(n, v)| {
            let parts: Vec<String> = v.components().iter().map(|x| format!("{x:?}")).collect();
            match parts.len() {
                1 => format!("{n} = {}", parts[0]),
                _ => format!("{n} = ({})", parts.join(", ")),
            }
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// lhs − rhs in balls at `p`: a witness, undecided, or why it cannot be evaluated.
fn at_point(ctx: Ctx<'_>, lhs: &PExpr, rhs: &PExpr, p: &Point) -> Result<AtPoint, String> {
    at_points(ctx, (lhs, p), (rhs, p))
}

/// lhs at `p` − rhs at `q` in balls: a witness, undecided, or why it cannot be
/// evaluated (the witness names `p`; see [`refine_independence`] for two points).
fn at_points(
    ctx: Ctx<'_>,
    (lhs, p): (&PExpr, &Point),
    (rhs, q): (&PExpr, &Point),
) -> Result<AtPoint, String> {
    let span = Decisions::start();
    let l = eval(&ctx.setup(p, Ball::exact(0.0, BITS))?, lhs)?;
    let r = eval(&ctx.setup(q, Ball::exact(0.0, BITS))?, rhs)?;
    let d = l.sub(&r)?;
    if !span.all_decided() {
        return Ok(AtPoint::Undecided);
    }
    let comps = d.components();
    let Some((i, b)) = comps.iter().enumerate().find(|(_, b)| !b.contains_zero()) else {
        return Ok(AtPoint::Undecided);
    };
    let which = match comps.len() {
        1 => String::new(),
        _ => format!(" (component {})", i + 1),
    };
    let at = match std::ptr::eq(p, q) {
        true => format!("at the sampled point {}: lhs − rhs{which}", show_point(p)),
        false => format!(
            "between the sampled point {} and the same point with {}: the difference{which}",
            show_point(q),
            show_point(&changed(p, q))
        ),
    };
    let witness = format!(
        "{at} ∈ {} (Arb ball arithmetic, every comparison decided), which excludes 0",
        b.show(15)
    );
    let counterexample = Counterexample {
        bits: BITS,
        point: named(p),
        lhs: render(&l),
        rhs: render(&r),
        log2_residual: Some(d.log2_magnitude()),
    };
    Ok(AtPoint::Witness(witness, counterexample))
}

/// The variables of `p` whose values differ from those of `q`.
fn changed(p: &Point, q: &Point) -> Point {
    let mut out = p.clone();
    out.vars
        .retain(|(n, v)| q.get(n).is_none_or(|w| w.components() != v.components()));
    out
}

/// A witness from the claim's sample stream, or why there is none: the first `skip`
/// points are drawn but not evaluated (the ladder found lhs = rhs there), then up to
/// `count` are evaluated.
fn search(
    ctx: Ctx<'_>,
    lhs: &PExpr,
    rhs: &PExpr,
    skip: usize,
    count: usize,
) -> Result<(String, Counterexample), String> {
    let mut sampler = ctx.sampler(Stream::Samples).map_err(|c| c.to_string())?;
    for k in 0..skip + count {
        let Ok(p) = sampler.draw() else {
            break;
        };
        if k < skip {
            continue;
        }
        if let AtPoint::Witness(w, c) = at_point(ctx, lhs, rhs, &p)? {
            return Ok((w, c));
        }
    }
    Err(format!(
        "lhs − rhs in balls contains 0 at each of {count} sampled points"
    ))
}

/// How many points a witness search takes for the evidence `ev` (`skip` drawn but not
/// evaluated, then `count`), or `None` when none is sought: the verdict has a
/// certificate already, is not open (refuted, inconclusive or holding), or the claim
/// states hypotheses (a sign condition, a branch restricts the domain beyond what the
/// sampler draws: no witness is sought outside the proved setting).  A claim that holds
/// at its samples is tried at as many points past them; a refuted or inconclusive one
/// at its samples and three times as many more.
fn search_size(ctx: Ctx<'_>, ev: &Evidence) -> Option<(usize, usize)> {
    let method = ev.proof.as_ref().map_or(ProofMethod::None, |p| p.method);
    let open = matches!(
        ev.verdict,
        Verdict::Refuted | Verdict::Inconclusive | Verdict::Holds
    );
    if method != ProofMethod::None || !open || !ctx.claim.hypotheses.is_empty() {
        return None;
    }
    let n = ctx.claim.samples.max(1);
    Some(match ev.verdict {
        Verdict::Holds => (n, n),
        _ => (0, 4 * n),
    })
}

/// Records the witness `w` as the evidence's certificate: the verdict becomes a
/// certified refutation, `what` naming what the witness shows.
fn certify(ev: &mut Evidence, what: &str, (w, counterexample): (String, Counterexample)) {
    let mut info = ev.proof.take().unwrap_or_else(|| ProofInfo::none(""));
    info.method = ProofMethod::Witness;
    info.witness = Some(w.clone());
    ev.reason = match ev.verdict {
        Verdict::Refuted => format!("{}; certified: {what} {w}", ev.reason),
        _ => format!("certified: {what} {w} (numerically: {})", ev.reason),
    };
    ev.verdict = Verdict::Refuted;
    ev.proof = Some(info);
    if ev.counterexample.is_none() {
        ev.counterexample = Some(counterexample);
    }
}

/// Certifies a refutation, or refutes an inconclusive or sampled claim, by a witness in
/// ball arithmetic when the evidence has no certificate yet (see the module).
pub fn refine(ctx: Ctx<'_>, lhs: &PExpr, rhs: &PExpr, ev: &mut Evidence) {
    let Some((skip, count)) = search_size(ctx, ev) else {
        return;
    };
    match search(ctx, lhs, rhs, skip, count) {
        Ok(found) => certify(ev, "lhs − rhs ≠ 0", found),
        // a refutation without a certificate says why the balls give none
        Err(why) => {
            if ev.verdict != Verdict::Holds
                && let Some(p) = ev.proof.as_mut()
            {
                let before = p.reason.take().unwrap_or_default();
                p.reason = Some(format!("{before}; no witness in ball arithmetic: {why}"));
            }
        }
    }
}

/// A witness that `expr` depends on `wrt`: a base point of the claim's sample stream
/// and one of its redraws of `wrt` at which the balls of `expr` are disjoint.
fn search_dependence(
    ctx: Ctx<'_>,
    expr: &PExpr,
    (wrt, redraws): (&str, usize),
    count: usize,
) -> Result<Option<(String, Counterexample)>, String> {
    let mut sampler = ctx.sampler(Stream::Samples).map_err(|c| c.to_string())?;
    let mut alts = ctx.sampler(Stream::Redraws).map_err(|c| c.to_string())?;
    for _ in 0..count {
        let Ok((base, others)) = super::independence::draw(&mut sampler, &mut alts, wrt, redraws)
        else {
            break;
        };
        for alt in &others {
            if let AtPoint::Witness(w, c) = at_points(ctx, (expr, alt), (expr, &base))? {
                return Ok(Some((w, c)));
            }
        }
    }
    Ok(None)
}

/// Refutes an independence claim that is refuted or inconclusive at its samples, or
/// tries one that holds, by a witness in ball arithmetic: a base point of the claim's
/// sample stream and one of its redraws of `wrt` (the other variables equal) at which
/// the balls of `expr` are disjoint, so that `expr` changes with `wrt`.  The same
/// conditions as [`refine`]; `(wrt, redraws)` as the claim states them.
pub fn refine_independence(
    ctx: Ctx<'_>,
    expr: &PExpr,
    (wrt, redraws): (&str, usize),
    ev: &mut Evidence,
) {
    let Some((_, count)) = search_size(ctx, ev) else {
        return;
    };
    if let Ok(Some(found)) = search_dependence(ctx, expr, (wrt, redraws), count) {
        certify(ev, &format!("expr depends on {wrt}:"), found);
    }
}
