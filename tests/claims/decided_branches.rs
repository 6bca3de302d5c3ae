//! Branches decided on the domain: the condition of an `if` that selects between two
//! formulas is decided at the domain points and recorded as an assumption; an equality
//! with a nonzero normal form is decided only where it is nonzero at every point; a
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
        // abs and sign are decided only exactly: abs(x) = x on x > 0 is a condition
        // x − 1/2 > 0 at every point of x ∈ (1, 2), but not for every x > 0: the sign is
        // not proved, and a sign taken at the points would prove nothing
        ("t.abs.sampled", X, "abs(x - 1/2)", "x - 1/2"),
        ("t.sign.sampled", X, "sign(x - 1/2) * (x - 1/2)", "x - 1/2"),
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
        // a continuous ax is never equal to 1: decided, with an assumption
        (
            "t.if.generic-unequal",
            AXN,
            "if ax == 1 then 2*x else x",
            "x",
        ),
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
fn a_regime_decided_on_the_domain_selects_the_branch_and_is_an_assumption() {
    let cat = catalogue();
    let p = attempt(&cat, "t.if.regime");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(
        p.assumptions
            .iter()
            .any(|a| a.contains("> 0") || a.contains("< 0")),
        "{:?}",
        p.assumptions
    );
    assert!(!attempt(&cat, "t.if.wrong-branch").is_proved());
}

#[test]
fn an_indicator_if_states_a_condition_and_is_not_attempted() {
    assert_refused(&catalogue(), "t.if.indicator", &["states a condition"]);
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
fn an_equality_with_a_nonzero_normal_form_is_decided_on_the_domain() {
    let cat = catalogue();
    let p = attempt(&cat, "t.if.generic-unequal");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(
        p.assumptions.iter().any(|a| a.contains('≠')),
        "{:?}",
        p.assumptions
    );
}

#[test]
fn abs_and_sign_are_decided_only_where_the_sign_is_exact_or_proved() {
    let cat = catalogue();
    for id in ["t.abs.sampled", "t.sign.sampled"] {
        assert_refused(&cat, id, &["neither exact nor proved"]);
    }
    let p = attempt(&cat, "t.abs.exact");
    assert!(p.is_proved(), "{:?}", p.reason);
    let p = attempt(&cat, "t.abs.proved");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(p.assumptions.is_empty(), "{:?}", p.assumptions);
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
