//! sn, cn, dn of a complex argument with a real modulus.

use super::jacobi::sncndn_imp;
use super::modulus::{Modulus, Spec};
use super::{GUARD, SpecialError, check_finite, show};
use crate::numbers::{ComplexScalar, Real, Scalar};

/// `(sn, cn, dn)(u, k)` for complex `u = x + iy` and real **modulus** `k ≥ 0`.
///
/// Algorithm: the addition theorem DLMF 22.8.1–3 for `u = x + iy` combined with
/// Jacobi's imaginary transformation `sn(iy|m) = i sc(y|1−m)`, `cn(iy|m) = nc(y|1−m)`,
/// `dn(iy|m) = dc(y|1−m)` (DLMF Table 22.6.1, an identity for every real parameter
/// `m = k²`), i.e. Abramowitz–Stegun 16.21.2–4:
/// `sn = (s d₁ + i c d s₁ c₁)/δ`, `cn = (c c₁ − i s d s₁ d₁)/δ`,
/// `dn = (d c₁ d₁ − i k² s c s₁)/δ`, `δ = c₁² + k² s² s₁²`,
/// with `s, c, d` at `(x, k)` and `s₁, c₁, d₁` at `(y, k')` from the real algorithm
/// (whose reduction measures `y` from the nearest multiple of `K'`, keeping relative
/// accuracy next to the poles `2jK + (2l+1)iK'`).  For `k < 1` no cancellation occurs,
/// so the error is a few ulp of `max(1,|value|)` componentwise-relative; at `N` bits the
/// result is rounded from `N + 40` (or more) bits.  `k = 0` uses `sin`, `cos` of the
/// complex argument directly (`K' = ∞`); `k = 1` gives `tanh u`, `sech u` through the
/// same formula (`s₁, c₁, d₁ = sin y, cos y, 1`); for `k > 1` the real functions of
/// `x` take the modulus by DLMF 22.17.2–4 and those of `y` the parameter
/// `1 − k² = −(k − 1)(k + 1) < 0` (DLMF 22.17.6–8).
///
/// Errors: [`SpecialError::ModulusOutOfRange`] (`k < 0` or not finite),
/// [`SpecialError::NotFinite`] (also for overflowing results),
/// [`SpecialError::ArgumentTooLarge`], [`SpecialError::Pole`] when `δ` vanishes
/// (argument at a pole).
///
/// ```
/// use eulertop_numerics::numbers::C64;
/// use eulertop_numerics::special::sncndn_complex;
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
/// // k > 1: mpmath: ellipfun('sn', mpc(0.5, 0.25), m=4)
/// //   = (0.459282591831489683626926170959 + 0.130497094745324312433505639583j)
/// let (sn, _, _) = sncndn_complex(&C64::new(0.5, 0.25), &2.0).unwrap();
/// assert!((sn.re - 0.4592825918314897).abs() < 1e-14);
/// assert!((sn.im - 0.13049709474532431).abs() < 1e-14);
/// ```
pub fn sncndn_complex<C: ComplexScalar>(u: &C, k: &C::R) -> Result<(C, C, C), SpecialError> {
    if <C::R as Real>::BY_RULE {
        return by_rule(u, k);
    }
    super::check_modulus(k)?;
    let (x, y) = (u.re(), u.im());
    check_finite(&x, "Re u")?;
    check_finite(&y, "Im u")?;
    let n = x.prec().max(y.prec()).max(k.prec());
    if k.is_zero() {
        return circular(&x, &y, n);
    }
    let w = n + GUARD;
    let one = k.one();
    let real = sncndn_imp(&x, Spec::Modulus(k, Modulus::K), n).map_err(part("Re u", "K"))?;
    let imag = if *k < one {
        sncndn_imp(&y, Spec::Modulus(k, Modulus::Complement), n).map_err(part("Im u", "K'"))?
    } else {
        // 1 − k² = −(k − 1)(k + 1), exact in the first factor
        let kw = k.with_prec(w);
        let mc = -((kw.clone() - kw.one()) * (kw.clone() + kw.one()));
        sncndn_imp(&y, Spec::Parameter(&mc), n).map_err(part("Im u", "K'"))?
    };
    combine(&x, &y, real, imag, &k.with_prec(w).sqr(), n)
}

/// Names the part of a complex argument (`Re u`, with its period `K`; `Im u`, with `K'`)
/// that the argument reduction of the real algorithm refused.
fn part(label: &'static str, period: &'static str) -> impl Fn(SpecialError) -> SpecialError {
    move |e| match e {
        SpecialError::ArgumentTooLarge(m) => SpecialError::ArgumentTooLarge(
            m.replace("|u|/K", &format!("|{label}|/{period}"))
                .replace("(u = ", &format!("({label} = ")),
        ),
        other => other,
    }
}

