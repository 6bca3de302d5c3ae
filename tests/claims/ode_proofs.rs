//! Identities between Jacobi functions of two moduli, proved by the uniqueness of the
//! solution of an ODE (proof method `ode`), and the claims the method must not prove:
//! misprinted transformations, a wrong initial value, a singular starting point.
//! The true claims are DLMF 22.7.2 (Gauss's transformation) and 22.17.2–3; each false
//! one differs from a true one by a factor or a sign, so its falsity is a mathematical
//! fact, not a printed number.

use super::support::{attempt, controls_only, identity_claim_with};
use eulertop::claims::verdict::ProofMethod;

const JACOBI: &str = r#"vars = [["k", "uniform(0.05, 0.95)"], ["u", "uniform(-2, 2)"]]"#;

/// `k₁ = (1 − k')/(1 + k')` and `w = z/(1 + k₁)` of DLMF 22.7.1–2.
const LANDEN: &str =
    "let = '''\nk1 = (1 - sqrt(1 - k^2)) / (1 + sqrt(1 - k^2))\nw = u / (1 + k1)\n'''";

/// (id, let fields, lhs, rhs, true?)
const CLAIMS: &[(&str, &str, &str, &str, bool)] = &[
    (
        "gauss",
        LANDEN,
        "sn(u, k)",
        "(1 + k1) * sn(w, k1) / (1 + k1 * sn(w, k1)^2)",
        true,
    ),
    // the factor 1 + k₁ misprinted as 1 + k₁²
    (
        "gauss.misprint",
        LANDEN,
        "sn(u, k)",
        "(1 + k1^2) * sn(w, k1) / (1 + k1 * sn(w, k1)^2)",
        false,
    ),
    ("reciprocal.cn", "", "cn(u, 1/k)", "dn(u/k, k)", true),
    // 22.17.3 with the sides' functions swapped: cn(u, 1/k) = cn(u/k, k) is false
    ("reciprocal.swapped", "", "cn(u, 1/k)", "cn(u/k, k)", false),
    // −k sn(u/k, k) solves the ODE of sn(u, 1/k), with y'(0) = −1 instead of 1
    (
        "reciprocal.sign",
        "",
        "sn(u, 1/k)",
        "-k * sn(u/k, k)",
        false,
    ),
    // 1/(k sn(u, k)) = sn(u + iK', k) solves the ODE of sn(u, k) (DLMF 22.4.3), with a
    // pole at u = 0
    ("pole", "", "sn(u, k)", "1 / (k * sn(u, k))", false),
];

fn catalogue() -> eulertop::claims::catalogue::Catalogue {
    let text: String = CLAIMS
        .iter()
        .map(|(id, fields, lhs, rhs, _)| {
            identity_claim_with(id, "ODE method", &format!("{JACOBI}\n{fields}"), lhs, rhs)
        })
        .collect();
    controls_only(text)
}

#[test]
fn transformations_between_moduli_are_proved_by_the_ode_method() {
    let cat = catalogue();
    for (id, .., true_claim) in CLAIMS {
        let p = attempt(&cat, id);
        if *true_claim {
            assert!(p.is_proved(), "{id}: {:?}", p.reason);
            assert_eq!(p.method, ProofMethod::Ode, "{id}");
            assert!(
                p.notes
                    .iter()
                    .any(|n| n.contains("initial values at u = 0"))
            );
            // the certificate: the jets, the ODE, both sides' derivatives, the initial
            // values and the nonsingularity value
            let cert = p.certificate.as_deref().unwrap_or_default();
            for line in [
                "jet ",
                "ode equation y2 - ",
                "ode side rhs ",
                "ode nonsingular ",
            ] {
                assert!(cert.contains(line), "{id}: no `{line}` line in\n{cert}");
            }
            assert!(p.uncertified.is_empty(), "{id}: {:?}", p.uncertified);
        } else {
            assert!(!p.is_proved(), "{id} was proved: {:?}", p.notes);
        }
    }
}

#[test]
fn the_reasons_name_what_fails() {
    let cat = catalogue();
    let why = |id: &str| attempt(&cat, id).reason.unwrap_or_default();
    assert!(why("gauss.misprint").contains("does not satisfy the ODE"));
    assert!(why("reciprocal.swapped").contains("does not satisfy the ODE"));
    assert!(why("reciprocal.sign").contains("initial values differ: y'(0)"));
    // a point where the sides differ is certified: the ODE method is not tried (its
    // rejection of the singular start is tested in the prover's unit tests)
    assert!(why("pole").contains("differ at domain point"));
}
