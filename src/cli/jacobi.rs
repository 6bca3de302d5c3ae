//! `eulertop jacobi`: Jacobi elliptic functions of arguments read from standard input.
//!
//! Each input line is `u k` with `k ≥ 0` the **modulus** (`--parameter`: `u m` with the
//! parameter `m = k²`, any real), or `re(u) im(u) k` with `--complex` (any `k ≥ 0`;
//! with `--parameter`: `re(u) im(u) m`, any real `m`).
//! Each output line holds the functions chosen by `--functions` (default `sn,cn,dn`;
//! any of the twelve `sn cn dn cd dc ns nc nd sc sd cs ds`), each as one number (with
//! `--complex`: real and imaginary part).  Blank lines and lines starting with `#` are
//! skipped.  `--bits 53` (default) uses the `f64` code path and prints 17 significant
//! digits; any other `N ≥ 2` uses MPFR at `N` bits and prints `ceil(N·log10 2) + 2`
//! digits.  Inputs are read as decimals rounded to the working precision.  A malformed
//! line (also one that is not UTF-8 or longer than 4096 bytes), a number that overflows
//! the working precision (or underflows to 0 there), a modulus or parameter that rounds
//! to 1 without being 1, an out-of-domain modulus or a pole stops with
//! `eulertop: <stdin>:LINE:COL: …` (the offending text cut to 40 characters, control
//! characters escaped) on standard error and exit status 2.
//!
//! Next to a pole of a quotient (real argument) the value depends on the last bits of
//! `u`: where a requested quotient's relative condition number
//! `κ_u = |u f'(u)/f(u)|` ([`JacobiFn::condition`]) reaches `2^⌈N/2⌉` at `N` bits (at
//! least half of the result's bits then move with the rounding of `u`), the run ends
//! with one warning line on standard error (how many lines, the first of them, its
//! function and `κ_u`); the values are printed as always and the exit status is 0.

use super::CliError;
use crate::numbers::{Cplx, Real};
use crate::special::{
    JacobiFn, SpecialError, jacobi_complex_m_set, jacobi_complex_set, jacobi_m_set, jacobi_set,
};
use std::io::{BufRead, Read, Write};

/// Longest accepted input line in bytes.
const MAX_LINE: usize = 4096;

/// Arguments of `eulertop jacobi`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Precision in bits: 53 = f64 code path, otherwise MPFR at this many bits.
    #[arg(long, default_value_t = 53, allow_negative_numbers = true, value_parser = super::whole::<u32>)]
    pub bits: u32,
    /// Complex argument: lines are `re(u) im(u) k` (with --parameter: `re(u) im(u) m`).
    #[arg(long)]
    pub complex: bool,
    /// Lines are `u m` with the parameter m = k² (any real; m < 0 is an imaginary
    /// modulus) instead of the modulus k.
    #[arg(long)]
    pub parameter: bool,
    /// The functions to print, comma-separated, from sn cn dn cd dc ns nc nd sc sd cs ds.
    #[arg(long, default_value = "sn,cn,dn", value_parser = parse_functions)]
    pub functions: Functions,
}

/// A list of Jacobi functions (`--functions`).
#[derive(Clone, Debug)]
pub struct Functions(pub Vec<JacobiFn>);

/// Parses `--functions`.
fn parse_functions(s: &str) -> Result<Functions, String> {
    let list: Result<Vec<JacobiFn>, String> = s
        .split(',')
        .map(|name| {
            JacobiFn::from_name(name.trim()).ok_or_else(|| {
                format!(
                    "unknown function '{}' (expected sn cn dn cd dc ns nc nd sc sd cs ds)",
                    excerpt(name)
                )
            })
        })
        .collect();
    list.map(Functions)
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
    let opts = Options {
        complex: args.complex,
        parameter: args.parameter,
        functions: args.functions.0,
    };
    if args.bits == 53 {
        process(input, &mut out, 0.0_f64, 17, &opts)
    } else {
        let digits = (args.bits as f64 * std::f64::consts::LOG10_2).ceil() as usize + 2;
        process(input, &mut out, rug::Float::new(args.bits), digits, &opts)
    }
}

/// What to compute for each line.
pub struct Options {
    /// Complex argument (`re(u) im(u) k`).
    pub complex: bool,
    /// The second number is the parameter `m = k²`.
    pub parameter: bool,
    /// The functions to print.
    pub functions: Vec<JacobiFn>,
}

/// `s` cut to 40 characters (with `…` when cut), control characters escaped (`\0`,
/// `\u{1b}`) so that none reaches the terminal.
fn excerpt(s: &str) -> String {
    super::printable(&s.chars().take(40).collect::<String>())
        + if s.chars().nth(40).is_some() {
            "…"
        } else {
            ""
        }
}

/// The position `<stdin>:LINE:COL` of `field`, a slice of `line` (columns count
/// characters from 1).
fn at(line: &str, field: &str, lno: usize) -> String {
    let offset = (field.as_ptr() as usize).saturating_sub(line.as_ptr() as usize);
    let col = line.get(..offset).map_or(1, |h| h.chars().count() + 1);
    format!("<stdin>:{lno}:{col}")
}

