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
    for k in [1.0, -0.5, f64::NAN] {
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
