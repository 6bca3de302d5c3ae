//! Certified refutations: a refuted identity carries a domain point at which lhs − rhs
//! is provably nonzero (Arb balls at the point's exact values), and a claim whose
//! residual is too small for the ladder to judge is refuted by such a point.

use super::support::{controls_only, identity_claim_with, with_catalogue};
use eulertop::claims::verdict::{Options, ProofMethod, Verdict, run_claim};

/// The double-angle formula for sn with its right side times `factor`.
fn double_angle(id: &str, factor: &str) -> String {
    identity_claim_with(
        id,
        "control: sn(2u) times a factor",
        r#"vars = [["u", "uniform(-1, 1)"], ["k", "uniform(0.1, 0.9)"]]"#,
        "sn(2*u, k)",
        &format!("2*sn(u, k)*cn(u, k)*dn(u, k) / (1 - k^2*sn(u, k)^4) * ({factor})"),
    )
}

fn run(
    cat: &eulertop::claims::catalogue::Catalogue,
    id: &str,
) -> eulertop::claims::verdict::ClaimResult {
    let claim = cat.claims.iter().find(|c| c.id == id).expect("claim");
    run_claim(cat, claim, &Options::default())
}

#[test]
fn a_wrong_factor_is_refuted_with_a_witness() {
    let cat = controls_only(double_angle("wrong", "1 + k/7"));
    let r = run(&cat, "wrong");
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    assert_eq!(r.proof.method, ProofMethod::Witness, "{}", r.reason);
    let w = r.proof.witness.as_deref().unwrap_or_default();
    assert!(w.contains("exclude 0"), "{w}");
}

#[test]
fn a_perturbation_of_one_part_in_ten_to_the_thirty_is_refuted_with_a_witness() {
    let cat = controls_only(double_angle("tiny", "1 + 10^(-30)"));
    let r = run(&cat, "tiny");
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    assert_eq!(r.proof.method, ProofMethod::Witness, "{}", r.reason);
    assert!(r.reason.starts_with("certified"), "{}", r.reason);
}

#[test]
fn the_true_formula_has_no_witness() {
    let cat = controls_only(double_angle("true", "1"));
    let r = run(&cat, "true");
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert!(r.proof.witness.is_none());
}

#[test]
fn the_papers_misprints_are_refuted_with_witnesses() {
    let cat = with_catalogue(String::new());
    for id in [
        "bg.sn-addition.wrong-sign",
        "sec5.ident2.123.printed",
        "sec5.impl-spec.printed",
        "sec7.lhs-master.g1.printed.up",
    ] {
        let r = run(&cat, id);
        assert_eq!(r.verdict, Verdict::Refuted, "{id}: {}", r.reason);
        assert_eq!(r.proof.method, ProofMethod::Witness, "{id}: {}", r.reason);
    }
}

#[test]
fn the_misprints_outside_the_provers_field_are_refuted_with_witnesses_in_balls() {
    // Section 8's root counts: the roots of the cubic are Newton's method written out,
    // enclosed as certified fixed points; the witness must not depend on the seed
    for seed in [0, 1] {
        let mut cat = with_catalogue(String::new());
        cat.reseed(seed);
        for id in [
            "sec8.decomp.SO3.printed",
            "sec8.S-minus.positive.printed",
            "sec8.omega-as.only.printed",
        ] {
            let claim = cat.claims.iter().find(|c| c.id == id).expect("claim");
            let r = run_claim(&cat, claim, &Options::default());
            assert_eq!(r.verdict, Verdict::Refuted, "{id}: {}", r.reason);
            assert_eq!(r.proof.method, ProofMethod::Witness, "{id}: {}", r.reason);
            let w = r.proof.witness.as_deref().unwrap_or_default();
            assert!(
                w.contains("Arb ball arithmetic") && w.contains("excludes 0"),
                "{w}"
            );
        }
    }
}

#[test]
fn a_true_claim_outside_the_provers_field_has_no_witness_in_balls() {
    // the corrected counts of Section 8 hold: the balls decide them at every point and
    // find no witness
    let cat = with_catalogue(String::new());
    for id in ["sec8.decomp.O3", "sec8.S-minus.positive.tri"] {
        let r = run(&cat, id);
        assert_eq!(r.verdict, Verdict::Holds, "{id}: {}", r.reason);
        assert!(r.proof.witness.is_none(), "{id}");
    }
}

/// A negation of "`expr` does not depend on `v`" over `u`, `v`, `k`.
fn not_independent(id: &str, expr: &str) -> String {
    format!(
        r#"
[[claim]]
id = "{id}"
environment = "Section 2"
role = "statement"
labels = []
location = "control: {expr} depends on v"
printed = 'x'
kind = "negation"
expect = "holds"
vars = [["u", "uniform(-1, 1)"], ["v", "uniform(0.2, 1.5)"], ["k", "uniform(0.1, 0.9)"]]
[claim.inner]
kind = "independence"
expr = "{expr}"
wrt = "v"
"#
    )
}

#[test]
fn a_dependence_through_the_elliptic_functions_is_proved_by_two_points_in_balls() {
    // sn(u + e^v) changes with v: exp is outside the prover's field, and the balls of sn
    // at two sampled v (Jacobi's theta functions in Arb) are disjoint
    let cat = controls_only(not_independent("dep", "sn(u + exp(v), k) * dn(u, k)"));
    let r = run(&cat, "dep");
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert_eq!(r.proof.method, ProofMethod::Witness, "{}", r.reason);
    let w = r.proof.witness.as_deref().unwrap_or_default();
    assert!(
        w.contains("the same point with v =") && w.contains("excludes 0"),
        "{w}"
    );
}

#[test]
fn an_expression_constant_in_the_variable_gets_no_witness() {
    // sn² + cn² = 1 for every v: the negation is refuted, whatever the balls give
    let cat = controls_only(not_independent("const", "sn(u * v, k)^2 + cn(u * v, k)^2"));
    let r = run(&cat, "const");
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    assert!(r.proof.witness.is_none(), "{:?}", r.proof.witness);
}

#[test]
fn every_negation_of_the_paper_is_proved_by_a_witness() {
    // γ₀ is not Poisson (Proposition 5), the constructed map of Proposition 3 is not
    // Poisson (a Jacobian of elliptic coordinates, derivatives in balls), Lemma 1's
    // "others move", the obtuse case of Lemma 2 …: each by a certified point
    let cat = with_catalogue(String::new());
    let negations: Vec<_> = (cat.claims.iter())
        .filter(|c| matches!(c.body, eulertop::claims::catalogue::Body::Negation(_)))
        .map(|c| c.id.clone())
        .collect();
    assert!(negations.len() >= 9, "{negations:?}");
    for id in &negations {
        let r = run(&cat, id);
        assert_eq!(r.verdict, Verdict::Proved, "{id}: {}", r.reason);
    }
}