/// [`sncndn_complex`] for the **parameter** `m = k²`, any real `m` (mpmath:
/// `ellipfun(·, u, m)`): `m < 0` is an imaginary modulus.  The same formula, with
/// `s, c, d` at `(x | m)` and `s₁, c₁, d₁` at `(y | 1 − m)` from the real algorithm
/// ([`sncndn_m`](super::sncndn_m), DLMF 22.17.6–8 for a negative parameter).  For
/// `m < 0` the denominator `c₁² + m s² s₁²` is a difference, so next to the poles the
/// relative accuracy drops with the distance to them.
///
/// Errors: as [`sncndn_complex`].
///
/// ```
/// use eulertop_numerics::numbers::C64;
/// use eulertop_numerics::special::sncndn_complex_m;
/// // mpmath: ellipfun('cn', mpc(0.5, 0.25), m=-0.5)
/// //   = (0.906711785018456790013598506369 - 0.128651621685050470852382626965j)
/// let (_, cn, _) = sncndn_complex_m(&C64::new(0.5, 0.25), &-0.5).unwrap();
/// assert!((cn.re - 0.9067117850184568).abs() < 1e-14);
/// assert!((cn.im + 0.12865162168505047).abs() < 1e-14);
/// ```
pub fn sncndn_complex_m<C: ComplexScalar>(u: &C, m: &C::R) -> Result<(C, C, C), SpecialError> {
    super::refuse_by_rule::<C::R>("sn, cn, dn of a parameter m")?;
    if !m.is_finite() {
        return Err(SpecialError::ModulusOutOfRange(format!(
            "parameter m = {} is not finite",
            show(m)
        )));
    }
    let (x, y) = (u.re(), u.im());
    check_finite(&x, "Re u")?;
    check_finite(&y, "Im u")?;
    let n = x.prec().max(y.prec()).max(m.prec());
    if m.is_zero() {
        return circular(&x, &y, n);
    }
    let w = n + GUARD;
    let mw = m.with_prec(w);
    let mc = mw.one() - mw.clone();
    let real = sncndn_imp(&x, Spec::Parameter(m), n).map_err(part("Re u", "K"))?;
    let imag = sncndn_imp(&y, Spec::Parameter(&mc), n).map_err(part("Im u", "K'"))?;
    combine(&x, &y, real, imag, &mw, n)
}

/// `k = 0`: `sn = sin u`, `cn = cos u`, `dn = 1` of `u = x + iy`.
fn circular<C: ComplexScalar>(x: &C::R, y: &C::R, n: u32) -> Result<(C, C, C), SpecialError> {
    let w = n + GUARD;
    let (xw, yw) = (x.with_prec(w), y.with_prec(w));
    let (s, c) = xw.sin_cos();
    let (sh, ch) = (yw.sinh(), yw.cosh());
    let out = |re: C::R, im: C::R| finite::<C>(x, y, re, im, n);
    let sn = out(s.clone() * ch.clone(), c.clone() * sh.clone())?;
    let cn = out(c * ch, -(s * sh))?;
    let dn = out(xw.one(), xw.zero())?;
    Ok((sn, cn, dn))
}

/// `re + i·im` rounded to `n` bits, or an overflow error naming `u = x + iy`.
fn finite<C: ComplexScalar>(
    x: &C::R,
    y: &C::R,
    re: C::R,
    im: C::R,
    n: u32,
) -> Result<C, SpecialError> {
    if !re.is_finite() || !im.is_finite() {
        return Err(SpecialError::NotFinite(format!(
            "result overflows at u = {} + {}i",
            show(x),
            show(y)
        )));
    }
    Ok(C::from_parts(re.with_prec(n), im.with_prec(n)))
}

/// Abramowitz–Stegun 16.21.2–4 from `(s, c, d)` of `x` with parameter `m` and
/// `(s₁, c₁, d₁)` of `y` with parameter `1 − m`.
fn combine<C: ComplexScalar>(
    x: &C::R,
    y: &C::R,
    (s, c, d): (C::R, C::R, C::R),
    (s1, c1, d1): (C::R, C::R, C::R),
    m: &C::R,
    n: u32,
) -> Result<(C, C, C), SpecialError> {
    let w = n + GUARD;
    let p = |v: C::R| v.with_prec(w);
    let (s, c, d, s1, c1, d1) = (p(s), p(c), p(d), p(s1), p(c1), p(d1));
    let den = c1.sqr() + m.clone() * s.sqr() * s1.sqr();
    if den.is_zero() {
        return Err(SpecialError::Pole(format!(
            "sn, cn, dn have a pole at u = {} + {}i (m = {})",
            show(x),
            show(y),
            show(m)
        )));
    }
    let out = |re: C::R, im: C::R| finite::<C>(x, y, re, im, n);
    let sn = out(
        s.clone() * d1.clone() / den.clone(),
        c.clone() * d.clone() * s1.clone() * c1.clone() / den.clone(),
    )?;
    let cn = out(
        c.clone() * c1.clone() / den.clone(),
        -(s.clone() * d.clone() * s1.clone() * d1.clone() / den.clone()),
    )?;
    let dn = out(d * c1 * d1 / den.clone(), -(m.clone() * s * c * s1 / den))?;
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
