//! sn, cn, dn at thirds of the quarter period (module `algebra::thirds`), a negative
//! modulus, the shift by iK' (the quarter period of the complementary modulus) and the
//! derivative rules of `ln` and `am`: true identities proved, and variants that differ
//! from them by a sign, a factor or a function refused by the prover and refuted.  The
//! true claims are DLMF 22.9.13 (κ = dn(2K/3), DLMF 22.9.7), DLMF 22.4.3 at z = K/3 and
//! at z + iK', 22.17.1, 22.14.1 (as a derivative) and 22.16.3; each false one differs
//! from a true one by a sign, a factor or a function, so its falsity is a mathematical
//! fact, not a printed number.

use super::support::{attempt, controls_only, identity_claim_with};
use eulertop::claims::verdict::{Options, ProofMethod, Verdict, run_claim};

const JACOBI: &str = r#"vars = [["k", "uniform(0.05, 0.95)"], ["u", "uniform(-2, 2)"]]"#;

/// The three points of DLMF 22.9.4 with p = 3 and κ of DLMF 22.9.7.
const CYCLIC: &str = "let = '''\nkappa = dn(2*K(k)/3, k)\ns1 = sn(u, k)\ns2 = sn(u + 4*K(k)/3, k)\ns3 = sn(u + 8*K(k)/3, k)\n'''";

/// (id, let fields, lhs, rhs, true?)
const CLAIMS: &[(&str, &str, &str, &str, bool)] = &[
    (
        "cyclic",
        CYCLIC,
        "s1 * s2 * s3",
        "-(s1 + s2 + s3) / (1 - kappa^2)",
        true,
    ),
    // the minus sign of 22.9.13 lost
    (
        "cyclic.sign",
        CYCLIC,
        "s1 * s2 * s3",
        "(s1 + s2 + s3) / (1 - kappa^2)",
        false,
    ),
    // sn(K − z) = cd z at z = K/3
    ("third", "", "sn(2*K(k)/3, k)", "cd(K(k)/3, k)", true),
    ("third.cn", "", "sn(2*K(k)/3, k)", "cn(K(k)/3, k)", false),
    ("negative", "", "cd(u, -k)", "cd(u, k)", true),
    ("negative.sign", "", "cd(u, -k)", "-cd(u, k)", false),
    (
        "ln",
        "",
        "d(ln(dn(u, k) - k*cn(u, k))/k, u)",
        "sn(u, k)",
        true,
    ),
    (
        "ln.cn",
        "",
        "d(ln(dn(u, k) - k*cn(u, k))/k, u)",
        "cn(u, k)",
        false,
    ),
    // DLMF 22.4.3: sn(z + iK') = ns z / k, through K(k') = K'(k)
    ("ikp", "", "sn(u + i*Kp(k), k)", "1/(k*sn(u, k))", true),
    ("ikp.k", "", "sn(u + i*Kp(k), k)", "1/sn(u, k)", false),
    ("am", "", "d(am(u, k), u)", "dn(u, k)", true),
    ("am.cn", "", "d(am(u, k), u)", "cn(u, k)", false),
];

fn catalogue() -> eulertop::claims::catalogue::Catalogue {
    let text: String = CLAIMS
        .iter()
        .map(|(id, fields, lhs, rhs, _)| {
            identity_claim_with(
                id,
                "rational shifts",
                &format!("{JACOBI}\n{fields}"),
                lhs,
                rhs,
            )
        })
        .collect();
    controls_only(text)
}

#[test]
fn thirds_of_k_negative_moduli_ikp_ln_and_am_are_proved_and_their_variants_refuted() {
    let cat = catalogue();
    for (i, (id, .., true_claim)) in CLAIMS.iter().enumerate() {
        let p = attempt(&cat, id);
        if *true_claim {
            assert!(p.is_proved(), "{id}: {:?}", p.reason);
            assert_eq!(p.method, ProofMethod::Symbolic, "{id}");
        } else {
            assert!(!p.is_proved(), "{id} was proved: {:?}", p.notes);
            let r = run_claim(&cat, &cat.claims[i], &Options::default());
            assert_eq!(r.verdict, Verdict::Refuted, "{id}: {}", r.reason);
        }
    }
}

#[test]
fn a_proof_with_a_third_of_k_names_the_triplication_polynomial() {
    let cat = catalogue();
    let p = attempt(&cat, "cyclic");
    assert!(
        p.notes
            .iter()
            .any(|n| n.contains("k^2 s^4 - 2 k^2 s^3 + 2 s - 1")),
        "{:?}",
        p.notes
    );
    assert!(
        p.notes
            .iter()
            .any(|n| n.contains("modulo the defining polynomials")),
        "{:?}",
        p.notes
    );
}
