//! Asymptotic claims `f = O(hᵖ)` as `h → 0⁺` proved by exact power series in `h`
//! ([`crate::algebra::series`]).
//!
//! The claim's variables are bound as in an identity's proof (indeterminates, cases,
//! sign symbols); the small variable is the series variable, the claim's `let`s and
//! `expr` are evaluated on power series with coefficients in the prover's tower, and the
//! implicit maps are solved as series ([`crate::claims::implicit::Implicit::series`]).
//! The claim is **proved** when every coefficient of an exponent below `p` has normal
//! form 0; it is **refuted** when one of them is certified nonzero at a domain point
//! (there `f ~ c·hᵉ` with `e < p`).  For `expr = norm(X)` the components of `X` are
//! examined (also for `vnorm_inf` and `abs`): `‖X‖ = O(hᵖ)` exactly when every
//! component is.

use super::binding::bind_one;
use super::case::Signs;
use super::cases::{Role, case_points};
use super::{ProofInfo, ProofMethod, merge};
use crate::algebra::series::{Series, with_precision};
use crate::algebra::{AlgResult, AlgebraError, Proof, Ring, RingOptions, Sym, prove_components};
use crate::claims::ast::ExprKind;
use crate::claims::catalogue::PExpr;
use crate::claims::catalogue::claim::HypothesisKind;
use crate::claims::eval::Evaluator;
use crate::claims::kind::Verdict;
use crate::claims::sampler::Point;
use crate::claims::value::Value;
use crate::claims::verdict::context::{Ctx, eval};
use crate::claims::verdict::result::Evidence;
use crate::numbers::Scalar;
use std::time::Instant;

/// Outer functions whose argument's components are examined instead: each of `‖X‖₂`,
/// `‖X‖∞` and `|x|` is `O(hᵖ)` exactly when every real component of its argument is.
const PEELED: [&str; 3] = ["norm", "vnorm_inf", "abs"];

/// The expression whose coefficients a proof examines, and the factor of the order:
/// `‖X‖`, `‖X‖∞` and `|x|` give their argument ([`PEELED`]), and `√x = O(hᵖ)` exactly
/// when `x = O(h²ᵖ)` (`|√x| = |x|^(1/2)`); `None` when nothing is peeled.
fn peeled(expr: &PExpr) -> (Option<&crate::claims::ast::Expr>, f64) {
    let mut inner = None;
    let mut factor = 1.0;
    let mut at = &expr.expr;
    while let ExprKind::Call(name, args) = &at.kind {
        if args.len() != 1 || !(PEELED.contains(&name.as_str()) || name == "sqrt") {
            break;
        }
        if name == "sqrt" {
            factor *= 2.0;
        }
        at = &args[0];
        inner = Some(at);
    }
    (inner, factor)
}

/// The most orders of `h` beyond the claimed one that a proof computes.
const EXTRA_ORDERS: i32 = 4;

/// The asymptotic claim as the series proof reads it.
#[derive(Clone, Copy)]
pub struct Order<'a> {
    /// The expression.
    pub expr: &'a PExpr,
    /// The small variable.
    pub var: &'a str,
    /// The claimed order `p`.
    pub order: f64,
    /// Record the derivation of every coefficient as a certificate
    /// ([`crate::algebra::certificate`]).
    pub certificate: bool,
}

/// Attempts the series proof of `expr = O(var^order)` on the claim's domain (every case
/// of it).
pub fn prove_order(ctx: Ctx<'_>, claim: Order<'_>) -> ProofInfo {
    let t0 = Instant::now();
    let dom = match super::cases::domain(ctx) {
        Ok(d) => d,
        Err(m) => return ProofInfo::none(m),
    };
    if let Some(why) = super::scope::not_analytic(ctx, &dom.vars, &[claim.expr]) {
        return ProofInfo::none(why);
    }
    let signs = Signs {
        positivity: dom.positivity.clone(),
    };
    let (plain, roles) = (&dom.plain, &dom.roles);
    let mut info = each_case(ctx, plain, |points| {
        prove_case(ctx, roles, points, claim, &signs)
    });
    if info.is_proved() {
        info.notes.push(format!(
            "the coefficients of {}^e for e < {} of the power series are 0",
            claim.var, claim.order
        ));
    }
    info.ms = t0.elapsed().as_secs_f64() * 1e3;
    info
}

