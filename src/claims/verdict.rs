//! The verdict engine: evaluates each claim on a precision ladder (and exactly, for
//! rational claims) and decides holds / refuted / proved / inconclusive, with evidence.
//!
//! Residual of a sample at precision p: |lhs − rhs| / max(|lhs|, |rhs|, S) (largest
//! component modulus; S = the claim's `scale`, else the size of the sampled inputs), kept
//! as log2 so nothing underflows at 1024 bits.  r_p = max over samples;
//! g = max_p (p + log2 r_p) is the number of bits lost to conditioning.
//! * holds: g ≤ max_loss_bits.
//! * refuted: r_p ≥ 2^(−refute_floor_bits) at every rung ≥ 128 bits (all rungs if none).
//! * proved: exact zero at N rational points (with a Schwartz–Zippel bound) and holds.
//! * inconclusive: otherwise.
//!
//! Samples that cannot be evaluated are reported as failures and replaced, never counted.

use super::ast::{Expr, ExprKind, Span};
use super::backend::{Num, RealFn};
use super::catalogue::{Body, Catalogue, Claim, Kind, PExpr};
use super::eval::Evaluator;
use super::latex::{binding_to_latex, to_latex};
use super::sampler::{Point, Sampler};
use super::value::{Layout, Value};
use crate::numbers::{Rational, Scalar};
use rayon::prelude::*;
use rug::Float;
use serde::Serialize;

/// The default precision ladder.
pub const DEFAULT_BITS: [u32; 5] = [53, 128, 256, 512, 1024];

/// A verdict.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    /// Numerically true at every rung within the conditioning bound.
    Holds,
    /// False, with a counterexample.
    Refuted,
    /// Exactly true at random rational points (Schwartz–Zippel).
    Proved,
    /// Neither.
    Inconclusive,
    /// A definition: no verdict.
    Defined,
}

impl Verdict {
    /// Lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Holds => "holds",
            Verdict::Refuted => "refuted",
            Verdict::Proved => "proved",
            Verdict::Inconclusive => "inconclusive",
            Verdict::Defined => "defined",
        }
    }
}

/// Residual at one rung.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Rung {
    /// Precision in bits.
    pub bits: u32,
    /// The residual (for asymptotic claims: the fitted slope).  May underflow to 0 in
    /// f64 at very high precision: use `log2`.
    pub residual: f64,
    /// log2 of the residual (−∞ serialised as null: exactly zero).
    pub log2: Option<f64>,
}

/// A named value.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Named {
    /// Name.
    pub name: String,
    /// Rendered value.
    pub value: String,
}

/// A counterexample.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Counterexample {
    /// Precision of the values shown ("exact" = 0).
    pub bits: u32,
    /// The sample point.
    pub point: Vec<Named>,
    /// Left side (or the expression) there.
    pub lhs: String,
    /// Right side (or the comparison value) there.
    pub rhs: String,
    /// Residual (log2).
    pub log2_residual: Option<f64>,
}

/// A sample that could not be evaluated.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Failure {
    /// The point.
    pub point: Vec<Named>,
    /// Rung (bits) where it failed, 0 for sampling / exact.
    pub bits: u32,
    /// What went wrong.
    pub message: String,
}

/// Evidence of an exact evaluation.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct ExactInfo {
    /// Rational points evaluated.
    pub points: usize,
    /// Declared total-degree bound.
    pub degree: u32,
    /// Smallest primitive set size |S| (None: a non-uniform primitive was used).
    pub set_size: Option<u64>,
    /// Fraction of candidate points accepted by the constraints.
    pub acceptance: f64,
    /// degree / (|S| · acceptance): probability bound per point for a nonzero numerator.
    pub per_point_bound: Option<f64>,
    /// per_point_bound ^ points.
    pub overall_bound: Option<f64>,
    /// Was lhs − rhs exactly zero at every point?
    pub all_zero: bool,
    /// Explanation.
    pub note: String,
}

