//! The proof checker: runs the whole catalogue (`identities/`) at 53 and 256 bits, and
//! exactly where a claim is rational, and fails on any verdict different from `expect`.

use eulertop::bindings::euler_top::registry;
use eulertop::claims::catalogue::load_dir;
use eulertop::claims::verdict::{verify, Options, Verdict};
use std::path::Path;

#[test]
fn every_verdict_matches_expect() {
    let cat = match load_dir(Path::new("identities"), registry().unwrap()) {
        Ok(c) => c,
        Err(e) => panic!("catalogue does not load:\n{e}"),
    };
    assert!(!cat.claims.is_empty(), "empty catalogue");
    let opts = Options {
        bits: vec![53, 256],
        exact: true,
    };
    let results = verify(&cat, &opts, &|_| true, &|_| {});
    let bad: Vec<String> = results
        .iter()
        .filter(|r| !r.as_expected)
        .map(|r| {
            format!(
                "{} ({}): verdict {} but expect {} — {}",
                r.id,
                r.position,
                r.verdict.name(),
                r.expect.map_or("-", |v| v.name()),
                r.reason
            )
        })
        .collect();
    assert!(
        bad.is_empty(),
        "{} claims not as expected:\n{}",
        bad.len(),
        bad.join("\n")
    );
    // every refuted claim carries a counterexample; every proved one its exact evidence
    for r in &results {
        if r.verdict == Verdict::Refuted {
            assert!(
                r.counterexample.is_some(),
                "{} refuted without counterexample",
                r.id
            );
        }
        if r.verdict == Verdict::Proved {
            let ex = r.exact.as_ref().expect("proved without exact info");
            assert!(
                ex.all_zero && ex.points > 0 && ex.per_point_bound.is_some(),
                "{}",
                r.id
            );
        }
    }
}