/// A series proof over every case of the domain (each case's points drawn by
/// [`case_points`]), stopping at the first case not proved; method `series`.
pub(super) fn each_case(
    ctx: Ctx<'_>,
    plain: &[(String, (Role, usize))],
    mut prove: impl FnMut(&[Point]) -> Proof,
) -> ProofInfo {
    each_case_parts(ctx, plain, |key, points| {
        vec![(key.to_vec(), prove(&points))]
    })
}

/// [`each_case`] for a proof that may split a case into parts: `prove` gives each part's
/// labels and proof, from the case's key and points.
pub(super) fn each_case_parts(
    ctx: Ctx<'_>,
    plain: &[(String, (Role, usize))],
    mut prove: impl FnMut(&[String], Vec<Point>) -> Vec<(Vec<String>, Proof)>,
) -> ProofInfo {
    let cases = match case_points(ctx, plain) {
        Ok(c) if !c.is_empty() => c,
        Ok(_) => return ProofInfo::none("no case of the domain has enough points"),
        Err(m) => return ProofInfo::none(m),
    };
    let mut info = ProofInfo::none("");
    info.reason = None;
    info.method = ProofMethod::Series;
    for (key, points) in cases {
        for (label, p) in prove(&key, points) {
            let stop = !p.is_proved();
            merge(ctx, &mut info, &label, p);
            if stop {
                return info;
            }
        }
    }
    info
}

/// One case: the coefficients below the order, each tested for 0; in `t = √var` where
/// a value has no power series in `var` ([`ODD`]).
fn prove_case(
    ctx: Ctx<'_>,
    roles: &[(String, Role, &PExpr)],
    points: &[Point],
    claim: Order<'_>,
    signs: &Signs,
) -> Proof {
    let reason = |p: &Proof| match &p.outcome {
        crate::algebra::Outcome::NotProved(why) => why.clone(),
        _ => String::new(),
    };
    let mut step = 1;
    let mut extra = 0;
    loop {
        let proof = prove_case_in(ctx, roles, points, claim, signs, (step, extra));
        let why = reason(&proof);
        if step == 1 && why.contains(ODD) {
            (step, extra) = (2, 0);
        } else if (why.contains(SHORT) || why.contains(VANISH)) && extra < EXTRA_ORDERS * step {
            // more orders may reach the coefficient or decide the sign: a fresh ring
            extra += 1;
        } else {
            return proof;
        }
    }
}

/// [`prove_case`] with `var = tˢᵗᵉᵖ`, from `extra` orders beyond the claimed one.
fn prove_case_in(
    ctx: Ctx<'_>,
    roles: &[(String, Role, &PExpr)],
    points: &[Point],
    claim: Order<'_>,
    signs: &Signs,
    (step, extra): (i32, i32),
) -> Proof {
    let opts = RingOptions {
        points: points.len(),
        positivity: signs.positivity.clone(),
        certificate: claim.certificate,
        ..RingOptions::default()
    };
    let labels = std::sync::Mutex::new(Vec::new());

    let mut proof = prove_components(opts, &ctx.claim.id, |ring| {
        let (pairs, names): (Vec<_>, Vec<_>) =
            (in_powers(ctx, ring, roles, points, claim, (step, extra))?)
                .into_iter()
                .unzip();
        *labels.lock().unwrap_or_else(|e| e.into_inner()) = names;
        Ok(pairs)
    });
    let names = labels.into_inner().unwrap_or_else(|e| e.into_inner());
    if let Some(c) = proof.certificate.as_mut() {
        let n = working_precision(claim, (step, extra));
        *c = series_line(c, (claim.var, claim.order), step, n);
    }
    let rename = |text: &mut String| {
        let named = (names.iter().enumerate().rev())
            .find_map(|(i, n)| Some((text.strip_prefix(&format!("component {}: ", i + 1))?, n)));
        let single = (names.len() == 1).then(|| (text.as_str(), &names[0]));
        if let Some((rest, n)) = named.or(single) {
            *text = format!("{n}: {rest}");
        }
    };
    if let Some(w) = proof.witness.as_mut() {
        rename(w);
    }
    if let crate::algebra::Outcome::NotProved(why) = &mut proof.outcome {
        rename(why);
    }
    proof
}