/// Everything known about one claim after verification (consumed by the report writer).
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct ClaimResult {
    /// Claim id.
    pub id: String,
    /// Paper labels.
    pub labels: Vec<String>,
    /// Location in the paper.
    pub location: String,
    /// `file:line` in the catalogue.
    pub position: String,
    /// Verbatim LaTeX from the paper.
    pub printed: String,
    /// LaTeX of the evaluated expressions (let bindings, then the claim).
    pub rendered: Vec<String>,
    /// Kind.
    pub kind: String,
    /// printed | corrected.
    pub form: String,
    /// The printed claim this one corrects.
    pub corrects: Option<String>,
    /// Expected verdict.
    pub expect: Option<String>,
    /// The verdict.
    pub verdict: Verdict,
    /// verdict == expect (definitions: true).
    pub as_expected: bool,
    /// Residual per rung.
    pub residuals: Vec<Rung>,
    /// Bits lost to conditioning g (None when not applicable).
    pub loss_bits: Option<f64>,
    /// The bound on g.
    pub max_loss_bits: f64,
    /// Samples evaluated successfully.
    pub samples: usize,
    /// Samples that could not be evaluated.
    pub failures: Vec<Failure>,
    /// Counterexample (refuted claims).
    pub counterexample: Option<Counterexample>,
    /// Exact evaluation evidence.
    pub exact: Option<ExactInfo>,
    /// Catalogue note.
    pub note: Option<String>,
    /// Why this verdict, in one line.
    pub reason: String,
}

/// Verification options.
#[derive(Clone, Debug)]
pub struct Options {
    /// The precision ladder (53 = f64; others MPFR).
    pub bits: Vec<u32>,
    /// Run exact evaluations of `exact = true` claims.
    pub exact: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            bits: DEFAULT_BITS.to_vec(),
            exact: true,
        }
    }
}

/// Verifies the claims selected by `select`, in parallel, calling `done` as each finishes.
/// Results are in catalogue order.  With the environment variable `EULERTOP_TIMING`
/// set, per-claim wall times are printed on standard error.
pub fn verify(
    cat: &Catalogue,
    opts: &Options,
    select: &(dyn Fn(&Claim) -> bool + Sync),
    done: &(dyn Fn(&ClaimResult) + Sync),
) -> Vec<ClaimResult> {
    let chosen: Vec<&Claim> = cat.claims.iter().filter(|c| select(c)).collect();
    // Opt-in per-claim timings on standard error (never part of the results).
    let timing = std::env::var_os("EULERTOP_TIMING").is_some();
    chosen
        .par_iter()
        .map(|c| {
            let t0 = std::time::Instant::now();
            let r = run_claim(cat, c, opts);
            if timing {
                eprintln!(
                    "timing {:8.1} ms  {}",
                    t0.elapsed().as_secs_f64() * 1e3,
                    c.id
                );
            }
            done(&r);
            r
        })
        .collect()
}

fn render_value<T: Num>(v: &Value<T>) -> String {
    v.render(20, Layout::Inline)
}

fn log2_mag<T: Num>(v: &Value<T>) -> f64 {
    v.components()
        .iter()
        .map(|c| c.log2_abs())
        .fold(f64::NEG_INFINITY, f64::max)
}

fn named(p: &Point) -> Vec<Named> {
    p.render()
        .into_iter()
        .map(|(name, value)| Named { name, value })
        .collect()
}

/// Binds a point (f64 values, exactly) and the claim's `let` bindings.
fn setup<'r, T: Num>(
    cat: &'r Catalogue,
    claim: &Claim,
    point: &Point,
    like: T,
) -> Result<Evaluator<'r, T>, String> {
    let mut ev = Evaluator::new(&cat.registry, like.clone());
    for (n, v) in &point.vars {
        ev.bind(n, v.map(&mut |x: &f64| like.from_f64(*x)));
    }
    for b in &claim.lets {
        ev.bind_let(b)
            .map_err(|e| format!("let {}: {}", b.name, e.message))?;
    }
    Ok(ev)
}

fn eval_p<T: Num>(ev: &Evaluator<'_, T>, p: &PExpr) -> Result<Value<T>, String> {
    ev.eval(&p.expr).map_err(|e| {
        let at = e
            .span
            .and_then(|s| p.text.get(s.start..s.end))
            .map(|t| format!(" at '{t}'"))
            .unwrap_or_default();
        format!("{}{at}", e.message)
    })
}

/// log2 of the residual scale S at this point.
fn log2_scale<T: Num>(ev: &Evaluator<'_, T>, claim: &Claim, point: &Point) -> Result<f64, String> {
    match &claim.scale {
        Some(s) => {
            let v = eval_p(ev, s)?;
            let l = log2_mag(&v);
            if l.is_finite() {
                Ok(l)
            } else {
                Err("scale evaluates to zero".into())
            }
        }
        None => Ok(point.size().log2()),
    }
}

