//! `eulertop jacobi`: sn, cn, dn of arguments read from standard input.
//!
//! Each input line is `u k` (or `re(u) im(u) k` with `--complex`); each output line is
//! `sn cn dn` (with `--complex`: `sn.re sn.im cn.re cn.im dn.re dn.im`).  Blank lines
//! and lines starting with `#` are skipped.  `--bits 53` (default) uses the `f64` code
//! path and prints 17 significant digits; any other `N ≥ 2` uses MPFR at `N` bits and
//! prints `ceil(N·log10 2) + 2` digits.  Inputs are read as decimals rounded to the
//! working precision.  A malformed line or an out-of-domain modulus stops with
//! `eulertop: line L: …` on standard error and exit status 2.

use super::CliError;
use crate::numbers::{Cplx, Real};
use crate::special::{sncndn, sncndn_complex};
use std::io::{BufRead, Write};

/// Arguments of `eulertop jacobi`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Precision in bits: 53 = f64 code path, otherwise MPFR at this many bits.
    #[arg(long, default_value_t = 53)]
    pub bits: u32,
    /// Complex argument: lines are `re(u) im(u) k`.
    #[arg(long)]
    pub complex: bool,
}

/// Runs the subcommand on stdin/stdout; returns the exit status.
pub fn run(args: Args) -> Result<i32, CliError> {
    if !(2..=1 << 20).contains(&args.bits) {
        return Err(CliError::new(format!(
            "--bits {} is outside 2..=1048576",
            args.bits
        )));
    }
    let stdin = std::io::stdin();
    let stdout = std::io::stdout();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let input = stdin.lock();
    if args.bits == 53 {
        process(input, &mut out, 0.0_f64, 17, args.complex)
    } else {
        let digits = (args.bits as f64 * std::f64::consts::LOG10_2).ceil() as usize + 2;
        process(
            input,
            &mut out,
            rug::Float::new(args.bits),
            digits,
            args.complex,
        )
    }
}

/// Reads all lines from `input` and writes the results, generically over the real type
/// whose precision `proto` carries.
pub fn process<R: Real>(
    input: impl BufRead,
    out: &mut impl Write,
    proto: R,
    digits: usize,
    complex: bool,
) -> Result<i32, CliError> {
    let io = |e: std::io::Error| CliError::new(format!("I/O error: {e}"));
    for (i, line) in input.lines().enumerate() {
        let lno = i + 1;
        let line = line.map_err(io)?;
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = t.split_whitespace().collect();
        let want = if complex { 3 } else { 2 };
        if fields.len() != want {
            return Err(CliError::new(format!(
                "line {lno}: expected {want} numbers ({}), found {} in '{t}'",
                if complex { "re(u) im(u) k" } else { "u k" },
                fields.len()
            )));
        }
        let num = |s: &str, what: &str| {
            proto
                .parse_like(s)
                .map_err(|_| CliError::new(format!("line {lno}: malformed {what} '{s}'")))
        };
        let err = |e: crate::special::SpecialError| CliError::new(format!("line {lno}: {e}"));
        let text = if complex {
            let u = Cplx::new(num(fields[0], "re(u)")?, num(fields[1], "im(u)")?);
            let k = num(fields[2], "modulus k")?;
            let (s, c, d) = sncndn_complex(&u, &k).map_err(err)?;
            [s, c, d]
                .iter()
                .flat_map(|z| [z.re.to_decimal(digits), z.im.to_decimal(digits)])
                .collect::<Vec<_>>()
                .join(" ")
        } else {
            let u = num(fields[0], "u")?;
            let k = num(fields[1], "modulus k")?;
            let (s, c, d) = sncndn(&u, &k).map_err(err)?;
            [s, c, d]
                .iter()
                .map(|v| v.to_decimal(digits))
                .collect::<Vec<_>>()
                .join(" ")
        };
        writeln!(out, "{text}").map_err(io)?;
    }
    out.flush().map_err(io)?;
    Ok(0)
}
