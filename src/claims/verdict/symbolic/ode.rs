//! Identities proved by the uniqueness of the solution of an ODE
//! ([`crate::algebra::ode`]), when the normal form of `lhs − rhs` does not prove them:
//! the claim's Jacobi functions become jet symbols, one real variable of the domain is
//! the ODE's variable, and both sides must satisfy the ODE of a side that is sn, cn or
//! dn with the same initial values at 0.  The proof's method is `ode`; its notes state
//! its scope (both sides analytic on an interval of the variable containing 0).
//!
//! ```
//! use eulertop::bindings::euler_top::registry;
//! use eulertop::claims::catalogue::load_sources;
//! use eulertop::claims::verdict::{run_claim, Options, ProofMethod, Verdict};
//! let toml = r#"
//! [[claim]]
//! id = "reciprocal-modulus"
//! environment = "Section 2"
//! role = "statement"
//! labels = []
//! location = "a doc example"
//! printed = 'sn(u, k) = sn(ku, 1/k)/k'
//! kind = "identity"
//! expect = "proved"
//! vars = [["u", "uniform(-1, 1)"], ["k", "uniform(0.1, 0.9)"]]
//! lhs = "sn(u, k)"
//! rhs = "sn(k*u, 1/k) / k"
//! "#;
//! let cat = load_sources(&[("doc.toml".into(), toml.into())], registry().unwrap()).unwrap();
//! let r = run_claim(&cat, &cat.claims[0], &Options::default());
//! assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
//! assert_eq!(r.proof.method, ProofMethod::Ode);
//! ```

use super::binding::bind_variables;
use super::cases::{self, Role, case_points};
use super::{ProofInfo, ProofMethod};
use crate::algebra::ode::{OdeProof, prove_by_ode};
use crate::algebra::{Ring, RingOptions, Sym};
use crate::claims::catalogue::PExpr;
use crate::claims::value::Value;
use crate::claims::verdict::context::{Ctx, eval};
use std::time::Instant;

/// Attempts the ODE proof of `lhs = rhs` on the claim's domain (one case only).
pub(super) fn prove(ctx: Ctx<'_>, lhs: &PExpr, rhs: &PExpr) -> ProofInfo {
    let t0 = Instant::now();
    let mut info = match attempt(ctx, lhs, rhs) {
        Ok((var, proof, ring)) => proved(&var, &proof, &ring),
        Err(why) => ProofInfo::none(format!("by the ODE method: {why}")),
    };
    info.ms = t0.elapsed().as_secs_f64() * 1e3;
    info
}

/// The ring, the sides and the first variable of the domain by which the ODE method
/// proves the claim.
fn attempt(ctx: Ctx<'_>, lhs: &PExpr, rhs: &PExpr) -> Result<(String, OdeProof, Ring), String> {
    let dom = cases::domain(ctx)?;
    let cases = case_points(ctx, &dom.plain)?;
    let points = match cases.values().collect::<Vec<_>>().as_slice() {
        [p] if !p.is_empty() => (*p).clone(),
        _ => return Err("the domain has more than one case".into()),
    };
    if !ctx.claim.hypotheses.is_empty() || ctx.claim.hint.is_some() {
        return Err("the claim states hypotheses or a hint".into());
    }
    let ring = Ring::new(RingOptions {
        points: points.len(),
        positivity: dom.positivity.clone(),
        jets: true,
        expand_named: true,
        max_vars: 48,
        max_roots: 32,
        ..RingOptions::default()
    });
    let bound = bind_variables(ctx, &ring, &dom.roles, &points, (&[], &[]), None)
        .map_err(|e| e.to_string())?;
    let side = |p: &PExpr| -> Result<Sym, String> {
        match eval(&bound.ev, p)? {
            Value::Real(x) => Ok(x),
            v => Err(format!("a side is of type {}, not real", v.type_name())),
        }
    };
    let (l, r) = (side(lhs)?, side(rhs)?);
    if let Some(e) = ring.error() {
        return Err(e.to_string());
    }
    let mut why = Vec::new();
    for (name, role, _) in &dom.roles {
        let Some(Value::Real(x)) = (*role == Role::Free)
            .then(|| bound.ev.lookup(name))
            .flatten()
        else {
            continue;
        };
        match prove_by_ode(x, &l, &r) {
            Ok(p) => return Ok((name.clone(), p, ring.clone())),
            Err(e) => why.push(format!("in {name}: {e}")),
        }
    }
    Err(if why.is_empty() {
        "the domain has no real variable".into()
    } else {
        why.join("; ")
    })
}

/// The proof's record: the ODE, the initial values, the hypothesis of analyticity.
fn proved(var: &str, p: &OdeProof, ring: &Ring) -> ProofInfo {
    let mut info = ProofInfo::none("");
    info.reason = None;
    info.method = ProofMethod::Ode;
    info.certificate = Some(format!(
        "# eulertop certificate 1\n# claim: lhs = rhs by the uniqueness of the solution of an ODE in {var}\nclaims 1\n{}",
        p.certificate
    ));
    info.notes = ring.notes();
    info.notes.push(format!(
        "the ODE in {var}: {} ({}); both sides satisfy it identically: y'' - a^2*Phi(y) of each reduces to 0 modulo cn^2 = 1 - sn^2, dn^2 = 1 - k^2 sn^2 of every argument",
        p.ode, p.source
    ));
    info.notes.push(format!(
        "initial values at {var} = 0, the same on both sides: y(0) = {}, y'(0) = {}; the denominators do not vanish there",
        p.initial[0], p.initial[1]
    ));
    info.notes.push(
        "y'' = Phi(y) with Phi polynomial is locally Lipschitz as a first-order system: by Picard-Lindelöf the solution with these initial values is unique (van der Hoeven's zero test for D-algebraic functions, ISSAC 2002)".into(),
    );
    info.notes.push(format!(
        "scope: lhs = rhs on every interval of {var} containing 0 on which both sides are analytic (rational in {var}, sn, cn, dn: their denominators do not vanish), for every value of the other variables at which the initial values are defined"
    ));
    info
}
