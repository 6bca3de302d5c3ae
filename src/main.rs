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
enum Command {}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result: Result<i32, eulertop::cli::CliError> = match cli.command {};
    match result {
        Ok(code) => ExitCode::from(code as u8),
        Err(e) => {
            eprintln!("eulertop: {e}");
            ExitCode::from(2)
        }
    }
}