/// Reads the next line (without its end) into `buf`, at most [`MAX_LINE`] bytes;
/// `Ok(false)` at the end of the input.
fn next_line(input: &mut impl BufRead, buf: &mut Vec<u8>, lno: usize) -> Result<bool, CliError> {
    buf.clear();
    let io = |e: std::io::Error| CliError::new(format!("<stdin>:{lno}: cannot read: {e}"));
    let n = input
        .by_ref()
        .take(MAX_LINE as u64 + 1)
        .read_until(b'\n', buf)
        .map_err(io)?;
    if n == 0 {
        return Ok(false);
    }
    if buf.last() == Some(&b'\n') {
        buf.pop();
    } else if buf.len() > MAX_LINE {
        let head = String::from_utf8_lossy(&buf[..40]).into_owned();
        return Err(CliError::new(format!(
            "<stdin>:{lno}:1: longer than {MAX_LINE} bytes ('{}…')",
            excerpt(&head)
        )));
    }
    Ok(true)
}

/// Parses one number `s` of a line at the precision of `proto` (the decimal grammar of
/// [`crate::numbers::is_decimal`]); `pos` is its position.  A decimal that overflows or
/// underflows to 0 at the working precision is an error saying so.
fn number<R: Real>(proto: &R, s: &str, what: &str, pos: &str) -> Result<R, CliError> {
    let bits = proto.precision().unwrap_or(53);
    let decimal = crate::numbers::is_decimal(s);
    match proto.parse_like(s) {
        Ok(v) if v.is_zero() && decimal && crate::numbers::nonzero_mantissa(s) => {
            Err(CliError::new(format!(
                "{pos}: {what} = {} underflows to 0 at {bits} bits",
                excerpt(s)
            )))
        }
        Ok(v) => Ok(v),
        Err(_) if decimal => Err(CliError::new(format!(
            "{pos}: {what} = {} overflows at {bits} bits",
            excerpt(s)
        ))),
        Err(_) => Err(CliError::new(format!(
            "{pos}: malformed {what} '{}' (a decimal such as 0.5, -2 or 1e-3)",
            excerpt(s)
        ))),
    }
}

/// Refuses a modulus or parameter that the rounding to the working precision made 1
/// (where the functions change regime: cn = dn = sech u) although the text is not 1.
fn check_not_rounded_to_one<R: Real>(
    k: &R,
    s: &str,
    what: &str,
    pos: &str,
) -> Result<(), CliError> {
    if (k.clone() - k.one()).is_zero() && !crate::numbers::decimal_is_one(s) {
        let bits = k.precision().unwrap_or(53);
        return Err(CliError::new(format!(
            "{pos}: {what} = {} rounds to 1 at {bits} bits, where the functions differ (cn = dn = sech u); give more --bits",
            excerpt(s)
        )));
    }
    Ok(())
}

/// Reads all lines from `input` and writes the results, generically over the real type
/// whose precision `proto` carries; at the end, the warning about ill-conditioned
/// quotients (see the module documentation) on standard error, if any.
pub fn process<R: Real>(
    mut input: impl BufRead,
    out: &mut impl Write,
    proto: R,
    digits: usize,
    opts: &Options,
) -> Result<i32, CliError> {
    let io = super::write_error("standard output");
    let bits = proto.precision().unwrap_or(53);
    let bound = 2f64.powi(bits.div_ceil(2).min(1023) as i32);
    let mut ill = IllConditioned::default();
    let mut buf = Vec::new();
    let mut lno = 0usize;
    while {
        lno += 1;
        next_line(&mut input, &mut buf, lno)?
    } {
        let line = std::str::from_utf8(&buf).map_err(|_| {
            let lossy = String::from_utf8_lossy(&buf).into_owned();
            CliError::new(format!(
                "<stdin>:{lno}:{}: not valid UTF-8 ('{}')",
                std::str::from_utf8(&buf).map_or_else(|e| e.valid_up_to(), |_| 0) + 1,
                excerpt(&lossy)
            ))
        })?;
        let t = line.trim();
        if t.is_empty() || t.starts_with('#') {
            continue;
        }
        let (text, worst) = line_values(&proto, t, lno, digits, opts)?;
        ill.note(lno, worst, bound);
        writeln!(out, "{text}").map_err(&io)?;
    }
    out.flush().map_err(&io)?;
    if let Some(w) = ill.warning(bits) {
        eprintln!("eulertop: {w}");
    }
    Ok(0)
}