/// One identity sample at one rung: (log2 residual, lhs, rhs).
fn identity_at<T: Num>(
    cat: &Catalogue,
    claim: &Claim,
    lhs: &PExpr,
    rhs: &PExpr,
    point: &Point,
    like: T,
) -> Result<(f64, String, String), String> {
    let ev = setup(cat, claim, point, like)?;
    let l = eval_p(&ev, lhs)?;
    let r = eval_p(&ev, rhs)?;
    let diff = l
        .sub(&r)
        .map_err(|m| format!("lhs and rhs have different types: {m}"))?;
    let s = log2_scale(&ev, claim, point)?;
    let den = log2_mag(&l).max(log2_mag(&r)).max(s);
    Ok((log2_mag(&diff) - den, render_value(&l), render_value(&r)))
}

fn with_backend<R>(bits: u32, f64f: impl FnOnce(f64) -> R, mpfr: impl FnOnce(Float) -> R) -> R {
    if bits == 53 {
        f64f(0.0)
    } else {
        mpfr(Float::new(bits))
    }
}

fn expr_independence_at<T: Num>(
    cat: &Catalogue,
    claim: &Claim,
    expr: &PExpr,
    base: &Point,
    alts: &[Point],
    like: T,
) -> Result<(f64, String, String), String> {
    let ev0 = setup(cat, claim, base, like.clone())?;
    let v0 = eval_p(&ev0, expr)?;
    let s = log2_scale(&ev0, claim, base)?;
    let mut worst = (f64::NEG_INFINITY, render_value(&v0), render_value(&v0));
    for a in alts {
        let ev = setup(cat, claim, a, like.clone())?;
        let v = eval_p(&ev, expr)?;
        let d = v.sub(&v0)?;
        let r = log2_mag(&d) - log2_mag(&v0).max(log2_mag(&v)).max(s);
        if r > worst.0 || worst.0 == f64::NEG_INFINITY {
            worst = (r.max(worst.0), render_value(&v0), render_value(&v));
        }
    }
    Ok(worst)
}

/// Least-squares slope of log2|q| against log2 h for q(h) at h0·2^-j.
#[allow(clippy::too_many_arguments)]
fn asymptotic_at<T: Num>(
    cat: &Catalogue,
    claim: &Claim,
    expr: &PExpr,
    var: &str,
    h0: f64,
    steps: usize,
    point: &Point,
    like: T,
) -> Result<f64, String> {
    let mut xs = Vec::new();
    let mut ys = Vec::new();
    for j in 0..steps {
        let h = h0 * (-(j as f64)).exp2();
        let mut p = point.clone();
        p.vars.push((var.to_string(), Value::Real(h)));
        let ev = setup(cat, claim, &p, like.clone())?;
        let v = eval_p(&ev, expr)?;
        let l = log2_mag(&v);
        if l.is_finite() {
            xs.push(h.log2());
            ys.push(l);
        }
    }
    if xs.len() < 2 {
        return Ok(f64::INFINITY); // exactly zero: O(h^anything)
    }
    let n = xs.len() as f64;
    let mx = xs.iter().sum::<f64>() / n;
    let my = ys.iter().sum::<f64>() / n;
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    Ok(sxy / sxx)
}

/// Gaussian elimination with partial pivoting over any backend.
fn solve<T: Num>(mut a: Vec<Vec<T>>, mut b: Vec<T>) -> Result<Vec<T>, String> {
    let n = b.len();
    for c in 0..n {
        let mut piv = c;
        for r in c + 1..n {
            if a[r][c].real_fn(RealFn::Abs)? > a[piv][c].real_fn(RealFn::Abs)? {
                piv = r;
            }
        }
        if a[piv][c].is_zero() {
            return Err("singular Jacobian in Newton's method".into());
        }
        a.swap(c, piv);
        b.swap(c, piv);
        for r in c + 1..n {
            let f = a[r][c].clone() / a[c][c].clone();
            let pivot_row = a[c].clone();
            for (k, pk) in pivot_row.iter().enumerate().skip(c) {
                let t = pk.clone() * f.clone();
                a[r][k] = a[r][k].clone() - t;
            }
            let t = b[c].clone() * f;
            b[r] = b[r].clone() - t;
        }
    }
    let mut x = b.clone();
    for c in (0..n).rev() {
        let mut s = b[c].clone();
        for k in c + 1..n {
            s = s - a[c][k].clone() * x[k].clone();
        }
        x[c] = s / a[c][c].clone();
    }
    Ok(x)
}

