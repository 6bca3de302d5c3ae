//! Existence claims proved for every small enough `h > 0` by the implicit function
//! theorem, as the paper argues them ("for h small, … has a solution near …").
//!
//! The claim's `start` expressions at `h = 0` (each `uniform(a, b)` of a start taken at
//! its midpoint, `normal(μ, σ)` at `μ`) must solve the equations at `h = 0` exactly, and
//! the Jacobian there must have a determinant of proved sign; then the power-series
//! solution ([`crate::algebra::series_solve::solve`]) is the Taylor series of a solution
//! that exists for small `h`.  The claim's `in` condition is evaluated on that series:
//! every comparison is decided by a leading coefficient of proved sign, so it holds for
//! every small enough `h`.  Otherwise the claim keeps its sampled verdict.

use super::ProofInfo;
use super::cases::Domain;
use super::cases::Role;
use super::series::{each_case_parts, scope, symbols};
use super::split::{MAX_SPLITS, draw_part};
use crate::algebra::series::{Series, with_precision};
use crate::algebra::series_solve::solve;
use crate::algebra::split::SignSplit;
use crate::algebra::{AlgResult, AlgebraError, Ring, RingOptions, prove_components};
use crate::algebra::{Outcome, Proof};
use crate::claims::ast::{BinOp, Expr, ExprKind};
use crate::claims::catalogue::PExpr;
use crate::claims::eval::Evaluator;
use crate::claims::kind::Verdict;
use crate::claims::sampler::Point;
use crate::claims::value::Value;
use crate::claims::verdict::context::Ctx;
use crate::claims::verdict::result::Evidence;
use crate::numbers::Scalar;
use std::time::Instant;

/// The existence claim as the proof reads it.
#[derive(Clone, Copy)]
pub struct System<'a> {
    /// Unknown names.
    pub unknowns: &'a [String],
    /// Equations (= 0).
    pub equations: &'a [PExpr],
    /// Start expressions.
    pub start: &'a [PExpr],
    /// Membership predicate.
    pub in_set: Option<&'a PExpr>,
    /// Record the derivation as a certificate (module [`crate::algebra::certificate`]).
    pub certificate: bool,
}

/// The working precision of the series: the `in` condition's comparisons are decided
/// by their first nonzero coefficient below it.
const PRECISION: i32 = 4;

/// Turns a sampled `holds` into `proved` (method `series`) when the implicit function
/// theorem proves the solution for every small enough `h` (see the module doc); an
/// attempt that does not prove leaves the sampled evidence (and its certificates) as it
/// is.
pub fn judge_existence(ctx: Ctx<'_>, sys: System<'_>, ev: &mut Evidence) {
    if ev.verdict != Verdict::Holds {
        return;
    }
    let info = prove_existence(ctx, sys);
    if info.is_proved() {
        ev.verdict = Verdict::Proved;
        ev.reason = format!(
            "a solution exists for every small enough h > 0, by the implicit function theorem at h = 0 ({}), and lies in the stated set; sampled: {}",
            info.extent(),
            ev.reason
        );
        ev.proof = Some(info);
    } else if ev.proof.is_none() {
        ev.proof = Some(info);
    }
}

/// The proof attempt over every case of the claim's domain.
pub fn prove_existence(ctx: Ctx<'_>, sys: System<'_>) -> ProofInfo {
    let t0 = Instant::now();
    let dom = match super::cases::domain(ctx) {
        Ok(d) => d,
        Err(m) => return ProofInfo::none(m),
    };
    if !(dom.plain.iter()).any(|(n, (r, _))| n == "h" && *r == Role::Free) {
        return ProofInfo::none("no free variable h to take to 0");
    }
    let mut info = each_case_parts(ctx, &dom.plain, |key, points| {
        parts(ctx, (&dom, sys), key, points, Vec::new())
    });
    info.ms = t0.elapsed().as_secs_f64() * 1e3;
    info
}

/// The proof of one part of a case (the whole case when `conds` is empty): when a sign
/// that the proof must decide differs between the part's points (the sign of `J₁ = (B + C
/// − A)/2` in `1/|J₁|`, say), the part is split by it, each side drawn afresh and proved
/// with that sign as its condition, at most [`MAX_SPLITS`] deep (as the identity proofs
/// do, `super::split`).  The parts cover the domain except where the sign's value is 0.
fn parts(
    ctx: Ctx<'_>,
    (dom, sys): (&Domain<'_>, System<'_>),
    key: &[String],
    points: Vec<Point>,
    conds: Vec<(SignSplit, i32)>,
) -> Vec<(Vec<String>, Proof)> {
    let mut label = key.to_vec();
    label.extend(
        conds
            .iter()
            .map(|(c, s)| format!("{} {} 0", c.what, if *s > 0 { ">" } else { "<" })),
    );
    let opts = RingOptions {
        points: points.len(),
        positivity: dom.positivity.clone(),
        hypotheses: conds.clone(),
        certificate: sys.certificate,
        ..RingOptions::default()
    };
    let mut p = prove_components(opts, &ctx.claim.id, |ring| {
        with_precision(PRECISION, || {
            in_set_for_small_h(ctx, ring, (&dom.roles, &points), sys)
        })
    });
    if let Some(c) = p.certificate.as_mut() {
        *c = super::series::series_line(c, ("h", 0.0), 1, PRECISION);
    }
    let split = match &p.split {
        Some(s)
            if !p.is_proved()
                && conds.len() < MAX_SPLITS
                && !conds.iter().any(|(c, _)| c.same(s)) =>
        {
            s.clone()
        }
        _ => return vec![(label, p)],
    };
    let mut out = Vec::new();
    for sign in [1, -1] {
        let mut c = conds.clone();
        c.push((split.clone(), sign));
        let side = match draw_part(ctx, &dom.roles, key, &c) {
            Ok(pts) => parts(ctx, (dom, sys), key, pts, c),
            Err(why) => {
                let mut q = p.clone();
                q.outcome = Outcome::NotProved(format!(
                    "the part where {} {} 0 is not reached ({why}), so it is neither proved nor refuted",
                    split.what,
                    if sign > 0 { ">" } else { "<" }
                ));
                vec![(label.clone(), q)]
            }
        };
        let stop = side.iter().any(|(_, q)| !q.is_proved());
        out.extend(side);
        if stop {
            break;
        }
    }
    out
}

