//! `eulertop prove ID`: the symbolic proof of one identity (or of `d(expr, wrt) = 0` for
//! an independence claim), as a derivation a reader can
//! follow — the variables and how they enter, the symbols and their relations, the
//! addition-theorem instances, the decisions taken from the domain, and the final normal
//! form — with `--certificate FILE` a script of polynomial equalities that SymPy rechecks
//! (`scripts/recheck-certificates.py`).

use super::cert_source::{bind, premise_lines};
use super::{CliError, stdout, write_error};
use crate::claims::catalogue::lookup::{Scope, find};
use crate::claims::catalogue::{Body, Catalogue, Claim, PExpr};
use crate::claims::verdict::context::Ctx;
use crate::claims::verdict::independence::derivative_sides;
use crate::claims::verdict::proof_info::ProofMethod;
use crate::claims::verdict::symbolic::{
    Order, ProofInfo, System, prove, prove_existence, prove_order,
};
use clap::Parser;
use std::io::Write;

/// Arguments of `eulertop prove`.
#[derive(Parser, Debug)]
pub struct Args {
    /// The claim id (an identity, or an independence claim: d(expr, wrt) = 0), an
    /// environment name (its statement claims) or a paper label (the claims carrying it).
    pub id: String,
    /// Catalogue directory or file (default: the paper's catalogue, built into the
    /// binary).
    #[arg(long)]
    pub catalogue: Option<String>,
    /// Write the certificate (a SymPy-recheckable script) to this file.
    #[arg(long)]
    pub certificate: Option<String>,
    /// Write the proof as a Coq script (checked by `coqc`) to this file.
    #[arg(long)]
    pub coq: Option<String>,
    /// The budget of every proof attempt.
    #[command(flatten)]
    pub budget: super::ProofBudgetArgs,
}

/// The derivation as text.
pub fn derivation(id: &str, printed: &str, p: &ProofInfo) -> String {
    let mut out = format!("claim {id}\n  printed: {}\n", printed.replace('\n', " "));
    let list = |out: &mut String, title: &str, items: &[String]| {
        if !items.is_empty() {
            out.push_str(&format!("{title}:\n"));
            for i in items {
                out.push_str(&format!("  {i}\n"));
            }
        }
    };
    list(&mut out, "cases (each proved separately)", &p.cases);
    list(&mut out, "symbols", &p.symbols);
    list(&mut out, "relations", &p.relations);
    list(&mut out, "steps", &p.notes);
    if let Some(par) = &p.parametrization {
        out.push_str(&format!(
            "domain parametrized by positive parameters:\n  {par}\n"
        ));
    }
    list(
        &mut out,
        "signs proved (every coefficient of one sign after substituting the parametrization; a root of a radicand proved positive is its positive root)",
        &p.proved_signs,
    );
    list(
        &mut out,
        "hypotheses (stated by the claim, quoted from the paper; lemmas proved separately)",
        &p.hypotheses.iter().map(|h| h.line()).collect::<Vec<_>>(),
    );
    match &p.reason {
        None if p.method == crate::claims::verdict::ProofMethod::Ode => out.push_str(
            "both sides solve the ODE with the same initial values: proved by the ODE method\n",
        ),
        None if p.method == crate::claims::verdict::ProofMethod::Series => out.push_str(
            "every coefficient below the order has normal form 0: proved by exact power series\n",
        ),
        None => out.push_str("normal form of lhs - rhs: 0: proved\n"),
        Some(r) if p.method == crate::claims::verdict::ProofMethod::Witness => {
            out.push_str(&format!("{r}\n"));
        }
        Some(r) => out.push_str(&format!("not proved: {r}\n")),
    }
    out
}

