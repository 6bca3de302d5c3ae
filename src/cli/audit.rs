//! `eulertop audit ID`: residual of one claim against precision up to ≥ 8192 bits, with
//! the fitted slope (bits of agreement gained per bit of precision) and the verdict; an
//! asymptotic claim shows its slope in h (order of convergence) at each precision instead.

use super::verify::{fmt_log2, load, parse_bits};
use super::{CliError, stdout, write_error};
use crate::claims::catalogue::lookup::{Scope, find};
use crate::claims::catalogue::{Catalogue, Claim};
use crate::claims::kind::Kind;
use crate::claims::verdict::{Options, Rung, run_claim};
use crate::stats::ls_slope;
use clap::Parser;
use std::io::{IsTerminal, Write};

/// Arguments of `eulertop audit`.
#[derive(Parser, Debug)]
pub struct Args {
    /// The claim id, an environment name (its statement claims) or a paper label.
    pub id: String,
    /// Precision ladder in bits.
    #[arg(
        long,
        default_value = "64,128,256,512,1024,2048,4096,8192",
        allow_hyphen_values = true
    )]
    pub bits: String,
    /// Catalogue directory or file (default: the paper's catalogue, built into the
    /// binary).
    #[arg(long)]
    pub catalogue: Option<String>,
}

/// What the rungs of an audit measured: residuals (with `(bits, −log2 residual)` of the
/// nonzero ones, for the fit against precision) or, for an asymptotic claim, the order of
/// convergence in h at each precision.
#[derive(Default)]
struct Measured {
    xs: Vec<f64>,
    ys: Vec<f64>,
    slopes: Vec<f64>,
}

/// Writes one row per rung: the residual of the claim run at that precision alone (or the
/// slope in h of an asymptotic claim), flushed as soon as it is known.
fn ladder(
    out: &mut impl Write,
    cat: &Catalogue,
    claim: &Claim,
    bits: &[u32],
    bar: Option<&indicatif::ProgressBar>,
) -> Result<Measured, CliError> {
    let err = write_error("standard output");
    let mut m = Measured::default();
    for &b in bits {
        let opts = Options {
            bits: vec![b],
            exact: false,
        };
        let r = run_claim(cat, claim, &opts);
        let rung = r.residuals.first();
        let cell = match rung {
            None => format!("- ({})", r.reason),
            Some(Rung::Slope { slope, .. }) => {
                m.slopes.push(*slope);
                format!("{slope:.3}")
            }
            Some(x) => fmt_log2(x.log2()),
        };
        if let Some(l) = rung.and_then(|x| x.log2()) {
            m.xs.push(f64::from(b));
            m.ys.push(-l);
        }
        let mut row = || writeln!(out, "{b:>8}  {cell:>14}").and_then(|()| out.flush());
        match bar {
            Some(p) => {
                p.suspend(row).map_err(&err)?;
                p.inc(1);
            }
            None => row().map_err(&err)?,
        }
    }
    Ok(m)
}

/// The line under the ladder of an asymptotic claim: the range of its slopes in h.
fn order_line(slopes: &[f64]) -> String {
    let lo = slopes.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = slopes.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let range = if format!("{lo:.3}") == format!("{hi:.3}") {
        format!("{lo:.3} at every precision")
    } else {
        format!("{lo:.3} to {hi:.3}")
    };
    format!(
        "slope in h: {range} (the smallest slope over the samples of log2 |residual| against \
         log2 h, the order of convergence in h; no slope against precision is fitted)"
    )
}

/// The line under the ladder: the least-squares slope of −log2 residual against
/// precision, or why there is none; for an asymptotic claim, its slopes in h.
fn slope_line(bits: &[u32], m: &Measured) -> String {
    if !m.slopes.is_empty() && m.xs.is_empty() {
        return order_line(&m.slopes);
    }
    if let Some(s) = ls_slope(&m.xs, &m.ys) {
        return format!("fitted slope: {s:.3} bits of agreement per bit of precision");
    }
    let why = if bits.len() < 2 {
        format!("{} rung run; two are needed", bits.len())
    } else if m.xs.len() < 2 {
        format!(
            "{} of the {} rungs have a nonzero residual; two are needed",
            m.xs.len(),
            bits.len()
        )
    } else {
        "the residuals do not determine a slope".to_string()
    };
    format!("fitted slope: n/a ({why})")
}

/// Runs `eulertop audit`: `ID` may also name an environment (its statement claims) or a
/// paper label (the claims carrying it), audited one after another in catalogue order;
/// exit status 0 iff every verdict is as expected.
pub fn run(args: Args) -> Result<i32, CliError> {
    let bits = parse_bits(&args.bits)?;
    let cat = load(args.catalogue.as_deref())?;
    let sel = find(&cat, &args.id, Scope::Statement).map_err(CliError::new)?;
    let mut out = stdout();
    if sel.claims.len() > 1 || sel.claims[0].id != args.id {
        let n = sel.claims.len();
        let s = if n == 1 { "" } else { "s" };
        writeln!(out, "{}: {n} claim{s}\n", sel.what).map_err(write_error("standard output"))?;
    }
    let mut as_expected = true;
    for (j, claim) in sel.claims.iter().enumerate() {
        if j > 0 {
            writeln!(out).map_err(write_error("standard output"))?;
        }
        as_expected &= audit_one(&mut out, &cat, claim, &bits)?;
    }
    Ok(i32::from(!as_expected))
}

/// Audits one claim: the ladder, the fitted slope and the verdict.  Returns whether the
/// verdict is as expected.
fn audit_one(
    out: &mut impl Write,
    cat: &Catalogue,
    claim: &Claim,
    bits: &[u32],
) -> Result<bool, CliError> {
    let err = write_error("standard output");
    let column = if claim.kind == Kind::Asymptotic {
        "slope in h"
    } else {
        "residual"
    };
    writeln!(
        out,
        "{} ({}, {})",
        claim.id,
        claim.location,
        claim.kind.name()
    )
    .and_then(|()| writeln!(out, "{:>8}  {:>14}", "bits", column))
    .map_err(&err)?;
    let bar = std::io::stderr()
        .is_terminal()
        .then(|| indicatif::ProgressBar::new(bits.len() as u64 + 1));
    let measured = ladder(out, cat, claim, bits, bar.as_ref())?;
    let opts = Options {
        bits: bits.to_vec(),
        exact: true,
    };
    let full = run_claim(cat, claim, &opts);
    if let Some(p) = &bar {
        p.finish_and_clear();
    }
    let slope = slope_line(bits, &measured);
    writeln!(out, "{slope}")
        .and_then(|()| {
            writeln!(
                out,
                "verdict: {} (expect {}): {}",
                full.verdict.name(),
                full.expect.map_or("-", |v| v.name()),
                full.reason
            )
        })
        .and_then(|()| out.flush())
        .map_err(&err)?;
    Ok(full.as_expected)
}
