//! Limits in the modulus: Jacobi functions whose modulus tends to 1 or 0 with the small
//! variable are power series known to the order at which the modulus moves, and values
//! such as `√ε·c` are expanded in `t = √ε`.  True limits are proved; a limit stated at
//! an order the expansion does not reach is not; a wrong limit is refuted.

use super::support::controls_only;
use eulertop::claims::verdict::{Options, ProofMethod, Verdict, run_claim};

/// An asymptotic control claim `expr = O(e^order)` over `vars`.
fn limit_claim(vars: &str, expr: &str, order: &str) -> String {
    format!(
        r#"
[[claim]]
id = "zz.limit"
environment = "Section 2"
role = "statement"
labels = []
location = "control: a limit in the modulus"
printed = "O(e^p)"
kind = "asymptotic"
expect = "holds"
vars = [{vars}]
expr = "{expr}"
var = "e"
order = {order}
h0 = 0.01
steps = 6
"#
    )
}

fn verdict(
    vars: &str,
    expr: &str,
    order: &str,
    seed: u64,
) -> eulertop::claims::verdict::ClaimResult {
    let cat = controls_only(limit_claim(vars, expr, order));
    let mut claim = cat.claims[0].clone();
    claim.seed ^= seed;
    run_claim(&cat, &claim, &Options::default())
}

const U: &str = r#"["u", "uniform(-2, 2)"]"#;

#[test]
fn the_hyperbolic_limit_is_proved_and_a_wrong_one_refuted() {
    // sn(u, k) → tanh u as k → 1 (DLMF 22.5.ii), k² = 1 − e
    let right = "abs(sn(u, sqrt(1 - e)) - tanh(u)) + abs(dn(u, sqrt(1 - e)) - 1 / cosh(u))";
    for seed in 0..4 {
        let r = verdict(U, right, "0.9", seed);
        assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
        assert_eq!(r.proof.method, ProofMethod::Series, "{}", r.reason);
    }
    // cn → sech, not tanh
    let wrong = "abs(cn(u, sqrt(1 - e)) - tanh(u))";
    let r = verdict(U, wrong, "0.5", 0);
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    assert!(r.reason.contains("coefficient of e^0"), "{}", r.reason);
}

#[test]
fn an_order_beyond_the_moving_modulus_is_not_proved() {
    // the remainder is (e/4)(sinh u cosh u − u) sech² u + O(e²): O(e) but not O(e^1.5),
    // and the expansion at a moving modulus knows only the coefficient of e^0
    let e = "sn(u, sqrt(1 - e)) - tanh(u)";
    for seed in 0..8 {
        let r = verdict(U, e, "1.5", seed);
        assert_ne!(r.verdict, Verdict::Proved, "{}", r.reason);
    }
}

#[test]
fn a_square_root_of_the_small_variable_is_expanded_in_its_root() {
    // k = √e → 0: dn(u, k) − 1 = O(e), and √e·sn(u, k) = O(e^0.5) but not O(e^0.6)
    let vars = r#"["u", "uniform(-2, 2)"], ["c", "uniform(0.5, 2)"]"#;
    let r = verdict(vars, "abs(sqrt(c * e) * sn(u, sqrt(e)))", "0.5", 0);
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    let r = verdict(vars, "abs(sqrt(c * e) * sn(u, sqrt(e)))", "0.6", 0);
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    assert!(r.reason.contains("e^(1/2)"), "{}", r.reason);
}

#[test]
fn a_quarter_period_at_its_logarithmic_singularity_is_not_expanded() {
    // e·K(√(1 − e)) → 0, but K has no power series at k = 1 (DLMF 19.12.1)
    let r = verdict(U, "abs(e * K(sqrt(1 - e)))", "0.5", 0);
    assert_ne!(r.verdict, Verdict::Proved, "{}", r.reason);
    // at k → 0 it has one: K(√e) → π/2, so K(√e) is not O(e^0.5)
    let r = verdict(U, "abs(K(sqrt(e)) + u - u)", "0.5", 0);
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
}

/// [`limit_claim`] with a `let` block.
fn with_let(
    vars: &str,
    lets: &str,
    expr: &str,
    order: &str,
) -> eulertop::claims::verdict::ClaimResult {
    let text = limit_claim(vars, expr, order)
        .replace("expr = ", &format!("let = '''\n{lets}\n'''\nexpr = "));
    let cat = controls_only(text);
    run_claim(&cat, &cat.claims[0], &Options::default())
}

#[test]
fn the_derivative_in_the_parameter_has_its_limit_at_one() {
    // ∂sn/∂m → −(tanh u − u sech² u)/4 as m → 1 (DLMF 22.10.7), under a square root
    let lets = "m = 1 - e";
    let limit = "(tanh(u) - u / cosh(u)^2) / 4";
    let right = format!("sqrt(abs(d(sn(u, sqrt(m)), m) + {limit}))");
    let r = with_let(U, lets, &right, "0.25");
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    let wrong = format!("sqrt(abs(d(sn(u, sqrt(m)), m) - {limit}))");
    let r = with_let(U, lets, &wrong, "0.25");
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    assert_eq!(r.proof.method, ProofMethod::Witness, "{}", r.reason);
}
