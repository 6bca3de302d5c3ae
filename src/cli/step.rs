//! `eulertop step`: iterates one of the special discretizations (impl spec) —
//! γ₀, γ₁ (gamma1), γ₂ (gamma2), γ_VM (gammaMV) — or, with `--matrix`, the
//! Veselov–Moser matrix algorithm (M thru omega), (VM).
//!
//! Prints `M₁ … M_N`, one line each with three numbers, as they are computed (memory
//! does not depend on `--steps`).  `--bits 53` (default) uses the `f64` code path and 17
//! significant digits; any other `P ≥ 2` uses MPFR at `P` bits and `ceil(P·log10 2) + 2`
//! digits.  Inputs are decimals rounded to the working precision.  Bad input (malformed
//! or out-of-range number, A,B,C not in the order A > B > C > 0, `M = 0`, invariants
//! `M²`, `E`, `k`, `ν` of the start point that overflow or underflow at the working
//! precision, Newton failing because `h` is too large) and failed writes stop with one
//! line on standard error and exit status 2; rows printed before a failing step stay
//! printed.

use super::{CliError, stdout, write_error};
use crate::linalg::Vec3;
use crate::model::{EllipticParams, Gamma, Inertia, Stepper, orbit};
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
    #[arg(long, default_value_t = 1, allow_negative_numbers = true, value_parser = super::whole::<usize>)]
    pub steps: usize,
    /// Precision in bits (53 = f64).
    #[arg(long, default_value_t = 53, allow_negative_numbers = true, value_parser = super::whole::<u32>)]
    pub bits: u32,
    /// Start point M1 M2 M3.
    #[arg(num_args = 3, required = true, value_names = ["M1", "M2", "M3"])]
    pub m: Vec<String>,
}

/// Parsed, validated inputs at the working precision.
pub struct Problem<R> {
    /// Moments of inertia.
    pub inertia: Inertia<R>,
    /// γ (γ_VM for the matrix algorithm).
    pub gamma: Gamma,
    /// The map iterated: the implicit map with `gamma`, or the matrix algorithm.
    pub stepper: Stepper,
    /// Step size.
    pub h: R,
    /// Start point.
    pub m0: Vec3<R>,
    /// The parameters of the start point's level set (checked to be finite).
    pub params: EllipticParams<R>,
}

/// Parses a decimal at the precision of `like`; a valid decimal outside the range of the
/// working precision (overflow, or underflow to 0) is reported as such.
fn num<R: Real>(like: &R, s: &str, what: &str) -> Result<R, CliError> {
    let t = s.trim();
    let decimal = crate::numbers::is_decimal(t);
    let bits = like.precision().unwrap_or(53);
    match like.parse_like(s) {
        Ok(v) if v.is_zero() && decimal && crate::numbers::nonzero_mantissa(t) => Err(
            CliError::new(format!("{what} = {t} underflows to 0 at {bits} bits")),
        ),
        Ok(v) => Ok(v),
        Err(_) if decimal => Err(CliError::new(format!(
            "{what} = {t} overflows at {bits} bits"
        ))),
        Err(_) => Err(CliError::new(format!("malformed number '{s}' in {what}"))),
    }
}

fn parse_inertia<R: Real>(like: &R, text: &str) -> Result<Inertia<R>, CliError> {
    let parts: Vec<&str> = text.split(',').collect();
    if parts.len() != 3 {
        return Err(CliError::new(format!(
            "--inertia needs three numbers A,B,C, got '{text}'"
        )));
    }
    let a = num(like, parts[0], "A in --inertia")?;
    let b = num(like, parts[1], "B in --inertia")?;
    let c = num(like, parts[2], "C in --inertia")?;
    Inertia::new(a, b, c).map_err(|e| CliError::new(format!("--inertia: {e}")))
}

fn parse_stepper(args: &Args) -> Result<(Gamma, Stepper), CliError> {
    let gamma = Gamma::parse(&args.gamma).ok_or_else(|| {
        CliError::new(format!(
            "--gamma must be 0, 1, 2 or vm, got '{}'",
            args.gamma
        ))
    })?;
    match (args.matrix, gamma) {
        (false, g) => Ok((g, Stepper::Implicit(g))),
        (true, Gamma::Vm) => Ok((gamma, Stepper::Matrix)),
        (true, _) => Err(CliError::new(
            "--matrix is the Veselov-Moser algorithm and needs --gamma vm",
        )),
    }
}

