//! Derivatives through the f64 Jacobi path (nome series, Landen climb, Cody–Waite
//! reduction with the triple-double quarter period, imaginary-argument series for `k`
//! near 1) by forward-mode automatic differentiation with `Dual<f64>`:
//!
//! * `∂/∂k` of sn, cn, dn (seed on `k`, `u` constant) against a central difference of
//!   the 256-bit MPFR `sncndn` (an independent algorithm) at a few hundred `(u, k)`;
//! * `∂/∂u` (seed on `u`) against the identities `sn' = cn·dn`, `cn' = −sn·dn`,
//!   `dn' = −k²·sn·cn` (DLMF 22.13.1–3) evaluated from the 256-bit values.
//!
//! The points: `k` spread over `(0, 1)` including 0.8, 0.95, 0.99, 0.999, `1 − 10⁻⁶`,
//! and `u/K` on an irregular grid in `[−20, 20]` plus points next to multiples of `K`.

use eulertop::numbers::Dual;
use eulertop::special::{ellipk, sncndn};
use rug::Float;

const REF: u32 = 256;

const KS: [f64; 14] = [
    1e-5,
    1e-4,
    2e-4,
    1e-3,
    0.1,
    0.3,
    0.5,
    0.7,
    0.8,
    0.9,
    0.95,
    0.99,
    0.999,
    1.0 - 1e-6,
];

/// `u/K` values: an irregular grid in `[−20, 20]` (step 40/29 shifted by an irrational
/// fraction) and points next to `±K`, `±2K`, `±7K`, `±20K` and `0`.
fn u_over_k() -> Vec<f64> {
    let mut v: Vec<f64> = (0..30)
        .map(|i| -20.0 + 40.0 * (i as f64 + 0.381_966) / 30.0)
        .collect();
    for m in [1.0, 2.0, 7.0, 20.0] {
        for s in [-1.0, 1.0] {
            v.push(s * m * (1.0 + 1e-9));
            v.push(s * (m - 1e-6));
        }
    }
    v.push(1e-7);
    v.push(0.5);
    v
}

fn f256(x: f64) -> Float {
    Float::with_val(REF, x)
}

/// `(sn, cn, dn)(u, k)` at 256 bits.
fn mp(u: f64, k: &Float) -> [Float; 3] {
    let (s, c, d) = sncndn(&f256(u), k).unwrap();
    [s, c, d]
}

/// ∂/∂k of sn, cn, dn.
///
/// Reference: `(f(k+h) − f(k−h))/(2h)` at 256 bits with `h = 2⁻⁶⁰·min(k, 1−k)` (so
/// `k ± h` stays in `(0, 1)` and is exact at 256 bits).  Its truncation error
/// `h²/6·|∂³f/∂k³|` is, even for `k' ≈ 1.4·10⁻³` (`k = 1 − 10⁻⁶`) where each
/// `k`-derivative gains a factor of order `|u|/k'²`, below `10⁻²⁰` relative, and its
/// rounding error `2⁻²⁵⁶/h` is far smaller: the reference is exact to f64 accuracy.
///
/// Tolerance.  The derivative is large where the function is ill-conditioned in `k`:
/// `u = jK + t` with `dt/dk = −j·dK/dk`, and `dK/dk = (E − k'²K)/(k·k'²)` grows like
/// `1/k'²` as `k → 1`, so `∂f/∂k` contains terms of size `|u/K|·|dK/dk|` (about
/// `10⁷` for `u = 20K`, `k = 1 − 10⁻⁶`) which can cancel against the others.  In f64
/// the derivative parts are carried with relative error a few ε of these terms, so the
/// error is measured relative to `S = max(1, |∂f/∂k|, |u/K|·|dK/dk|)`.  The bound
/// `10⁻⁹·S` allows for ~10⁶ ε of error amplification (the derivatives of the series
/// coefficients pass through the nome `q(k)` and `AGM(1, k')`, whose own `k`-derivatives
/// carry `1/k'²` factors; for small `k` the coefficient derivatives are differences
/// of terms of size `1/k`, so there the error grows like `ε·|u|/k`), while any missing
/// or wrong term (e.g. dropping `j·dK/dk`
/// in the reduction) gives an O(1) relative error.
#[test]
fn derivative_in_k_against_central_difference() {
    let mut worst = (0.0f64, 0.0f64, 0.0f64, 0usize);
    let mut count = 0;
    let mut bad = Vec::new();
    for k in KS {
        let kk = ellipk(&k).unwrap();
        let h = f256(2f64.powi(-60) * k.min(1.0 - k));
        let (kp, km) = (f256(k) + &h, f256(k) - &h);
        // dK/dk at 256 bits, the same central difference
        let dkk = ((ellipk(&kp).unwrap() - ellipk(&km).unwrap()) / (h.clone() * 2u32)).to_f64();
        let mut worst_k = 0f64;
        for r in u_over_k() {
            let u = r * kk;
            let (s, c, d) = sncndn(&Dual::constant(u), &Dual::var(k)).unwrap();
            let (fp, fm) = (mp(u, &kp), mp(u, &km));
            let scale_u = (u / kk).abs() * dkk.abs();
            for (i, got) in [s.d, c.d, d.d].into_iter().enumerate() {
                let fd = (Float::with_val(REF, &fp[i] - &fm[i]) / (h.clone() * 2u32)).to_f64();
                let scale = 1f64.max(fd.abs()).max(scale_u);
                let err = (got - fd).abs() / scale;
                count += 1;
                worst_k = worst_k.max(err);
                if err > worst.0 {
                    worst = (err, k, u, i);
                }
                if err > 1e-9 {
                    bad.push(format!(
                        "k = {k:?} u = {u:?}: d{}/dk = {got:e}, reference {fd:e}, error {err:e} of scale {scale:e}",
                        ["sn", "cn", "dn"][i]
                    ));
                }
            }
        }
        eprintln!(
            "d/dk: k = {k:<12?} max error {worst_k:.3e} of the scale ({:.0} eps)",
            worst_k / f64::EPSILON
        );
    }
    eprintln!(
        "d/dk: {count} derivatives, max error {:e} of the scale (= {:.1} eps) at k = {:?}, u = {:e} (d{}/dk)",
        worst.0,
        worst.0 / f64::EPSILON,
        worst.1,
        worst.2,
        ["sn", "cn", "dn"][worst.3]
    );
    assert!(count >= 300);
    assert!(
        bad.is_empty(),
        "{} derivatives outside the tolerance:\n{}",
        bad.len(),
        bad.iter().take(20).cloned().collect::<Vec<_>>().join("\n")
    );
}