/// Newton's method for an existence claim at one rung, from `start` (f64 values).
/// Returns (solution, log2 residual, in-set).
#[allow(clippy::too_many_arguments)]
fn newton_at<T: Num>(
    cat: &Catalogue,
    claim: &Claim,
    unknowns: &[String],
    equations: &[PExpr],
    in_set: Option<&PExpr>,
    point: &Point,
    start: &[f64],
    like: T,
) -> Result<(Vec<f64>, f64, bool), String> {
    let n = unknowns.len();
    let prec = like.precision().unwrap_or(53) as f64;
    let jac: Vec<Vec<Expr>> = equations
        .iter()
        .map(|e| {
            unknowns
                .iter()
                .map(|u| Expr {
                    kind: ExprKind::Deriv {
                        body: Box::new(e.expr.clone()),
                        var: u.clone(),
                        component: None,
                    },
                    span: Span::default(),
                })
                .collect()
        })
        .collect();
    let mut x: Vec<T> = start.iter().map(|s| like.from_f64(*s)).collect();
    let base = setup(cat, claim, point, like.clone())?;
    let s = log2_scale(&base, claim, point)?;
    let mut best = f64::INFINITY;
    let mut small_steps = 0;
    for _ in 0..100 {
        let mut ev = base.clone();
        for (u, v) in unknowns.iter().zip(&x) {
            ev.bind(u, Value::Real(v.clone()));
        }
        let f: Vec<T> = equations
            .iter()
            .map(|e| eval_p(&ev, e)?.as_real())
            .collect::<Result<_, _>>()?;
        let r = f
            .iter()
            .map(|v| v.log2_abs())
            .fold(f64::NEG_INFINITY, f64::max)
            - s;
        best = best.min(r);
        if r == f64::NEG_INFINITY || small_steps >= 2 {
            break;
        }
        let mut a = Vec::with_capacity(n);
        for row in &jac {
            let mut rr = Vec::with_capacity(n);
            for d in row {
                rr.push(ev.eval(d).map_err(|e| e.message)?.as_real()?);
            }
            a.push(rr);
        }
        let dx = solve(a, f)?;
        let mut step = f64::NEG_INFINITY;
        let mut size = 0.0f64;
        for (xi, di) in x.iter_mut().zip(&dx) {
            *xi = xi.clone() - di.clone();
            step = step.max(di.log2_abs());
            size = size.max(xi.log2_abs());
        }
        if step <= size.max(0.0) - prec + 4.0 {
            small_steps += 1;
        }
    }
    let mut ev = base.clone();
    for (u, v) in unknowns.iter().zip(&x) {
        ev.bind(u, Value::Real(v.clone()));
    }
    let inside = match in_set {
        Some(p) => eval_p(&ev, p)?.as_bool()?,
        None => true,
    };
    Ok((x.iter().map(|v| v.to_f64_()).collect(), best, inside))
}

struct Ladder {
    /// per rung: (bits, max log2 residual, argmax sample index)
    rungs: Vec<(u32, f64, usize)>,
}

fn ladder_verdict(l: &Ladder, claim: &Claim) -> (Verdict, Option<f64>, String) {
    let g = l
        .rungs
        .iter()
        .map(|(p, r, _)| f64::from(*p) + r)
        .fold(f64::NEG_INFINITY, f64::max);
    let g_rep = if g.is_finite() { g.max(0.0) } else { 0.0 };
    if g <= claim.max_loss_bits {
        return (
            Verdict::Holds,
            Some(g_rep),
            format!(
                "residual ≤ 2^(−p+{g_rep:.1}) at every rung (bound {})",
                claim.max_loss_bits
            ),
        );
    }
    let judged: Vec<_> = if l.rungs.iter().any(|r| r.0 >= 128) {
        l.rungs.iter().filter(|r| r.0 >= 128).collect()
    } else {
        l.rungs.iter().collect()
    };
    if !judged.is_empty() && judged.iter().all(|r| r.1 >= -claim.refute_floor_bits) {
        return (
            Verdict::Refuted,
            Some(g_rep),
            format!(
                "residual ≥ 2^-{} at every rung ≥ 128 bits: it does not shrink with precision",
                claim.refute_floor_bits
            ),
        );
    }
    (
        Verdict::Inconclusive,
        Some(g_rep),
        format!(
            "residual neither within 2^(−p+{}) at every rung nor above 2^-{} from 128 bits on (g = {g_rep:.1})",
            claim.max_loss_bits, claim.refute_floor_bits
        ),
    )
}

fn rung_list(l: &Ladder) -> Vec<Rung> {
    l.rungs
        .iter()
        .map(|(b, r, _)| Rung {
            bits: *b,
            residual: r.exp2(),
            log2: if r.is_finite() { Some(*r) } else { None },
        })
        .collect()
}

