//! jacobi_inverse: round trips u → (sn, cn, dn) → u on (−2K, 2K], f64 and MPFR.

use eulertop::special::{SpecialError, ellipk, jacobi_inverse, sncndn};
use proptest::prelude::*;
use rug::Float;

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, rng_seed: proptest::test_runner::RngSeed::Fixed(20261121), ..ProptestConfig::default() })]
    /// f64: the recovered u reproduces sn, cn, dn (to a few ulp) and lies in (−2K, 2K].
    #[test]
    fn round_trip_f64(x in -0.999f64..1.0, ki in 0usize..6) {
        let k = [0.0, 1e-10, 0.3, 0.8, 0.99, 1.0 - 1e-6][ki];
        let kk = ellipk(&k).unwrap();
        let u = 2.0 * kk * x;
        let (s, c, d) = sncndn(&u, &k).unwrap();
        let v = jacobi_inverse(&s, &c, &d, &k).unwrap();
        prop_assert!(v > -2.0 * kk && v <= 2.0 * kk * (1.0 + 1e-15));
        let (s2, c2, d2) = sncndn(&v, &k).unwrap();
        prop_assert!((s2 - s).abs() < 1e-14 && (c2 - c).abs() < 1e-14 && (d2 - d).abs() < 1e-14);
        // u itself, to within the conditioning 1/dn
        prop_assert!((v - u).abs() <= 1e-14 * (1.0 + u.abs()) / d, "u={u} v={v}");
    }
}

/// MPFR at 256 and 1024 bits: |u' − u| ≤ 2^(8−N)·(1+|u|)/dn.
#[test]
fn round_trip_mpfr() {
    for n in [256u32, 1024] {
        for kf in [0.3, 0.9, 0.999999] {
            let k = Float::with_val(n, kf);
            let kk = ellipk(&k).unwrap();
            for x in [-0.97, -0.5, -0.1, 0.0, 0.3, 0.5, 0.77, 0.999, 1.0] {
                let u = Float::with_val(n, &kk * 2u32) * x;
                let (s, c, d) = sncndn(&u, &k).unwrap();
                let v = jacobi_inverse(&s, &c, &d, &k).unwrap();
                let tol = Float::with_val(n, Float::u_exp(1, 8 - n as i32))
                    * (u.clone().abs() + 1u32)
                    / &d;
                // u = 2K (rounded) may lie just outside (−2K, 2K]: compare modulo 4K
                let mut diff = Float::with_val(n, &v - &u);
                let four_k = Float::with_val(n, &kk * 4u32);
                if diff > Float::with_val(n, &kk * 2u32) {
                    diff -= &four_k;
                } else if diff < -Float::with_val(n, &kk * 2u32) {
                    diff += &four_k;
                }
                assert!(diff.abs() <= tol, "N={n} k={kf} x={x}");
            }
        }
    }
}

#[test]
fn inconsistent_or_bad_input() {
    let k = 0.6_f64;
    assert!(matches!(
        jacobi_inverse(&0.6, &0.6, &0.9, &k),
        Err(SpecialError::Inconsistent(_))
    ));
    // dn must be positive and satisfy dn² + k² sn² = 1
    assert!(jacobi_inverse(&0.6, &0.8, &-0.93808315, &k).is_err());
    assert!(jacobi_inverse(&0.6, &0.8, &0.5, &k).is_err());
    assert!(matches!(
        jacobi_inverse(&0.6, &0.8, &0.9, &1.0),
        Err(SpecialError::ModulusOutOfRange(_))
    ));
    assert!(matches!(
        jacobi_inverse(&f64::NAN, &0.8, &0.9, &0.5),
        Err(SpecialError::NotFinite(_))
    ));
}
