//! Asymptotic claims decided by exact power series in the small variable: an order is
//! proved when every coefficient below it is 0, and an order stated too high is refuted
//! with a coefficient certified nonzero at a domain point.

use super::support::{controls_only, with_catalogue};
use eulertop::claims::verdict::{Options, ProofMethod, Verdict, run_claim};

/// An asymptotic control claim `expr = O(h^order)` over `vars`.
fn order_claim(id: &str, vars: &str, expr: &str, order: &str) -> String {
    format!(
        r#"
[[claim]]
id = "{id}"
environment = "Section 2"
role = "statement"
labels = []
location = "control: an order in h"
printed = "O(h^p)"
kind = "asymptotic"
expect = "holds"
vars = [{vars}]
expr = "{expr}"
var = "h"
order = {order}
h0 = 0.05
steps = 6
"#
    )
}

fn verdict(text: String, seed: u64) -> eulertop::claims::verdict::ClaimResult {
    let cat = controls_only(text);
    let mut claim = cat.claims[0].clone();
    claim.seed ^= seed;
    run_claim(&cat, &claim, &Options::default())
}

const SN_VARS: &str = r#"["u", "uniform(-1, 1)"], ["k", "uniform(0.1, 0.9)"]"#;

#[test]
fn a_second_order_remainder_is_proved_and_third_order_refuted() {
    // cn(u + h) − cn u + h sn u dn u = −(h²/2)(cn u)(dn² u − k² sn² u) + O(h³)
    let e = "cn(u + h, k) - cn(u, k) + h * sn(u, k) * dn(u, k)";
    let r = verdict(order_claim("o2", SN_VARS, e, "2"), 0);
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert_eq!(r.proof.method, ProofMethod::Series, "{}", r.reason);
    let r = verdict(order_claim("o3", SN_VARS, e, "3"), 0);
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    assert_eq!(r.proof.method, ProofMethod::Witness, "{}", r.reason);
    assert!(r.reason.contains("coefficient of h^2"), "{}", r.reason);
}

#[test]
fn a_third_order_remainder_is_proved_and_fourth_order_refuted() {
    // sn h − h = −(1 + k²) h³/6 + O(h⁵) (DLMF 22.10.1)
    let e = "sn(h, k) - h";
    let r = verdict(order_claim("o3", SN_VARS, e, "3"), 0);
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    let r = verdict(order_claim("o4", SN_VARS, e, "4"), 0);
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    assert!(r.reason.contains("coefficient of h^3"), "{}", r.reason);
    // with the printed coefficient the remainder is O(h⁵)
    let exact = "sn(h, k) - h + (1 + k^2) * h^3 / 6";
    let r = verdict(order_claim("o5", SN_VARS, exact, "5"), 0);
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
}

#[test]
fn an_implicit_step_is_expanded_as_a_series() {
    // the midpoint rule γ₀ = 1: M̂ = M + h M×Ω(M) + O(h²) with the right-handed
    // orientation of (impl spec) is wrong at first order, the left-handed one right
    let vars = r#"["M", "vec(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1))"], ["A", "uniform(3, 4)"], ["B", "uniform(2, 2.5)"], ["C", "uniform(1, 1.5)"]"#;
    let right = "norm(step_gamma0(M, h, A, B, C) - M - h * cross(OmP(M, A, B, C), M))";
    let wrong = "norm(step_gamma0(M, h, A, B, C) - M - h * cross(M, OmP(M, A, B, C)))";
    let with_branch = |t: String| t.replace("vars = ", "hypotheses = [\"branch-gamma0\"]\nvars = ");
    let cat = with_catalogue(
        with_branch(order_claim("zz.right", vars, right, "2"))
            + &with_branch(order_claim("zz.wrong", vars, wrong, "2")),
    );
    let run = |id: &str| {
        let c = cat.claims.iter().find(|c| c.id == id).expect("claim");
        run_claim(&cat, c, &Options::default())
    };
    let r = run("zz.right");
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    let r = run("zz.wrong");
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    assert_eq!(r.proof.method, ProofMethod::Witness, "{}", r.reason);
}

