//! sn, cn, dn of a complex argument and a complex modulus, by the descending Landen
//! (Gauss) transformation in complex arithmetic.

use super::complex::sncndn_complex;
use super::{GUARD, SpecialError, check_finite, refuse_by_rule, show};
use crate::numbers::{ComplexScalar, Cplx, Real, Scalar};

/// Most Landen steps (each squares the modulus, roughly).
const MAX_STEPS: usize = 64;

/// `(sn, cn, dn)(u, k)` for complex `u` and a **complex modulus** `k` (mpmath:
/// `ellipfun(·, u, m = k²)` with complex `m`).  A real `k` (zero imaginary part) goes
/// to [`sncndn_complex`] with `|k|`.
///
/// Algorithm: for `|k| > 1` the reciprocal-modulus transformation DLMF 22.17.2–4
/// (`sn(u, k) = sn(ku, 1/k)/k`, `cn(u, k) = dn(ku, 1/k)`, `dn(u, k) = cn(ku, 1/k)`,
/// identities of analytic functions), so that `|k| ≤ 1` and `Re(1 − k²) > 0`; then the
/// descending Landen transformation DLMF 22.7.1–3 with
/// `k₁ = k²/(1 + k')²`, `k₁' = 2√k'/(1 + k')`, `u₁ = u/(1 + k₁)` (principal square
/// roots, `Re k' > 0`, so `|k₁| < 1`), until `|k_N|⁴` is below the working epsilon; at
/// the bottom DLMF 22.10.4–6 (`sn ≈ sin v − ¼k²(v − sin v cos v) cos v`, …), then up the
/// chain `sn = (1 + k₁)s/(1 + k₁s²)`, `cn = c d/(1 + k₁s²)`,
/// `dn = (1 − k₁s²)/(1 + k₁s²)`.  Working precision `N + 40` bits (`f64` through MPFR
/// at 120 bits), one rounding at the end.  There is no reduction by the (complex)
/// periods, so the guard bits must absorb the growth of the chain with `|u|`; measured
/// against mpmath for `|u| ≤ 3`, `|k| ≤ 2.9`: below 0.5 ε_N relative to
/// `max(1, |value|)` from `f64` to 320 bits (`tests/special/jacobi_complex.rs`).
///
/// Errors: [`SpecialError::ModulusOutOfRange`] for a non-finite `k`;
/// [`SpecialError::NotFinite`]; [`SpecialError::Pole`] at a pole;
/// [`SpecialError::NoConvergence`] if the chain does not converge in 64 steps.
///
/// ```
/// use eulertop_numerics::numbers::C64;
/// use eulertop_numerics::special::sncndn_complex_modulus;
/// // mpmath: ellipfun('sn', mpc(0.7, 0.3), m=mpc(0.6, 0.4)**2)
/// //   = (0.686872830304476434317506823729 + 0.207606714095479789806181357229j)
/// let (sn, cn, _) = sncndn_complex_modulus(&C64::new(0.7, 0.3), &C64::new(0.6, 0.4)).unwrap();
/// assert!((sn.re - 0.6868728303044764).abs() < 1e-15);
/// assert!((sn.im - 0.20760671409547979).abs() < 1e-15);
/// let e = sn.clone() * sn + cn.clone() * cn - C64::new(1.0, 0.0);
/// assert!(e.re.abs() < 1e-15 && e.im.abs() < 1e-15);
/// ```
pub fn sncndn_complex_modulus<C: ComplexScalar>(u: &C, k: &C) -> Result<(C, C, C), SpecialError> {
    refuse_by_rule::<C::R>("sn, cn, dn of a complex modulus")?;
    let (x, y) = (u.re(), u.im());
    check_finite(&x, "Re u")?;
    check_finite(&y, "Im u")?;
    if !k.re().is_finite() || !k.im().is_finite() {
        return Err(SpecialError::ModulusOutOfRange(format!(
            "k = {} + {}i is not finite",
            show(&k.re()),
            show(&k.im())
        )));
    }
    if k.im().is_zero() {
        return sncndn_complex(u, &k.re().abs());
    }
    let n = x.prec().max(y.prec()).max(k.re().prec()).max(k.im().prec());
    if <C::R as Real>::PLAIN_F64 {
        let big = |v: C::R| rug::Float::with_val(120, v.to_f64());
        let uu = Cplx::new(big(x.clone()), big(y.clone()));
        let kk = Cplx::new(big(k.re()), big(k.im()));
        let (s, c, d) = reciprocal(&uu, &kk)?;
        let back = |z: Cplx<rug::Float>| {
            C::from_parts(x.from_f64(z.re.to_f64()), x.from_f64(z.im.to_f64()))
        };
        return finite(&x, &y, (back(s), back(c), back(d)));
    }
    let w = n + GUARD;
    let widen = |z: &C| C::from_parts(z.re().with_prec(w), z.im().with_prec(w));
    let (s, c, d) = reciprocal(&widen(u), &widen(k))?;
    let round = |z: C| C::from_parts(z.re().with_prec(n), z.im().with_prec(n));
    finite(&x, &y, (round(s), round(c), round(d)))
}

