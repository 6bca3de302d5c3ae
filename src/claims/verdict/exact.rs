//! Exact evaluation of an identity over BigRational (`exact = true`): lhs − rhs exactly
//! zero at `exact_samples` random rational points is reported as evidence (it never
//! proves: only the symbolic normal form does, see [`super::symbolic`]); an exact nonzero
//! is a refutation with an exact counterexample.

use super::context::{Ctx, eval, named, render};
use super::result::{Cause, Counterexample, Evidence, ExactInfo, Failure};
use crate::claims::catalogue::{ExactSpec, PExpr};
use crate::claims::kind::Verdict;
use crate::claims::sampler::{DrawStats, Point, Stream};
use crate::numbers::{Rational, Scalar};

/// One rational point: is lhs − rhs exactly zero, and both sides.
fn at_point(
    ctx: Ctx<'_>,
    lhs: &PExpr,
    rhs: &PExpr,
    p: &Point,
) -> Result<(bool, String, String), String> {
    let zero = Rational::from_integer(0.into());
    let ev = ctx.setup(p, zero)?;
    let l = eval(&ev, lhs)?;
    let r = eval(&ev, rhs)?;
    let d = l.sub(&r)?;
    Ok((
        d.components().iter().all(|c| c.is_zero()),
        render(&l),
        render(&r),
    ))
}

/// What the exact points showed.
struct Points {
    evaluated: usize,
    all_zero: bool,
    /// Why evaluation stopped early ("not evaluable exactly: ...").
    note: Option<String>,
}

/// Evaluates the exact points; a nonzero point refutes `ev` with an exact counterexample.
fn points(
    ctx: Ctx<'_>,
    lhs: &PExpr,
    rhs: &PExpr,
    spec: ExactSpec,
    ev: &mut Evidence,
) -> Result<(Points, DrawStats), Cause> {
    let mut sampler = ctx.sampler(Stream::Exact)?;
    let mut out = Points {
        evaluated: 0,
        all_zero: true,
        note: None,
    };
    for _ in 0..spec.samples {
        let p = sampler.draw().map_err(Cause::Sampling)?;
        match at_point(ctx, lhs, rhs, &p) {
            Ok((true, _, _)) => out.evaluated += 1,
            Ok((false, l, r)) => {
                out.all_zero = false;
                out.evaluated += 1;
                ev.verdict = Verdict::Refuted;
                ev.reason = "exact rational evaluation gives lhs ≠ rhs".into();
                ev.counterexample = Some(Counterexample {
                    bits: 0,
                    point: named(&p),
                    lhs: l,
                    rhs: r,
                    log2_residual: None,
                });
                break;
            }
            Err(m) => {
                out.all_zero = false;
                out.note = Some(format!("not evaluable exactly: {m}"));
                break;
            }
        }
    }
    Ok((out, sampler.stats))
}

/// The exact evaluation on top of the float ladder's evidence `ladder`.
pub fn refine(
    ctx: Ctx<'_>,
    lhs: &PExpr,
    rhs: &PExpr,
    spec: ExactSpec,
    ladder: Evidence,
) -> Result<Evidence, Failure> {
    let mut ev = ladder;
    let (pts, st) = match points(ctx, lhs, rhs, spec, &mut ev) {
        Ok(x) => x,
        Err(cause) => return Err(Failure::new(cause, ev)),
    };
    let n = pts.evaluated;
    let acceptance = if st.draws == 0 {
        1.0
    } else {
        st.accepted as f64 / st.draws as f64
    };
    let set_size = if st.nonuniform { None } else { st.min_set };
    let note = pts.note.unwrap_or_else(|| {
        if pts.all_zero {
            format!("lhs − rhs is exactly 0 at {n} random rational points (evidence, not a proof)")
        } else {
            "exact evaluation found lhs ≠ rhs".into()
        }
    });
    if pts.all_zero && ev.verdict == Verdict::Refuted {
        ev.verdict = Verdict::Inconclusive;
        ev.reason =
            "exact evaluation is zero but the float ladder refutes: engine inconsistency".into();
    }
    ev.exact = Some(ExactInfo {
        points: n,
        set_size,
        acceptance,
        all_zero: pts.all_zero,
        note,
    });
    Ok(ev)
}
