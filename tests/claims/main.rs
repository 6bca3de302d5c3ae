//! Integration tests of the claims engine: verdicts on synthetic catalogues, the fuzzed
//! lexer, parser, loader and evaluator, and the coverage of the paper's labels.

/// The allocator of the `eulertop` binary (mimalloc, serving GMP and FLINT too), so that
/// the tests run the product's configuration.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

mod claims_engine;
mod conditions;
mod coverage;
mod decided_branches;
mod dominant_roots;
mod fuzz_claims;
mod implicit_proofs;
mod intervals;
mod iterations;
mod lemmas;
mod moving_moduli;
mod ode_proofs;
mod partials;
mod perturbations;
mod proof_hints;
mod prose;
mod rational_shifts;
mod root_splits;
mod series_orders;
mod sign_cases;
mod sound_proofs;
mod splits;
mod support;
mod verdict_rules;
mod witnesses;
