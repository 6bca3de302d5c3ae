//! `existence`: the equations have a solution (in the stated set).  At each sample an
//! f64 solution is found by Newton's method from up to `tries` sampled starts; at every
//! rung Newton is run again from it at that precision, with the Jacobian by automatic
//! differentiation, and the residual enters the usual ladder.  A failure to converge is
//! inconclusive: existence cannot be refuted numerically.
//!
//! When the claim holds, each sample's solution is then certified by the Krawczyk test
//! ([`crate::linalg::krawczyk`]) in Arb ball arithmetic: at the sample's exact point,
//! the equations have exactly one solution in a small box around the one Newton found,
//! and every point of that box is in the stated set.  The proof method is then
//! `interval`.  This certifies the sampled points only: the verdict stays `holds`, as the
//! claim is stated on the whole domain.

use super::context::{AtRung, Ctx, Sides, at_rung, collect, eval};
use super::ladder;
use super::proof_info::{ProofInfo, ProofMethod};
use super::result::{Cause, Evidence, Failure};
use crate::claims::ast::{Expr, ExprKind, Span};
use crate::claims::catalogue::PExpr;
use crate::claims::eval::{Backend, Evaluator};
use crate::claims::kind::Verdict;
use crate::claims::sampler::{Point, Sampler, Stream};
use crate::claims::value::Value;
use crate::linalg::krawczyk::{BallSystem, Certificate, krawczyk};
use crate::linalg::newton::{Limits, System, newton};
use crate::numbers::{Ball, Decisions};

/// The existence claim's fields.
#[derive(Clone, Copy)]
pub struct Spec<'a> {
    /// Unknown names.
    pub unknowns: &'a [String],
    /// Equations (= 0).
    pub equations: &'a [PExpr],
    /// Start expressions (sampling context).
    pub start: &'a [PExpr],
    /// Membership predicate.
    pub in_set: Option<&'a PExpr>,
    /// Attempts per sample.
    pub tries: usize,
}

/// The equations at a sample, with the unknowns bound on top of the point and `let`s.
struct Equations<'e, 'c, T> {
    base: &'e Evaluator<'c, T>,
    spec: Spec<'e>,
    jacobian: &'e [Vec<Expr>],
    last: Option<Evaluator<'c, T>>,
}

impl<'c, T: Backend> Equations<'_, 'c, T> {
    fn bound(&self, x: &[T]) -> Evaluator<'c, T> {
        let mut ev = self.base.clone();
        for (u, v) in self.spec.unknowns.iter().zip(x) {
            ev.bind(u, Value::Real(v.clone()));
        }
        ev
    }
}

impl<T: Backend> System<T> for Equations<'_, '_, T> {
    type Error = String;
    fn residual(&mut self, x: &[T]) -> Result<Vec<T>, String> {
        let ev = self.bound(x);
        let f = self
            .spec
            .equations
            .iter()
            .map(|e| eval(&ev, e)?.as_real())
            .collect::<Result<_, _>>()?;
        self.last = Some(ev);
        Ok(f)
    }
    fn jacobian(&mut self, x: &[T]) -> Result<Vec<Vec<T>>, String> {
        let ev = match self.last.take() {
            Some(ev) => ev,
            None => self.bound(x),
        };
        let mut a = Vec::with_capacity(self.jacobian.len());
        for row in self.jacobian {
            let mut r = Vec::with_capacity(row.len());
            for d in row {
                r.push(ev.eval(d).map_err(|e| e.message)?.as_real()?);
            }
            a.push(r);
        }
        Ok(a)
    }
}

impl BallSystem for Equations<'_, '_, Ball> {
    fn residual(&mut self, x: &[Ball]) -> Result<Vec<Ball>, String> {
        System::residual(self, x)
    }
    fn jacobian(&mut self, x: &[Ball]) -> Result<Vec<Vec<Ball>>, String> {
        // never the evaluator of the last residual: that one is bound at another point
        self.last = None;
        System::jacobian(self, x)
    }
}