/// The part of the message of a square root with no power series in `h`
/// ([`Series::try_sqrt`]), after which the proof is run in `t = √h`.
const ODD: &str = "of odd valuation";

/// [`coefficients`] at `extra` orders beyond the claimed one, in the series variable
/// `t` with `var = tˢᵗᵉᵖ` (`step` 2: a power series in `√var`, for values such as
/// `√var·c`; `f = O(varᵖ)` exactly when `f = O(t^(step·p))` as `t → 0⁺`).
fn in_powers(
    ctx: Ctx<'_>,
    ring: &Ring,
    roles: &[(String, Role, &PExpr)],
    points: &[Point],
    claim: Order<'_>,
    (step, extra): (i32, i32),
) -> AlgResult<Vec<((Sym, Sym), String)>> {
    let n = working_precision(claim, (step, extra));
    with_precision(n, || coefficients(ctx, ring, roles, points, claim, step))
}

/// The working precision `n` (series cut at `O(tⁿ)`) of a proof with `var = tˢᵗᵉᵖ`,
/// `extra` orders beyond the claimed one.
fn working_precision(claim: Order<'_>, (step, extra): (i32, i32)) -> i32 {
    (claim.order * peeled(claim.expr).1 * f64::from(step)).ceil() as i32 + 1 + extra
}

/// The part of the message of a coefficient beyond the working precision.
const SHORT: &str = "the power series is known to O(";

/// The part of the message of a sign asked of a series whose known coefficients are all
/// 0 ([`Series::sign`]): more orders may decide it.
const VANISH: &str = "whose known coefficients vanish";

/// `var^(e/step)`, as a message names a coefficient.
fn power(var: &str, e: i32, step: i32) -> String {
    if step == 1 || e % step == 0 {
        format!("{var}^{}", e / step)
    } else {
        format!("{var}^({e}/{step})")
    }
}

/// The coefficients of the exponents below the order, against 0, each with its name; a
/// [`SHORT`] error when the working precision does not reach them.
fn coefficients(
    ctx: Ctx<'_>,
    ring: &Ring,
    roles: &[(String, Role, &PExpr)],
    points: &[Point],
    claim: Order<'_>,
    step: i32,
) -> AlgResult<Vec<((Sym, Sym), String)>> {
    let fail = AlgebraError::Domain;
    let t = Series::var(ring);
    let at = if step == 2 { t.try_mul(&t)? } else { t };
    let ev = bind(ctx, ring, roles, points, (claim.var, at))?;
    let (inner, factor) = peeled(claim.expr);
    let order = claim.order * factor;
    let value = match inner {
        Some(x) => ev.eval(x).map_err(|e| fail(e.message))?,
        None => eval(&ev, claim.expr).map_err(fail)?,
    };
    if let Some(e) = ring.error() {
        return Err(e);
    }
    let zero = ring.integer(0);
    let mut pairs = Vec::new();
    let comps = value.components();
    let several = comps.len() > 1;
    for (j, s) in comps.into_iter().enumerate() {
        let mut e = s.valuation().min(0);
        while f64::from(e) < order * f64::from(step) {
            let c = s.coefficient(e).ok_or_else(|| {
                AlgebraError::Domain(format!(
                    "the power series is known to O({}) only",
                    power(claim.var, s.precision(), step)
                ))
            })?;
            let of = if several {
                format!(" of component {}", j + 1)
            } else {
                String::new()
            };
            s.note_coefficient(j + 1, e);
            pairs.push((
                (c, zero.clone()),
                format!("the coefficient of {}{of}", power(claim.var, e, step)),
            ));
            e += 1;
        }
        s.claim_vanishing(j + 1, e);
    }
    Ok(pairs)
}

/// The certificate `cert` of one case with its `series` line after the `claims N` line:
/// `series VAR step S order P precision N`, the series variable `t` with `VAR = tˢ`,
/// the claimed order (0 for an existence claim), and the working precision (module
/// [`crate::algebra::certificate`]).
pub(super) fn series_line(cert: &str, (var, order): (&str, f64), step: i32, n: i32) -> String {
    let line = format!("series {var} step {step} order {order} precision {n}\n");
    let mut out = String::with_capacity(cert.len() + line.len());
    let mut done = false;
    for l in cert.split_inclusive('\n') {
        out.push_str(l);
        if !done && l.starts_with("claims ") {
            out.push_str(&line);
            done = true;
        }
    }
    out
}

