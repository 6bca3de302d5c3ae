//! Cross-checks of the bottoms of the Jacobi evaluation ([`Bottom`]) against each other
//! and against MPFR at random moduli and arguments (in the manner of Arb's
//! `t-theta.c`): each bottom is an exact formula for every modulus, so where two of them
//! apply they must agree to rounding.

use super::bottom::Bottom;
use super::bottom::tanh_sech;
use super::dd::Dd;
use super::fixed::sncndn_theta;
use super::modulus::Modulus;
use super::multi::reduced;
use super::theta::Theta;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rug::Float;

/// `(sn, cn, dn)(u, k)` at 256 bits (Landen chain and [`Bottom::Sine`] with guard bits).
fn mpfr(u: f64, k: f64) -> [f64; 3] {
    let r = reduced(
        &Float::with_val(256, u),
        &Float::with_val(256, k),
        Modulus::K,
        256,
    )
    .expect("in domain")
    .finish();
    [r.0.to_f64(), r.1.to_f64(), r.2.to_f64()]
}

/// `κ² = k²`, `κ'² = 1 − k²` in double-double.
fn pair(k: f64) -> (Dd<f64>, Dd<f64>) {
    let m = Dd::from(k).sqr();
    let (s, e) = super::dd::two_sum(1.0, -m.v());
    (
        m.clone(),
        Dd {
            hi: s,
            lo: e - m.lo,
        }
        .norm(),
    )
}

/// The theta bottom `imaginary` (or the series) forced at modulus `k`.
fn theta(u: f64, k: f64, imaginary: bool) -> [f64; 3] {
    let (m, mc) = pair(k);
    let th = Theta::with_bottom(&m, &mc, imaginary, false);
    assert_eq!(
        th.bottom,
        if imaginary {
            Bottom::Imaginary
        } else {
            Bottom::Series
        }
    );
    let (s, c, d) = sncndn_theta(&u, 0.0, &th, &m, &mc).expect("in domain");
    [s, c, d]
}

fn assert_close(a: [f64; 3], b: [f64; 3], tol: f64, what: &str) {
    for i in 0..3 {
        assert!(
            (a[i] - b[i]).abs() <= tol,
            "{what}: {} {:e} vs {:e}",
            ["sn", "cn", "dn"][i],
            a[i],
            b[i]
        );
    }
}

/// Series and Imaginary at moduli where both nomes are at most 0.08 (`κ ∈ [0.55, 0.85]`),
/// against each other and against the 256-bit Sine bottom; the Sine bottom in `f64`
/// (no guard bits, so a looser bound) against the same reference.
#[test]
fn bottoms_agree_at_random_moduli() {
    let mut rng = ChaCha8Rng::seed_from_u64(20261123);
    let tol = 4.0 * f64::EPSILON;
    for _ in 0..400 {
        let k: f64 = rng.gen_range(0.55..0.85);
        let u: f64 = rng.gen_range(-30.0..30.0);
        let want = mpfr(u, k);
        let (series, imag) = (theta(u, k, false), theta(u, k, true));
        assert_close(series, want, tol, &format!("series k = {k} u = {u}"));
        assert_close(imag, want, tol, &format!("imaginary k = {k} u = {u}"));
        assert_close(
            series,
            imag,
            tol,
            &format!("series/imaginary k = {k} u = {u}"),
        );
        let r = reduced(&u, &k, Modulus::K, 53).expect("in domain").finish();
        assert_close(
            [r.0, r.1, r.2],
            want,
            1e-13,
            &format!("f64 sine k = {k} u = {u}"),
        );
    }
}

/// TanhSech (DLMF 22.10.7–9) against Imaginary and MPFR for `κ'² < 2⁻⁵⁰`, `|u| ≤ 4`,
/// where the neglected `O(κ'⁴ e^{2|u|})` terms are below the rounding.
#[test]
fn tanh_sech_agrees_near_one() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    for _ in 0..200 {
        let k = 1.0 - rng.gen_range(1.0..2.0e6) * f64::EPSILON / 4.0;
        let u: f64 = rng.gen_range(-4.0..4.0);
        let (_, mc) = pair(k);
        let (s, c, d) = tanh_sech(&u, &mc.to_r());
        let want = mpfr(u, k);
        assert_close(
            [s, c, d],
            want,
            3.0 * f64::EPSILON,
            &format!("tanh/sech k = {k} u = {u}"),
        );
        assert_close(
            theta(u, k, true),
            [s, c, d],
            3.0 * f64::EPSILON,
            "tanh/sech vs imaginary",
        );
    }
}
