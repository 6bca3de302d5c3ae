//! sn, cn, dn of a complex argument with a real modulus.

use super::jacobi::sncndn_imp;
use super::modulus::{Modulus, Spec};
use super::{GUARD, SpecialError, check_finite, check_modulus_below_one, show};
use crate::numbers::{ComplexScalar, Real, Scalar};

/// `(sn, cn, dn)(u, k)` for complex `u = x + iy` and real **modulus** `0 ≤ k < 1`.
///
/// Algorithm: the addition theorem DLMF 22.8.1–3 for `u = x + iy` combined with
/// Jacobi's imaginary transformation `sn(iy,k) = i sc(y,k')`, `cn(iy,k) = nc(y,k')`,
/// `dn(iy,k) = dc(y,k')` (Jacobi's imaginary transformation, DLMF Table 22.6.1), i.e.
/// Abramowitz–Stegun 16.21.2–4:
/// `sn = (s d₁ + i c d s₁ c₁)/δ`, `cn = (c c₁ − i s d s₁ d₁)/δ`,
/// `dn = (d c₁ d₁ − i k² s c s₁)/δ`, `δ = c₁² + k² s² s₁²`,
/// with `s, c, d` at `(x, k)` and `s₁, c₁, d₁` at `(y, k')` from the real algorithm
/// (whose reduction measures `y` from the nearest multiple of `K'`, keeping relative
/// accuracy next to the poles `2jK + (2l+1)iK'`).  No cancellation occurs, so the
/// error is a few ulp of `max(1,|value|)` componentwise-relative; at `N` bits the
/// result is rounded from `N + 40` (or more) bits.  `k = 0` uses `sin`, `cos` of the
/// complex argument directly (`K' = ∞`).
///
/// Errors: [`SpecialError::ModulusOutOfRange`], [`SpecialError::NotFinite`] (also
/// for overflowing results), [`SpecialError::ArgumentTooLarge`],
/// [`SpecialError::Pole`] when `δ` vanishes (argument at a pole).
///
/// ```
/// use eulertop::numbers::C64;
/// use eulertop::special::sncndn_complex;
/// // mpmath: ellipfun('sn', mpc(0.5, 0.25), m=0.25)
/// //   = (0.492218840478357096475607622427 + 0.215722356526344564680618469113j)
/// let (sn, cn, dn) = sncndn_complex(&C64::new(0.5, 0.25), &0.5).unwrap();
/// assert!((sn.re - 0.4922188404783571).abs() < 1e-15);
/// assert!((sn.im - 0.21572235652634456).abs() < 1e-15);
/// let one = C64::new(1.0, 0.0);
/// let e = sn.clone() * sn.clone() + cn.clone() * cn.clone() - one;
/// assert!(e.re.abs() < 1e-15 && e.im.abs() < 1e-15);
/// let e2 = dn.clone() * dn + C64::new(0.25, 0.0) * sn.clone() * sn.clone() - C64::new(1.0, 0.0);
/// assert!(e2.re.abs() < 1e-15 && e2.im.abs() < 1e-15);
/// ```
pub fn sncndn_complex<C: ComplexScalar>(u: &C, k: &C::R) -> Result<(C, C, C), SpecialError> {
    if <C::R as Real>::BY_RULE {
        return by_rule(u, k);
    }
    check_modulus_below_one(k)?;
    let (x, y) = (u.re(), u.im());
    check_finite(&x, "Re u")?;
    check_finite(&y, "Im u")?;
    let n = x.prec().max(y.prec()).max(k.prec());
    let w = n + GUARD;
    let out = |re: C::R, im: C::R| -> Result<C, SpecialError> {
        if !re.is_finite() || !im.is_finite() {
            return Err(SpecialError::NotFinite(format!(
                "result overflows at u = {} + {}i",
                show(&x),
                show(&y)
            )));
        }
        Ok(C::from_parts(re.with_prec(n), im.with_prec(n)))
    };
    if k.is_zero() {
        let xw = x.with_prec(w);
        let yw = y.with_prec(w);
        let (s, c) = xw.sin_cos();
        let (sh, ch) = (yw.sinh(), yw.cosh());
        let sn = out(s.clone() * ch.clone(), c.clone() * sh.clone())?;
        let cn = out(c * ch, -(s * sh))?;
        let dn = out(xw.one(), xw.zero())?;
        return Ok((sn, cn, dn));
    }
    let (s, c, d) = sncndn_imp(&x, Spec::Modulus(k, Modulus::K), n)?;
    let (s1, c1, d1) = sncndn_imp(&y, Spec::Modulus(k, Modulus::Complement), n)?;
    let p = |v: C::R| v.with_prec(w);
    let (s, c, d, s1, c1, d1) = (p(s), p(c), p(d), p(s1), p(c1), p(d1));
    let k2 = k.with_prec(w).sqr();
    let den = c1.sqr() + k2.clone() * s.sqr() * s1.sqr();
    if den.is_zero() {
        return Err(SpecialError::Pole(format!(
            "sn, cn, dn have a pole at u = {} + {}i (k = {})",
            show(&x),
            show(&y),
            show(k)
        )));
    }
    let sn = out(
        s.clone() * d1.clone() / den.clone(),
        c.clone() * d.clone() * s1.clone() * c1.clone() / den.clone(),
    )?;
    let cn = out(
        c.clone() * c1.clone() / den.clone(),
        -(s.clone() * d.clone() * s1.clone() * d1.clone() / den.clone()),
    )?;
    let dn = out(d * c1 * d1 / den.clone(), -(k2 * s * c * s1 / den))?;
    Ok((sn, cn, dn))
}

/// [`sncndn_complex`] for a type that evaluates by rules ([`Real::BY_RULE`]): the same
/// imaginary transformation (A&S 16.21.1–4) on the rule's `sn, cn, dn` of `Re u` with
/// modulus `k` and of `Im u` with modulus `k' = √(1 − k²)`; a real argument directly.
fn by_rule<C: ComplexScalar>(u: &C, k: &C::R) -> Result<(C, C, C), SpecialError> {
    let (x, y) = (u.re(), u.im());
    let (s, c, d) = super::sncndn(&x, k)?;
    if y.is_zero() {
        let z = || x.zero();
        return Ok((
            C::from_parts(s, z()),
            C::from_parts(c, z()),
            C::from_parts(d, z()),
        ));
    }
    let k2 = k.sqr();
    let kp = (k.one() - k2.clone()).sqrt();
    let (s1, c1, d1) = super::sncndn(&y, &kp)?;
    let den = c1.sqr() + k2.clone() * s.sqr() * s1.sqr();
    let sn = C::from_parts(
        s.clone() * d1.clone() / den.clone(),
        c.clone() * d.clone() * s1.clone() * c1.clone() / den.clone(),
    );
    let cn = C::from_parts(
        c.clone() * c1.clone() / den.clone(),
        -(s.clone() * d.clone() * s1.clone() * d1.clone() / den.clone()),
    );
    let dn = C::from_parts(d * c1 * d1 / den.clone(), -(k2 * s * c * s1 / den));
    Ok((sn, cn, dn))
}