/// The values, or an overflow error naming `u = x + iy`.
fn finite<C: ComplexScalar>(x: &C::R, y: &C::R, v: (C, C, C)) -> Result<(C, C, C), SpecialError> {
    let ok = |z: &C| z.re().is_finite() && z.im().is_finite();
    if ok(&v.0) && ok(&v.1) && ok(&v.2) {
        return Ok(v);
    }
    Err(SpecialError::NotFinite(format!(
        "result overflows at u = {} + {}i",
        show(x),
        show(y)
    )))
}

/// DLMF 22.17.2–4 for `|k| > 1`, then [`landen`].
fn reciprocal<C: ComplexScalar>(u: &C, k: &C) -> Result<(C, C, C), SpecialError> {
    let one = C::from_real(u.re().one());
    if ComplexScalar::abs(k) <= u.re().one() {
        return landen(u, k);
    }
    let (s, c, d) = landen(&(u.clone() * k.clone()), &(one / k.clone()))?;
    Ok((s / k.clone(), d, c))
}

/// The descending Landen chain for `|k| ≤ 1`, non-real `k²` or `k² < 0`.
fn landen<C: ComplexScalar>(u: &C, k: &C) -> Result<(C, C, C), SpecialError> {
    let one = C::from_real(u.re().one());
    let small = u.re().epsilon().mul_2si(-4);
    let (mut kk, mut v) = (k.clone(), u.clone());
    let mut kp = ComplexScalar::sqrt(&(one.clone() - k.clone() * k.clone()));
    let mut chain = Vec::new();
    while ComplexScalar::abs(&kk).sqr().sqr() > small {
        if chain.len() >= MAX_STEPS {
            return Err(SpecialError::NoConvergence(
                "Landen chain of a complex modulus".into(),
            ));
        }
        let den = one.clone() + kp.clone();
        let k1 = kk.clone() * kk.clone() / (den.clone() * den.clone());
        kp = ComplexScalar::sqrt(&kp).mul_two() / den;
        v = v / (one.clone() + k1.clone());
        chain.push(k1.clone());
        kk = k1;
    }
    let (sv, cv) = sin_cos(&v);
    let k2 = kk.clone() * kk;
    let quarter = C::from_real(u.re().from_ratio(1, 4));
    let t = v - sv.clone() * cv.clone();
    let mut sn = sv.clone() - quarter.clone() * k2.clone() * t.clone() * cv.clone();
    let mut cn = cv + quarter.clone() * k2.clone() * t * sv.clone();
    let mut dn = one.clone() - quarter.clone() * k2 * sv.clone() * sv.mul_two();
    for k1 in chain.iter().rev() {
        let ks2 = k1.clone() * sn.clone() * sn.clone();
        let den = one.clone() + ks2.clone();
        if den.re().is_zero() && den.im().is_zero() {
            return Err(SpecialError::Pole(
                "sn, cn, dn of a complex modulus: pole".into(),
            ));
        }
        sn = (one.clone() + k1.clone()) * sn / den.clone();
        cn = cn * dn / den.clone();
        dn = (one.clone() - ks2) / den;
    }
    Ok((sn, cn, dn))
}

/// `sin v`, `cos v` of `v = x + iy` from the real functions (no cancellation).
fn sin_cos<C: ComplexScalar>(v: &C) -> (C, C) {
    let (x, y) = (v.re(), v.im());
    let (s, c) = x.sin_cos();
    let (sh, ch) = (y.sinh(), y.cosh());
    (
        C::from_parts(s.clone() * ch.clone(), c.clone() * sh.clone()),
        C::from_parts(c * ch, -(s * sh)),
    )
}

/// `2z`.
trait Twice {
    fn mul_two(&self) -> Self;
}

impl<C: ComplexScalar> Twice for C {
    fn mul_two(&self) -> Self {
        C::from_parts(self.re().mul_2si(1), self.im().mul_2si(1))
    }
}
