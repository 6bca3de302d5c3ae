//! End-to-end tests of the `eulertop` binary: the claims commands, hostile input, the
//! `jacobi`, `step` and `orbit` commands, the report's figures, and the commands run
//! outside the repository.

mod anywhere;
mod cli_claims;
mod cli_hostile;
mod coq_cli;
mod jacobi;
mod model_cli;
mod prove_cli;
mod report_figures;
mod seeds;