/// ∂/∂u of sn, cn, dn (seed on `u`) against cn·dn, −sn·dn, −k²·sn·cn from the 256-bit
/// values.  The derivatives are at most 1 in size and `dt/du = 1` exactly in the
/// reduction, so the AD result carries only the roundings of the f64 algorithm: the
/// absolute error must be within 8 ulp of 1 (`2⁻⁴⁹`), twice the bound on the values.
#[test]
fn derivative_in_u_against_identities() {
    let tol = 2f64.powi(-49);
    let mut worst = (0.0f64, 0.0f64, 0.0f64, 0usize);
    let mut count = 0;
    let mut bad = Vec::new();
    for k in KS {
        let kk = ellipk(&k).unwrap();
        let kr = f256(k);
        let k2 = Float::with_val(REF, &kr * &kr);
        let mut worst_k = 0f64;
        for r in u_over_k() {
            let u = r * kk;
            let (s, c, d) = sncndn(&Dual::var(u), &Dual::constant(k)).unwrap();
            let [rs, rc, rd] = mp(u, &kr);
            let want = [
                Float::with_val(REF, &rc * &rd),
                -Float::with_val(REF, &rs * &rd),
                -(Float::with_val(REF, &rs * &rc) * &k2),
            ];
            for (i, got) in [s.d, c.d, d.d].into_iter().enumerate() {
                let err = Float::with_val(REF, got - &want[i]).abs().to_f64();
                count += 1;
                worst_k = worst_k.max(err);
                if err > worst.0 {
                    worst = (err, k, u, i);
                }
                if err > tol {
                    bad.push(format!(
                        "k = {k:?} u = {u:?}: d{}/du = {got:e}, identity {:e}, error {:.2}·2^-52",
                        ["sn", "cn", "dn"][i],
                        want[i].to_f64(),
                        err * 2f64.powi(52)
                    ));
                }
            }
        }
        eprintln!(
            "d/du: k = {k:<12?} max abs error {:.3}·2^-52",
            worst_k * 2f64.powi(52)
        );
    }
    eprintln!(
        "d/du: {count} derivatives, max abs error {:.3}·2^-52 at k = {:?}, u = {:e} (d{}/du)",
        worst.0 * 2f64.powi(52),
        worst.1,
        worst.2,
        ["sn", "cn", "dn"][worst.3]
    );
    assert!(count >= 300);
    assert!(
        bad.is_empty(),
        "{} derivatives outside 2^-49:\n{}",
        bad.len(),
        bad.iter().take(20).cloned().collect::<Vec<_>>().join("\n")
    );
}