/// The output line for one input line `t`.
fn line_values<R: Real>(
    proto: &R,
    t: &str,
    lno: usize,
    digits: usize,
    opts: &Options,
) -> Result<(String, Option<Worst>), CliError> {
    let fields: Vec<&str> = t.split_whitespace().take(4).collect();
    let mut ill = None;
    let (want, shape) = match (opts.complex, opts.parameter) {
        (true, true) => (3, "re(u) im(u) m"),
        (true, false) => (3, "re(u) im(u) k"),
        (false, true) => (2, "u m"),
        (false, false) => (2, "u k"),
    };
    if fields.len() != want {
        let found = if fields.len() > want {
            format!("more than {want}")
        } else {
            fields.len().to_string()
        };
        return Err(CliError::new(format!(
            "<stdin>:{lno}:1: expected {want} numbers ({shape}), found {found} in '{}'",
            excerpt(t)
        )));
    }
    let pos = |j: usize| at(t, fields[j], lno);
    // a modulus out of range is at the modulus, anything else at u
    let err = |e: SpecialError| {
        let j = match e {
            SpecialError::ModulusOutOfRange(_) => fields.len() - 1,
            _ => 0,
        };
        CliError::new(format!("{}: {e}", pos(j)))
    };
    let values: Vec<String> = if opts.complex {
        let u = Cplx::new(
            number(proto, fields[0], "re(u)", &pos(0))?,
            number(proto, fields[1], "im(u)", &pos(1))?,
        );
        let second = if opts.parameter {
            "parameter m"
        } else {
            "modulus k"
        };
        let k = number(proto, fields[2], second, &pos(2))?;
        check_not_rounded_to_one(&k, fields[2], second, &pos(2))?;
        // sn, cn, dn once per line, the requested functions from them
        let values = if opts.parameter {
            jacobi_complex_m_set(&opts.functions, &u, &k)
        } else {
            jacobi_complex_set(&opts.functions, &u, &k)
        };
        let values = values.map_err(err)?;
        let parts = values.iter().flat_map(|z| [&z.re, &z.im]);
        parts.map(|x| x.to_decimal(digits)).collect()
    } else {
        let u = number(proto, fields[0], "u", &pos(0))?;
        let second = if opts.parameter {
            "parameter m"
        } else {
            "modulus k"
        };
        let k = number(proto, fields[1], second, &pos(1))?;
        check_not_rounded_to_one(&k, fields[1], second, &pos(1))?;
        let (values, worst) = real_values(&u, &k, opts).map_err(err)?;
        ill = worst;
        values.iter().map(|x| x.to_decimal(digits)).collect()
    };
    Ok((values.join(" "), ill))
}

/// The largest relative condition number `κ_u` of a line's quotients, with its function.
type Worst = (f64, JacobiFn);

/// The requested functions of a real argument (sn, cn, dn computed once, the others
/// from them) and, when a quotient with a denominator is among them, the largest of
/// their relative condition numbers `κ_u` ([`JacobiFn::condition`]) with its function.
fn real_values<R: Real>(
    u: &R,
    k: &R,
    opts: &Options,
) -> Result<(Vec<R>, Option<Worst>), SpecialError> {
    let fs = &opts.functions;
    let quotients: Vec<JacobiFn> = fs
        .iter()
        .copied()
        .filter(|f| f.parts().1.is_some())
        .collect();
    if quotients.is_empty() {
        let values = if opts.parameter {
            jacobi_m_set(fs, u, k)?
        } else {
            jacobi_set(fs, u, k)?
        };
        return Ok((values, None));
    }
    // sn, cn, dn along with the requested functions, from the same evaluation
    let mut all = fs.clone();
    all.extend([JacobiFn::Sn, JacobiFn::Cn, JacobiFn::Dn]);
    let mut values = if opts.parameter {
        jacobi_m_set(&all, u, k)?
    } else {
        jacobi_set(&all, u, k)?
    };
    let (s, c, d) = (
        &values[fs.len()],
        &values[fs.len() + 1],
        &values[fs.len() + 2],
    );
    let m = if opts.parameter { k.clone() } else { k.sqr() };
    let worst = quotients
        .iter()
        .map(|f| (f.condition(u, &m, (s, c, d)).to_f64(), *f))
        .max_by(|a, b| a.0.total_cmp(&b.0));
    values.truncate(fs.len());
    Ok((values, worst))
}

/// Lines whose quotients are ill-conditioned (`κ_u ≥ 2^⌈N/2⌉`): how many, and the
/// first of them (line, function, `κ_u`).
#[derive(Default)]
struct IllConditioned {
    lines: usize,
    first: Option<(usize, JacobiFn, f64)>,
}

impl IllConditioned {
    /// Counts line `lno` if its worst `κ_u` reaches `bound`.
    fn note(&mut self, lno: usize, worst: Option<Worst>, bound: f64) {
        if let Some((kappa, f)) = worst.filter(|w| w.0 >= bound) {
            self.lines += 1;
            self.first.get_or_insert((lno, f, kappa));
        }
    }

    /// The one-line warning (without the `eulertop: ` prefix), if any line was counted.
    fn warning(&self, bits: u32) -> Option<String> {
        let (lno, f, kappa) = self.first?;
        let half = bits.div_ceil(2);
        Some(format!(
            "warning: {} line(s) evaluate a quotient next to its pole, where its relative condition number κ_u = |u f'(u)/f(u)| reaches 2^{half} or more (first: <stdin>:{lno}, {} with κ_u = {kappa:.3e}): there a change of u in its last bit moves the value by about κ_u units of its last bit",
            self.lines,
            f.name()
        ))
    }
}
