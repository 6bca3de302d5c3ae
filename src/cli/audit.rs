//! `eulertop audit ID`: residual of one claim against precision up to ≥ 8192 bits, with
//! the fitted slope (bits of agreement gained per bit of precision) and the verdict.

use super::verify::{fmt_log2, load, parse_bits};
use super::{CliError, stdout, write_error};
use crate::claims::catalogue::lookup::{Scope, find};
use crate::claims::catalogue::{Catalogue, Claim};
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

/// Writes one row per rung: the residual of the claim run at that precision alone, flushed as
/// soon as it is known.  Returns `(bits, −log2 residual)` of the rungs with a nonzero
/// residual, and whether any rung was an order of convergence instead of a residual.
fn ladder(
    out: &mut impl Write,
    cat: &Catalogue,
    claim: &Claim,
    bits: &[u32],
    bar: Option<&indicatif::ProgressBar>,
) -> Result<(Vec<f64>, Vec<f64>, bool), CliError> {
    let err = write_error("standard output");
    let mut xs = Vec::new();
    let mut ys = Vec::new();
    let mut slopes = false;
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
                slopes = true;
                format!("slope {slope:.3}")
            }
            Some(x) => fmt_log2(x.log2()),
        };
        if let Some(l) = rung.and_then(|x| x.log2()) {
            xs.push(f64::from(b));
            ys.push(-l);
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
    Ok((xs, ys, slopes))
}

/// The "fitted slope" line: the least-squares slope of −log2 residual against precision,
/// or why there is none.
fn slope_line(slopes: bool, bits: &[u32], xs: &[f64], ys: &[f64]) -> String {
    if let Some(s) = ls_slope(xs, ys) {
        return format!("fitted slope: {s:.3} bits of agreement per bit of precision");
    }
    let why = if slopes {
        "an asymptotic claim: each rung shows its order of convergence in h, not a residual"
            .to_string()
    } else if bits.len() < 2 {
        format!("{} rung run; two are needed", bits.len())
    } else if xs.len() < 2 {
        format!(
            "{} of the {} rungs have a nonzero residual; two are needed",
            xs.len(),
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
    writeln!(
        out,
        "{} ({}, {})",
        claim.id,
        claim.location,
        claim.kind.name()
    )
    .and_then(|()| writeln!(out, "{:>8}  {:>14}", "bits", "residual"))
    .map_err(&err)?;
    let bar = std::io::stderr()
        .is_terminal()
        .then(|| indicatif::ProgressBar::new(bits.len() as u64 + 1));
    let (xs, ys, slopes) = ladder(out, cat, claim, bits, bar.as_ref())?;
    let opts = Options {
        bits: bits.to_vec(),
        exact: true,
    };
    let full = run_claim(cat, claim, &opts);
    if let Some(p) = &bar {
        p.finish_and_clear();
    }
    let slope = slope_line(slopes, bits, &xs, &ys);
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
