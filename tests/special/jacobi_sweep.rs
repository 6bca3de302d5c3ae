//! Dense sweep of the f64 Jacobi functions `sncndn(&u, &k)` (fdlibm kernel, Cody–Waite
//! reduction, nome series after a short Landen chain, imaginary-argument series for `k`
//! near 1) against the 80-bit MPFR evaluation of the same function at the same exact
//! inputs (a different algorithm: full Landen chain with DLMF 22.10.4–6 at the bottom
//! and adaptive multi-precision reduction, itself checked against mpmath in
//! tests/special/jacobi_real.rs; its error, at most 2⁻⁷⁶ absolute, is negligible
//! against the bound 2⁻⁵¹).  Arguments next to multiples of `K` are formed at 128 bits,
//! and the relative accuracy of cn next to its zeros, where an absolute reference error
//! would count up to 2⁴⁹ times, is measured against 128-bit values.
//!
//! * absolute error ≤ 2⁻⁵¹ for each of sn, cn, dn for `|u| ≤ 64·K(k)` (the accuracy
//!   requirement: 4 ulp of 1), on a uniform grid of 20 001 points per modulus and on a
//!   grid concentrated next to the multiples of `K` and the quadrant boundaries
//!   `(j + ½)K`, where the reduction changes branch;
//! * relative accuracy of cn next to its zeros `u = (2j+1)K`: for `u` the double
//!   nearest `(2j+1)K·(1 ± 2⁻³⁰)` (formed in MPFR), `|cn − cn_ref| ≤ 8·2⁻⁵³·|cn_ref|`.

use eulertop::special::{ellipk, sncndn};
use rayon::prelude::*;
use rug::Float;

/// Bits of the reference evaluation for absolute errors: its error bound `2^(4−80)`
/// is `2⁻²⁵` of the tested bound, so the printed maxima are those of any higher precision.
const REF: u32 = 80;

/// Bits at which arguments next to multiples of `K` are formed, and of the reference
/// for relative errors.
const FORM: u32 = 128;

/// The moduli of the sweep: small, moderate, the Landen/series switch points and the
/// imaginary-argument regime (`k ≳ 0.986`) down to `1 − 10⁻¹²`.
const KS: [f64; 16] = [
    1e-4,
    0.1,
    0.3,
    0.5,
    0.7,
    0.8,
    0.85,
    0.9,
    0.95,
    0.98,
    0.99,
    0.995,
    0.999,
    1.0 - 1e-6,
    1.0 - 1e-9,
    1.0 - 1e-12,
];

/// The absolute bound: 4 ulp of 1.
fn bound() -> f64 {
    2f64.powi(-51)
}

/// Absolute errors of f64 `(sn, cn, dn)(u, k)` against the 80-bit evaluation.
fn errors(u: f64, k: f64) -> [f64; 3] {
    let got = sncndn(&u, &k).unwrap_or_else(|e| panic!("f64 sncndn(u = {u:e}, k = {k}): {e}"));
    let (rs, rc, rd) = sncndn(&Float::with_val(REF, u), &Float::with_val(REF, k))
        .unwrap_or_else(|e| panic!("{REF}-bit sncndn(u = {u:e}, k = {k}): {e}"));
    let e = |g: f64, w: &Float| Float::with_val(REF, g - w).abs().to_f64();
    [e(got.0, &rs), e(got.1, &rc), e(got.2, &rd)]
}

/// Worst absolute error over `us` (with its argument and function index) and the
/// points above the bound.
fn sweep(k: f64, us: &[f64]) -> ((f64, f64, usize), Vec<String>) {
    let results: Vec<(f64, [f64; 3])> = us.par_iter().map(|&u| (u, errors(u, k))).collect();
    let mut worst = (0.0, 0.0, 0);
    let mut bad = Vec::new();
    for (u, es) in results {
        for (i, e) in es.into_iter().enumerate() {
            if e > worst.0 {
                worst = (e, u, i);
            }
            if e > bound() {
                bad.push(format!(
                    "k = {k:?} u = {u:?} ({:#x}): {} error {e:e} = {:.2}·2^-52",
                    u.to_bits(),
                    ["sn", "cn", "dn"][i],
                    e * 2f64.powi(52)
                ));
            }
        }
    }
    (worst, bad)
}

fn report(kind: &str, rows: &[(f64, (f64, f64, usize))], bad: &[String]) {
    for (k, (e, u, i)) in rows {
        eprintln!(
            "{kind}: k = {k:<22?} max abs error {:6.3}·2^-52 ({} at u = {u:e})",
            e * 2f64.powi(52),
            ["sn", "cn", "dn"][*i]
        );
    }
    assert!(
        bad.is_empty(),
        "{kind}: {} values above 2^-51, first ones:\n{}",
        bad.len(),
        bad.iter().take(20).cloned().collect::<Vec<_>>().join("\n")
    );
}

/// Uniform grid `u = K·(−64 + 128·i/(n−1))`, `n = 20 001`.
#[test]
fn uniform_grid_abs_error() {
    let n = 20_001usize;
    let mut rows = Vec::new();
    let mut bad = Vec::new();
    for k in KS {
        let kk = ellipk(&k).unwrap();
        let us: Vec<f64> = (0..n)
            .map(|i| kk * (-64.0 + 128.0 * i as f64 / (n - 1) as f64))
            .collect();
        let (w, b) = sweep(k, &us);
        rows.push((k, w));
        bad.extend(b);
    }
    report("uniform grid", &rows, &bad);
}

