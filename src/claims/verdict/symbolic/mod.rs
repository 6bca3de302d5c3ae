//! Symbolic proofs of identities: the claim's formulas evaluated exactly in the prover's
//! tower ([`crate::algebra`]), and `lhs − rhs` reduced to its normal form.  A claim is
//! `proved` when that normal form is 0, and only then.
//!
//! **Variables.**  A sampled variable whose definition draws a continuous primitive
//! (`uniform`, `randint`, `normal`) becomes an indeterminate (one per component of a
//! vec3): an identity proved for independent indeterminates holds in particular on the
//! sampled domain.  A variable drawn only by `sign()` or `choice(…)` takes finitely many
//! values: the proof enumerates them as cases and every case must be proved.  A variable
//! without primitives is evaluated symbolically from the earlier ones.
//!
//! **Decisions.**  Comparisons, `abs`, `sign`, `min`, `max`, the branch of a square
//! root, the condition of an `if` and the choice of a regime are decided as
//! [`crate::algebra::Decision`]s: proved on the domain (its parametrization by
//! positive parameters, module `positivity`), given by a hypothesis the claim states
//! (field `hypotheses`), fixed by the definition of a sign symbol, or by the part of a
//! split domain the proof is on.  The values at the domain points never decide one: a
//! sign that none of these decides splits the domain by it (module `split`), or leaves
//! the claim unproved with that sign as the reason.
//! A comparison yields a truth value, which only an `if` can use.
//!
//! ```
//! use eulertop::bindings::euler_top::registry;
//! use eulertop::claims::catalogue::load_sources;
//! use eulertop::claims::verdict::{run_claim, Options, ProofMethod, Verdict};
//! let toml = r#"
//! [[claim]]
//! id = "double-angle"
//! environment = "Section 2"
//! role = "statement"
//! labels = []
//! location = "a doc example"
//! printed = 'sn(2u)'
//! kind = "identity"
//! expect = "proved"
//! vars = [["u", "uniform(-1, 1)"], ["k", "uniform(0.1, 0.9)"]]
//! lhs = "sn(2*u, k)"
//! rhs = "2*sn(u, k)*cn(u, k)*dn(u, k) / (1 - k^2*sn(u, k)^4)"
//! "#;
//! let cat = load_sources(&[("doc.toml".into(), toml.into())], registry().unwrap()).unwrap();
//! let r = run_claim(&cat, &cat.claims[0], &Options::default());
//! assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
//! assert_eq!(r.proof.method, ProofMethod::Symbolic);
//! ```

mod binding;
mod case;
mod cases;
mod existence_ift;
mod linear;
mod ode;
mod scope;
mod series;
mod split;

use super::context::Ctx;
pub use super::proof_info::{ProofInfo, ProofMethod};
use super::result::Evidence;
use crate::algebra::{Outcome, Proof};
use crate::claims::catalogue::PExpr;
use crate::claims::kind::Verdict;
use crate::claims::sampler::Point;
use crate::claims::value::Value;
use case::{Signs, prove_case};
use cases::{Cases, Role, case_points};
pub use existence_ift::{System, judge_existence, prove_existence};
use scope::{evaluates_pi, iteration, not_analytic, states_condition};
pub use series::{Order, judge_order, prove_order};
use std::time::Instant;

