//! Lemmas and the inverse of sn, cn, dn in proofs: a proved identity that states a step's
//! value supplies it to the claims that use it, a wrong lemma proves nothing, and the
//! phase of `ell_coords` is a symbol whose sn, cn, dn are known.

use super::support::{attempt, with_catalogue};
use eulertop::claims::catalogue::Catalogue;

fn control(id: &str, uses: &str, lhs: &str, rhs: &str) -> String {
    format!(
        r#"
[[claim]]
id = "{id}"
environment = "Proposition 6"
role = "control"
uses = [{uses}]
labels = []
location = "control: lemmas"
printed = 'x'
kind = "identity"
expect = "proved"
hypotheses = ["branch-gamma1", "branch-delta1"]
domain = "ell_up"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
X = ellM(A, B, C, Msq, E, phi, sa, sc)
kk = kE(A, B, C, Msq, E)
'''
lhs = "{lhs}"
rhs = "{rhs}"
"#
    )
}

const SHIFT: &str =
    "sn(ell_coords(step_gamma1(X, h, A, B, C), A, B, C)[3] - ell_coords(X, A, B, C)[3], kk)";

fn controls() -> String {
    let wrong_lemma = r#"
[[claim]]
id = "t.lemma.wrong"
environment = "Proposition 6"
role = "control"
uses = []
labels = []
location = "control: a wrong step value"
printed = 'x'
kind = "identity"
expect = "proved"
hypotheses = ["branch-gamma1", "branch-delta2"]
domain = "ell_up"
vars = [["h", "uniform(0.01, 0.1)"]]
lhs = "step_gamma1(ellM(A, B, C, Msq, E, phi, sa, sc), h, A, B, C)"
rhs = "ellM(A, B, C, Msq, E, phi + 2 * delta2(A, B, C, Msq, E, h), sa, sc)"
"#;
    [
        control(
            "t.lemma.shift",
            r#""sec7.master12.step.up""#,
            &format!("d({SHIFT}, phi)"),
            "0",
        ),
        control(
            "t.lemma.shift-value",
            r#""sec7.master12.step.up""#,
            SHIFT,
            "sn(2 * delta1(A, B, C, Msq, E, h), kk)",
        ),
        control(
            "t.lemma.sum-depends",
            r#""sec7.master12.step.up""#,
            "d(sn(ell_coords(step_gamma1(X, h, A, B, C), A, B, C)[3] + ell_coords(X, A, B, C)[3], kk), phi)",
            "0",
        ),
        control(
            "t.lemma.through-wrong",
            r#""t.lemma.wrong""#,
            &format!("d({SHIFT}, phi)"),
            "0",
        ),
        control("t.inverse.phase", "", "d(ell_coords(X, A, B, C)[3], phi)", "1"),
        control("t.inverse.wrong", "", "d(ell_coords(X, A, B, C)[3], phi)", "2"),
        wrong_lemma.to_string(),
    ]
    .concat()
}

fn catalogue() -> Catalogue {
    with_catalogue(controls())
}

#[test]
fn a_step_value_stands_as_a_lemma_only_when_its_claim_is_proved() {
    let cat = catalogue();
    let lemma = attempt(&cat, "sec7.master12.step.up");
    for id in ["t.lemma.shift", "t.lemma.shift-value"] {
        let p = attempt(&cat, id);
        if lemma.is_proved() {
            assert!(p.is_proved(), "{id}: {:?}", p.reason);
            assert!(
                p.hypotheses
                    .iter()
                    .any(|h| h.kind == "lemma" && h.source == "sec7.master12.step.up"),
                "{id}: {:?}",
                p.hypotheses
            );
        } else {
            assert!(!p.is_proved(), "{id} proved on a lemma that is not");
        }
    }
}

#[test]
fn a_quantity_that_depends_on_phi_is_not_proved_independent() {
    let cat = catalogue();
    assert!(!attempt(&cat, "t.lemma.sum-depends").is_proved());
}

#[test]
fn a_claim_resting_on_a_wrong_lemma_is_not_proved() {
    let cat = catalogue();
    assert!(!attempt(&cat, "t.lemma.wrong").is_proved());
    assert!(!attempt(&cat, "t.lemma.through-wrong").is_proved());
}

#[test]
fn the_phase_of_the_elliptic_coordinates_has_derivative_one() {
    let cat = catalogue();
    let p = attempt(&cat, "t.inverse.phase");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(!attempt(&cat, "t.inverse.wrong").is_proved());
}