/// Runs `eulertop prove`; exit status 0 if proved, 1 if not.  `ID` may also name an
/// environment (its statement claims) or a paper label (the claims carrying it): each
/// identity or independence claim among them is proved in catalogue order, and the exit
/// status is 0 iff every one is proved.
pub fn run(args: Args) -> Result<i32, CliError> {
    args.budget.apply()?;
    let cat = super::verify::load(args.catalogue.as_deref())?;
    let sel = find(&cat, &args.id, Scope::Statement).map_err(CliError::new)?;
    if let [claim] = sel.claims[..] {
        if claim.id != args.id {
            let mut out = stdout();
            writeln!(out, "{}: 1 claim\n", sel.what).map_err(write_error("standard output"))?;
        }
        return prove_one(&args, &cat, claim);
    }
    if args.certificate.is_some() || args.coq.is_some() {
        let flag = match args.certificate {
            Some(_) => "--certificate",
            None => "--coq",
        };
        return Err(CliError(format!(
            "{flag} needs one claim, and '{}' names {} ({})",
            args.id,
            sel.claims.len(),
            sel.what
        )));
    }
    if !sel.claims.iter().any(|c| provable(c)) {
        return Err(CliError(format!(
            "none of the {} claims of {} is an identity, an independence, an asymptotic, an existence or a negation claim, the kinds proved symbolically",
            sel.claims.len(),
            sel.what
        )));
    }
    let mut out = stdout();
    let err = write_error("standard output");
    writeln!(out, "{}: {} claims", sel.what, sel.claims.len()).map_err(&err)?;
    let mut all_proved = true;
    for claim in &sel.claims {
        writeln!(out).map_err(&err)?;
        if !provable(claim) {
            writeln!(
                out,
                "claim {}\n  skipped: of kind {}, which is not proved symbolically",
                claim.id,
                claim.kind.name()
            )
            .map_err(&err)?;
            continue;
        }
        let p = attempt(Ctx { cat: &cat, claim }, false)?;
        all_proved &= proves(claim, &p);
        out.write_all(derivation(&claim.id, &claim.printed, &p).as_bytes())
            .and_then(|()| out.flush())
            .map_err(&err)?;
    }
    out.flush().map_err(&err)?;
    Ok(i32::from(!all_proved))
}

/// The symbolic proof of the claim: of `lhs − rhs = 0` for an identity, of
/// `d(expr, wrt) = 0` for an independence claim, by exact power series for an
/// asymptotic claim ([`prove_order`]); recording its certificate if `certify`.
fn attempt(ctx: Ctx<'_>, certify: bool) -> Result<ProofInfo, CliError> {
    let claim = ctx.claim;
    let (lhs, rhs): (PExpr, PExpr) = match &claim.body {
        Body::Identity { lhs, rhs } => (lhs.clone(), rhs.clone()),
        Body::Independence { expr, wrt, .. } => derivative_sides(expr, wrt),
        Body::Asymptotic {
            expr, var, order, ..
        } => {
            let order = Order {
                expr,
                var,
                order: *order,
                certificate: certify,
            };
            return Ok(prove_order(ctx, order));
        }
        Body::Existence {
            unknowns,
            equations,
            start,
            in_set,
            ..
        } => {
            let sys = System {
                unknowns,
                equations,
                start,
                in_set: in_set.as_ref(),
                certificate: certify,
            };
            return Ok(prove_existence(ctx, sys));
        }
        Body::Negation(inner) => {
            let p = attempt(
                Ctx {
                    cat: ctx.cat,
                    claim: inner,
                },
                certify,
            )?;
            return Ok(negation_proof(p));
        }
        _ => {
            return Err(CliError(format!(
                "claim '{}' is of kind {}, and only identities, independence, asymptotic, existence and negation claims are proved symbolically",
                claim.id,
                claim.kind.name()
            )));
        }
    };
    Ok(prove(ctx, &lhs, &rhs, certify))
}

/// A negation ("the inner identity fails somewhere") from the attempt at its inner
/// identity: proved when that attempt found a point where lhs − rhs is certified nonzero
/// (its certificate is then the refutation's, with the point).
fn negation_proof(p: ProofInfo) -> ProofInfo {
    let Some(w) = p.witness.clone() else {
        let why = p.reason.clone().unwrap_or_default();
        return ProofInfo {
            reason: Some(format!(
                "no point certifies that the inner identity fails: {why}"
            )),
            certificate: None,
            ..p
        };
    };
    ProofInfo {
        method: ProofMethod::Witness,
        reason: Some(format!(
            "proved by a witness: the inner identity's lhs − rhs is certified nonzero {w}"
        )),
        ..p
    }
}

