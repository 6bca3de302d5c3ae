//! The paper's identities proved through the algebra API (exact normal form 0), and
//! deliberately wrong variants that must never be proved.

use crate::algebra_identities;

use crate::algebra_identities::{
    Regime, Variant, addition, cayley, g0g1, g1_alphabeta, mm, sol_et,
};
use eulertop::algebra::{Proof, RingOptions, prove_components};

fn opts() -> RingOptions {
    opts_in(Regime::Upper)
}

/// Certificates, and the domain of the regime to prove signs with.
fn opts_in(regime: Regime) -> RingOptions {
    RingOptions {
        certificate: true,
        positivity: Some(algebra_identities::domain(regime)),
        ..Default::default()
    }
}

/// Asserts the proof and, when `EULERTOP_CERT_DIR` is set, writes its certificate there
/// (for `scripts/recheck-certificates.py`).
fn assert_proved(p: &Proof, what: &str) {
    assert!(p.is_proved(), "{what}: {:?}", p.outcome);
    let cert = p.certificate.as_ref().expect("a certificate");
    assert!(
        cert.contains("claim t"),
        "{what}: certificate without a claim"
    );
    if let Ok(dir) = std::env::var("EULERTOP_CERT_DIR") {
        let file: String = what
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect();
        std::fs::create_dir_all(&dir).expect("certificate directory");
        std::fs::write(format!("{dir}/{file}.cert"), cert).expect("certificate written");
    }
}

#[test]
fn dlmf_addition_formulae() {
    for f in 0..3 {
        let p = prove_components(opts(), "DLMF 22.8", |r| addition(r, f, Variant::True));
        assert_proved(&p, &format!("addition formula {f}"));
    }
}

#[test]
fn wrong_addition_formulae_are_never_proved() {
    for f in 0..3 {
        for v in [Variant::SignFlipped, Variant::Scaled] {
            let p = prove_components(opts(), "wrong", |r| addition(r, f, v));
            assert!(!p.is_proved(), "{f} {v:?}");
        }
    }
    let p = prove_components(opts(), "k for k²", |r| addition(r, 2, Variant::KForK2));
    assert!(!p.is_proved());
}

#[test]
fn g0g1_in_both_regimes() {
    for regime in [Regime::Upper, Regime::Lower] {
        let p = prove_components(opts_in(regime), "(G0G1)", |r| {
            g0g1(r, regime, Variant::True, false)
        });
        assert_proved(&p, &format!("(G0G1) {regime:?}"));
        // the roots' branches are proved on the regime, never taken at the points
        assert!(p.assumptions.is_empty(), "{:?}", p.assumptions);
        assert!(!p.proved_signs.is_empty());
    }
}

#[test]
fn g0g1_with_named_k_and_nu_needs_their_definitions() {
    let p = prove_components(opts(), "(G0G1) named", |r| {
        g0g1(r, Regime::Upper, Variant::True, true)
    });
    assert_proved(&p, "(G0G1) named");
    assert!(p.expanded_named, "k and ν free cannot prove it");
}

#[test]
fn wrong_g0g1_variants_are_never_proved() {
    for v in [
        Variant::SignFlipped,
        Variant::KForK2,
        Variant::MissingSquare,
        Variant::Scaled,
    ] {
        for regime in [Regime::Upper, Regime::Lower] {
            let p = prove_components(opts_in(regime), "wrong (G0G1)", |r| {
                g0g1(r, regime, v, false)
            });
            assert!(!p.is_proved(), "{v:?} {regime:?}");
        }
    }
}

#[test]
fn g1_alpha_beta_in_both_regimes() {
    for regime in [Regime::Upper, Regime::Lower] {
        let p = prove_components(opts_in(regime), "(MV alphabeta)", |r| {
            g1_alphabeta(r, regime)
        });
        assert_proved(&p, &format!("G1 = k²ν²(1 + α sn² − β sn⁴) {regime:?}"));
    }
}

#[test]
fn mm_differences_and_sums_from_the_addition_formulae() {
    for regime in [Regime::Upper, Regime::Lower] {
        let p = prove_components(opts_in(regime), "(M-M 1-3)", |r| mm(r, regime, false));
        assert_proved(&p, &format!("(M-M) {regime:?}"));
    }
}

#[test]
fn mm_from_phi_and_phi_hat_refines_the_base_arguments() {
    let p = prove_components(opts(), "(M-M 1-3) from phi, phih", |r| {
        mm(r, Regime::Upper, true)
    });
    assert_proved(&p, "(M-M) from φ, φ̂");
    assert!(p.attempts >= 2);
}

#[test]
fn the_solution_solves_the_euler_top() {
    for regime in [Regime::Upper, Regime::Lower] {
        let p = prove_components(opts_in(regime), "(sol) solves (ET)", |r| sol_et(r, regime));
        assert_proved(&p, &format!("(sol) {regime:?}"));
    }
}

#[test]
fn lemma_2_cayley_form() {
    // the positive root needs |v| < 1, which the domain does not fix: it is a
    // hypothesis (as 'h small enough' makes it in Section 8)
    let p = prove_components(opts(), "Lemma 2", cayley);
    assert!(!p.is_proved(), "proved without |v| < 1");
    let p = prove_components(
        opts(),
        "Lemma 2 with |v| < 1",
        algebra_identities::cayley_small_v,
    );
    assert!(p.is_proved(), "{:?}", p.outcome);
    assert!(
        p.assumptions
            .iter()
            .any(|a| a.statement.contains("small-v")),
        "{:?}",
        p.assumptions
    );
}

#[test]
fn the_models_generic_code_runs_on_symbols() {
    use eulertop::model::{EllipticParams, Inertia, Regime as ModelRegime};
    // (G0G1) with k², a², b², c², ν² and the regime from the model's own code
    let p = prove_components(opts(), "(G0G1) from the model", |r| {
        let t = algebra_identities::top(r, Regime::Upper)?;
        let inertia = Inertia::new(t.a_.clone(), t.b_.clone(), t.c_.clone())
            .expect("A > B > C > 0 on the domain");
        let ep = EllipticParams::new(&inertia, &t.m2, &t.e).expect("E/M² in range");
        assert_eq!(ep.regime, ModelRegime::Upper);
        let (k, nu) = (ep.k(), ep.nu());
        let dphi = r.indeterminate_f64("dphi", &[0.3, -0.7, 1.1])?;
        let (s, c, d) = dphi.sncndn(&k)?;
        let (cc, dd) = (&c * &c, &d * &d);
        let k2 = &k * &k;
        let fa = &ep.a2 / &(&t.a_ * &t.a_);
        let fb = &ep.b2 / &(&t.b_ * &t.b_);
        let fc = &ep.c2 / &(&t.c_ * &t.c_);
        let g0 = &(&fa * &cc) + &(&fc * &dd);
        let g1 = &(&(&fa * &cc) + &(&(&fc * &k2) * &dd)) - &(&(&fb * &cc) * &dd);
        let lhs = &g1 - &(&(&k2 * &(&s * &s)) * &g0);
        Ok(vec![(lhs, &(&(&k2 * &(&nu * &nu)) * &cc) * &dd)])
    });
    assert_proved(&p, "(G0G1) from the model");
    // the regime and the inertia order are proved on the domain, not assumed
    assert!(p.assumptions.is_empty(), "{:?}", p.assumptions);
    assert!(
        p.proved_signs.iter().any(|s| s.contains("B*E")),
        "{:?}",
        p.proved_signs
    );
}
