//! Proof hints: the paper's multipliers of the defining equations (ideal membership).
//! A right hint proves the claim by that route; a wrong one never proves it, even
//! where the claim is true and the automatic route would prove it; malformed hints are
//! load errors that point at the hint.

use eulertop::bindings::euler_top::registry;
use eulertop::claims::catalogue::{Body, Catalogue, load_sources, read_sources};
use eulertop::claims::verdict::context::Ctx;
use eulertop::claims::verdict::symbolic::prove;
use eulertop::claims::verdict::{Options, Verdict, run_claim};

/// A Proposition 4 control for γ₂ with the given hint line (empty: no hint).
fn control(id: &str, hint: &str) -> String {
    format!(
        r#"
[[claim]]
id = "{id}"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: the integrals of gamma2"
printed = 'x'
kind = "identity"
expect = "proved"
hypotheses = ["branch-gamma2"]
domain = "top"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
Mh = step_gamma2(M, h, A, B, C)
'''
lhs = "vec(MsqP(Mh), EnP(Mh, A, B, C), 0)"
rhs = "vec(MsqP(M), EnP(M, A, B, C), 0)"
{hint}
"#
    )
}

fn hint(q: [&str; 3]) -> String {
    format!(
        r#"hint = {{ value = "Mh", multipliers = ["{}", "{}", "{}"] }}"#,
        q[0], q[1], q[2]
    )
}

const RIGHT: [&str; 3] = ["M + Mh", "Omega(M + Mh, A, B, C)", "vec(0, 0, 0)"];

fn catalogue(extra: &str) -> Result<Catalogue, String> {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/identities"));
    let mut sources = read_sources(dir).expect("catalogue files");
    sources.push(("controls.toml".into(), extra.into()));
    load_sources(&sources, registry().expect("registry")).map_err(|e| e.to_string())
}

fn attempt(cat: &Catalogue, id: &str) -> (bool, String, Vec<String>) {
    let claim = cat.claims.iter().find(|c| c.id == id).expect("claim");
    let Body::Identity { lhs, rhs } = &claim.body else {
        panic!("{id} is not an identity")
    };
    let p = prove(Ctx { cat, claim }, lhs, rhs, false);
    (p.is_proved(), p.reason.clone().unwrap_or_default(), p.notes)
}

#[test]
fn the_papers_multipliers_prove_proposition_4_by_ideal_membership() {
    let cat = catalogue(&control("t.hint.right", &hint(RIGHT))).unwrap();
    let (ok, why, notes) = attempt(&cat, "t.hint.right");
    assert!(ok, "{why}");
    assert!(
        notes.iter().any(|n| n.contains("ideal membership")),
        "the hint route was not taken: {notes:?}"
    );
    for g in ["g0", "g1", "g2"] {
        let (ok, why, notes) = attempt(&cat, &format!("sec6.prop4.{g}"));
        assert!(ok, "sec6.prop4.{g}: {why}");
        assert!(notes.iter().any(|n| n.contains("ideal membership")));
    }
}

#[test]
fn a_wrong_hint_is_rejected_although_the_claim_is_true() {
    let wrong = [
        ("t.hint.sign", ["M - Mh", RIGHT[1], RIGHT[2]]),
        (
            "t.hint.half",
            [RIGHT[0], "Omega(M + Mh, A, B, C) / 2", RIGHT[2]],
        ),
        ("t.hint.swapped", [RIGHT[1], RIGHT[0], RIGHT[2]]),
        ("t.hint.third", [RIGHT[0], RIGHT[1], "M"]),
    ];
    let mut text = control("t.hint.none", "");
    for (id, q) in &wrong {
        text += &control(id, &hint(*q));
    }
    let cat = catalogue(&text).unwrap();
    let (ok, why, _) = attempt(&cat, "t.hint.none");
    assert!(
        ok,
        "without a hint the claim is proved automatically: {why}"
    );
    for (id, _) in &wrong {
        let (ok, why, _) = attempt(&cat, id);
        assert!(!ok, "{id} was proved with a wrong hint");
        assert!(!why.is_empty(), "{id}: no reason");
        let claim = cat.claims.iter().find(|c| c.id == *id).unwrap();
        let r = run_claim(&cat, claim, &Options::default());
        assert_eq!(r.verdict, Verdict::Holds, "{id}: {}", r.reason);
    }
}

#[test]
fn a_hint_with_the_wrong_number_of_multipliers_says_so() {
    let two = r#"hint = { value = "Mh", multipliers = ["M + Mh", "Omega(M + Mh, A, B, C)"] }"#;
    let cat = catalogue(&control("t.hint.two", two)).unwrap();
    let (ok, why, _) = attempt(&cat, "t.hint.two");
    assert!(!ok);
    assert!(why.contains("2 multipliers for 3 components"), "{why}");
}

#[test]
fn malformed_hints_are_load_errors_at_the_hint() {
    let cases = [
        (
            r#"hint = { value = "Q", multipliers = ["M"] }"#,
            "the hint's value 'Q' is not a let of this claim",
        ),
        (
            r#"hint = { value = "Mh", multipliers = ["M + Nope"] }"#,
            "Nope",
        ),
        (
            r#"hint = { value = "Mh", multipliers = [] }"#,
            "at least one multiplier",
        ),
        (
            r#"hint = { value = "Mh", multiplier = ["M"] }"#,
            "multiplier",
        ),
    ];
    for (line, expected) in cases {
        let err = catalogue(&control("t.hint.bad", line)).unwrap_err();
        assert!(err.contains(expected), "{line}: {err}");
        assert!(err.contains("controls.toml:"), "no position: {err}");
    }
    let independence = r#"
[[claim]]
id = "t.hint.kind"
environment = "Proposition 4"
role = "control"
labels = []
location = "control"
printed = 'x'
kind = "independence"
expect = "holds"
domain = "top"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
Mh = step_gamma2(M, h, A, B, C)
'''
expr = "MsqP(Mh)"
wrt = "h"
hint = { value = "Mh", multipliers = ["M"] }
"#;
    let err = catalogue(independence).unwrap_err();
    assert!(err.contains("only read for identity claims"), "{err}");
}