fn base_result(claim: &Claim) -> ClaimResult {
    let mut rendered: Vec<String> = claim.lets.iter().map(binding_to_latex).collect();
    match &claim.body {
        Body::Identity { lhs, rhs } => {
            rendered.push(format!("{} = {}", to_latex(&lhs.expr), to_latex(&rhs.expr)))
        }
        Body::Independence { expr, wrt, .. } => rendered.push(format!(
            "\\frac{{\\partial}}{{\\partial {wrt}}}\\left({}\\right) = 0",
            to_latex(&expr.expr)
        )),
        Body::Asymptotic {
            expr, var, order, ..
        } => rendered.push(format!("{} = O({var}^{{{order}}})", to_latex(&expr.expr))),
        Body::Existence { equations, .. } => rendered.extend(
            equations
                .iter()
                .map(|e| format!("{} = 0", to_latex(&e.expr))),
        ),
        Body::Negation(inner) => {
            let r = base_result(inner);
            rendered.extend(
                r.rendered
                    .into_iter()
                    .map(|s| format!("\\neg\\left({s}\\right)")),
            );
        }
        Body::Definition(bs) => rendered.extend(bs.iter().map(binding_to_latex)),
    }
    ClaimResult {
        id: claim.id.clone(),
        labels: claim.labels.clone(),
        location: claim.location.clone(),
        position: claim.position.clone(),
        printed: claim.printed.clone(),
        rendered,
        kind: claim.kind.name().to_string(),
        form: claim.form.clone(),
        corrects: claim.corrects.clone(),
        expect: claim.expect.clone(),
        verdict: Verdict::Inconclusive,
        as_expected: false,
        residuals: Vec::new(),
        loss_bits: None,
        max_loss_bits: claim.max_loss_bits,
        samples: 0,
        failures: Vec::new(),
        counterexample: None,
        exact: None,
        note: claim.note.clone(),
        reason: String::new(),
    }
}

/// A per-sample evaluation across all rungs: per rung (log2 residual, lhs, rhs).
type SampleRungs = Vec<(f64, String, String)>;

/// Draws samples and evaluates `at(point, bits)` at every rung; failed samples are
/// recorded and replaced (at most `claim.samples` failures).
fn collect<P: Clone>(
    claim: &Claim,
    bits: &[u32],
    res: &mut ClaimResult,
    mut draw: impl FnMut() -> Result<(P, Point), String>,
    mut at: impl FnMut(&P, u32) -> Result<(f64, String, String), String>,
) -> Result<Vec<(P, Point, SampleRungs)>, String> {
    let mut good = Vec::new();
    while good.len() < claim.samples {
        if res.failures.len() >= claim.samples {
            return Err(format!(
                "{} samples could not be evaluated (first: {})",
                res.failures.len(),
                res.failures.first().map_or("", |f| f.message.as_str())
            ));
        }
        let (p, pt) = draw()?;
        let mut per = Vec::new();
        let mut failed = None;
        for &b in bits {
            match at(&p, b) {
                Ok(x) => per.push(x),
                Err(m) => {
                    failed = Some((b, m));
                    break;
                }
            }
        }
        match failed {
            Some((b, m)) => res.failures.push(Failure {
                point: named(&pt),
                bits: b,
                message: m,
            }),
            None => good.push((p, pt, per)),
        }
    }
    Ok(good)
}

fn ladder_from<P>(bits: &[u32], good: &[(P, Point, SampleRungs)]) -> Ladder {
    let rungs = bits
        .iter()
        .enumerate()
        .map(|(j, b)| {
            let mut best = (f64::NEG_INFINITY, 0usize);
            for (i, (_, _, per)) in good.iter().enumerate() {
                if i == 0 || per[j].0 > best.0 {
                    best = (per[j].0, i);
                }
            }
            (*b, best.0, best.1)
        })
        .collect();
    Ladder { rungs }
}

fn counterexample<P>(
    bits: &[u32],
    l: &Ladder,
    good: &[(P, Point, SampleRungs)],
) -> Option<Counterexample> {
    let j = bits.len().checked_sub(1)?;
    let (b, r, i) = l.rungs[j];
    let (_, pt, per) = good.get(i)?;
    Some(Counterexample {
        bits: b,
        point: named(pt),
        lhs: per[j].1.clone(),
        rhs: per[j].2.clone(),
        log2_residual: if r.is_finite() { Some(r) } else { None },
    })
}