#[test]
fn a_claim_false_on_a_few_percent_of_its_domain_is_never_proved() {
    // the first-order coefficient x − 0.97 vanishes nowhere but is negative on 3 % of
    // [0, 1]; |·| of it is no O(h²), and no seed may prove it
    let vars = r#"["x", "uniform(0, 1)"]"#;
    for seed in 0..8 {
        for e in [
            "h * max(x - 0.97, 0)",
            "h * abs(x - 0.97)",
            "h * (x - 0.97)",
        ] {
            let r = verdict(order_claim("probe", vars, e, "2"), seed);
            assert_ne!(r.verdict, Verdict::Proved, "seed {seed}, {e}: {}", r.reason);
        }
    }
}

/// A control identity `|a| = a` in `h` resting on the sign hypothesis `when`.
fn sign_claim(id: &str, name: &str, when: &str, a: &str) -> String {
    format!(
        r#"
[hypothesis.{name}]
when = "{when}"
statement = "a control condition"
paper = "none: a control"

[[claim]]
id = "{id}"
environment = "Section 2"
role = "statement"
labels = []
location = "control: a sign hypothesis in h"
printed = "|a| = a"
kind = "identity"
expect = "holds"
hypotheses = ["{name}"]
vars = [["h", "uniform(0.01, 0.1)"], ["k", "uniform(0.1, 0.9)"]]
lhs = "abs({a})"
rhs = "{a}"
"#
    )
}

#[test]
fn a_sign_hypothesis_true_for_small_h_is_discharged_and_one_false_there_is_not() {
    let cat = with_catalogue(
        sign_claim(
            "zz.small",
            "zz-small",
            "cn(h, k) > sn(h, k)",
            "cn(h, k) - sn(h, k)",
        ) + &sign_claim("zz.far", "zz-far", "sn(h, k) > 0.005", "sn(h, k) - 0.005"),
    );
    let run = |id: &str| {
        let c = cat.claims.iter().find(|c| c.id == id).expect("claim");
        run_claim(&cat, c, &Options::default())
    };
    let kinds = |r: &eulertop::claims::verdict::ClaimResult| -> Vec<&str> {
        r.proof.hypotheses.iter().map(|h| h.kind).collect()
    };
    let r = run("zz.small");
    assert_eq!(
        r.verdict,
        Verdict::Proved,
        "{} {:?}",
        r.reason,
        r.proof.reason
    );
    assert_eq!(kinds(&r), ["small h"], "{:?}", r.proof.hypotheses);
    // sn(h) > 0.005 holds on the sampled h but not as h → 0: it stays a stated sign
    let r = run("zz.far");
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert_eq!(kinds(&r), ["sign"], "{:?}", r.proof.hypotheses);
}

#[test]
fn the_papers_sign_hypotheses_hold_for_small_h() {
    let cat = with_catalogue(String::new());
    for id in [
        "sec8.thm2.gammaMV",
        "sec8.GammaMV.up",
        "sec8.master-vm-form.lo",
    ] {
        let c = cat.claims.iter().find(|c| c.id == id).expect("claim");
        let r = run_claim(&cat, c, &Options::default());
        assert_eq!(r.verdict, Verdict::Proved, "{id}: {}", r.reason);
        assert!(
            r.proof.hypotheses.iter().all(|h| h.kind != "sign"),
            "{id}: {:?}",
            r.proof.hypotheses
        );
    }
}

#[test]
fn existence_for_small_h_needs_an_exact_solution_at_h_zero() {
    let cat = with_catalogue(String::new());
    let run = |id: &str| {
        let c = cat.claims.iter().find(|c| c.id == id).expect("claim");
        run_claim(&cat, c, &Options::default())
    };
    // M̂ = M at h = 0, the Jacobian I: the implicit function theorem applies
    let r = run("sec3.impl-map.existence");
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert!(
        r.reason.contains("implicit function theorem"),
        "{}",
        r.reason
    );
    // the set condition |λ·J₁ − 1| < 1/2 with λ·J₁ − 1 = O(h) of either sign: |·| is
    // O(h), below 1/2 for small h
    let r = run("sec8.roots.positive.tri");
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    // 1/|J₁| on a domain where J₁ changes sign: the domain is split by the sign of
    // J₁ = (B + C − A)/2, each part proved (the Jacobian at h = 0 is −q²/(J₁J₂J₃)³ with
    // q = 64ABC(A − B)(A − C)(B − C) of proved sign)
    let r = run("sec8.S.roots");
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert_eq!(r.proof.method, ProofMethod::Series, "{}", r.reason);
    assert_eq!(
        r.proof.cases,
        ["(C + B - A)/(2) > 0", "(C + B - A)/(2) < 0"],
        "{}",
        r.reason
    );
}