/// The series solution and its `in` condition: `Ok` with nothing left to test when the
/// condition holds for small `h`.
fn in_set_for_small_h(
    ctx: Ctx<'_>,
    ring: &Ring,
    (roles, points): (&[(String, Role, &PExpr)], &[Point]),
    sys: System<'_>,
) -> AlgResult<Vec<(crate::algebra::Sym, crate::algebra::Sym)>> {
    let fail = AlgebraError::Domain;
    let h = Series::var(ring);
    let syms = symbols(ctx, ring, roles, points, "h")?;
    let at = |v: Series| scope(ctx, roles, &syms, ("h", v));
    let ev = at(h.clone())?;
    let mut x0 = Vec::new();
    for s in sys.start {
        let v = ev.eval(&midpoints(&s.expr)).map_err(|e| fail(e.message))?;
        let v = v.as_real().map_err(fail)?;
        x0.push(Series::constant(
            &v.coefficient(0).unwrap_or_else(|| ring.integer(0)),
        ));
    }
    let zero = at(h.zero())?;
    let e = |x: &[Series], hh: &Series| -> Result<Vec<Series>, String> {
        let base = if hh.is_zero() { &zero } else { &ev };
        equations(base, sys, x)
    };
    let x = solve(x0, &e, &h).map_err(fail)?;
    Series::record_solution(sys.unknowns, &x);
    ring.note(format!(
        "the start values at h = 0 solve the equations there exactly, and the Jacobian at h = 0 has a determinant of proved sign: by the implicit function theorem a solution exists for small h, with the power series {}",
        (sys.unknowns.iter().zip(&x))
            .map(|(u, s)| format!("{u} = {}", s.render_short(60)))
            .collect::<Vec<_>>()
            .join(", ")
    ));
    if let Some(cond) = sys.in_set {
        let inside = bound(&ev, sys, &x).eval(&cond.expr);
        match inside {
            Ok(Value::Bool(true)) if ring.error().is_none() => {}
            Ok(_) => {
                return Err(fail(
                    "the solution's set condition is not proved for small h".into(),
                ));
            }
            Err(e) => return Err(fail(format!("the set condition: {}", e.message))),
        }
    }
    if let Some(e) = ring.error() {
        return Err(e);
    }
    Ok(vec![(ring.integer(0), ring.integer(0))])
}

/// `ev` with the unknowns bound to `x`.
fn bound<'c>(ev: &Evaluator<'c, Series>, sys: System<'_>, x: &[Series]) -> Evaluator<'c, Series> {
    let mut ev = ev.clone();
    for (u, v) in sys.unknowns.iter().zip(x) {
        ev.bind(u, Value::Real(v.clone()));
    }
    ev
}

/// The equations at the unknowns `x`.
fn equations(
    ev: &Evaluator<'_, Series>,
    sys: System<'_>,
    x: &[Series],
) -> Result<Vec<Series>, String> {
    let ev = bound(ev, sys, x);
    (sys.equations.iter())
        .map(|q| ev.eval(&q.expr).map_err(|e| e.message)?.as_real())
        .collect()
}

/// `e` with every `uniform(a, b)` replaced by `(a + b)/2` and `normal(μ, σ)` by `μ`.
fn midpoints(e: &Expr) -> Expr {
    let mut out = e.clone();
    replace_draws(&mut out);
    out
}

fn replace_draws(e: &mut Expr) {
    let span = e.span;
    let node = |kind| Expr { kind, span };
    match &mut e.kind {
        ExprKind::Call(name, args) if name == "uniform" && args.len() == 2 => {
            let sum = node(ExprKind::Binary(
                BinOp::Add,
                Box::new(args[0].clone()),
                Box::new(args[1].clone()),
            ));
            let two = node(ExprKind::Num("2".into()));
            e.kind = ExprKind::Binary(BinOp::Div, Box::new(sum), Box::new(two));
        }
        ExprKind::Call(name, args) if name == "normal" && args.len() == 2 => {
            *e = args[0].clone();
        }
        ExprKind::Call(_, args) | ExprKind::List(args) => args.iter_mut().for_each(replace_draws),
        ExprKind::Unary(_, a) => replace_draws(a),
        ExprKind::Binary(_, a, b) => {
            replace_draws(a);
            replace_draws(b);
        }
        ExprKind::If(c, a, b) => {
            replace_draws(c);
            replace_draws(a);
            replace_draws(b);
        }
        ExprKind::Index(a, ix) => {
            replace_draws(a);
            ix.iter_mut().for_each(replace_draws);
        }
        _ => {}
    }
}