/// `d(equation_i, unknown_j)` for every pair.
fn jacobian_exprs(spec: Spec<'_>) -> Vec<Vec<Expr>> {
    let d = |e: &PExpr, u: &String| Expr {
        kind: ExprKind::Deriv {
            body: Box::new(e.expr.clone()),
            var: u.clone(),
            component: None,
        },
        span: Span::default(),
    };
    spec.equations
        .iter()
        .map(|e| spec.unknowns.iter().map(|u| d(e, u)).collect())
        .collect()
}

/// Newton at one rung from an f64 start: the solution in f64, the log2 residual
/// relative to the scale, and whether the solution is in the stated set.
struct Solve<'a> {
    ctx: Ctx<'a>,
    spec: Spec<'a>,
    point: &'a Point,
    start: &'a [f64],
}

impl AtRung for Solve<'_> {
    type Output = Result<(Vec<f64>, f64, bool), String>;
    fn run<T: Backend>(&self, like: T) -> Self::Output {
        let base = self.ctx.setup(self.point, like.clone())?;
        let s = self.ctx.log2_scale(&base, self.point)?;
        let jacobian = jacobian_exprs(self.spec);
        let mut system = Equations {
            base: &base,
            spec: self.spec,
            jacobian: &jacobian,
            last: None,
        };
        let limits = Limits {
            bits: like.precision().unwrap_or(53),
            ..Limits::default()
        };
        let x0 = self.start.iter().map(|s| like.from_f64(*s)).collect();
        let run = newton(&mut system, x0, limits).map_err(|e| e.to_string())?;
        let inside = match self.spec.in_set {
            Some(p) => eval(&system.bound(&run.x), p)?.as_bool()?,
            None => true,
        };
        let x = run.x.iter().map(|v| v.to_f64()).collect();
        Ok((x, run.best_log2 - s, inside))
    }
}

/// An f64 solution at `p` from up to `tries` sampled starts.
fn find_start(
    ctx: Ctx<'_>,
    spec: Spec<'_>,
    starts: &mut Sampler<'_>,
    p: &Point,
) -> Result<Vec<f64>, Cause> {
    let mut last = String::from("no start converged");
    for _ in 0..spec.tries {
        let ev = match ctx.setup(p, 0.0f64) {
            Ok(ev) => ev,
            Err(m) => {
                last = m;
                continue;
            }
        };
        let st: Result<Vec<f64>, String> = spec
            .start
            .iter()
            .map(|s| starts.eval_sampling(&s.expr, &ev)?.as_real())
            .collect();
        let st = match st {
            Ok(s) => s,
            Err(m) => {
                last = m;
                continue;
            }
        };
        let job = Solve {
            ctx,
            spec,
            point: p,
            start: &st,
        };
        match job.run(0.0f64) {
            Ok((x, r, true)) if r <= -53.0 + ctx.claim.max_loss_bits => return Ok(x),
            Ok((_, r, inside)) => {
                last = format!("Newton stalled at log2 residual {r:.1} (in set: {inside})")
            }
            Err(m) => last = m,
        }
    }
    Err(Cause::NoSolution(last))
}

/// The ladder of an existence claim.
pub fn run(ctx: Ctx<'_>, spec: Spec<'_>, bits: &[u32]) -> Result<Evidence, Failure> {
    let mut sampler = ctx.sampler(Stream::Samples).map_err(Failure::bare)?;
    let mut starts = ctx.sampler(Stream::Starts).map_err(Failure::bare)?;
    let mut failures = Vec::new();
    let draw = || {
        let p = sampler.draw().map_err(Cause::Sampling)?;
        let x = find_start(ctx, spec, &mut starts, &p)?;
        Ok(((p.clone(), x), p))
    };
    let at = |(point, start): &(Point, Vec<f64>), b: u32| {
        let job = Solve {
            ctx,
            spec,
            point,
            start,
        };
        let (x, r, inside) = at_rung(b, &job)?;
        if !inside {
            return Err(format!(
                "the solution at {b} bits is outside the stated set"
            ));
        }
        let sol = spec
            .unknowns
            .iter()
            .zip(&x)
            .map(|(u, v)| format!("{u} = {v:e}"))
            .collect::<Vec<_>>()
            .join(", ");
        Ok(Sides {
            log2: r,
            lhs: sol,
            rhs: "0".into(),
        })
    };
    let samples = match collect(ctx.claim, bits, &mut failures, draw, at) {
        Ok(s) => s,
        Err(cause) => return Err(Failure::with_failures(cause, failures)),
    };
    let mut ev = ladder::finish(ctx.claim, bits, &samples, failures);
    if ev.verdict == Verdict::Refuted {
        ev.verdict = Verdict::Inconclusive;
        ev.reason = "Newton did not converge to working precision (existence cannot be refuted numerically)".into();
    }
    if ev.verdict == Verdict::Holds {
        let solved: Vec<(&Point, &[f64])> = (samples.iter())
            .map(|s| (&s.drawn.0, s.drawn.1.as_slice()))
            .collect();
        ev.proof = Some(certify_samples(ctx, spec, &solved));
    }
    Ok(ev)
}

