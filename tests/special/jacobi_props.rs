//! Identities of the Jacobi functions as properties (proptest), in f64 and at 256 bits:
//! Pythagorean relations (DLMF 22.6.1), addition theorems (DLMF 22.8.1–3), periods
//! (DLMF 22.4.3), derivatives via automatic differentiation (DLMF 22.13.1–3), amplitude.

use eulertop::numbers::{C64, Cplx, Dual, Real};
use eulertop::special::{am, ellipf, ellipk, ellipkp, sncndn, sncndn_complex};
use proptest::prelude::*;
use rug::Float;

const KS: [f64; 8] = [0.0, 1e-10, 0.3, 0.5, 0.9, 0.99, 1.0 - 1e-6, 1.0 - 1e-12];

fn f256(x: f64) -> Float {
    Float::with_val(256, x)
}

fn close256(a: &Float, b: &Float, scale: f64) -> bool {
    Float::with_val(256, a - b).abs() <= Float::with_val(256, Float::u_exp(1, -240)) * scale
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 300, rng_seed: proptest::test_runner::RngSeed::Fixed(20261121), ..ProptestConfig::default() })]

    #[test]
    fn pythagoras_f64(u in -1e3f64..1e3, ki in 0usize..8) {
        let k = KS[ki];
        let (s, c, d) = sncndn(&u, &k).unwrap();
        // from |error| ≤ 2^-51 per value: 2(|s|+|c|)·2^-51 + rounding ≤ 2e-15
        prop_assert!((s * s + c * c - 1.0).abs() <= 2e-15);
        prop_assert!((d * d + k * k * s * s - 1.0).abs() <= 2e-15);
        prop_assert!(d > 0.0);
    }

    #[test]
    fn pythagoras_256(u in -1e3f64..1e3, ki in 0usize..8) {
        let k = f256(KS[ki]);
        let (s, c, d) = sncndn(&f256(u), &k).unwrap();
        let one = f256(1.0);
        prop_assert!(close256(&(s.clone() * &s + c.clone() * &c), &one, 4.0));
        prop_assert!(close256(&(d.clone() * &d + k.clone() * &k * &s * &s), &one, 4.0));
    }

    /// DLMF 22.8.1–3 with u, v of 20 bits so that u + v is exact.
    #[test]
    fn addition_theorems_f64(a in -2_000_000i32..2_000_000, b in -2_000_000i32..2_000_000, ki in 0usize..5) {
        let k = KS[ki];
        let (u, v) = (a as f64 / 262144.0, b as f64 / 262144.0);
        let (s1, c1, d1) = sncndn(&u, &k).unwrap();
        let (s2, c2, d2) = sncndn(&v, &k).unwrap();
        let (s, c, d) = sncndn(&(u + v), &k).unwrap();
        let den = 1.0 - k * k * s1 * s1 * s2 * s2;
        let tol = 1e-14 / den;
        prop_assert!((s - (s1 * c2 * d2 + s2 * c1 * d1) / den).abs() <= tol);
        prop_assert!((c - (c1 * c2 - s1 * d1 * s2 * d2) / den).abs() <= tol);
        prop_assert!((d - (d1 * d2 - k * k * s1 * c1 * s2 * c2) / den).abs() <= tol);
    }

    #[test]
    fn addition_theorems_256(a in -2_000_000i32..2_000_000, b in -2_000_000i32..2_000_000, ki in 0usize..8) {
        let k = f256(KS[ki]);
        let (u, v) = (f256(a as f64 / 262144.0), f256(b as f64 / 262144.0));
        let (s1, c1, d1) = sncndn(&u, &k).unwrap();
        let (s2, c2, d2) = sncndn(&v, &k).unwrap();
        let (s, c, d) = sncndn(&Float::with_val(256, &u + &v), &k).unwrap();
        let k2 = Float::with_val(256, &k * &k);
        let den = f256(1.0) - k2.clone() * &s1 * &s1 * &s2 * &s2;
        let scale = 16.0 / den.to_f64();
        prop_assert!(close256(&s, &((s1.clone() * &c2 * &d2 + s2.clone() * &c1 * &d1) / &den), scale));
        prop_assert!(close256(&c, &((c1.clone() * &c2 - s1.clone() * &d1 * &s2 * &d2) / &den), scale));
        prop_assert!(close256(&d, &((d1.clone() * &d2 - k2 * &s1 * &c1 * &s2 * &c2) / &den), scale));
    }

    /// Real period 4K (sn, cn) and 2K (dn), at 256 bits.
    #[test]
    fn real_periods_256(u in -50f64..50.0, ki in 0usize..8) {
        let k = f256(KS[ki]);
        let kk = ellipk(&k).unwrap();
        let u = f256(u);
        let (s, c, d) = sncndn(&u, &k).unwrap();
        let (s4, c4, _) = sncndn(&(u.clone() + Float::with_val(256, &kk * 4u32)), &k).unwrap();
        let (s2, c2, d2) = sncndn(&(u.clone() + Float::with_val(256, &kk * 2u32)), &k).unwrap();
        let sc = 4.0 * (1.0 + u.to_f64().abs() + 4.0 * kk.to_f64());
        prop_assert!(close256(&s4, &s, sc) && close256(&c4, &c, sc));
        prop_assert!(close256(&s2, &(-s), sc) && close256(&c2, &(-c), sc) && close256(&d2, &d, sc));
    }

    /// Imaginary period: sn(u + 2iK') = sn u, cn(u + 2iK') = −cn u, dn(u + 2iK') = −dn u.
    #[test]
    fn imaginary_period_f64(x in -5f64..5.0, y in -0.7f64..0.7, ki in 2usize..7) {
        let k = KS[ki];
        let kp = ellipkp(&k).unwrap();
        let u = C64::new(x, y * kp);
        let w = C64::new(x, y * kp + 2.0 * kp);
        let (s, c, d) = sncndn_complex(&u, &k).unwrap();
        let (s2, c2, d2) = sncndn_complex(&w, &k).unwrap();
        for (a, b) in [(s, s2), (c, -c2), (d, -d2)] {
            let scale = 1.0f64.max(a.re.hypot(a.im));
            prop_assert!((a.re - b.re).abs() <= 1e-10 * scale && (a.im - b.im).abs() <= 1e-10 * scale);
        }
    }

    #[test]
    fn imaginary_period_256(x in -5f64..5.0, y in -0.7f64..0.7, ki in 1usize..8) {
        let k = f256(KS[ki]);
        let kp = ellipkp(&k).unwrap();
        let yy = Float::with_val(256, &kp * y);
        let u = Cplx::new(f256(x), yy.clone());
        let w = Cplx::new(f256(x), yy.clone() + Float::with_val(256, &kp * 2u32));
        let (s, c, d) = sncndn_complex(&u, &k).unwrap();
        let (s2, c2, d2) = sncndn_complex(&w, &k).unwrap();
        for (a, b) in [(s, s2), (c, -c2), (d, -d2)] {
            let scale = 16.0 * 1.0f64.max(a.re.to_f64().hypot(a.im.to_f64())) * (1.0 + kp.to_f64());
            prop_assert!(close256(&a.re, &b.re, scale) && close256(&a.im, &b.im, scale));
        }
    }

    /// d/du (sn, cn, dn) = (cn dn, −sn dn, −k² sn cn) (DLMF 22.13.1–3) through the
    /// algorithm, by forward-mode AD.
    #[test]
    fn derivative_in_u_f64(u in -300f64..300.0, ki in 0usize..8) {
        let k = KS[ki];
        let (s, c, d) = sncndn(&Dual::var(u), &Dual::constant(k)).unwrap();
        prop_assert!((s.d - c.v * d.v).abs() <= 1e-14);
        prop_assert!((c.d + s.v * d.v).abs() <= 1e-14);
        prop_assert!((d.d + k * k * s.v * c.v).abs() <= 1e-14);
    }

    #[test]
    fn derivative_in_u_256(u in -300f64..300.0, ki in 0usize..8) {
        let k = Dual::constant(f256(KS[ki]));
        let (s, c, d) = sncndn(&Dual::var(f256(u)), &k).unwrap();
        prop_assert!(close256(&s.d, &(c.v.clone() * &d.v), 64.0));
        prop_assert!(close256(&c.d, &(-(s.v.clone() * &d.v)), 64.0));
        prop_assert!(close256(&d.d, &(-(k.v.clone() * &k.v * &s.v * &c.v)), 64.0));
    }

    /// d/dk through the algorithm (incl. the quarter period in the reduction) against a
    /// central difference at 256 bits (h = 2^-70, truncation error ~2^-140).
    #[test]
    fn derivative_in_k(u in -40f64..40.0, ki in 2usize..6) {
        let kf = KS[ki];
        let (s, _, _) = sncndn(&Dual::constant(u), &Dual::var(kf)).unwrap();
        let h = Float::with_val(256, Float::u_exp(1, -70));
        let (sp, _, _) = sncndn(&f256(u), &(f256(kf) + &h)).unwrap();
        let (sm, _, _) = sncndn(&f256(u), &(f256(kf) - &h)).unwrap();
        let fd = ((sp - sm) / (h * 2u32)).to_f64();
        prop_assert!((s.d - fd).abs() <= 1e-12 * (1.0 + fd.abs()) * (1.0 + u.abs()), "{} vs {}", s.d, fd);
    }

    /// am: sin am = sn, cos am = cn, F(am(u)) = u, am(u + 2K) = am(u) + π.
    #[test]
    fn amplitude(u in -100f64..100.0, ki in 0usize..6) {
        let k = KS[ki];
        let a = am(&u, &k).unwrap();
        let (s, c, _) = sncndn(&u, &k).unwrap();
        prop_assert!((a.sin() - s).abs() <= 1e-13 && (a.cos() - c).abs() <= 1e-13);
        let back = ellipf(&a, &k).unwrap();
        prop_assert!((back - u).abs() <= 1e-13 * (1.0 + u.abs()));
        let kk = ellipk(&k).unwrap();
        let a2 = am(&(u + 2.0 * kk), &k).unwrap();
        prop_assert!((a2 - a - std::f64::consts::PI).abs() <= 1e-13 * (1.0 + a.abs()));
    }
}

/// Dual numbers over MPFR keep their precision through `with_prec`.
#[test]
fn dual_mpfr_precision() {
    let (s, _, _) = sncndn(&Dual::var(f256(0.3)), &Dual::constant(f256(0.5))).unwrap();
    assert_eq!(s.v.prec(), 256);
    assert_eq!(s.d.prec(), 256);
    assert_eq!(Real::prec(&s), 256);
}

/// Complex argument through AD: ∂/∂x sn(x + iy) = cn·dn (complex), with
/// `Cplx<Dual<f64>>` (derivative seeded on the real part).
#[test]
fn complex_derivative_via_dual() {
    for (x, y, k) in [(0.3, 0.4, 0.5), (-1.2, 0.9, 0.9), (2.0, -0.3, 0.99)] {
        let u = Cplx::new(Dual::var(x), Dual::constant(y));
        let (s, c, d) = sncndn_complex(&u, &Dual::constant(k)).unwrap();
        let cv = C64::new(c.re.v, c.im.v);
        let dv = C64::new(d.re.v, d.im.v);
        let want = cv * dv;
        assert!((s.re.d - want.re).abs() < 1e-13 && (s.im.d - want.im).abs() < 1e-13);
    }
}