/// The claim's variables as constant series, the small variable `var` as `at` (the
/// series variable, or 0 for the equations at `var = 0`), and the claim's `let`s.
pub(super) fn bind<'c>(
    ctx: Ctx<'c>,
    ring: &Ring,
    roles: &[(String, Role, &PExpr)],
    points: &[Point],
    var: (&str, Series),
) -> AlgResult<Evaluator<'c, Series>> {
    let syms = symbols(ctx, ring, roles, points, var.0)?;
    scope(ctx, roles, &syms, var)
}

/// The symbols of the sampled variables other than `var` and the computed ones, as
/// constant series (`None` where the value is computed), created once per ring.
pub(super) fn symbols(
    ctx: Ctx<'_>,
    ring: &Ring,
    roles: &[(String, Role, &PExpr)],
    points: &[Point],
    var: &str,
) -> AlgResult<Vec<Option<Value<Series>>>> {
    let syms = Evaluator::new(&ctx.cat.registry, ring.integer(0));
    (roles.iter())
        .map(|(name, role, def)| {
            if name == var || *role == Role::Computed {
                return Ok(None);
            }
            let v = bind_one(&syms, ring, name, role, def, points)?;
            Ok(Some(v.map(&mut |s: &Sym| Series::constant(s))))
        })
        .collect()
}

/// The evaluator of the claim's variables ([`symbols`]) with `var` at `at`, the computed
/// variables and the `let`s evaluated from them.
pub(super) fn scope<'c>(
    ctx: Ctx<'c>,
    roles: &[(String, Role, &PExpr)],
    syms: &[Option<Value<Series>>],
    (var, at): (&str, Series),
) -> AlgResult<Evaluator<'c, Series>> {
    let fail = AlgebraError::Domain;
    let mut ev = Evaluator::new(&ctx.cat.registry, at.zero());
    let mut bound = false;
    for ((name, _, def), sym) in roles.iter().zip(syms) {
        let value = match sym {
            _ if name == var => {
                bound = true;
                Value::Real(at.clone())
            }
            Some(v) => v.clone(),
            None => eval(&ev, def).map_err(fail)?,
        };
        ev.bind(name, value);
    }
    if !bound {
        ev.bind(var, Value::Real(at));
    }
    for b in &ctx.claim.lets {
        ev.bind_let(b)
            .map_err(|e| fail(format!("let {}: {}", b.name, e.message)))?;
    }
    Ok(ev)
}

/// Makes a sampled asymptotic verdict `proved` when the series proof succeeds, and
/// `refuted` with a certificate when a coefficient below the order is certified nonzero
/// at a domain point (whatever the slopes said).  A series proof against a refutation
/// by slopes is reported as the conflict it is.
pub fn judge_order(ctx: Ctx<'_>, claim: Order<'_>, ev: &mut Evidence) {
    if !matches!(
        ev.verdict,
        Verdict::Holds | Verdict::Refuted | Verdict::Inconclusive
    ) {
        return;
    }
    let mut info = prove_order(ctx, claim);
    if info.is_proved() {
        if ev.verdict == Verdict::Refuted {
            ev.reason = format!(
                "{}; the power series proves the order against this refutation (a conflict to investigate)",
                ev.reason
            );
            info.method = ProofMethod::None;
        } else {
            ev.verdict = Verdict::Proved;
            ev.reason = format!(
                "every coefficient of {}^e, e < {}, of its exact power series is 0 ({}); the slopes agree",
                claim.var,
                claim.order,
                info.extent()
            );
        }
    } else if let Some(w) = info.witness.clone() {
        info.method = ProofMethod::Witness;
        ev.reason = format!(
            "certified: in its exact power series, {w} (numerically: {})",
            ev.reason
        );
        ev.verdict = Verdict::Refuted;
    }
    ev.proof = Some(info);
}