/// The working precision of the Krawczyk test, in bits.
const CERT_BITS: u32 = 128;

/// The half-width of the box around a solution `x` found in `f64`: far above the
/// solution's error, far below the distance to another solution.
fn box_radius(x: f64) -> f64 {
    1e-9 * x.abs().max(1e-3)
}

/// The Krawczyk certificate of the solution `x` at `point`: exactly one solution of the
/// equations in the box around `x`, and every point of the box in the stated set.
pub fn certify(
    ctx: Ctx<'_>,
    spec: Spec<'_>,
    point: &Point,
    x: &[f64],
    radius: &[f64],
) -> Result<Certificate, String> {
    // every comparison decided, from the `let`s (an implicit map's enclosure) on
    let span = Decisions::start();
    let like = Ball::exact(0.0, CERT_BITS);
    let base = ctx.setup(point, like)?;
    let jacobian = jacobian_exprs(spec);
    let mut system = Equations {
        base: &base,
        spec,
        jacobian: &jacobian,
        last: None,
    };
    let cert = krawczyk(&mut system, x, radius, CERT_BITS)?;
    if !span.all_decided() {
        return Err("a comparison could not be decided in balls".into());
    }
    if let Some(p) = spec.in_set {
        let boxes: Vec<Ball> = (x.iter().zip(radius))
            .map(|(&c, &r)| Ball::with_radius(c, r, CERT_BITS))
            .collect();
        let inside = eval(&system.bound(&boxes), p)?.as_bool()?;
        if !span.all_decided() || !inside {
            return Err("the box is not certified to lie in the stated set".into());
        }
    }
    Ok(cert)
}

/// The proof record of an existence claim that holds: every sample's solution certified
/// (method `interval`, the boxes in the notes), or why not.
fn certify_samples(ctx: Ctx<'_>, spec: Spec<'_>, solved: &[(&Point, &[f64])]) -> ProofInfo {
    let t0 = std::time::Instant::now();
    let mut notes = Vec::with_capacity(solved.len());
    for (i, (point, x)) in solved.iter().enumerate() {
        let radius: Vec<f64> = x.iter().map(|v| box_radius(*v)).collect();
        match certify(ctx, spec, point, x, &radius) {
            Ok(c) => notes.push(format!("sample {}: {}", i + 1, c.describe(spec.unknowns))),
            Err(why) => {
                return ProofInfo::none(format!(
                    "{}the Krawczyk test fails at sample {}: {why}",
                    super::proof_info::NO_INTERVAL,
                    i + 1
                ));
            }
        }
    }
    let mut info = ProofInfo::none("");
    info.method = ProofMethod::Interval;
    info.reason = Some(format!(
        "at each of the {} sampled points the solution is certified by the Krawczyk test in Arb ball arithmetic (exactly one solution in a box of relative half-width 1e-9 around the one Newton found, every point of the box in the stated set); this certifies the sampled points, not the whole domain",
        solved.len()
    ));
    info.notes = notes;
    info.ms = t0.elapsed().as_secs_f64() * 1e3;
    info
}