/// Attempts a symbolic proof of `lhs = rhs` on the claim's domain.
pub fn prove(ctx: Ctx<'_>, lhs: &PExpr, rhs: &PExpr, certificate: bool) -> ProofInfo {
    let t0 = Instant::now();
    let condition = states_condition(ctx, &[lhs, rhs]);
    let dom = match cases::domain(ctx) {
        Ok(d) => d,
        Err(m) => return ProofInfo::none(m),
    };
    if let Some(why) = not_analytic(ctx, &dom.vars, &[lhs, rhs]) {
        return ProofInfo::none(why);
    }
    if let Some(why) = iteration(ctx, &[lhs, rhs]).or_else(|| evaluates_pi(ctx, &[lhs, rhs])) {
        return ProofInfo::none(why);
    }
    let signs = Signs {
        positivity: dom.positivity.clone(),
    };
    if let (Some(why), None) = (&condition, &signs.positivity) {
        return ProofInfo::none(format!(
            "{why} (no variable of its domain can be parametrized to prove signs)"
        ));
    }
    let (plain, roles) = (&dom.plain, &dom.roles);
    let cases = match case_points(ctx, plain) {
        Ok(c) if !c.is_empty() => c,
        Ok(_) => return ProofInfo::none("no case of the domain has enough points"),
        Err(m) => return ProofInfo::none(m),
    };
    if let Some(mut joint) =
        prove_signs_jointly(ctx, roles, &cases, (lhs, rhs), (certificate, &signs))
    {
        small_h(ctx, &mut joint);
        joint.ms = t0.elapsed().as_secs_f64() * 1e3;
        return with_lemmas(ctx, on_the_branch(ctx, (lhs, rhs), joint));
    }
    let mut info = ProofInfo::none("");
    info.reason = None;
    info.method = ProofMethod::Symbolic;
    let mut hints = Vec::new();
    let input = split::CaseInput {
        ctx,
        roles,
        sides: (lhs, rhs),
        certificate,
        signs: &signs,
    };
    for (key, points) in &cases {
        // the cases differ in signs only: the bases that served one serve the next
        match split::prove_parts(&input, key, points.clone(), hints.clone()) {
            Ok(parts) => {
                for (label, p) in parts {
                    hints = p.base_hints.clone();
                    merge(ctx, &mut info, &label, p);
                }
            }
            Err(part) => {
                let (label, p) = *part;
                merge(ctx, &mut info, &label, p);
                break;
            }
        }
    }
    small_h(ctx, &mut info);
    info.ms = t0.elapsed().as_secs_f64() * 1e3;
    let info = on_the_branch(ctx, (lhs, rhs), info);
    with_lemmas(ctx, by_ode_if_not_proved(ctx, (lhs, rhs), info))
}

/// A proof that substituted a stated value into an implicit map's equations stands only
/// when that value is the map's branch ([`series::stated_value_is_the_branch`]).
fn on_the_branch(ctx: Ctx<'_>, sides: (&PExpr, &PExpr), info: ProofInfo) -> ProofInfo {
    let stated = info
        .notes
        .iter()
        .any(|n| n.starts_with("the claim states the value of"));
    if !info.is_proved() || !stated {
        return info;
    }
    match series::stated_value_is_the_branch(ctx, sides) {
        Ok(()) => {
            let mut info = info;
            info.notes.push(
                "the stated value is the map's branch: with the call solved as the power series of its branch continuous at h = 0, lhs - rhs = O(h), and near h = 0 that branch is the only solution (implicit function theorem)".into(),
            );
            info
        }
        Err(why) => ProofInfo {
            ms: info.ms,
            ..ProofInfo::none(why)
        },
    }
}

/// The ODE method ([`ode`]) where the normal form does not prove the claim and a side
/// is a call of sn, cn or dn: its proof replaces the attempt, and otherwise its reason
/// is added to the attempt's.
fn by_ode_if_not_proved(ctx: Ctx<'_>, (lhs, rhs): (&PExpr, &PExpr), info: ProofInfo) -> ProofInfo {
    use crate::claims::ast::ExprKind;
    let jacobi = |p: &PExpr| matches!(&p.expr.kind, ExprKind::Call(name, _) if ["sn", "cn", "dn"].contains(&name.as_str()));
    if info.is_proved() || info.witness.is_some() || !(jacobi(lhs) || jacobi(rhs)) {
        return info;
    }
    let ms = info.ms;
    let by_ode = ode::prove(ctx, lhs, rhs);
    if by_ode.is_proved() {
        return ProofInfo {
            ms: ms + by_ode.ms,
            ..by_ode
        };
    }
    let reason = match (&info.reason, &by_ode.reason) {
        (Some(a), Some(b)) => Some(format!("{a}; {b}")),
        (a, _) => a.clone(),
    };
    ProofInfo { reason, ..info }
}

