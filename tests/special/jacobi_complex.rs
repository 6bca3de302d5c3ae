//! sn, cn, dn of a complex argument against the mpmath reference table
//! (tests/data/jacobi_ref_complex.csv), including points next to the poles
//! `2jK + (2l+1)iK'` and the zero of dn at `K + iK'`.

use crate::common::*;
use eulertop::numbers::{C64, Cplx};
use eulertop::special::{SpecialError, sncndn_complex};
use rug::Float;

/// Error of `got` relative to max(1, |want|).
fn rel(got: &Float, want: &str, n: u32) -> f64 {
    let w = mp(want, n + 64);
    let scale = w.clone().abs().max(&Float::with_val(n + 64, 1));
    (Float::with_val(n + 64, got - &w).abs() / scale).to_f64()
}

/// f64: error relative to max(1,|value|) ≤ 2^(4−53), the same rule as at N bits.
#[test]
fn f64_against_reference() {
    let rows = read_table("jacobi_ref_complex.csv");
    assert!(rows.len() > 80);
    for r in &rows {
        let k: f64 = r[0].parse().unwrap();
        let u = C64::new(r[1].parse().unwrap(), r[2].parse().unwrap());
        let (s, c, d) = sncndn_complex(&u, &k).unwrap();
        let got = [s.re, s.im, c.re, c.im, d.re, d.im];
        for (g, w) in got.iter().zip(&r[4..10]) {
            let e = rel(&Float::with_val(53, *g), w, 53);
            assert!(
                e <= 2f64.powi(4 - 53),
                "k={k} u={u:?}: {g:e} vs {w} ({e:e})"
            );
        }
    }
}

/// MPFR at N bits: error relative to max(1,|value|) ≤ 2^(4−N).
#[test]
fn mpfr_against_reference() {
    let rows = read_table("jacobi_ref_complex.csv");
    for n in PRECS {
        let need = digits_needed(n);
        let mut count = 0;
        for r in rows
            .iter()
            .filter(|r| r[3].parse::<usize>().unwrap() >= need)
        {
            let u = Cplx::new(mp(&r[1], n), mp(&r[2], n));
            let (s, c, d) = sncndn_complex(&u, &mp(&r[0], n)).unwrap();
            let got = [s.re, s.im, c.re, c.im, d.re, d.im];
            for (g, w) in got.iter().zip(&r[4..10]) {
                assert_eq!(g.prec(), n);
                let e = rel(g, w, n);
                assert!(
                    e <= 2f64.powi(4 - n as i32),
                    "N={n} k={} u=({}, {}): {e:e}",
                    r[0],
                    r[1],
                    r[2]
                );
            }
            count += 1;
        }
        assert!(count >= 7, "N={n}: only {count} rows");
    }
}

/// rug::Complex (MPC) works through the same generic code.
#[test]
fn mpc_matches_cplx() {
    let u = rug::Complex::with_val(200, (0.3, 1.1));
    let k = Float::with_val(200, 0.8);
    let (s, _, _) = sncndn_complex(&u, &k).unwrap();
    let u2 = Cplx::new(Float::with_val(200, 0.3), Float::with_val(200, 1.1));
    let (s2, _, _) = sncndn_complex(&u2, &k).unwrap();
    let d = Float::with_val(200, s.real() - &s2.re).abs();
    assert!(d < 1e-55);
}

#[test]
fn bad_input_is_an_error() {
    let u = C64::new(0.1, 0.2);
    for k in [-0.5, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            sncndn_complex(&u, &k),
            Err(SpecialError::ModulusOutOfRange(_))
        ));
    }
    assert!(matches!(
        sncndn_complex(&C64::new(f64::NAN, 0.0), &0.5),
        Err(SpecialError::NotFinite(_))
    ));
    // k = 0: sin/cos of a complex argument overflow for huge imaginary parts
    assert!(sncndn_complex(&C64::new(0.0, 800.0), &0.0).is_err());
}

