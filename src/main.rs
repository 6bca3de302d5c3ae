//! The `eulertop` command-line tool.  See `eulertop --help`.

use clap::{Parser, Subcommand};
use std::process::ExitCode;

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
    /// sn, cn, dn of `u k` lines from stdin (`--complex`: `re(u) im(u) k`).
    Jacobi(eulertop::cli::jacobi::Args),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result: Result<i32, eulertop::cli::CliError> = match cli.command {
        Command::Jacobi(a) => eulertop::cli::jacobi::run(a),
    };
    match result {
        Ok(code) => ExitCode::from(code as u8),
        Err(e) => {
            eprintln!("eulertop: {e}");
            ExitCode::from(2)
        }
    }
}
