//! Iterations written out in the catalogue: a function applied to its own result three
//! times (Newton's method, say) is not expanded by the prover, with the reason; the
//! same function applied twice is still attempted, and proved where the identity holds.

use super::support::{assert_refused, attempt, controls_only, identity_claim};

const DEFINITIONS: &str = r#"
[[claim]]
id = "t.def"
environment = "Section 2"
role = "definition"
location = "control: iterations"
printed = 'x'
kind = "definition"
define = '''
nwt(x, a) = (x + a / x) / 2
nwt3(x, a) = nwt(nwt(nwt(x, a), a), a)
twice(x, a) = nwt(nwt(x, a), a)
'''
"#;

/// `lhs = a` on `a ∈ (1, 2)`.
fn claim(id: &str, lhs: &str) -> String {
    identity_claim(
        id,
        "control: iterations",
        r#"["a", "uniform(1, 2)"]"#,
        lhs,
        "a",
    )
}

fn catalogue() -> eulertop::claims::catalogue::Catalogue {
    let text = format!(
        "{DEFINITIONS}{}{}",
        claim("t.iter.three", "nwt3(a, a^2)"),
        claim("t.iter.two", "twice(a, a^2)")
    );
    controls_only(text)
}

#[test]
fn a_threefold_self_application_is_not_expanded_and_says_why() {
    assert_refused(&catalogue(), "t.iter.three", &["iteration", "nwt", "nwt3"]);
}

#[test]
fn a_twofold_application_is_attempted_and_proved() {
    // a is the root of x² = a², a fixed point of the step: two steps give a exactly
    let cat = catalogue();
    let p = attempt(&cat, "t.iter.two");
    assert!(p.is_proved(), "{:?}", p.reason);
}
