//! The `eulertop` command-line tool.  See `eulertop --help`.

use clap::{Parser, Subcommand};
use std::io::Write;
use std::process::ExitCode;

/// mimalloc serves every allocation of the process, GMP's and FLINT's included
/// (feature `override`): the symbolic proofs allocate and free polynomials at a high
/// rate, and `verify` takes 11 % less CPU than with the system allocator.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// Formula-by-formula verification of Bobenko–Lorbeer–Suris,
/// "Integrable discretizations of the Euler top".
#[derive(Parser)]
#[command(name = "eulertop", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Verify the claim catalogue on a precision ladder.
    Verify(eulertop::cli::verify::Args),
    /// The symbolic proof of one identity, step by step (and its certificate).
    Prove(eulertop::cli::prove::Args),
    /// Residual of one claim against precision, up to thousands of bits.
    Audit(eulertop::cli::audit::Args),
    /// Evaluate an expression of the catalogue language.
    Eval(eulertop::cli::eval::Args),
    /// Jacobi functions of `u k` lines from stdin, k the modulus (`--parameter`: m = k²).
    Jacobi(eulertop::cli::jacobi::Args),
    /// Iterates a discretization of the Euler top (impl spec / VM) from M1 M2 M3.
    Step(eulertop::cli::step::Args),
    /// Iterates and compares with the continuous solution; writes CSV and SVG.
    Orbit(eulertop::cli::orbit::Args),
    /// Verify the catalogue and write the Markdown reports into reports/.
    Report(eulertop::cli::report::Args),
    /// Start the catalogue of a new paper in DIR (a [paper] table and two claims).
    Init(eulertop::cli::init::Args),
}

fn main() -> ExitCode {
    // before any other thread runs (see the module's documentation)
    eulertop::numbers::gmp_kernels::select();
    eulertop::allocator::small_pages();
    // a closed standard output (`>&-`) would swallow every write, and the next file
    // opened would take its descriptor: refused before anything runs
    if let Some(which) = closed_standard_stream() {
        let _ = writeln!(
            std::io::stderr(),
            "eulertop: {which} is closed; nothing would be written (redirect it to a file or /dev/null)"
        );
        return ExitCode::from(2);
    }
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        // help and version (exit 0) go to standard output, the help asked for by no
        // command at all to standard error (exit 2); a failed write exits with status 2
        // and says so
        Err(e)
            if !e.use_stderr()
                || e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand =>
        {
            return match e.print().and_then(|()| std::io::stdout().flush()) {
                Ok(()) => ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2)),
                Err(w) => {
                    let dest = if e.use_stderr() {
                        "standard error"
                    } else {
                        "standard output"
                    };
                    let _ = writeln!(std::io::stderr(), "eulertop: cannot write to {dest}: {w}");
                    ExitCode::from(2)
                }
            };
        }
        // a usage error: one line on standard error, status 2
        Err(e) => {
            let _ = writeln!(std::io::stderr(), "eulertop: {}", usage_error(&e));
            return ExitCode::from(2);
        }
    };
    let result: Result<i32, eulertop::cli::CliError> = match cli.command {
        Command::Verify(a) => eulertop::cli::verify::run(a),
        Command::Prove(a) => eulertop::cli::prove::run(a),
        Command::Audit(a) => eulertop::cli::audit::run(a),
        Command::Eval(a) => eulertop::cli::eval::run(a),
        Command::Jacobi(a) => eulertop::cli::jacobi::run(a),
        Command::Step(a) => eulertop::cli::step::run(a),
        Command::Orbit(a) => eulertop::cli::orbit::run(a),
        Command::Report(a) => eulertop::cli::report::run(a),
        Command::Init(a) => eulertop::cli::init::run(a),
    };
    match result {
        Ok(code) => ExitCode::from(u8::try_from(code).unwrap_or(2)),
        Err(e) => {
            // standard error may be closed too (`2>&1 | head`): never panic on it
            let _ = writeln!(std::io::stderr(), "eulertop: {e}");
            ExitCode::from(2)
        }
    }
}

/// `Some("standard output")` when it was closed when the process started.  The Rust
/// runtime opens `/dev/null` read-write on a closed standard descriptor before `main`;
/// a shell's `>/dev/null` opens it write-only, so a read-write `/dev/null` on descriptor
/// 1 is a closed standard output (`>&-`).
fn closed_standard_stream() -> Option<&'static str> {
    #[cfg(unix)]
    {
        // SAFETY: F_GETFD and F_GETFL only query the descriptor; fstat and stat write
        // into the zeroed structures passed.
        unsafe {
            if libc::fcntl(1, libc::F_GETFD) == -1 {
                return Some("standard output");
            }
            let flags = libc::fcntl(1, libc::F_GETFL);
            if flags == -1 || flags & libc::O_ACCMODE != libc::O_RDWR {
                return None;
            }
            let mut fd: libc::stat = std::mem::zeroed();
            let mut null: libc::stat = std::mem::zeroed();
            if libc::fstat(1, &mut fd) == 0
                && libc::stat(c"/dev/null".as_ptr(), &mut null) == 0
                && fd.st_mode & libc::S_IFMT == libc::S_IFCHR
                && fd.st_rdev == null.st_rdev
            {
                return Some("standard output");
            }
        }
    }
    None
}

/// clap's message for a usage error on one line: the message with the lines that
/// continue it (the missing arguments, say) and clap's tips, without the usage block.
fn usage_error(e: &clap::Error) -> String {
    let text = e.render().to_string();
    let mut parts: Vec<String> = Vec::new();
    let mut tips: Vec<String> = Vec::new();
    let mut in_message = true;
    for line in text.lines() {
        let t = line.trim();
        if t.is_empty() {
            in_message = false;
        } else if let Some(tip) = t.strip_prefix("tip: ") {
            tips.push(tip.to_string());
        } else if in_message {
            parts.push(t.strip_prefix("error: ").unwrap_or(t).to_string());
        }
    }
    let mut line = parts.join(" ");
    for tip in tips {
        line.push_str(&format!("; {tip}"));
    }
    line.push_str(" (eulertop --help lists the commands and options)");
    line
}

#[cfg(test)]
mod tests {
    use super::Cli;
    use clap::CommandFactory;

    /// clap's own consistency checks (unique argument and group ids, …) for every
    /// subcommand; they run only in debug builds of the binary otherwise.
    #[test]
    fn cli_definition_is_consistent() {
        Cli::command().debug_assert();
    }
}