/// Marks the proof's sign hypotheses that hold for every small enough `h > 0`
/// ([`series::small_h_signs`]): the claim then holds for h small enough, as the paper
/// states it, with no sign condition beyond that.
fn small_h(ctx: Ctx<'_>, info: &mut ProofInfo) {
    if !info.is_proved() || !info.hypotheses.iter().any(|h| h.kind == "sign") {
        return;
    }
    let small = series::small_h_signs(ctx);
    for h in info.hypotheses.iter_mut() {
        let name = h.source.trim_start_matches("hypothesis.");
        if h.kind == "sign" && small.iter().any(|s| s == name) {
            h.kind = "small h";
            h.statement = format!("{}{}", h.statement, super::proof_info::SMALL_H_NOTE);
        }
    }
}

/// A proof that rests on lemmas stands only when they are proved.
fn with_lemmas(ctx: Ctx<'_>, info: ProofInfo) -> ProofInfo {
    let lemmas = super::lemmas::lemmas(ctx);
    if !info.is_proved() || lemmas.is_empty() {
        return info;
    }
    match super::lemmas::check(ctx, &lemmas, prove) {
        Ok(()) => info,
        Err(why) => ProofInfo {
            ms: info.ms,
            ..ProofInfo::none(why)
        },
    }
}

/// One proof for every sign case at once, where the case variables take the values ±1
/// only: they become sign symbols (σ² = 1), and the points of all cases serve as the
/// domain points.  `None` when this does not apply or does not prove the claim (the
/// cases are then enumerated).
fn prove_signs_jointly(
    ctx: Ctx<'_>,
    roles: &[(String, Role, &PExpr)],
    cases: &Cases,
    sides: (&PExpr, &PExpr),
    certificate: (bool, &Signs),
) -> Option<ProofInfo> {
    let points: Vec<Point> = cases.values().flatten().cloned().collect();
    let is_sign = |name: &str| {
        points.iter().all(|p| match p.get(name) {
            Some(Value::Real(x)) => *x == 1.0 || *x == -1.0,
            _ => false,
        })
    };
    let signs: Vec<&str> = roles
        .iter()
        .filter(|(_, r, _)| *r == Role::Case)
        .map(|(n, _, _)| n.as_str())
        .collect();
    if cases.len() < 2 || !signs.iter().all(|n| is_sign(n)) {
        return None;
    }
    let joint: Vec<(String, Role, &PExpr)> = roles
        .iter()
        .map(|(n, r, p)| {
            let r = if *r == Role::Case {
                Role::Sign
            } else {
                r.clone()
            };
            (n.clone(), r, *p)
        })
        .collect();
    let region = case::Region::default();
    let p = prove_case(
        ctx,
        &joint,
        &points,
        sides,
        certificate,
        Vec::new(),
        &region,
    );
    if !matches!(p.outcome, Outcome::Proved) {
        return None;
    }
    let mut info = ProofInfo::none("");
    info.reason = None;
    info.method = ProofMethod::Symbolic;
    merge(ctx, &mut info, &[], p);
    info.notes.push(format!(
        "{} {} sign symbols: one normal form covers all {} sign cases",
        signs.join(", "),
        if signs.len() == 1 { "is a" } else { "are" },
        cases.len()
    ));
    Some(info)
}

/// Adds one case's proof to the record; a case that is not proved ends the proof.
fn merge(ctx: Ctx<'_>, info: &mut ProofInfo, key: &[String], p: Proof) {
    let label = key.join(", ");
    if let Outcome::NotProved(r) = &p.outcome {
        info.method = ProofMethod::None;
        info.reason = Some(if label.is_empty() {
            r.clone()
        } else {
            format!("case {label}: {r}")
        });
    }
    if !label.is_empty() {
        info.cases.push(label.clone());
    }
    let add = |dst: &mut Vec<String>, src: Vec<String>| {
        for s in src {
            if !dst.contains(&s) {
                dst.push(s);
            }
        }
    };
    add(
        &mut info.symbols,
        p.symbols.iter().map(|(n, w)| format!("{n}: {w}")).collect(),
    );
    add(&mut info.relations, p.relations.clone());
    add(&mut info.notes, p.notes.clone());
    add(&mut info.proved_signs, p.proved_signs.clone());
    add(&mut info.uncertified, p.uncertified.clone());
    if info.parametrization.is_none() {
        info.parametrization = p.parametrization.clone();
    }
    match super::hypotheses::uses(ctx, &p.assumptions) {
        Ok(uses) => {
            for u in uses {
                if !info.hypotheses.contains(&u) {
                    info.hypotheses.push(u);
                }
            }
        }
        Err(why) if info.is_proved() => {
            info.method = ProofMethod::None;
            info.reason = Some(if label.is_empty() {
                why
            } else {
                format!("case {label}: {why}")
            });
        }
        Err(_) => {}
    }
    info.terms = info.terms.max(p.terms);
    if info.witness.is_none()
        && let Some(w) = p.witness
    {
        info.witness = Some(if label.is_empty() {
            w
        } else {
            format!("case {label}, {w}")
        });
    }
    if let Some(c) = p.certificate {
        let prev = info.certificate.take().unwrap_or_default();
        info.certificate = Some(prev + &c);
    }
}

