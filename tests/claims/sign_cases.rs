//! Sign cases proved at once: case variables drawn by `sign()` become sign symbols
//! (σ² = 1), so one normal form covers every case.  An identity that holds for one
//! sign only is never proved, and where the joint route cannot decide (a square root
//! that vanishes in one case), the cases are enumerated.

use super::support::{attempt, with_catalogue};
use eulertop::claims::catalogue::Catalogue;
use eulertop::claims::verdict::ProofInfo;

fn control(id: &str, lhs: &str, rhs: &str) -> String {
    format!(
        r#"
[[claim]]
id = "{id}"
environment = "Section 2"
role = "control"
labels = []
location = "control: sign cases"
printed = 'x'
kind = "identity"
expect = "holds"
domain = "inertia"
vars = [["s", "sign()"], ["t", "sign()"], ["x", "uniform(1, 2)"]]
lhs = "{lhs}"
rhs = "{rhs}"
"#
    )
}

const CONTROLS: [(&str, &str, &str); 6] = [
    ("t.sign.square", "s*s*t*t*x", "x"),
    ("t.sign.both-vanish", "(1 + s)*x*s", "(1 + s)*x"),
    ("t.sign.one-sign-only", "s*x", "x"),
    ("t.sign.product-only", "s*t*x", "x"),
    (
        "t.sign.vanishing-root",
        "sqrt((1 + s)^2*x)",
        "(1 + s)*sqrt(x)",
    ),
    ("t.sign.zero-divisor", "x/(1 + s)*(1 + s)", "x"),
];

fn catalogue() -> Catalogue {
    let text: String = CONTROLS
        .iter()
        .map(|(id, l, r)| control(id, l, r))
        .collect();
    with_catalogue(text)
}

fn joint(p: &ProofInfo) -> bool {
    p.notes.iter().any(|n| n.contains("sign symbols"))
}

#[test]
fn identities_true_for_every_sign_are_proved_once_for_all_cases() {
    let cat = catalogue();
    for id in ["t.sign.square", "t.sign.both-vanish"] {
        let p = attempt(&cat, id);
        assert!(p.is_proved(), "{id}: {:?}", p.reason);
        assert!(joint(&p), "{id}: not proved jointly: {:?}", p.notes);
        assert!(p.cases.is_empty(), "{id}: {:?}", p.cases);
        assert!(
            p.relations.iter().any(|r| r == "s**2 = 1"),
            "{:?}",
            p.relations
        );
    }
}

#[test]
fn identities_true_for_some_signs_only_are_not_proved() {
    let cat = catalogue();
    // x/(1 + s)·(1 + s) = x fails at s = −1, where 1 + s is 0: in the joint ring 1 + s
    // is a zero divisor and has no inverse
    for id in [
        "t.sign.one-sign-only",
        "t.sign.product-only",
        "t.sign.zero-divisor",
    ] {
        let p = attempt(&cat, id);
        assert!(!p.is_proved(), "{id} was proved");
        assert!(
            p.reason.as_deref().unwrap_or("").contains("case"),
            "{id}: the failing case is not named: {:?}",
            p.reason
        );
    }
}

#[test]
fn cases_are_enumerated_where_the_joint_route_cannot_decide() {
    let cat = catalogue();
    let p = attempt(&cat, "t.sign.vanishing-root");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(!joint(&p));
    assert_eq!(p.cases.len(), 4, "{:?}", p.cases);
}