/// Verifies one claim.
pub fn run_claim(cat: &Catalogue, claim: &Claim, opts: &Options) -> ClaimResult {
    let mut res = base_result(claim);
    let bits: Vec<u32> = opts.bits.clone();
    // A panic in another layer (a bug there) must not take the whole run down: it makes
    // this claim inconclusive with the panic message as the reason.
    let mut scratch = res.clone();
    let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let o = run_body(cat, claim, opts, &bits, &mut scratch);
        (o, scratch)
    }));
    let outcome = match caught {
        Ok((o, r)) => {
            res = r;
            o
        }
        Err(p) => {
            let msg = p
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| p.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "unknown panic".into());
            Err(format!("internal error (panic) while evaluating: {msg}"))
        }
    };
    if let Err(m) = outcome {
        res.verdict = Verdict::Inconclusive;
        res.reason = m;
    }
    res.as_expected = match (&res.expect, res.verdict) {
        (None, Verdict::Defined) => true,
        (Some(e), v) => e == v.name(),
        _ => false,
    };
    res
}

fn run_body(
    cat: &Catalogue,
    claim: &Claim,
    opts: &Options,
    bits: &[u32],
    res: &mut ClaimResult,
) -> Result<(), String> {
    if bits.is_empty() {
        return Err("empty precision ladder".into());
    }
    match &claim.body {
        Body::Definition(_) => {
            res.verdict = Verdict::Defined;
            res.reason = "definition: no verdict".into();
            Ok(())
        }
        Body::Identity { lhs, rhs } => {
            let mut sampler = Sampler::new(cat, claim, 0)?;
            let good = collect(
                claim,
                bits,
                res,
                || sampler.draw().map(|p| (p.clone(), p)),
                |p: &Point, b| {
                    with_backend(
                        b,
                        |x| identity_at(cat, claim, lhs, rhs, p, x),
                        |x| identity_at(cat, claim, lhs, rhs, p, x),
                    )
                },
            )?;
            finish_ladder(claim, bits, res, &good);
            if let (Some(spec), true) = (claim.exact, opts.exact) {
                exact_identity(cat, claim, lhs, rhs, spec, res)?;
            }
            Ok(())
        }
        Body::Independence { expr, wrt, redraws } => {
            let mut sampler = Sampler::new(cat, claim, 0)?;
            let mut alt_sampler = Sampler::new(cat, claim, 2)?;
            let good = collect(
                claim,
                bits,
                res,
                || {
                    let base = sampler.draw()?;
                    if base.get(wrt).is_none() {
                        return Err(format!("'{wrt}' is not a sampled variable of this claim"));
                    }
                    let mut alts = Vec::new();
                    let mut tries = 0;
                    while alts.len() < *redraws {
                        tries += 1;
                        if tries > super::sampler::MAX_DRAWS {
                            return Err(format!("domain too thin to redraw '{wrt}'"));
                        }
                        let other = alt_sampler.draw()?;
                        let mut p = base.clone();
                        for (n, v) in p.vars.iter_mut() {
                            if n == wrt {
                                if let Some(nv) = other.get(wrt) {
                                    *v = nv.clone();
                                }
                            }
                        }
                        if sampler.accepts(&p).unwrap_or(false) {
                            alts.push(p);
                        }
                    }
                    Ok(((base.clone(), alts), base))
                },
                |(base, alts): &(Point, Vec<Point>), b| {
                    with_backend(
                        b,
                        |x| expr_independence_at(cat, claim, expr, base, alts, x),
                        |x| expr_independence_at(cat, claim, expr, base, alts, x),
                    )
                },
            )?;
            finish_ladder(claim, bits, res, &good);
            Ok(())
        }
        Body::Asymptotic {
            expr,
            var,
            order,
            h0,
            steps,
            slope_tol,
        } => {
            let mut sampler = Sampler::new(cat, claim, 0)?;
            let good = collect(
                claim,
                bits,
                res,
                || sampler.draw().map(|p| (p.clone(), p)),
                |p: &Point, b| {
                    let s = with_backend(
                        b,
                        |x| asymptotic_at(cat, claim, expr, var, *h0, *steps, p, x),
                        |x| asymptotic_at(cat, claim, expr, var, *h0, *steps, p, x),
                    )?;
                    Ok((s, format!("{s:.3}"), format!("{order}")))
                },
            )?;
            res.samples = good.len();
            let mut rungs = Vec::new();
            for (j, b) in bits.iter().enumerate() {
                let (mut worst, mut wi) = (f64::INFINITY, 0);
                for (i, g) in good.iter().enumerate() {
                    if g.2[j].0 < worst {
                        worst = g.2[j].0;
                        wi = i;
                    }
                }
                rungs.push((*b, worst, wi));
            }
            res.residuals = rungs
                .iter()
                .map(|(b, s, _)| Rung {
                    bits: *b,
                    residual: *s,
                    log2: None,
                })
                .collect();
            let judged: Vec<_> = if rungs.iter().any(|r| r.0 >= 128) {
                rungs.iter().filter(|r| r.0 >= 128).collect()
            } else {
                rungs.iter().collect()
            };
            let thr = order - slope_tol;
            if judged.iter().all(|r| r.1 >= thr) {
                res.verdict = Verdict::Holds;
                res.reason =
                    format!("fitted slope ≥ {thr} at every judged rung (claimed order {order})");
            } else if judged.iter().all(|r| r.1 < thr) {
                res.verdict = Verdict::Refuted;
                let (b, s, i) = *judged[judged.len() - 1];
                res.reason = format!("fitted slope {s:.3} < {thr} (claimed order {order})");
                res.counterexample = good.get(i).map(|g| Counterexample {
                    bits: b,
                    point: named(&g.1),
                    lhs: format!("slope {s:.4}"),
                    rhs: format!("order {order}"),
                    log2_residual: None,
                });
            } else {
                res.verdict = Verdict::Inconclusive;
                res.reason = "fitted slopes straddle the claimed order".into();
            }
            Ok(())
        }
        Body::Existence {
            unknowns,
            equations,
            start,
            in_set,
            tries,
        } => {
            let mut sampler = Sampler::new(cat, claim, 0)?;
            let mut start_sampler = Sampler::new(cat, claim, 3)?;
            let good = collect(
                claim,
                bits,
                res,
                || {
                    let p = sampler.draw()?;
                    // find an f64 solution from up to `tries` starts
                    let mut last = String::from("no start converged");
                    for _ in 0..*tries {
                        let ev = match setup(cat, claim, &p, 0.0f64) {
                            Ok(ev) => ev,
                            Err(m) => {
                                last = m;
                                continue;
                            }
                        };
                        let st: Result<Vec<f64>, String> = start
                            .iter()
                            .map(|s| start_sampler.eval_sampling(&s.expr, &ev)?.as_real())
                            .collect();
                        let st = match st {
                            Ok(s) => s,
                            Err(m) => {
                                last = m;
                                continue;
                            }
                        };
                        match newton_at(
                            cat,
                            claim,
                            unknowns,
                            equations,
                            in_set.as_ref(),
                            &p,
                            &st,
                            0.0f64,
                        ) {
                            Ok((x, r, inside)) if r <= -53.0 + claim.max_loss_bits && inside => {
                                return Ok(((p.clone(), x), p));
                            }
                            Ok((_, r, inside)) => {
                                last = format!(
                                    "Newton stalled at log2 residual {r:.1} (in set: {inside})"
                                )
                            }
                            Err(m) => last = m,
                        }
                    }
                    // a sample with no f64 solution: evaluation failure of this sample
                    Ok(((p.clone(), vec![f64::NAN; unknowns.len()]), p)).and_then(|x| {
                        if x.0 .1.iter().any(|v| v.is_nan()) {
                            Err(format!("sample_failure:{last}"))
                        } else {
                            Ok(x)
                        }
                    })
                },
                |(p, x0): &(Point, Vec<f64>), b| {
                    let (x, r, inside) = with_backend(
                        b,
                        |z| newton_at(cat, claim, unknowns, equations, in_set.as_ref(), p, x0, z),
                        |z| newton_at(cat, claim, unknowns, equations, in_set.as_ref(), p, x0, z),
                    )?;
                    if !inside {
                        return Err(format!(
                            "the solution at {b} bits is outside the stated set"
                        ));
                    }
                    let sol = unknowns
                        .iter()
                        .zip(&x)
                        .map(|(u, v)| format!("{u} = {v:e}"))
                        .collect::<Vec<_>>()
                        .join(", ");
                    Ok((r, sol, "0".into()))
                },
            );
            let good = match good {
                Err(m) if m.starts_with("sample_failure:") => {
                    return Err(format!("no solution found: {}", &m[15..]));
                }
                g => g?,
            };
            finish_ladder(claim, bits, res, &good);
            if res.verdict == Verdict::Refuted {
                res.verdict = Verdict::Inconclusive;
                res.reason = "Newton did not converge to working precision (existence cannot be refuted numerically)".into();
            }
            Ok(())
        }
        Body::Negation(inner) => {
            let r = run_claim(cat, inner, opts);
            res.residuals = r.residuals.clone();
            res.loss_bits = r.loss_bits;
            res.samples = r.samples;
            res.failures = r.failures.clone();
            res.counterexample = r.counterexample.clone();
            res.exact = r.exact.clone();
            res.verdict = match r.verdict {
                Verdict::Refuted => Verdict::Holds,
                Verdict::Holds | Verdict::Proved => Verdict::Refuted,
                _ => Verdict::Inconclusive,
            };
            res.reason = format!("inner claim {}: {}", r.verdict.name(), r.reason);
            Ok(())
        }
    }
}

