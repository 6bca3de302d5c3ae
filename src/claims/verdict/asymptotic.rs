//! `asymptotic`: expr = O(var^order) as var → 0.  At every rung the slope of
//! log2 |expr| against log2 h (h = h0·2^-j, j < steps) is fitted by least squares; the
//! rung's value is the smallest slope over the samples.  holds if every
//! [judged](super::ladder::judged) slope is ≥ order − slope_tol, refuted if every one is
//! below, inconclusive otherwise.

use super::context::{at_rung, collect, eval, named, AtRung, Ctx, Sample};
use super::ladder::{judged, Worst};
use super::result::{Cause, Counterexample, Evidence, Failure, Rung};
use crate::claims::catalogue::PExpr;
use crate::claims::eval::Backend;
use crate::claims::kind::Verdict;
use crate::claims::sampler::{Point, Stream};
use crate::claims::value::Value;

/// The asymptotic claim's fields.
#[derive(Clone, Copy)]
pub struct Spec<'a> {
    /// The expression.
    pub expr: &'a PExpr,
    /// The small variable (set by the engine).
    pub var: &'a str,
    /// The claimed order.
    pub order: f64,
    /// The largest h.
    pub h0: f64,
    /// The number of halvings.
    pub steps: usize,
    /// The tolerance on the slope.
    pub slope_tol: f64,
}

/// The fitted slope at one sample and one rung.
struct At<'a> {
    ctx: Ctx<'a>,
    spec: Spec<'a>,
    point: &'a Point,
}

impl AtRung for At<'_> {
    type Output = Result<f64, String>;
    fn run<T: Backend>(&self, like: T) -> Self::Output {
        let mut xs = Vec::new();
        let mut ys = Vec::new();
        for j in 0..self.spec.steps {
            let h = self.spec.h0 * (-(j as f64)).exp2();
            let mut p = self.point.clone();
            p.vars.push((self.spec.var.to_string(), Value::Real(h)));
            let ev = self.ctx.setup(&p, like.clone())?;
            let l = eval(&ev, self.spec.expr)?.log2_magnitude();
            if l.is_finite() {
                xs.push(h.log2());
                ys.push(l);
            }
        }
        Ok(slope(&xs, &ys))
    }
}

/// Least-squares slope of `ys` against `xs`; +∞ with fewer than two points (an exact
/// zero is O(h^anything)).
fn slope(xs: &[f64], ys: &[f64]) -> f64 {
    if xs.len() < 2 {
        return f64::INFINITY;
    }
    let n = xs.len() as f64;
    let mx = xs.iter().sum::<f64>() / n;
    let my = ys.iter().sum::<f64>() / n;
    let sxy: f64 = xs.iter().zip(ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

/// Per rung, the sample with the smallest slope.
fn worst_slopes(bits: &[u32], samples: &[Sample<Point, f64>]) -> Vec<Worst> {
    bits.iter()
        .enumerate()
        .map(|(j, &b)| {
            let (mut worst, mut wi) = (f64::INFINITY, 0);
            for (i, s) in samples.iter().enumerate() {
                if s.rungs[j] < worst {
                    worst = s.rungs[j];
                    wi = i;
                }
            }
            Worst {
                bits: b,
                value: worst,
                sample: wi,
            }
        })
        .collect()
}

/// The slopes of an asymptotic claim and their verdict.
pub fn run(ctx: Ctx<'_>, spec: Spec<'_>, bits: &[u32]) -> Result<Evidence, Failure> {
    let mut sampler = ctx.sampler(Stream::Samples).map_err(Failure::bare)?;
    let mut failures = Vec::new();
    let draw = || {
        let p = sampler.draw().map_err(Cause::Sampling)?;
        Ok((p.clone(), p))
    };
    let at = |point: &Point, bits: u32| at_rung(bits, &At { ctx, spec, point });
    let samples = match collect(ctx.claim, bits, &mut failures, draw, at) {
        Ok(s) => s,
        Err(cause) => return Err(Failure::with_failures(cause, failures)),
    };
    let worst = worst_slopes(bits, &samples);
    let judged = judged(&worst, |w| w.bits);
    let (order, thr) = (spec.order, spec.order - spec.slope_tol);
    let mut ev = if judged.iter().all(|w| w.value >= thr) {
        let reason = format!("fitted slope ≥ {thr} at every judged rung (claimed order {order})");
        Evidence::new(Verdict::Holds, reason)
    } else if judged.iter().all(|w| w.value < thr) {
        let w = *judged[judged.len() - 1];
        let reason = format!(
            "fitted slope {:.3} < {thr} (claimed order {order})",
            w.value
        );
        let counterexample = samples.get(w.sample).map(|s| Counterexample {
            bits: w.bits,
            point: named(&s.point),
            lhs: format!("slope {:.4}", w.value),
            rhs: format!("order {order}"),
            log2_residual: None,
        });
        Evidence {
            counterexample,
            ..Evidence::new(Verdict::Refuted, reason)
        }
    } else {
        Evidence::new(
            Verdict::Inconclusive,
            "fitted slopes straddle the claimed order",
        )
    };
    ev.samples = samples.len();
    ev.failures = failures;
    ev.residuals = worst
        .iter()
        .map(|w| Rung::Slope {
            bits: w.bits,
            slope: w.value,
        })
        .collect();
    Ok(ev)
}
