//! Branches decided on the domain: the condition of an `if` that selects between two
//! formulas is decided by proof on the domain (never at its points); an equality is
//! decided only where the domain provably excludes it; a
//! variable drawn by `randint` over a few integers is enumerated case by case; and an
//! indicator `if c then 1 else 0` still states a condition that no normal form proves.

use super::support::{assert_refused, attempt, controls_only, identity_claim};
use eulertop::claims::catalogue::Catalogue;

fn control(id: &str, vars: &str, lhs: &str, rhs: &str) -> String {
    identity_claim(id, "control: decided branches", vars, lhs, rhs)
}

const X: &str = r#"["x", "uniform(1, 2)"], ["y", "uniform(3, 4)"]"#;
const AX: &str = r#"["x", "uniform(1, 2)"], ["ax", "randint(1, 3)"]"#;
const AXN: &str = r#"["x", "uniform(1, 2)"], ["ax", "uniform(1, 3)"]"#;

fn controls() -> Vec<(&'static str, &'static str, &'static str, &'static str)> {
    vec![
        // the regime y > x holds on the whole domain: the true branch is proved
        (
            "t.if.regime",
            X,
            "if y > x then (x + y)^2 else x",
            "x^2 + 2*x*y + y^2",
        ),
        // the regime decides the wrong branch: a remainder, never proved
        (
            "t.if.wrong-branch",
            X,
            "if y < x then (x + y)^2 else x",
            "(x + y)^2",
        ),
        // an indicator is a condition, not attempted
        ("t.if.indicator", X, "if y > x then 1 else 0", "1"),
        // the condition y > 7/2 holds on half of the box: not proved
        ("t.if.indicator-varies", X, "if y > 7/2 then 1 else 0", "1"),
        // every one of the three axes is proved, not the last one only
        (
            "t.if.all-axes",
            AX,
            "if ax == 1 then x else if ax == 2 then 2*x else 3*x",
            "ax*x",
        ),
        // true for ax = 3 only: the cases ax = 1, 2 leave a remainder
        (
            "t.if.one-axis",
            AX,
            "if ax == 1 then x else if ax == 2 then 2*x else 3*x",
            "3*x",
        ),
        // abs and sign are decided only by proof: x − 1/2 > 0 on the box x ∈ (1, 2) is
        // proved; x − 3/2 changes sign there, and a sign taken at the points would prove
        // nothing
        ("t.abs.sampled", X, "abs(x - 1/2)", "x - 1/2"),
        ("t.sign.sampled", X, "sign(x - 1/2) * (x - 1/2)", "x - 1/2"),
        ("t.abs.varies", X, "abs(x - 3/2)", "x - 3/2"),
        ("t.sign.varies", X, "sign(x - 3/2) * (x - 3/2)", "x - 3/2"),
        // x > 0 on the relaxation of x ∈ (1, 2): the sign is proved
        ("t.abs.proved", X, "abs(x) * sign(x*y)", "x"),
        (
            "t.abs.exact",
            X,
            "abs((x + y)^2 - x^2 - 2*x*y - y^2) + x",
            "x",
        ),
        // sin and cos are sn and cn of modulus 0
        ("t.sin.double", X, "sin(2*x)", "2*sin(x)*cos(x)"),
        ("t.sin.wrong", X, "sin(2*x)", "2*sin(x)"),
        ("t.cos.derivative", X, "d(cos(x*y), x)", "-y*sin(x*y)"),
        // a continuous ax ∈ (1, 3) is never equal to 1: proved
        (
            "t.if.generic-unequal",
            AXN,
            "if ax == 1 then 2*x else x",
            "x",
        ),
        // ax = 2 lies inside the domain: undecided, not proved
        ("t.if.inside", AXN, "if ax == 2 then 2*x else x", "x"),
    ]
}

fn catalogue() -> Catalogue {
    let text: String = controls()
        .iter()
        .map(|(id, v, l, r)| control(id, v, l, r))
        .collect();
    controls_only(text)
}

#[test]
fn a_regime_the_domain_fixes_is_proved_and_selects_the_branch() {
    let cat = catalogue();
    let p = attempt(&cat, "t.if.regime");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(p.hypotheses.is_empty(), "{:?}", p.hypotheses);
    assert!(!p.proved_signs.is_empty(), "y − x > 0 is proved on the box");
    assert!(!attempt(&cat, "t.if.wrong-branch").is_proved());
}

#[test]
fn an_indicator_if_is_proved_only_where_its_condition_is() {
    // y > x on the box x ∈ (1, 2), y ∈ (3, 4): the condition is proved, and so the claim
    let p = attempt(&catalogue(), "t.if.indicator");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(!p.proved_signs.is_empty());
    assert_refused(&catalogue(), "t.if.indicator-varies", &["case"]);
}

#[test]
fn a_few_integers_are_cases_and_every_case_is_proved() {
    let cat = catalogue();
    let p = attempt(&cat, "t.if.all-axes");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert_eq!(p.cases.len(), 3, "{:?}", p.cases);
    let q = attempt(&cat, "t.if.one-axis");
    assert!(!q.is_proved(), "true for one axis only, yet proved");
}

#[test]
fn an_equality_the_domain_excludes_is_decided_by_proof() {
    let cat = catalogue();
    let p = attempt(&cat, "t.if.generic-unequal");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(p.hypotheses.is_empty(), "{:?}", p.hypotheses);
    assert!(!p.proved_signs.is_empty(), "ax − 1 > 0 on ax ∈ (1, 3)");
    // ax = 2 inside the domain: the equality is undecided, and the claim is not proved
    assert_refused(&cat, "t.if.inside", &["not proved"]);
}

#[test]
fn abs_and_sign_are_decided_only_where_the_sign_is_exact_or_proved() {
    let cat = catalogue();
    for id in ["t.abs.varies", "t.sign.varies"] {
        assert_refused(&cat, id, &["< 0"]);
    }
    // x − 1/2 > 0 on the box x ∈ (1, 2): proved, not taken at the points
    for id in ["t.abs.sampled", "t.sign.sampled"] {
        let p = attempt(&cat, id);
        assert!(p.is_proved(), "{id}: {:?}", p.reason);
        assert!(!p.proved_signs.is_empty(), "{id}");
    }
    let p = attempt(&cat, "t.abs.exact");
    assert!(p.is_proved(), "{:?}", p.reason);
    let p = attempt(&cat, "t.abs.proved");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(p.hypotheses.is_empty(), "{:?}", p.hypotheses);
}

#[test]
fn circular_functions_are_sn_and_cn_of_modulus_zero() {
    let cat = catalogue();
    for id in ["t.sin.double", "t.cos.derivative"] {
        let p = attempt(&cat, id);
        assert!(p.is_proved(), "{id}: {:?}", p.reason);
    }
    assert!(!attempt(&cat, "t.sin.wrong").is_proved());
}
