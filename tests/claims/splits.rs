//! Proofs by parts: a sign that a definition decides and that differs between domain
//! points splits the domain, and every part is drawn afresh and proved on its own.

use super::support::{assert_refused, attempt, controls_only, identity_claim};

const DEFINITIONS: &str = r#"
[[claim]]
id = "t.def"
environment = "Section 2"
role = "definition"
location = "control: splits"
printed = 'x'
kind = "definition"
define = '''
mag(x) = if x > 0 then x else -x
'''
"#;

fn claim(id: &str, lhs: &str, rhs: &str) -> String {
    identity_claim(
        id,
        "control: splits",
        r#"["x", "uniform(-1, 1)"], ["y", "uniform(1, 2)"]"#,
        lhs,
        rhs,
    )
}

fn catalogue() -> eulertop::claims::catalogue::Catalogue {
    let text = format!(
        "{DEFINITIONS}{}{}{}{}",
        // |x|² = x² on both sides of x = 0
        claim("t.split.square", "mag(x)^2 * y", "x^2 * y"),
        // |x| = x only for x > 0
        claim("t.split.wrong", "mag(x) * y", "x * y"),
        // abs and sign of an indeterminate: a sign symbol, one part for both signs
        claim("t.split.stated", "abs(x) * sign(x) * y", "x * y"),
        // abs and sign of another value take the sign of the part
        claim(
            "t.split.stated-sum",
            "abs(x + y - 3/2) * sign(x + y - 3/2)",
            "x + y - 3/2",
        ),
    );
    controls_only(text)
}

#[test]
fn a_sign_that_differs_between_points_splits_the_domain_and_both_parts_are_proved() {
    let p = attempt(&catalogue(), "t.split.square");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert_eq!(p.cases, vec!["x > 0".to_string(), "x < 0".to_string()]);
}

#[test]
fn a_part_where_the_identity_fails_is_named() {
    assert_refused(&catalogue(), "t.split.wrong", &["case x < 0"]);
}

#[test]
fn abs_and_sign_of_an_indeterminate_are_a_sign_symbol_and_one_part_proves_both_signs() {
    let p = attempt(&catalogue(), "t.split.stated");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(p.cases.is_empty(), "{:?}", p.cases);
    assert!(
        p.notes.iter().any(|n| n.starts_with("sgnx = sign(x)")),
        "{:?}",
        p.notes
    );
    assert!(
        p.relations.iter().any(|r| r == "sgnx**2 = 1"),
        "{:?}",
        p.relations
    );
}

#[test]
fn abs_and_sign_of_another_value_take_the_sign_of_each_part() {
    let p = attempt(&catalogue(), "t.split.stated-sum");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert_eq!(p.cases.len(), 2, "{:?}", p.cases);
    assert!(p.notes.iter().all(|n| !n.contains("sgn")), "{:?}", p.notes);
}

/// A sign that only a comparison decides (`if x > 0`) is not carried by a sign symbol:
/// the domain is split, as before.
#[test]
fn a_comparison_with_an_indeterminate_still_splits_the_domain() {
    let p = attempt(&catalogue(), "t.split.square");
    assert!(p.notes.iter().all(|n| !n.contains("sgn")), "{:?}", p.notes);
}
