//! The outputs layer: the `eulertop` command-line interface.
//!
//! Every subcommand lives in its own module with an `Args` struct (clap derive) and a
//! `run(args) -> Result<i32, CliError>` function returning the exit status.
//! A [`CliError`] is printed as one line on standard error and exits with status 2.
//! Every write is checked: a full disk or a closed pipe on standard output is a
//! [`CliError`] too ([`write_error`]), never a panic and never a silent exit 0.

/// A user-facing error: one line naming what was wrong and where; exit status 2.
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct CliError(pub String);

impl CliError {
    /// Builds an error from anything displayable.
    pub fn new(msg: impl std::fmt::Display) -> Self {
        CliError(msg.to_string())
    }
}

/// A buffered, locked standard output.  Flush it explicitly and check the result: the
/// flush on drop ignores errors.
pub fn stdout() -> std::io::BufWriter<std::io::StdoutLock<'static>> {
    std::io::BufWriter::new(std::io::stdout().lock())
}

/// Turns a failed write to `dest` (a file name, or "standard output") into a
/// [`CliError`] naming the destination and the cause.
pub fn write_error(dest: impl std::fmt::Display) -> impl Fn(std::io::Error) -> CliError {
    move |e| CliError(format!("cannot write to {dest}: {e}"))
}

/// Writes `text` and a newline to standard output and flushes it; errors as
/// [`write_error`].
pub fn print(text: &str) -> Result<(), CliError> {
    use std::io::Write;
    let mut out = stdout();
    let err = write_error("standard output");
    writeln!(out, "{text}").map_err(&err)?;
    out.flush().map_err(&err)
}

/// `s` with control characters escaped (`\0`, `\u{1b}`, `\n`), for a message that
/// quotes input.
pub fn printable(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_control() {
                c.escape_default().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

/// Parses the value of a whole-number option (`--steps`, `--seed`, `--jobs`, `--bits`,
/// …): a negative number, a fraction or exponent form, and a value past the type's
/// maximum are each named as such (clap's own message would be "invalid digit").
///
/// ```
/// use eulertop::cli::whole;
/// assert_eq!(whole::<u32>("12"), Ok(12));
/// assert!(whole::<u32>("-5").unwrap_err().contains("negative"));
/// assert!(whole::<u32>("1e3").unwrap_err().contains("not a whole number"));
/// assert!(whole::<u32>("99999999999").unwrap_err().contains("too large"));
/// ```
pub fn whole<T>(s: &str) -> Result<T, String>
where
    T: std::str::FromStr + num_traits::Bounded + std::fmt::Display,
{
    let t = s.trim();
    if let Ok(v) = t.parse::<T>() {
        return Ok(v);
    }
    let max = T::max_value();
    let digits = |d: &str| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit());
    if let Some(rest) = t.strip_prefix('-')
        && digits(rest)
    {
        Err(format!(
            "{t} is negative (a whole number 0..={max} is expected)"
        ))
    } else if digits(t.strip_prefix('+').unwrap_or(t)) {
        Err(format!("{t} is too large (at most {max})"))
    } else {
        Err(format!(
            "'{}' is not a whole number (digits only, such as 12)",
            printable(t)
        ))
    }
}

/// Checks an output file option (`--certificate`, `--coq`, `--csv`, `--svg`) before the
/// work that fills it runs: a file name in an existing directory, not a directory itself.
pub fn check_output_path(flag: &str, p: &std::path::Path) -> Result<(), CliError> {
    let bad = |why: &str| Err(CliError(format!("{flag} '{}': {why}", p.display())));
    if p.as_os_str().is_empty() {
        return bad("an empty file name");
    }
    if p.is_dir() {
        return bad("is a directory");
    }
    let parent = match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => std::path::Path::new("."),
    };
    if !parent.is_dir() {
        return bad(&format!("no directory {}", parent.display()));
    }
    Ok(())
}

/// Whether `a` and `b` name one file: the same path once the directory is resolved, or
/// one existing file (a hard or symbolic link).
pub fn same_file(a: &std::path::Path, b: &std::path::Path) -> bool {
    let resolved = |p: &std::path::Path| {
        let dir = match p.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => std::path::Path::new("."),
        };
        Some(dir.canonicalize().ok()?.join(p.file_name()?))
    };
    if a == b || resolved(a).is_some_and(|x| Some(x) == resolved(b)) {
        return true;
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        if let (Ok(x), Ok(y)) = (std::fs::metadata(a), std::fs::metadata(b)) {
            return x.dev() == y.dev() && x.ino() == y.ino();
        }
    }
    false
}

/// The largest `--jobs` accepted (worker threads).
pub const MAX_JOBS: usize = 1024;

/// Checks `--jobs`: 1 to [`MAX_JOBS`] worker threads, or none given (all cores).
pub fn check_jobs(jobs: Option<usize>) -> Result<(), CliError> {
    match jobs {
        Some(j) if !(1..=MAX_JOBS).contains(&j) => Err(CliError(format!(
            "--jobs {j} is outside 1..={MAX_JOBS} (worker threads)"
        ))),
        _ => Ok(()),
    }
}

/// The budget of every symbolic proof attempt (`verify`, `prove`, `report`); see
/// [`crate::algebra::Budget`].
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct ProofBudgetArgs {
    /// Wall-clock time of one proof attempt in milliseconds, 1..=86400000; past it the
    /// claim is not proved and keeps its numerical verdict.
    #[arg(long, value_name = "MS", default_value_t = crate::algebra::DEFAULT_TIME_MS,
          value_parser = whole::<u64>, allow_negative_numbers = true)]
    pub proof_budget_ms: u64,
    /// Ceiling on the resident memory while a proof runs, in MiB, 64..=1048576.
    #[arg(long, value_name = "MB", default_value_t = crate::algebra::DEFAULT_MEMORY_MB,
          value_parser = whole::<u64>, allow_negative_numbers = true)]
    pub proof_memory_mb: u64,
}

impl ProofBudgetArgs {
    /// Checks the ranges and makes the budget that of every proof attempt.
    pub fn apply(&self) -> Result<(), CliError> {
        if !(1..=86_400_000).contains(&self.proof_budget_ms) {
            return Err(CliError(format!(
                "--proof-budget-ms {} is outside 1..=86400000 (milliseconds)",
                self.proof_budget_ms
            )));
        }
        if !(64..=1 << 20).contains(&self.proof_memory_mb) {
            return Err(CliError(format!(
                "--proof-memory-mb {} is outside 64..=1048576 (MiB)",
                self.proof_memory_mb
            )));
        }
        crate::algebra::set_default_budget(self.proof_budget_ms, self.proof_memory_mb);
        Ok(())
    }
}

pub mod jacobi;
pub mod orbit;
mod orbit_row;
mod orbit_svg;
pub mod step;

/// Parses a comma-separated list such as `53,128,256`.
pub fn parse_list<T: std::str::FromStr>(s: &str, what: &str) -> Result<Vec<T>, CliError> {
    s.split(',')
        .map(|t| {
            let t = t.trim();
            t.parse::<T>().map_err(|_| {
                let digits = t.strip_prefix(['-', '+']).unwrap_or(t);
                if !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit()) {
                    CliError(format!("{what} '{t}' in '{s}' is out of range"))
                } else {
                    CliError(format!("malformed {what} '{t}' in '{s}'"))
                }
            })
        })
        .collect()
}

pub mod audit;
pub mod catalogue_arg;
pub mod cert_source;
pub mod coq_export;
mod coq_poly;
pub mod eval;
pub mod init;
pub mod prove;
pub mod report;
mod report_install;
pub mod verify;
