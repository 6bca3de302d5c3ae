//! `asymptotic`: expr = O(var^order) as var → 0.  At every rung and sample, expr is
//! evaluated at h_j = h0·2^-j (j < steps); the slopes of log2 |expr| against log2 h
//! are the least-squares fit over every h_j ([`ls_slope`]) and the local slopes of the
//! last two halvings.  With thr = order − slope_tol, a sample passes at a rung if the
//! fitted slope and both local slopes are ≥ thr and the last local slope does not drift
//! below the order (it is ≥ order, or no smaller than the one before); it is below if
//! the fitted slope and the last local slope are both < thr.  The claim holds if every
//! sample passes at every [judged] rung, is refuted if at every
//! judged rung some sample is below, and is inconclusive otherwise.  The rung's value is
//! the smallest fitted slope over the samples.
//!
//! The bound is one-sided, as O(·) is: a slope above the order (the expression is
//! smaller than claimed) passes.

use super::context::{AtRung, Ctx, Sample, at_rung, collect, eval, named};
use super::ladder::{Worst, judged};
use super::result::{Cause, Counterexample, Evidence, Failure, Rung};
use crate::claims::catalogue::PExpr;
use crate::claims::eval::Backend;
use crate::claims::kind::Verdict;
use crate::claims::sampler::{Point, Stream};
use crate::claims::value::Value;
use crate::stats::ls_slope;

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

/// The slopes of one sample at one rung.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slopes {
    /// Least-squares slope of log2 |expr| against log2 h over every h_j
    /// ([`ls_slope`]); +∞ when fewer than two values are nonzero (an exact zero is
    /// O(h^anything)).
    pub fit: f64,
    /// The local slopes of the last two halvings, `(h_{n−3} → h_{n−2}, h_{n−2} → h_{n−1})`;
    /// `None` when one of the last three values is exactly zero.
    pub tail: Option<(f64, f64)>,
}

/// How one sample's slopes at one rung compare with the claimed order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Judgement {
    /// The fitted slope and the last two local slopes are ≥ order − tol, and the last
    /// local slope is ≥ order or no smaller than the one before (it does not drift
    /// below the order).
    Pass,
    /// The fitted slope and the last local slope are both < order − tol.
    Below,
    /// Neither: the slopes straddle the threshold, or drift below the order.
    Unclear,
}

impl Slopes {
    /// The slopes of the values `log2 |expr(h_j)|` at `log2 h_j` (in the order of the
    /// ladder of h, largest h first).  Non-finite values (exact zeros) are left out of
    /// the fit.
    pub fn of(log2_h: &[f64], log2_e: &[f64]) -> Slopes {
        let (xs, ys): (Vec<f64>, Vec<f64>) = log2_h
            .iter()
            .zip(log2_e)
            .filter(|(_, y)| y.is_finite())
            .map(|(x, y)| (*x, *y))
            .unzip();
        let fit = if xs.len() < 2 {
            f64::INFINITY
        } else {
            ls_slope(&xs, &ys).unwrap_or(f64::NAN)
        };
        let n = log2_h.len().min(log2_e.len());
        let local = |j: usize| (log2_e[j] - log2_e[j + 1]) / (log2_h[j] - log2_h[j + 1]);
        let tail = (n >= 3 && log2_e[n - 3..n].iter().all(|y| y.is_finite()))
            .then(|| (local(n - 3), local(n - 2)));
        Slopes { fit, tail }
    }

    /// Compares the slopes with `order` and the threshold `order − tol`.
    pub fn judge(&self, order: f64, tol: f64) -> Judgement {
        let thr = order - tol;
        match self.tail {
            // an exact zero among the last values: only the fit speaks
            None if self.fit >= thr => Judgement::Pass,
            None if self.fit < thr => Judgement::Below,
            None => Judgement::Unclear,
            Some((a, b)) => {
                let converging = b >= order || b >= a;
                if self.fit >= thr && a >= thr && b >= thr && converging {
                    Judgement::Pass
                } else if self.fit < thr && b < thr {
                    Judgement::Below
                } else {
                    Judgement::Unclear
                }
            }
        }
    }
}

/// The slopes at one sample and one rung.
struct At<'a> {
    ctx: Ctx<'a>,
    spec: Spec<'a>,
    point: &'a Point,
}

