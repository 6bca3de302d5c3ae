//! The proof checker, one trial per claim of the catalogue (`identities/`), named
//! `<environment>::<claim id>` (`proposition_6::sec7.prop6.g1-poisson.up`,
//! `section_2::sec2.def.ET`), so that `cargo test --test paper -- proposition_6` checks one
//! proposition and `cargo test --test paper -- --list` shows the paper's structure.
//!
//! Each trial verifies its claim at 53 and 256 bits, and exactly where the claim is
//! rational, and fails, with the verdict, the reason and the counterexample, when the
//! verdict differs from `expect`; a refuted claim must carry a counterexample and a proved
//! one its exact evidence.  One more trial checks that every environment the catalogue's
//! `[paper]` table lists (sections aside) has a statement claim, or a reason why not.
//!
//! The claims whose trials run (after `--skip`, `--exact` and the name filter) are
//! verified by one run of [`verify`] on a background thread, scheduled as
//! `eulertop verify` schedules them: the likely slowest first, one queue for all workers,
//! and each claim's samples spread over the same rayon pool.  Each trial waits for its
//! claim's result, in that order, on the harness's one thread.  (A trial per worker
//! thread, each claim's samples on a second pool, takes 1.08 of the wall time.)

/// The allocator of the `eulertop` binary, so that the timings are the product's.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

use eulertop::claims::catalogue::{Catalogue, Claim, load_dir};
use eulertop::claims::structure::{Role, place};
use eulertop::claims::verdict::{ClaimResult, Options, Verdict, run_order, verify};
use libtest_mimic::{Arguments, Failed, Trial};
use std::collections::{HashMap, HashSet};
use std::path::Path;
use std::sync::{Arc, Condvar, Mutex};

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

/// The results of the background verification, by claim id, as they arrive.
#[derive(Default)]
struct Results {
    state: Mutex<(HashMap<String, ClaimResult>, bool)>,
    arrived: Condvar,
}

impl Results {
    fn put(&self, r: &ClaimResult) {
        let mut st = self.state.lock().unwrap_or_else(|e| e.into_inner());
        st.0.insert(r.id.clone(), r.clone());
        self.arrived.notify_all();
    }

    /// No more results will come.
    fn finish(&self) {
        self.state.lock().unwrap_or_else(|e| e.into_inner()).1 = true;
        self.arrived.notify_all();
    }

    /// The result of claim `id`, once it has arrived.
    fn take(&self, id: &str) -> Result<ClaimResult, Failed> {
        let mut st = self.state.lock().unwrap_or_else(|e| e.into_inner());
        loop {
            if let Some(r) = st.0.remove(id) {
                return Ok(r);
            }
            if st.1 {
                return Err(format!("{id}: the verification ended without its result").into());
            }
            st = self.arrived.wait(st).unwrap_or_else(|e| e.into_inner());
        }
    }
}

/// Verifies the claims `ids` on a background thread, handing each result to `results`.
fn verify_in_background(cat: Arc<Catalogue>, ids: HashSet<String>, results: Arc<Results>) {
    std::thread::spawn(move || {
        let run = || {
            verify(&cat, &options(), &|c: &Claim| ids.contains(&c.id), &|r| {
                results.put(r)
            })
        };
        // a result not handed over fails its trial, also if the run stops by a panic
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(run));
        results.finish();
    });
}

fn check_claim(results: &Results, claim: &Claim) -> Result<(), Failed> {
    let r = results.take(&claim.id)?;
    if !r.as_expected {
        return Err(explain(&r).into());
    }
    if r.verdict == Verdict::Refuted && r.counterexample.is_none() {
        return Err(format!("{}: refuted without a counterexample", r.id).into());
    }
    // proved: symbolically, or (a negation) by a point where its inner identity is
    // certified false
    let witnessed = r.proof.method == eulertop::claims::verdict::ProofMethod::Witness;
    if r.verdict == Verdict::Proved && !r.proof.is_proved() && !witnessed {
        return Err(format!("{}: proved without a symbolic proof or a witness", r.id).into());
    }
    Ok(())
}

/// Every environment of the paper (the `[paper]` table's list, sections aside) has a
/// statement claim in the catalogue, or the table says why not.
fn check_environments(cat: &Catalogue) -> Result<(), Failed> {
    if cat.paper.is_none() {
        return Err("the catalogue has no [paper] table".into());
    }
    for (env, spec) in cat.all_environments().iter().zip(&cat.environments) {
        if env.section || spec.no_statement.is_some() {
            continue;
        }
        let stated = cat
            .claims
            .iter()
            .filter_map(|c| place(cat, c))
            .any(|p| p.environment == *env && p.role == Role::Statement);
        if !stated {
            return Err(format!("{} has no statement claim", env.name).into());
        }
    }
    Ok(())
}

fn main() {
    let mut args = Arguments::from_args();
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
    trials.push(Trial::test("paper::every_environment_stated", move || {
        check_environments(&whole)
    }));
    let results = Arc::new(Results::default());
    // `--list` shows the paper's order; a run lists the trials in the order the
    // background verification takes the claims (the likely slowest first), so that the
    // results are reported as they arrive
    let all: Vec<&Claim> = cat.claims.iter().collect();
    let order: Vec<usize> = if args.list {
        (0..all.len()).collect()
    } else {
        run_order(&cat, &all)
    };
    for j in order {
        let claim = &cat.claims[j];
        let env = place(&cat, claim)
            .map(|p| p.environment.slug())
            .unwrap_or_else(|| "unplaced".to_string());
        let (cat, results) = (cat.clone(), results.clone());
        trials.push(Trial::test(format!("{env}::{}", claim.id), move || {
            check_claim(&results, &cat.claims[j])
        }));
    }
    if !args.list {
        // the claims of the trials that will run: their names are `<environment>::<id>`
        let ids: HashSet<String> = trials[1..]
            .iter()
            .filter(|t| !args.is_filtered_out(t) && !args.is_ignored(t))
            .filter_map(|t| t.name().split_once("::").map(|(_, id)| id.to_string()))
            .collect();
        verify_in_background(cat.clone(), ids, results);
        args.test_threads = Some(1);
    }
    libtest_mimic::run(&args, trials).exit();
}
