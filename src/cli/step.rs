//! `eulertop step`: iterates one of the special discretizations (impl spec) —
//! γ₀, γ₁ (gamma1), γ₂ (gamma2), γ_VM (gammaMV) — or, with `--matrix`, the
//! Veselov–Moser matrix algorithm (M thru omega), (VM).
//!
//! Prints `M₁ … M_N`, one line each with three numbers.  `--bits 53` (default) uses
//! the `f64` code path and 17 significant digits; any other `P ≥ 2` uses MPFR at `P`
//! bits and `ceil(P·log10 2) + 2` digits.  Inputs are decimals rounded to the working
//! precision.  Bad input (malformed number, A,B,C not in the order A > B > C > 0,
//! `M = 0`, Newton failing because `h` is too large) stops with one line on standard
//! error and exit status 2.

use super::CliError;
use crate::linalg::Vec3;
use crate::model::discretization::step;
use crate::model::veselov_moser::vm_step;
use crate::model::{Gamma, Inertia};
use crate::numbers::Real;
use std::io::Write;

/// Arguments of `eulertop step`.
#[derive(clap::Args, Debug, Clone)]
#[command(allow_negative_numbers = true)]
pub struct Args {
    /// Moments of inertia `A,B,C` with A > B > C > 0.
    #[arg(long, allow_hyphen_values = true)]
    pub inertia: String,
    /// The function γ: 0, 1, 2 or vm.
    #[arg(long, default_value = "vm")]
    pub gamma: String,
    /// Use the Veselov–Moser matrix algorithm (requires --gamma vm, the default).
    #[arg(long)]
    pub matrix: bool,
    /// Step size h.
    #[arg(long = "h", allow_hyphen_values = true)]
    pub h: String,
    /// Number of steps N.
    #[arg(long, default_value_t = 1)]
    pub steps: usize,
    /// Precision in bits (53 = f64).
    #[arg(long, default_value_t = 53)]
    pub bits: u32,
    /// Start point M1 M2 M3.
    #[arg(num_args = 3, required = true, allow_hyphen_values = true, value_names = ["M1", "M2", "M3"])]
    pub m: Vec<String>,
}

/// Parsed, validated inputs at the working precision.
pub struct Problem<R> {
    /// Moments of inertia.
    pub inertia: Inertia<R>,
    /// γ.
    pub gamma: Gamma,
    /// Matrix Veselov–Moser algorithm instead of the implicit map.
    pub matrix: bool,
    /// Step size.
    pub h: R,
    /// Start point.
    pub m0: Vec3<R>,
}

fn num<R: Real>(like: &R, s: &str, what: &str) -> Result<R, CliError> {
    like.parse_like(s)
        .map_err(|_| CliError::new(format!("malformed number '{s}' in {what}")))
}

/// Parses and validates the arguments at the precision of `like`.
pub fn parse<R: Real>(like: &R, args: &Args) -> Result<Problem<R>, CliError> {
    let parts: Vec<&str> = args.inertia.split(',').collect();
    if parts.len() != 3 {
        return Err(CliError::new(format!(
            "--inertia needs three numbers A,B,C, got '{}'",
            args.inertia
        )));
    }
    let a = num(like, parts[0], "--inertia")?;
    let b = num(like, parts[1], "--inertia")?;
    let c = num(like, parts[2], "--inertia")?;
    let inertia = Inertia::new(a, b, c).map_err(|e| CliError::new(format!("--inertia: {e}")))?;
    let gamma = Gamma::parse(&args.gamma).ok_or_else(|| {
        CliError::new(format!(
            "--gamma must be 0, 1, 2 or vm, got '{}'",
            args.gamma
        ))
    })?;
    if args.matrix && gamma != Gamma::Vm {
        return Err(CliError::new(
            "--matrix is the Veselov-Moser algorithm and needs --gamma vm",
        ));
    }
    let h = num(like, &args.h, "--h")?;
    let m: Vec<R> = args
        .m
        .iter()
        .enumerate()
        .map(|(i, s)| num(like, s, &format!("M{}", i + 1)))
        .collect::<Result<_, _>>()?;
    let m0 = Vec3::new(m[0].clone(), m[1].clone(), m[2].clone());
    if m0.0.iter().all(|x| x.is_zero()) {
        return Err(CliError::new(
            "start point M = 0 is not allowed (degenerate fixed point)",
        ));
    }
    Ok(Problem {
        inertia,
        gamma,
        matrix: args.matrix,
        h,
        m0,
    })
}

/// The iterates `M₁ … M_N`.
pub fn iterate<R: Real>(p: &Problem<R>, steps: usize) -> Result<Vec<Vec3<R>>, CliError> {
    let mut out = Vec::with_capacity(steps);
    let mut cur = p.m0.clone();
    for n in 1..=steps {
        let next = if p.matrix {
            vm_step(&p.inertia, &cur, &p.h).map(|s| s.m_hat)
        } else {
            step(&p.inertia, p.gamma, &cur, &p.h)
        };
        cur = next.map_err(|e| CliError::new(format!("step {n}: {e}")))?;
        out.push(cur.clone());
    }
    Ok(out)
}

/// Significant digits printed at `bits` of precision.
pub fn digits_for(bits: u32) -> usize {
    if bits == 53 {
        17
    } else {
        (bits as f64 * std::f64::consts::LOG10_2).ceil() as usize + 2
    }
}

/// Checks `--bits`.
pub fn check_bits(bits: u32) -> Result<(), CliError> {
    if !(2..=1 << 20).contains(&bits) {
        return Err(CliError::new(format!(
            "--bits {bits} is outside 2..=1048576"
        )));
    }
    Ok(())
}

fn run_generic<R: Real>(like: R, args: &Args) -> Result<i32, CliError> {
    let p = parse(&like, args)?;
    let pts = iterate(&p, args.steps)?;
    let d = digits_for(args.bits);
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    for m in pts {
        writeln!(
            out,
            "{} {} {}",
            m.0[0].to_decimal(d),
            m.0[1].to_decimal(d),
            m.0[2].to_decimal(d)
        )
        .map_err(|e| CliError::new(format!("writing output: {e}")))?;
    }
    Ok(0)
}

/// Runs the subcommand; returns the exit status.
pub fn run(args: Args) -> Result<i32, CliError> {
    check_bits(args.bits)?;
    if args.bits == 53 {
        run_generic(0.0f64, &args)
    } else {
        run_generic(rug::Float::new(args.bits), &args)
    }
}
