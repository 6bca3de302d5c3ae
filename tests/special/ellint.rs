//! K(k), K'(k) and F(φ, k) against Arb (python-flint) values cross-checked with mpmath
//! (tests/data/ellint_ref.csv).

use crate::common::*;
use eulertop::special::{SpecialError, ellipf, ellipk, ellipkp};
use rug::Float;

fn rel(got: &Float, want: &str, n: u32) -> f64 {
    let w = mp(want, n + 64);
    (Float::with_val(n + 64, got - &w).abs() / w.abs()).to_f64()
}

/// f64 relative error ≤ 2^(4−53); MPFR at N bits ≤ 2^(4−N).
#[test]
fn against_reference() {
    let rows = read_table("ellint_ref.csv");
    assert!(rows.len() >= 70);
    for r in &rows {
        let k: f64 = r[1].parse().unwrap();
        let got = match r[0].as_str() {
            "K" => ellipk(&k),
            "Kp" => ellipkp(&k),
            _ => ellipf(&r[2].parse::<f64>().unwrap(), &k),
        }
        .unwrap();
        let e = rel(&Float::with_val(53, got), &r[4], 53);
        assert!(e <= 2f64.powi(4 - 53), "{} k={k} phi={}: {e:e}", r[0], r[2]);
    }
    for n in PRECS {
        let need = digits_needed(n);
        let mut count = 0;
        for r in rows
            .iter()
            .filter(|r| r[3].parse::<usize>().unwrap() >= need)
        {
            let k = mp(&r[1], n);
            let got = match r[0].as_str() {
                "K" => ellipk(&k),
                "Kp" => ellipkp(&k),
                _ => ellipf(&mp(&r[2], n), &k),
            }
            .unwrap();
            assert_eq!(got.prec(), n);
            let e = rel(&got, &r[4], n);
            assert!(
                e <= 2f64.powi(4 - n as i32),
                "N={n} {} k={}: {e:e}",
                r[0],
                r[1]
            );
            count += 1;
        }
        assert!(count >= 15, "N={n}: {count} rows");
    }
}

#[test]
fn errors() {
    assert!(matches!(ellipkp(&0.0_f64), Err(SpecialError::Pole(_))));
    for k in [1.0, 1.0 + 1e-15, -1e-300, f64::NAN] {
        assert!(matches!(
            ellipk(&k),
            Err(SpecialError::ModulusOutOfRange(_))
        ));
        assert!(ellipkp(&k).is_err());
        assert!(ellipf(&0.5, &k).is_err());
    }
    assert!(matches!(
        ellipf(&f64::INFINITY, &0.5),
        Err(SpecialError::NotFinite(_))
    ));
}

/// F is odd and quasi-periodic: F(φ + π) = F(φ) + 2K (DLMF 19.2.10), at 256 bits.
#[test]
fn quasi_periodicity_256() {
    let k = Float::with_val(256, 0.9);
    let kk = ellipk(&k).unwrap();
    let pi = Float::with_val(256, rug::float::Constant::Pi);
    for phi in [0.1, 1.2, -2.9, 40.0] {
        let p = Float::with_val(256, phi);
        let a = ellipf(&Float::with_val(256, &p + &pi), &k).unwrap();
        let b = ellipf(&p, &k).unwrap() + Float::with_val(256, &kk * 2u32);
        assert!(Float::with_val(256, &a - &b).abs() < 1e-70);
        let m = ellipf(&Float::with_val(256, -&p), &k).unwrap();
        assert!(Float::with_val(256, &m + ellipf(&p, &k).unwrap()).abs() < 1e-70);
    }
}
