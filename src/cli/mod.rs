//! The outputs layer: the `eulertop` command-line interface.
//!
//! Every subcommand lives in its own module with an `Args` struct (clap derive) and a
//! `run(args) -> Result<i32, CliError>` function returning the exit status.
//! A [`CliError`] is printed as one line on standard error and exits with status 2.

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

pub mod jacobi;
pub mod orbit;
pub mod step;

/// Parses a comma-separated list such as `53,128,256`.
pub fn parse_list<T: std::str::FromStr>(s: &str, what: &str) -> Result<Vec<T>, CliError> {
    s.split(',')
        .map(|t| {
            t.trim()
                .parse::<T>()
                .map_err(|_| CliError(format!("malformed {what} '{}' in '{s}'", t.trim())))
        })
        .collect()
}

pub mod audit;
pub mod eval;
pub mod report;
pub mod verify;