fn finish_ladder<P>(
    claim: &Claim,
    bits: &[u32],
    res: &mut ClaimResult,
    good: &[(P, Point, SampleRungs)],
) {
    let l = ladder_from(bits, good);
    res.samples = good.len();
    res.residuals = rung_list(&l);
    let (v, g, reason) = ladder_verdict(&l, claim);
    res.verdict = v;
    res.loss_bits = g;
    res.reason = reason;
    if v == Verdict::Refuted {
        res.counterexample = counterexample(bits, &l, good);
    }
}

fn exact_identity(
    cat: &Catalogue,
    claim: &Claim,
    lhs: &PExpr,
    rhs: &PExpr,
    spec: super::catalogue::ExactSpec,
    res: &mut ClaimResult,
) -> Result<(), String> {
    let mut sampler = Sampler::new(cat, claim, 1)?;
    let zero = Rational::from_integer(0.into());
    let mut all_zero = true;
    let mut note = String::new();
    let mut n = 0;
    for _ in 0..spec.samples {
        let p = sampler.draw()?;
        let out = (|| -> Result<(bool, String, String), String> {
            let ev = setup(cat, claim, &p, zero.clone())?;
            let l = eval_p(&ev, lhs)?;
            let r = eval_p(&ev, rhs)?;
            let d = l.sub(&r)?;
            Ok((
                d.components().iter().all(|c| c.is_zero()),
                render_value(&l),
                render_value(&r),
            ))
        })();
        match out {
            Ok((true, _, _)) => n += 1,
            Ok((false, l, r)) => {
                all_zero = false;
                n += 1;
                res.verdict = Verdict::Refuted;
                res.reason = "exact rational evaluation gives lhs ≠ rhs".into();
                res.counterexample = Some(Counterexample {
                    bits: 0,
                    point: named(&p),
                    lhs: l,
                    rhs: r,
                    log2_residual: None,
                });
                break;
            }
            Err(m) => {
                all_zero = false;
                note = format!("not evaluable exactly: {m}");
                break;
            }
        }
    }
    let st = &sampler.stats;
    let acceptance = if st.draws == 0 {
        1.0
    } else {
        st.accepted as f64 / st.draws as f64
    };
    let set_size = if st.nonuniform { None } else { st.min_set };
    let per_point = set_size.map(|s| (f64::from(spec.degree) / (s as f64 * acceptance)).min(1.0));
    let overall = per_point.map(|q| q.powi(n as i32));
    if note.is_empty() {
        note = match (all_zero, set_size) {
            (true, Some(s)) => format!(
                "lhs − rhs is exactly 0 at {n} random rational points; a nonzero numerator of degree ≤ {} vanishes at one with probability ≤ {}/({s}·{acceptance:.3})",
                spec.degree, spec.degree
            ),
            (true, None) => "exactly 0, but a non-uniform primitive (normal) was sampled: no Schwartz–Zippel bound".into(),
            (false, _) => "exact evaluation found lhs ≠ rhs".into(),
        };
    }
    if all_zero && set_size.is_some() && res.verdict == Verdict::Holds {
        res.verdict = Verdict::Proved;
        res.reason = format!(
            "exactly zero at {n} rational points (Schwartz–Zippel bound {:.3e}) and holds numerically",
            overall.unwrap_or(1.0)
        );
    } else if all_zero && res.verdict == Verdict::Refuted {
        res.verdict = Verdict::Inconclusive;
        res.reason =
            "exact evaluation is zero but the float ladder refutes: engine inconsistency".into();
    }
    res.exact = Some(ExactInfo {
        points: n,
        degree: spec.degree,
        set_size,
        acceptance,
        per_point_bound: per_point,
        overall_bound: overall,
        all_zero,
        note,
    });
    Ok(())
}

/// Labels → claim ids with verdicts, for `--coverage`.
pub fn coverage_table(
    labels: &[String],
    results: &[ClaimResult],
) -> Vec<(String, Vec<(String, Verdict)>)> {
    labels
        .iter()
        .map(|l| {
            let ids = results
                .iter()
                .filter(|r| r.labels.contains(l))
                .map(|r| (r.id.clone(), r.verdict))
                .collect();
            (l.clone(), ids)
        })
        .collect()
}

/// Number of claims of `kind` (helper for summaries).
pub fn count_kind(results: &[ClaimResult], kind: Kind) -> usize {
    results.iter().filter(|r| r.kind == kind.name()).count()
}