/// Whether the attempt proves the claim: a negation by a witness, any other claim by a
/// proof of what it states.
fn proves(claim: &Claim, p: &ProofInfo) -> bool {
    match claim.body {
        Body::Negation(_) => p.method == ProofMethod::Witness,
        _ => p.is_proved(),
    }
}

/// Whether the claim is of a kind `prove` attempts (the others get an error).
fn provable(c: &Claim) -> bool {
    matches!(
        c.body,
        Body::Identity { .. }
            | Body::Independence { .. }
            | Body::Asymptotic { .. }
            | Body::Existence { .. }
            | Body::Negation(_)
    )
}

/// Proves one claim, with the certificate if asked for.
fn prove_one(args: &Args, cat: &Catalogue, claim: &Claim) -> Result<i32, CliError> {
    if !provable(claim) {
        attempt(Ctx { cat, claim }, false)?;
    }
    for (flag, path) in [("--certificate", &args.certificate), ("--coq", &args.coq)] {
        if let Some(path) = path {
            super::check_output_path(flag, std::path::Path::new(path))?;
        }
    }
    if let (Some(c), Some(q)) = (&args.certificate, &args.coq)
        && super::same_file(std::path::Path::new(c), std::path::Path::new(q))
    {
        return Err(CliError(format!(
            "--certificate {c} and --coq {q} name the same file: the Coq script would overwrite the certificate"
        )));
    }
    let certify = args.certificate.is_some() || args.coq.is_some();
    let p = attempt(Ctx { cat, claim }, certify)?;
    let bound = match &p.certificate {
        Some(cert) if certify => {
            let source = super::catalogue_arg::CatalogueSource::new(args.catalogue.as_deref())
                .raw()?
                .source_lines(&claim.id)?;
            Some(bind(cert, &source, &premise_lines(&p.hypotheses)))
        }
        _ => None,
    };
    if let (Some(path), Some(cert)) = (&args.certificate, &bound) {
        std::fs::write(path, cert).map_err(|e| CliError(format!("cannot write {path}: {e}")))?;
    }
    if let Some(path) = &args.coq {
        write_coq(path, bound.as_deref(), &p)?;
    }
    let mut out = stdout();
    out.write_all(derivation(&claim.id, &claim.printed, &p).as_bytes())
        .and_then(|()| out.flush())
        .map_err(write_error("standard output"))?;
    if let (Some(path), None) = (&args.certificate, &p.certificate) {
        // no certificate: an older file at the path must not pass for this proof's
        let removed = match std::fs::remove_file(path) {
            Ok(()) => format!("; the older {path} was removed"),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => String::new(),
            Err(e) => return Err(CliError(format!("cannot remove the older {path}: {e}"))),
        };
        let why = if proves(claim, &p) {
            // proved, but a step recorded no derivation
            format!(
                "the certificate format does not record {}",
                p.uncertified.join("; ")
            )
        } else {
            "the claim is not proved".to_string()
        };
        let _ = writeln!(
            std::io::stderr(),
            "eulertop: no certificate written to {path}: {why}{removed}"
        );
        return Ok(1);
    }
    Ok(i32::from(!proves(claim, &p)))
}

/// Writes the Coq script of the proof's certificate to `path` (module
/// [`super::coq_export`]); without one (the claim not proved, a step the certificate
/// does not record, or one the export does not cover), removes an older file at `path`
/// and fails.
fn write_coq(path: &str, cert: Option<&str>, p: &ProofInfo) -> Result<(), CliError> {
    let script = match cert {
        Some(_) if !p.is_proved() => Err(
            "the claim is not proved: its certificate is a refutation's, which has no Coq proof"
                .to_string(),
        ),
        Some(c) => super::coq_export::coq_script(c),
        None if p.is_proved() => Err(format!(
            "the certificate format does not record {}",
            p.uncertified.join("; ")
        )),
        None => Err("the claim is not proved".to_string()),
    };
    let result = script.and_then(|s| std::fs::write(path, s).map_err(|e| e.to_string()));
    let Err(why) = result else { return Ok(()) };
    let removed = match std::fs::remove_file(path) {
        Ok(()) => format!("; the older {path} was removed"),
        Err(_) => String::new(),
    };
    Err(CliError(format!(
        "no Coq script written to {path}: {why}{removed}"
    )))
}
