//! `eulertop audit ID`: residual of one claim against precision up to ≥ 8192 bits, with
//! the fitted slope (bits of agreement gained per bit of precision) and the verdict.

use super::verify::{fmt_log2, load, parse_bits};
use super::CliError;
use crate::claims::verdict::{run_claim, Options, Rung};
use clap::Parser;
use std::io::IsTerminal;

/// Arguments of `eulertop audit`.
#[derive(Parser, Debug)]
pub struct Args {
    /// The claim id.
    pub id: String,
    /// Precision ladder in bits.
    #[arg(long, default_value = "64,128,256,512,1024,2048,4096,8192")]
    pub bits: String,
    /// Catalogue directory.
    #[arg(long, default_value = "identities")]
    pub catalogue: String,
}

/// Least-squares slope of y against x.
pub fn fit_slope(xs: &[f64], ys: &[f64]) -> Option<f64> {
    if xs.len() < 2 {
        return None;
    }
    let n = xs.len() as f64;
    let mx = xs.iter().sum::<f64>() / n;
    let my = ys.iter().sum::<f64>() / n;
    let sxx: f64 = xs.iter().map(|x| (x - mx).powi(2)).sum();
    if sxx == 0.0 {
        return None;
    }
    Some(
        xs.iter()
            .zip(ys)
            .map(|(x, y)| (x - mx) * (y - my))
            .sum::<f64>()
            / sxx,
    )
}

/// Runs `eulertop audit`.
pub fn run(args: Args) -> Result<i32, CliError> {
    let bits = parse_bits(&args.bits)?;
    let cat = load(&args.catalogue)?;
    let claim = cat
        .claims
        .iter()
        .find(|c| c.id == args.id)
        .ok_or_else(|| CliError(format!("no claim with id '{}'", args.id)))?;
    let bar = if std::io::stderr().is_terminal() {
        Some(indicatif::ProgressBar::new(bits.len() as u64 + 1))
    } else {
        None
    };
    println!("{} ({}, {})", claim.id, claim.location, claim.kind.name());
    println!("{:>8}  {:>14}", "bits", "residual");
    let mut xs = Vec::new();
    let mut ys = Vec::new();
    for &b in &bits {
        let r = run_claim(
            &cat,
            claim,
            &Options {
                bits: vec![b],
                exact: false,
            },
        );
        let rung = r.residuals.first();
        let cell = match rung {
            None => format!("- ({})", r.reason),
            Some(Rung::Slope { slope, .. }) => format!("slope {slope:.3}"),
            Some(x) => fmt_log2(x.log2()),
        };
        if let Some(l) = rung.and_then(|x| x.log2()) {
            xs.push(f64::from(b));
            ys.push(-l);
        }
        if let Some(p) = &bar {
            p.suspend(|| println!("{b:>8}  {cell:>14}"));
            p.inc(1);
        } else {
            println!("{b:>8}  {cell:>14}");
        }
    }
    let full = run_claim(
        &cat,
        claim,
        &Options {
            bits: bits.clone(),
            exact: true,
        },
    );
    if let Some(p) = &bar {
        p.finish_and_clear();
    }
    match fit_slope(&xs, &ys) {
        Some(s) => println!("fitted slope: {s:.3} bits of agreement per bit of precision"),
        None => println!("fitted slope: n/a (residual exactly zero or fewer than two rungs)"),
    }
    println!(
        "verdict: {} (expect {}): {}",
        full.verdict.name(),
        full.expect.map_or("-", |v| v.name()),
        full.reason
    );
    Ok(i32::from(!full.as_expected))
}
