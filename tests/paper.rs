//! The proof checker, one trial per claim of the catalogue (`identities/`), named
//! `<environment>::<claim id>` (`proposition_6::sec7.prop6.g1-poisson.up`,
//! `section_2::sec2.def.ET`), so that `cargo test --test paper -- proposition_6` checks one
//! proposition and `cargo test --test paper -- --list` shows the paper's structure.
//!
//! Each trial verifies its claim at 53 and 256 bits, and exactly where the claim is
//! rational, and fails, with the verdict, the reason and the counterexample, when the
//! verdict differs from `expect`; a refuted claim must carry a counterexample and a proved
//! one its exact evidence.  One more trial checks that every environment of the paper has
//! claims.

/// The allocator of the `eulertop` binary, so that the timings are the product's.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use eulertop::claims::catalogue::{Catalogue, Claim, load_dir};
use eulertop::claims::structure::{ENVIRONMENTS, Environment, Role, place};
use eulertop::claims::verdict::{ClaimResult, Options, Verdict, run_claim, run_order};
use libtest_mimic::{Arguments, Failed, Trial};
use std::path::Path;
use std::sync::Arc;

fn options() -> Options {
    Options {
        bits: vec![53, 256],
        exact: true,
    }
}

/// What a failing trial prints.
fn explain(r: &ClaimResult) -> String {
    let mut s = format!(
        "{} ({}): verdict {} but expect {}\nreason: {}",
        r.id,
        r.position,
        r.verdict.name(),
        r.expect.map_or("none", |v| v.name()),
        r.reason
    );
    if let Some(c) = &r.counterexample {
        let point: Vec<String> = c
            .point
            .iter()
            .map(|p| format!("{} = {}", p.name, p.value))
            .collect();
        s.push_str(&format!(
            "\ncounterexample (at {} bits): {}\n  left side:  {}\n  right side: {}",
            c.bits,
            point.join(", "),
            c.lhs,
            c.rhs
        ));
    }
    s
}

fn check_claim(cat: &Catalogue, claim: &Claim) -> Result<(), Failed> {
    let r = run_claim(cat, claim, &options());
    if !r.as_expected {
        return Err(explain(&r).into());
    }
    if r.verdict == Verdict::Refuted && r.counterexample.is_none() {
        return Err(format!("{}: refuted without a counterexample", r.id).into());
    }
    if r.verdict == Verdict::Proved && !r.proof.is_proved() {
        return Err(format!("{}: proved without a symbolic proof", r.id).into());
    }
    Ok(())
}

/// Every environment of the paper has a statement claim in the catalogue.
fn check_environments(cat: &Catalogue) -> Result<(), Failed> {
    for (j, name) in ENVIRONMENTS.iter().enumerate() {
        let stated = cat
            .claims
            .iter()
            .filter_map(place)
            .any(|p| p.environment == Environment::Named(j) && p.role == Role::Statement);
        if !stated {
            return Err(format!("{name} has no statement claim").into());
        }
    }
    Ok(())
}

fn main() {
    let args = Arguments::from_args();
    // GMP's kernels for this processor, before any other thread runs
    eulertop::numbers::gmp_kernels::select();
    eulertop::allocator::small_pages();
    let cat = match load_dir(
        Path::new("identities"),
        eulertop::bindings::euler_top::registry().expect("the model's registry"),
    ) {
        Ok(c) => Arc::new(c),
        Err(e) => {
            eprintln!("catalogue does not load:\n{e}");
            std::process::exit(101);
        }
    };
    let mut trials = Vec::with_capacity(cat.claims.len() + 1);
    let whole = cat.clone();
    trials.push(Trial::test("paper::thirteen_environments", move || {
        check_environments(&whole)
    }));
    // `--list` shows the paper's order; a run takes the likely slowest claims first, as
    // `eulertop verify` does, so that no thread idles at the end
    let all: Vec<&Claim> = cat.claims.iter().collect();
    let order: Vec<usize> = if args.list {
        (0..all.len()).collect()
    } else {
        run_order(&cat, &all)
    };
    for j in order {
        let claim = &cat.claims[j];
        let env = place(claim)
            .map(|p| p.environment.slug())
            .unwrap_or_else(|| "unplaced".to_string());
        let cat = cat.clone();
        trials.push(Trial::test(format!("{env}::{}", claim.id), move || {
            check_claim(&cat, &cat.claims[j])
        }));
    }
    libtest_mimic::run(&args, trials).exit();
}