/// The claim's sign hypotheses (`when = "a > b"`) that hold for every small enough
/// `h > 0`, as the paper's "for h small enough" says: with the claim's variable `h` the
/// series variable, the leading coefficient of `±(a − b)` is proved positive on the
/// domain, in every case of it.  Empty when the claim has no free variable `h`.
pub(super) fn small_h_signs(ctx: Ctx<'_>) -> Vec<String> {
    let signs: Vec<(String, PExpr, i32)> = (ctx.cat.hypotheses_of(ctx.claim).into_iter())
        .filter_map(|h| match &h.kind {
            HypothesisKind::Sign { condition, sign } => {
                Some((h.name.clone(), condition.clone(), *sign))
            }
            HypothesisKind::Branch(_) => None,
        })
        .collect();
    let Ok(dom) = super::cases::domain(ctx) else {
        return Vec::new();
    };
    let free_h = (dom.plain.iter()).any(|(n, (r, _))| n == "h" && *r == Role::Free);
    if signs.is_empty() || !free_h {
        return Vec::new();
    }
    let Ok(cases) = case_points(ctx, &dom.plain) else {
        return Vec::new();
    };
    let mut holds = vec![!cases.is_empty(); signs.len()];
    for points in cases.values() {
        let ring = Ring::new(RingOptions {
            points: points.len(),
            positivity: dom.positivity.clone(),
            ..RingOptions::default()
        });
        with_precision(4, || {
            let ev = bind(ctx, &ring, &dom.roles, points, ("h", Series::var(&ring))).ok();
            for (ok, (_, condition, sign)) in holds.iter_mut().zip(&signs) {
                *ok &= ev
                    .as_ref()
                    .is_some_and(|ev| positive_for_small_h(ev, condition, *sign));
            }
        });
    }
    (signs.into_iter().zip(holds))
        .filter(|(_, ok)| *ok)
        .map(|((name, _, _), _)| name)
        .collect()
}

/// Is `sign·(a − b)` of the condition `a ≷ b` positive for small `h > 0` (its leading
/// coefficient proved positive, no error in the ring)?
fn positive_for_small_h(ev: &Evaluator<'_, Series>, condition: &PExpr, sign: i32) -> bool {
    let ExprKind::Binary(_, a, b) = &condition.expr.kind else {
        return false;
    };
    let side = |e| match ev.eval(e) {
        Ok(Value::Real(x)) => Some(x),
        _ => None,
    };
    let (Some(a), Some(b)) = (side(a), side(b)) else {
        return false;
    };
    let d = if sign > 0 { a - b } else { b - a };
    let ring = d.ring().clone();
    matches!(d.sign(), Ok(1)) && ring.error().is_none()
}

/// Where a symbolic proof substituted a stated value into an implicit map's equations
/// ([`super::binding::stated_value`]), that value solves them; it is the map's value
/// only if it is the branch the map takes, the one continuous at `h = 0`.  By the
/// implicit function theorem that branch is, for small `h`, the only solution near its
/// value at `h = 0`, so it suffices that the stated value tends to it: `lhs − rhs`,
/// with the call solved as the power series of its branch, is `O(h)`.  `Ok` when the
/// claim states no such value; the reason otherwise.
pub(super) fn stated_value_is_the_branch(
    ctx: Ctx<'_>,
    (lhs, rhs): (&PExpr, &PExpr),
) -> Result<(), String> {
    let implicit = |p: &PExpr| {
        matches!(&p.expr.kind, ExprKind::Call(name, _)
            if ctx.cat.registry.ext(name).is_some_and(|r| r.f.implicit().is_some()))
    };
    if !(implicit(lhs) || implicit(rhs)) {
        return Ok(());
    }
    use crate::claims::ast::{BinOp, Expr};
    let span = lhs.expr.span;
    let diff = Expr {
        kind: ExprKind::Binary(
            BinOp::Sub,
            Box::new(lhs.expr.clone()),
            Box::new(rhs.expr.clone()),
        ),
        span,
    };
    let expr = PExpr {
        expr: Expr {
            kind: ExprKind::Call("vnorm_inf".into(), vec![diff]),
            span,
        },
        text: format!("vnorm_inf(({}) - ({}))", lhs.text.trim(), rhs.text.trim()),
        origin: lhs.origin.clone(),
    };
    let info = prove_order(
        ctx,
        Order {
            expr: &expr,
            var: "h",
            order: 1.0,
            certificate: false,
        },
    );
    if info.is_proved() {
        return Ok(());
    }
    Err(format!(
        "the stated value solves the map's equations, but it is not shown to be the map's branch, continuous at h = 0 (the difference of the two as power series in h is not shown to be O(h): {})",
        info.reason.unwrap_or_default()
    ))
}