/// Makes a refutation certified where the attempt found a domain point at which
/// lhs − rhs is provably nonzero: the proof's method is then `witness`.  The verdict
/// stays `refuted` either way; a symbolic 0 against a numerical refutation is reported
/// as the conflict it is, and proves nothing.
fn certify_refutation(ev: &mut Evidence, mut info: ProofInfo) {
    if info.is_proved() {
        ev.reason = format!(
            "{}; the symbolic normal form of lhs − rhs is 0 against this refutation (a conflict to investigate)",
            ev.reason
        );
        info.method = ProofMethod::None;
    } else if let Some(w) = &info.witness {
        info.method = ProofMethod::Witness;
        ev.reason = format!("{}; certified: lhs − rhs ≠ 0 {w}", ev.reason);
    }
    ev.proof = Some(info);
}

/// Turns a numerical `holds` into `proved` when the symbolic proof succeeds.  A claim
/// the ladder refutes (or cannot judge) is never passed to the prover as true.
pub fn judge(ctx: Ctx<'_>, lhs: &PExpr, rhs: &PExpr, ev: &mut Evidence) {
    upgrade(
        ev,
        || {
            if super::lemmas::is_lemma(ctx) {
                super::lemmas::proof_of(ctx, lhs, rhs, prove)
            } else {
                prove(ctx, lhs, rhs, false)
            }
        },
        |info| {
            match info.method {
            ProofMethod::Ode => "both sides solve the same ODE with the same initial values at 0 (proved by the ODE method); holds numerically".to_string(),
            _ => format!(
                "the symbolic normal form of lhs − rhs is 0 ({}); holds numerically",
                info.extent()
            ),
        }
        },
    );
}

/// Runs `attempt` only when the numerical verdict holds (a claim the ladder refutes or
/// cannot judge is never passed to the prover as true), and makes the verdict `proved`,
/// with the reason `why`, when the attempt proves; the attempt is the claim's evidence.
/// A refuted claim's attempt serves for its witness only (see [`certify_refutation`]).
pub(super) fn upgrade(
    ev: &mut Evidence,
    attempt: impl FnOnce() -> ProofInfo,
    why: impl FnOnce(&ProofInfo) -> String,
) {
    if ev.verdict == Verdict::Refuted {
        certify_refutation(ev, attempt());
        return;
    }
    if ev.verdict == Verdict::Inconclusive {
        let info = attempt();
        if let (false, Some(w)) = (info.is_proved(), &info.witness) {
            ev.verdict = Verdict::Refuted;
            ev.reason = format!("certified: lhs − rhs ≠ 0 {w} (numerically: {})", ev.reason);
            ev.proof = Some(ProofInfo {
                method: ProofMethod::Witness,
                ..info
            });
        } else {
            ev.proof = Some(ProofInfo::none(
                "not proved: the numerical verdict is inconclusive, and no point certifies lhs − rhs ≠ 0",
            ));
        }
        return;
    }
    if ev.verdict != Verdict::Holds {
        ev.proof = Some(ProofInfo::none(format!(
            "not attempted: the numerical verdict is {}",
            ev.verdict.name()
        )));
        return;
    }
    let info = attempt();
    if info.is_proved() {
        ev.verdict = Verdict::Proved;
        ev.reason = why(&info);
    }
    ev.proof = Some(info);
}
