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
        "{DEFINITIONS}{}{}{}",
        // |x|² = x² on both sides of x = 0
        claim("t.split.square", "mag(x)^2 * y", "x^2 * y"),
        // |x| = x only for x > 0
        claim("t.split.wrong", "mag(x) * y", "x * y"),
        // abs and sign in the claim's own formulas take the sign of the part
        claim("t.split.stated", "abs(x) * sign(x) * y", "x * y"),
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
fn abs_and_sign_in_the_claims_formulas_take_the_sign_of_each_part() {
    let p = attempt(&catalogue(), "t.split.stated");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert_eq!(p.cases.len(), 2, "{:?}", p.cases);
}