/// Parses and validates the arguments at the precision of `like`: the numbers, the
/// order A > B > C > 0, `M ≠ 0`, and [`check_invariants`].
pub fn parse<R: Real>(like: &R, args: &Args) -> Result<Problem<R>, CliError> {
    let inertia = parse_inertia(like, &args.inertia)?;
    let (gamma, stepper) = parse_stepper(args)?;
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
    let params = check_invariants(&inertia, &m0, &args.inertia)?;
    Ok(Problem {
        inertia,
        gamma,
        stepper,
        h,
        m0,
        params,
    })
}

/// `v` must be finite and nonzero at the working precision.
fn in_range<R: Real>(v: &R, what: &str) -> Result<(), CliError> {
    let bits = v.precision().unwrap_or(53);
    let hint = "rescale M, or use --bits 54 or more (MPFR has a far wider exponent range)";
    if !v.is_finite() {
        return Err(CliError::new(format!(
            "{what} of the start point overflows at {bits} bits; {hint}"
        )));
    }
    if v.is_zero() {
        return Err(CliError::new(format!(
            "{what} of the start point underflows to 0 at {bits} bits; {hint}"
        )));
    }
    Ok(())
}

/// Checks that the invariants of the start point — `M²` (M2), `E` (E) and the
/// parameters `k²` (k), `ν²` (nu), `a², b², c²` (abc) of its level set — can be formed
/// at the working precision.  `step` and `orbit` validate their input with it.
pub fn check_invariants<R: Real>(
    inertia: &Inertia<R>,
    m0: &Vec3<R>,
    inertia_text: &str,
) -> Result<EllipticParams<R>, CliError> {
    in_range(&inertia.m2(m0), "M² = M1² + M2² + M3²")?;
    in_range(&inertia.energy(m0), "the energy E = M1²/A + M2²/B + M3²/C")?;
    let p = EllipticParams::from_point(inertia, m0)
        .map_err(|e| CliError::new(format!("start point: {e}")))?;
    let finite = [&p.k2, &p.nu2, &p.a2, &p.b2, &p.c2]
        .iter()
        .all(|x| x.is_finite());
    let z = p.k2.zero();
    if !finite || p.k2 < z || p.k2 > z.one() {
        return Err(CliError::new(format!(
            "the modulus k cannot be formed from the inertia values A,B,C = {inertia_text} \
             and this start point at {} bits: k² = {}, ν² = {} (an intermediate result \
             overflows)",
            p.k2.precision().unwrap_or(53),
            p.k2.to_decimal(6),
            p.nu2.to_decimal(6)
        )));
    }
    Ok(p)
}

/// The iterates `M₁ … M_N`, computed lazily; an error names the failing step.
pub fn iterates<R: Real>(
    p: &Problem<R>,
    steps: usize,
) -> impl Iterator<Item = Result<Vec3<R>, CliError>> + '_ {
    orbit(&p.inertia, p.stepper, &p.m0, &p.h)
        .take(steps)
        .enumerate()
        .map(|(i, r)| r.map_err(|e| CliError::new(format!("step {}: {e}", i + 1))))
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

/// Writes `M` as one line of three decimals.
pub fn write_point<R: Real>(w: &mut impl Write, m: &Vec3<R>, d: usize) -> std::io::Result<()> {
    writeln!(
        w,
        "{} {} {}",
        m.0[0].to_decimal(d),
        m.0[1].to_decimal(d),
        m.0[2].to_decimal(d)
    )
}

fn run_generic<R: Real>(like: R, args: &Args) -> Result<i32, CliError> {
    let p = parse(&like, args)?;
    let d = digits_for(args.bits);
    let mut out = stdout();
    let err = write_error("standard output");
    for m in iterates(&p, args.steps) {
        write_point(&mut out, &m?, d).map_err(&err)?;
    }
    out.flush().map_err(&err)?;
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