impl AtRung for At<'_> {
    type Output = Result<Slopes, String>;
    fn run<T: Backend>(&self, like: T) -> Self::Output {
        let mut xs = Vec::new();
        let mut ys = Vec::new();
        for j in 0..self.spec.steps {
            let h = self.spec.h0 * (-(j as f64)).exp2();
            let mut p = self.point.clone();
            p.vars.push((self.spec.var.to_string(), Value::Real(h)));
            let ev = self.ctx.setup(&p, like.clone())?;
            xs.push(h.log2());
            ys.push(eval(&ev, self.spec.expr)?.log2_magnitude());
        }
        Ok(Slopes::of(&xs, &ys))
    }
}

/// Per rung, the sample with the smallest fitted slope (what the rung shows).
fn worst_slopes(bits: &[u32], samples: &[Sample<Point, Slopes>]) -> Vec<Worst> {
    bits.iter()
        .enumerate()
        .map(|(j, &b)| {
            let (mut worst, mut wi) = (f64::INFINITY, 0);
            for (i, s) in samples.iter().enumerate() {
                if s.rungs[j].fit < worst {
                    worst = s.rungs[j].fit;
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

/// The verdict from the judgements of every sample at every judged rung: holds if every
/// one passes, refuted if at every judged rung some sample is below, else inconclusive.
/// Also returns the (rung index, sample index) of the evidence: the sample below with the
/// smallest fitted slope at the highest judged rung, or the first sample that does not
/// pass.
fn decide(
    bits: &[u32],
    samples: &[Sample<Point, Slopes>],
    spec: &Spec<'_>,
) -> (Verdict, Option<(usize, usize)>) {
    let idx: Vec<usize> = (0..bits.len()).collect();
    let judged_idx: Vec<usize> = judged(&idx, |&j| bits[j]).into_iter().copied().collect();
    // the sample with the smallest fitted slope among those judged `want` at rung j
    let at = |j: usize, want: Judgement| {
        let mut best: Option<usize> = None;
        for (i, s) in samples.iter().enumerate() {
            let better = best.is_none_or(|b| s.rungs[j].fit < samples[b].rungs[j].fit);
            if s.rungs[j].judge(spec.order, spec.slope_tol) == want && better {
                best = Some(i);
            }
        }
        best
    };
    let last = judged_idx.last().copied();
    if judged_idx
        .iter()
        .all(|&j| at(j, Judgement::Below).is_some())
    {
        let j = last.unwrap_or(0);
        return (Verdict::Refuted, at(j, Judgement::Below).map(|i| (j, i)));
    }
    let not_pass = judged_idx.iter().find_map(|&j| {
        samples
            .iter()
            .position(|s| s.rungs[j].judge(spec.order, spec.slope_tol) != Judgement::Pass)
            .map(|i| (j, i))
    });
    match not_pass {
        None => (Verdict::Holds, None),
        Some(ji) => (Verdict::Inconclusive, Some(ji)),
    }
}

/// The reason of a verdict, quoting `slopes`: those of the sample that [`decide`] names.
fn reason(v: Verdict, spec: &Spec<'_>, slopes: Option<Slopes>) -> String {
    let (order, thr) = (spec.order, spec.order - spec.slope_tol);
    let tail = |s: &Slopes| match s.tail {
        Some((a, b)) => format!(", last local slopes {a:.3}, {b:.3}"),
        None => String::new(),
    };
    match (v, slopes) {
        (Verdict::Holds, _) => format!(
            "fitted and last two local slopes ≥ {thr}, not drifting below {order}, at every judged rung (claimed order {order})"
        ),
        (Verdict::Refuted, Some(s)) => format!(
            "fitted slope {:.3}{} < {thr} (claimed order {order})",
            s.fit,
            tail(&s)
        ),
        (_, Some(s)) => format!(
            "slopes straddle or drift below the claimed order {order}: fitted slope {:.3}{} (threshold {thr})",
            s.fit,
            tail(&s)
        ),
        (_, None) => format!("slopes straddle the claimed order {order}"),
    }
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
    let (verdict, at) = decide(bits, &samples, &spec);
    let slopes = at.map(|(j, i)| samples[i].rungs[j]);
    let mut ev = Evidence::new(verdict, reason(verdict, &spec, slopes));
    if verdict == Verdict::Refuted {
        ev.counterexample = at.zip(slopes).map(|((j, i), s)| Counterexample {
            bits: bits[j],
            point: named(&samples[i].point),
            lhs: format!("slope {:.4}", s.fit),
            rhs: format!("order {}", spec.order),
            log2_residual: None,
        });
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::claims::catalogue::load_sources;
    use crate::claims::registry::Registry;
    use crate::claims::verdict::{Options, run_claim};

    /// The slopes of e(h) at h_j = h0·2^-j, j < steps.
    fn slopes(e: impl Fn(f64) -> f64, h0: f64, steps: usize) -> Slopes {
        let hs: Vec<f64> = (0..steps).map(|j| h0 * (-(j as f64)).exp2()).collect();
        let xs: Vec<f64> = hs.iter().map(|h| h.log2()).collect();
        let ys: Vec<f64> = hs.iter().map(|&h| e(h).abs().log2()).collect();
        Slopes::of(&xs, &ys)
    }

    /// The ladders of h the catalogue uses (and the default).
    const LADDERS: [(f64, usize); 4] = [(0.1, 6), (0.05, 6), (0.125, 6), (0.01, 6)];

    #[test]
    fn a_lower_power_is_not_order_two() {
        for (h0, n) in LADDERS {
            let s = slopes(|h| h.powf(1.8), h0, n);
            assert_eq!(s.judge(2.0, 0.1), Judgement::Below, "{h0}: {s:?}");
        }
    }

    #[test]
    fn a_small_first_order_term_is_not_order_two() {
        for (h0, n) in LADDERS {
            let s = slopes(|h| h * h + 1e-3 * h, h0, n);
            assert_ne!(s.judge(2.0, 0.1), Judgement::Pass, "{h0}: {s:?}");
        }
        // the first-order term still hidden by h² at the smallest h: the local slopes
        // drift below 2, so the claim is not accepted either
        let s = slopes(|h| h * h + 1e-5 * h, 0.1, 6);
        assert_eq!(s.judge(2.0, 0.1), Judgement::Unclear, "{s:?}");
    }

    #[test]
    fn second_order_errors_are_order_two() {
        for (h0, n) in LADDERS {
            for s in [
                slopes(|h| h * h, h0, n),
                slopes(|h| 3.0 * h * h * (1.0 + h), h0, n),
                slopes(|h| h * h * (1.0 - 2.0 * h), h0, n),
            ] {
                assert_eq!(s.judge(2.0, 0.1), Judgement::Pass, "{h0}: {s:?}");
            }
        }
    }

    #[test]
    fn the_bound_is_one_sided() {
        // h³ is O(h²), and h² is o(h) (checked as order 1.5)
        assert_eq!(
            slopes(|h| h.powi(3), 0.1, 6).judge(2.0, 0.1),
            Judgement::Pass
        );
        assert_eq!(slopes(|h| h * h, 0.1, 6).judge(1.5, 0.1), Judgement::Pass);
        // but h is not O(h²)
        assert_eq!(slopes(|h| h, 0.1, 6).judge(2.0, 0.1), Judgement::Below);
    }

    #[test]
    fn exact_zeros_are_of_every_order() {
        let s = slopes(|_| 0.0, 0.1, 6);
        assert_eq!((s.fit, s.tail), (f64::INFINITY, None));
        assert_eq!(s.judge(2.0, 0.1), Judgement::Pass);
    }

    fn verdict_of(expr: &str) -> Verdict {
        let toml = format!(
            r#"
[[claim]]
id = "t"
environment = "Section 2"
role = "statement"
location = "here"
printed = "e = O(h^2)"
kind = "asymptotic"
expect = "holds"
vars = [["x", "uniform(1, 2)"]]
expr = "{expr}"
var = "h"
order = 2
"#
        );
        let cat = load_sources(&[("t.toml".into(), toml)], Registry::new()).unwrap();
        let opts = Options {
            bits: vec![53, 128, 256],
            exact: false,
        };
        run_claim(&cat, &cat.claims[0], &opts).verdict
    }

    #[test]
    fn the_engine_applies_the_rule() {
        assert_eq!(verdict_of("x*h^1.8"), Verdict::Refuted);
        assert_ne!(verdict_of("x*(h^2 + 0.001*h)"), Verdict::Holds);
        assert_eq!(verdict_of("x*h^2"), Verdict::Holds);
        assert_eq!(verdict_of("x*h^2*(1 + h)"), Verdict::Holds);
    }
}
