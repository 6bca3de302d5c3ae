//! Coverage: every `\label` of the paper and every environment of the catalogue's
//! `[paper]` table that is not a section has at least one claim in the catalogue.  Labels are read from the paper's LaTeX
//! source when the environment variable `EULERTOP_PAPER` names it; the `labels` of the
//! catalogue's `[paper]` table (`identities/paper.toml`) keep the test meaningful without
//! it (and are themselves checked against the paper when it is given).

use eulertop::bindings::euler_top::registry;
use eulertop::claims::catalogue::{coverage, latex_labels, load_dir};
use std::path::Path;

/// The paper's LaTeX source, if `EULERTOP_PAPER` names a readable file.
fn paper() -> Option<String> {
    std::fs::read_to_string(std::env::var_os("EULERTOP_PAPER")?).ok()
}

/// The `labels` of the catalogue's `[paper]` table.
fn checked_in_labels() -> Vec<String> {
    let cat = load_dir(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("identities"),
        registry().unwrap(),
    )
    .unwrap_or_else(|e| panic!("catalogue does not load:\n{e}"));
    cat.paper.expect("a [paper] table").labels
}

#[test]
fn checked_in_label_list_matches_the_paper() {
    let list = checked_in_labels();
    assert_eq!(list.len(), 96, "the paper has 96 labels");
    if let Some(tex) = paper() {
        assert_eq!(
            latex_labels(&tex),
            list,
            "the labels of identities/paper.toml are stale"
        );
        // 12 numbered environments and one Corollary
        for (env, n) in [
            ("definition", 1),
            ("proposition", 6),
            ("lemma", 2),
            ("theorem", 3),
        ] {
            assert_eq!(
                tex.matches(&format!("\\begin{{{env}}}")).count(),
                n,
                "{env}"
            );
        }
        assert_eq!(tex.matches("{\\bf Corollary.}").count(), 1);
    }
}

#[test]
fn every_label_and_environment_has_a_claim() {
    let cat = match load_dir(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("identities"),
        registry().unwrap(),
    ) {
        Ok(c) => c,
        Err(e) => panic!("catalogue does not load:\n{e}"),
    };
    let labels = match paper() {
        Some(tex) => latex_labels(&tex),
        None => checked_in_labels(),
    };
    let cov = coverage(&cat);
    let missing: Vec<&String> = labels.iter().filter(|l| !cov.contains_key(*l)).collect();
    assert!(missing.is_empty(), "labels without a claim: {missing:?}");
    // no claim names a label the paper does not have (catches typos in `labels`)
    let unknown: Vec<&String> = cov.keys().filter(|l| !labels.contains(l)).collect();
    assert!(
        unknown.is_empty(),
        "claims name labels not in the paper: {unknown:?}"
    );
    let envs: Vec<String> = cat
        .all_environments()
        .into_iter()
        .filter(|e| !e.section)
        .map(|e| e.name)
        .collect();
    // 12 numbered environments and one Corollary
    assert_eq!(envs.len(), 13, "{envs:?}");
    for env in &envs {
        let env = env.as_str();
        let found = cat.claims.iter().any(|c| {
            c.location.match_indices(env).any(|(j, _)| {
                !c.location[j + env.len()..]
                    .chars()
                    .next()
                    .is_some_and(|ch| ch.is_ascii_digit())
            })
        });
        assert!(found, "no claim for {env}");
    }
}
