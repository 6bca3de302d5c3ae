//! Conditions proved: a claim that states an inequality or an indicator is proved only
//! when every sign it decides is proved with the domain's parametrization by positive
//! parameters (never taken at domain points).

use super::support::{assert_refused, attempt, controls_only, identity_claim};

const VARS: &str = r#"["C", "uniform(0.5, 1.5)"], ["B", "C + uniform(0.2, 1.0)"], ["A", "B + uniform(0.2, 1.0)"], ["x", "uniform(-1, 1)"], ["t", "uniform(0.05, 0.95)"]"#;

fn claim(id: &str, lhs: &str) -> String {
    identity_claim(id, "control: conditions", VARS, lhs, "1")
}

fn catalogue() -> eulertop::claims::catalogue::Catalogue {
    let text = [
        // true on A > B > C > 0: proved
        claim("t.cond.order", "if 1/A < 1/B and 1/B < 1/C then 1 else 0"),
        // a convex combination lies between its ends: proved
        claim(
            "t.cond.between",
            "if 1/A + t*(1/C - 1/A) > 1/A and 1/A + t*(1/C - 1/A) < 1/C then 1 else 0",
        ),
        // a square of a nonzero variable of either sign: proved
        claim("t.cond.square", "if (A - C)*x^2 > 0 then 1 else 0"),
        // x takes both signs: false, never proved
        claim("t.cond.both-signs", "if x > 0 then 1 else 0"),
        // true on the sampled box t ∈ (0.05, 0.95), though not on its relaxation (0, 1):
        // proved with the box
        claim("t.cond.not-on-relaxation", "if t > 1/50 then 1 else 0"),
        // false on part of the box: not proved
        claim("t.cond.part-of-box", "if t > 1/2 then 1 else 0"),
        // the sign of abs's argument proved, and a positive square root's branch proved
        claim(
            "t.cond.abs",
            "if abs(C - A) * sqrt(B - C) > 0 then 1 else 0",
        ),
    ]
    .concat();
    controls_only(text)
}

#[test]
fn true_conditions_are_proved_with_every_sign_proved() {
    let cat = catalogue();
    for id in [
        "t.cond.order",
        "t.cond.between",
        "t.cond.square",
        "t.cond.abs",
    ] {
        let p = attempt(&cat, id);
        assert!(p.is_proved(), "{id}: {:?}", p.reason);
        assert!(!p.proved_signs.is_empty(), "{id}: no proved sign");
        assert!(p.parametrization.is_some(), "{id}: no parametrization");
        assert!(p.hypotheses.is_empty(), "{id}: {:?}", p.hypotheses);
    }
}

#[test]
fn a_condition_whose_sign_varies_is_not_proved() {
    // split by the sign of x: the part x < 0 is where the indicator is 0
    assert_refused(&catalogue(), "t.cond.both-signs", &["case x < 0"]);
}

#[test]
fn a_condition_true_on_the_sampled_box_is_proved_and_one_false_on_part_of_it_is_not() {
    // the relaxed range t ∈ (0, 1) does not prove t > 1/50; the box (0.05, 0.95) does
    let p = attempt(&catalogue(), "t.cond.not-on-relaxation");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(p.cases.is_empty(), "{:?}", p.cases);
    assert_refused(&catalogue(), "t.cond.part-of-box", &["case"]);
}