/// Complex `u` for a modulus `k ≥ 1` and for a parameter `m < 0` or `m > 1`, against
/// mpmath (tests/data/jacobi_ref_complex_ext.csv, scripts/gen_jacobi_complex_ext.py):
/// error relative to `max(1, |value|)` per part, in ε_N; returns the worst.
fn complex_ext_worst(bits: u32) -> f64 {
    use eulertop::special::sncndn_complex_m;
    let mut worst = 0f64;
    for r in read_table("jacobi_ref_complex_ext.csv") {
        let got: Vec<Float> = if bits == 53 {
            let (v, u) = (
                r[1].parse::<f64>().unwrap(),
                C64::new(r[2].parse().unwrap(), r[3].parse().unwrap()),
            );
            let t = if r[0] == "k" {
                sncndn_complex(&u, &v)
            } else {
                sncndn_complex_m(&u, &v)
            };
            let (s, c, d) = t.unwrap_or_else(|e| panic!("{r:?}: {e}"));
            [s, c, d]
                .iter()
                .flat_map(|z| [z.re, z.im])
                .map(|x| Float::with_val(53, x))
                .collect()
        } else {
            let v = mp(&r[1], bits);
            let u = Cplx::new(mp(&r[2], bits), mp(&r[3], bits));
            let t = if r[0] == "k" {
                sncndn_complex(&u, &v)
            } else {
                sncndn_complex_m(&u, &v)
            };
            let (s, c, d) = t.unwrap_or_else(|e| panic!("{r:?}: {e}"));
            [s, c, d].into_iter().flat_map(|z| [z.re, z.im]).collect()
        };
        let scale = |i: usize| {
            let re = mp(&r[4 + 2 * (i / 2)], bits + 64);
            let im = mp(&r[5 + 2 * (i / 2)], bits + 64);
            let m = Float::with_val(bits + 64, re.hypot(&im));
            m.max(&Float::with_val(bits + 64, 1))
        };
        for (i, g) in got.iter().enumerate() {
            let want = mp(&r[4 + i], bits + 64);
            let e = Float::with_val(bits + 64, g - &want).abs() / scale(i);
            worst = worst.max(e.to_f64() * 2f64.powi(bits as i32 - 1));
        }
    }
    worst
}

#[test]
fn modulus_above_one_and_negative_parameter() {
    let f64_worst = complex_ext_worst(53);
    assert!(f64_worst <= 6.0, "f64: {f64_worst} ε");
    for bits in [128, 256] {
        let w = complex_ext_worst(bits);
        assert!(w <= 1.0, "{bits} bits: {w} ε");
    }
}

/// sn, cn, dn of a complex modulus against mpmath
/// (tests/data/jacobi_ref_complex_modulus.csv, scripts/gen_jacobi_complex_modulus.py):
/// the worst error relative to `max(1, |value|)` per part, in ε_N.
fn complex_modulus_worst(bits: u32) -> f64 {
    use eulertop::special::sncndn_complex_modulus;
    let mut worst = 0f64;
    for r in read_table("jacobi_ref_complex_modulus.csv") {
        let got: Vec<Float> = if bits == 53 {
            let p = |i: usize| r[i].parse::<f64>().unwrap();
            let t = sncndn_complex_modulus(&C64::new(p(2), p(3)), &C64::new(p(0), p(1)));
            let (s, c, d) = t.unwrap_or_else(|e| panic!("{r:?}: {e}"));
            let parts = [s, c, d].into_iter().flat_map(|z| [z.re, z.im]);
            parts.map(|x| Float::with_val(53, x)).collect()
        } else {
            let p = |i: usize| mp(&r[i], bits);
            let t = sncndn_complex_modulus(&Cplx::new(p(2), p(3)), &Cplx::new(p(0), p(1)));
            let (s, c, d) = t.unwrap_or_else(|e| panic!("{r:?}: {e}"));
            [s, c, d].into_iter().flat_map(|z| [z.re, z.im]).collect()
        };
        for (i, g) in got.iter().enumerate() {
            let j = 4 + 2 * (i / 2);
            let (re, im) = (mp(&r[j], bits + 64), mp(&r[j + 1], bits + 64));
            let scale = Float::with_val(bits + 64, re.hypot(&im)).max(&Float::with_val(64, 1));
            let want = mp(&r[4 + i], bits + 64);
            let e = Float::with_val(bits + 64, g - &want).abs() / scale;
            worst = worst.max(e.to_f64() * 2f64.powi(bits as i32 - 1));
        }
    }
    worst
}

#[test]
fn complex_modulus() {
    use eulertop::special::sncndn_complex_modulus;
    let f64_worst = complex_modulus_worst(53);
    assert!(f64_worst <= 1.0, "f64: {f64_worst} ε");
    for bits in [64, 256, 320] {
        let w = complex_modulus_worst(bits);
        assert!(w <= 1.0, "{bits} bits: {w} ε");
    }
    // a real modulus goes to the real-modulus algorithm
    let u = C64::new(0.3, 0.2);
    let a = sncndn_complex_modulus(&u, &C64::new(0.5, 0.0)).unwrap();
    assert_eq!(a, sncndn_complex(&u, &0.5).unwrap());
    let bad = sncndn_complex_modulus(&u, &C64::new(f64::NAN, 1.0));
    assert!(matches!(bad, Err(SpecialError::ModulusOutOfRange(_))));
}