/// `u` next to `jK` and `(j + ½)K`, `|j| ≤ 64`: the doubles nearest `jK + δ` for
/// `δ/K ∈ {0, ±2⁻⁴⁵, ±2⁻³⁰, ±2⁻¹⁵, ±10⁻³}` (formed at 128 bits), and the two doubles
/// on either side of the one nearest `jK`.
#[test]
fn grid_near_quadrant_boundaries_abs_error() {
    let mut rows = Vec::new();
    let mut bad = Vec::new();
    for k in KS {
        let kk = ellipk(&Float::with_val(FORM, k)).unwrap();
        let mut us = Vec::new();
        for twice_j in -128i32..=128 {
            // u/K = twice_j / 2: multiples of K and the quadrant boundaries (j + ½)K
            let base = Float::with_val(FORM, &kk * twice_j) / 2u32;
            let near = base.to_f64();
            us.extend([near.next_down().next_down(), near.next_down(), near]);
            us.extend([near.next_up(), near.next_up().next_up()]);
            for rel in [2f64.powi(-45), 2f64.powi(-30), 2f64.powi(-15), 1e-3] {
                for sign in [-1.0, 1.0] {
                    let delta = Float::with_val(FORM, &kk * (sign * rel));
                    us.push(Float::with_val(FORM, &base + &delta).to_f64());
                }
            }
        }
        let (w, b) = sweep(k, &us);
        rows.push((k, w));
        bad.extend(b);
    }
    report("quadrant boundaries", &rows, &bad);
}

/// cn next to its zeros: `u` = the double nearest `(2j+1)K·(1 ± 2⁻³⁰)`, `|2j+1| ≤ 63`,
/// where `|cn| ≈ k'·2⁻³⁰·|(2j+1)K|`; relative error ≤ 8·2⁻⁵³.
#[test]
fn cn_relative_accuracy_next_to_zeros() {
    let tol = 8.0 * 2f64.powi(-53);
    let mut bad = Vec::new();
    for k in KS {
        let kk = ellipk(&Float::with_val(FORM, k)).unwrap();
        let mut worst = (0.0f64, 0.0f64);
        for odd in (-63i32..=63).step_by(2) {
            for sign in [-1.0, 1.0] {
                let f =
                    Float::with_val(FORM, 1) + Float::with_val(FORM, Float::u_exp(1, -30)) * sign;
                let u: Float = Float::with_val(FORM, &kk * odd) * f;
                let u = u.to_f64();
                let (_, c, _) = sncndn(&u, &k).unwrap();
                let (_, rc, _) =
                    sncndn(&Float::with_val(FORM, u), &Float::with_val(FORM, k)).unwrap();
                assert!(!rc.is_zero());
                let rel = (Float::with_val(FORM, c - &rc).abs() / rc.clone().abs()).to_f64();
                if rel > worst.0 {
                    worst = (rel, u);
                }
                if rel > tol {
                    bad.push(format!(
                        "k = {k:?} u = {u:?} ({:#x}), (2j+1) = {odd}, sign {sign}: cn = {c:e}, ref {:e}, rel error {:.2}·2^-53",
                        u.to_bits(),
                        Float::with_val(FORM, &rc).to_f64(),
                        rel * 2f64.powi(53)
                    ));
                }
            }
        }
        eprintln!(
            "cn next to zeros: k = {k:<22?} max rel error {:6.3}·2^-53 (u = {:e})",
            worst.0 * 2f64.powi(53),
            worst.1
        );
    }
    assert!(
        bad.is_empty(),
        "cn next to zeros: {} values above 8·2^-53 relative:\n{}",
        bad.len(),
        bad.iter().take(20).cloned().collect::<Vec<_>>().join("\n")
    );
}

/// The whole accepted range `|u|/K < 2⁵⁰`: `u = ±K·2^e·(1 + f)` for `e` from 8 to 49.9
/// and irregular `f ∈ [0, 1)` (600 points per modulus), absolute error ≤ 2⁻⁵¹ as on the
/// short grids; at and beyond `2⁵⁰ K` a clear refusal.
#[test]
fn huge_arguments_abs_error() {
    let mut rows = Vec::new();
    let mut bad = Vec::new();
    for k in [0.1, 0.5, 0.8, 0.9, 0.99, 0.999999, 1.0 - 1e-12] {
        let kk = ellipk(&k).unwrap();
        let us: Vec<f64> = (0..600)
            .map(|i| {
                let e = 8.0 + 41.9 * (i as f64) / 599.0;
                let f = (i as f64 * 0.618_033_988_749_895).fract();
                let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
                sign * kk * 2f64.powf(e) * (1.0 + f) / 2.0
            })
            .collect();
        let (w, b) = sweep(k, &us);
        rows.push((k, w));
        bad.extend(b);
        let beyond = kk * 2f64.powi(50) * 1.001;
        assert!(
            sncndn(&beyond, &k).is_err(),
            "k = {k}: u = {beyond:e} beyond 2^50 K must be refused"
        );
    }
    report("huge arguments", &rows, &bad);
}
