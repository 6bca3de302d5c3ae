//! The elliptic functions of a real modulus `0 < k < 1` in ball arithmetic: enclosures
//! computed by Arb (through FLINT), never by the numerical iterations of
//! [`crate::special`].
//!
//! * `K(k)` and `K'(k) = K(k')`: `acb_elliptic_k` at the parameter `m = k²` (resp. `1 − m`);
//! * `sn, cn, dn (u, k)` from Jacobi's theta functions (DLMF 22.2.4, 22.2.5, 22.2.6):
//!   with `τ = iK'/K` and `z = u/(2K)` (Arb's `θⱼ(z, τ)` is DLMF's `θⱼ(πz | τ)`),
//!   `sn = θ₃(0)θ₁(z) / (θ₂(0)θ₄(z))`, `cn = θ₄(0)θ₂(z) / (θ₂(0)θ₄(z))`,
//!   `dn = θ₄(0)θ₃(z) / (θ₃(0)θ₄(z))`, by `acb_modular_theta`;
//! * `F(φ, k)` and `E(φ, k)`: `acb_elliptic_f`, `acb_elliptic_e_inc` (DLMF 19.2.4–5,
//!   quasi-periodic continuation in `φ`); `E(k)`, `E'(k)`: `acb_elliptic_e`;
//! * the real `u ∈ (−2K, 2K]` with given `sn, cn, dn`: `F(atan2(sn, cn), k)`, the branch
//!   of [`crate::special::jacobi_inverse`].
//!
//! Each takes its argument balls as they are: the result encloses the function's value
//! at every point of them.  A modulus ball not inside `(0, 1)` (or exactly 0, where sn,
//! cn, dn are sin, cos, 1) is refused with a message.
//!
//! ```
//! use eulertop_numerics::numbers::{Ball, Real};
//! let (u, k) = (Ball::exact(0.7, 128), Ball::exact(0.8, 128));
//! let (s, c, d) = Real::sncndn_by_rule(&u, &k).unwrap();
//! // mpmath: ellipfun('sn', 0.7, m=0.64) = 0.618755648952545342744...
//! assert!((s.mid_f64() - 0.618_755_648_952_545_3).abs() < 2e-16);
//! assert!(s.rad_f64() < 1e-30);
//! let one = s.clone() * s + c.clone() * c;
//! assert!(one.contains_f64(1.0) && (d.clone() * d).mid_f64() > 0.0);
//! ```

use super::{Ball, Real, Scalar};
use flint_sys::acb::*;
use flint_sys::acb_elliptic::{acb_elliptic_e, acb_elliptic_e_inc, acb_elliptic_f, acb_elliptic_k};
use flint_sys::acb_modular::acb_modular_theta;
use flint_sys::acb_types::acb_struct;
use std::mem::MaybeUninit;

/// Guard bits of the Arb evaluations.
const GUARD: u32 = 32;

/// A complex ball owned for one computation.
struct Acb(acb_struct);

impl Drop for Acb {
    fn drop(&mut self) {
        // SAFETY: initialised by acb_init, cleared once.
        unsafe { acb_clear(&mut self.0) }
    }
}

impl Acb {
    fn zero() -> Acb {
        let mut z = MaybeUninit::<acb_struct>::uninit();
        // SAFETY: acb_init initialises the struct it is given.
        unsafe {
            acb_init(z.as_mut_ptr());
            Acb(z.assume_init())
        }
    }
    fn real(x: &Ball) -> Acb {
        let mut z = Acb::zero();
        // SAFETY: both are initialised.
        unsafe { acb_set_arb(&mut z.0, x.arb()) };
        z
    }
    /// The real part, as a ball at precision `prec`.
    fn re(&self, prec: u32) -> Ball {
        Ball::from_arb(&self.0.real, prec)
    }
    fn div(&self, o: &Acb, prec: u32) -> Acb {
        let mut r = Acb::zero();
        // SAFETY: every value is initialised; Arb allows aliasing.
        unsafe { acb_div(&mut r.0, &self.0, &o.0, i64::from(prec)) };
        r
    }
    fn mul(&self, o: &Acb, prec: u32) -> Acb {
        let mut r = Acb::zero();
        // SAFETY: as above.
        unsafe { acb_mul(&mut r.0, &self.0, &o.0, i64::from(prec)) };
        r
    }
}

/// `m = k²` when `0 < m < 1` is decided for the ball `k`.
fn parameter(k: &Ball) -> Result<Ball, String> {
    let m = k.clone() * k.clone();
    let (zero, one) = (m.zero(), m.one());
    if !(m.gt(&zero) && m.lt(&one)) {
        return Err(format!(
            "the modulus ball {} is not inside (0, 1): no enclosure of the elliptic functions",
            k.show(10)
        ));
    }
    Ok(m)
}

/// `K(m)` of a parameter ball, at `prec` bits.
fn k_of_parameter(m: &Ball, prec: u32) -> Acb {
    let mut r = Acb::zero();
    // SAFETY: both values are initialised.
    unsafe { acb_elliptic_k(&mut r.0, &Acb::real(m).0, i64::from(prec)) };
    r
}

/// `K(k)`, or `K'(k) = K(√(1 − k²))` when `complementary` (see the module).
pub(super) fn ellipk(k: &Ball, complementary: bool) -> Result<Ball, String> {
    let m = parameter(k)?;
    let m = if complementary { m.one() - m } else { m };
    let prec = k.prec_bits();
    Ok(k_of_parameter(&m, prec + GUARD).re(prec))
}

/// `E(k)`, or `E'(k) = E(√(1 − k²))` when `complementary` (see the module).
pub(super) fn ellipe(k: &Ball, complementary: bool) -> Result<Ball, String> {
    let m = parameter(k)?;
    let m = if complementary { m.one() - m } else { m };
    let prec = k.prec_bits();
    let mut r = Acb::zero();
    // SAFETY: both values are initialised.
    unsafe { acb_elliptic_e(&mut r.0, &Acb::real(&m).0, i64::from(prec + GUARD)) };
    Ok(r.re(prec))
}

/// `E(φ, k)` (see the module).
pub(super) fn ellipeinc(phi: &Ball, k: &Ball) -> Result<Ball, String> {
    let prec = phi.prec_bits().max(k.prec_bits());
    let m = parameter(k)?;
    let mut r = Acb::zero();
    // SAFETY: every value is initialised.
    unsafe {
        acb_elliptic_e_inc(
            &mut r.0,
            &Acb::real(phi).0,
            &Acb::real(&m).0,
            0,
            i64::from(prec + GUARD),
        )
    };
    Ok(r.re(prec))
}

/// `θ₁, θ₂, θ₃, θ₄ (z, τ)` (Arb's normalization, see the module).
fn thetas(z: &Acb, tau: &Acb, prec: u32) -> [Acb; 4] {
    let mut t = [Acb::zero(), Acb::zero(), Acb::zero(), Acb::zero()];
    let [t1, t2, t3, t4] = &mut t;
    // SAFETY: every value is initialised and distinct.
    unsafe {
        acb_modular_theta(
            &mut t1.0,
            &mut t2.0,
            &mut t3.0,
            &mut t4.0,
            &z.0,
            &tau.0,
            i64::from(prec),
        )
    };
    t
}

/// `(sn, cn, dn)(u, k)` (see the module).
pub(super) fn sncndn(u: &Ball, k: &Ball) -> Result<(Ball, Ball, Ball), String> {
    let prec = u.prec_bits().max(k.prec_bits());
    if k.is_zero() {
        return Ok((Real::sin(u), Real::cos(u), u.one()));
    }
    let m = parameter(k)?;
    let w = prec + GUARD;
    let kk = k_of_parameter(&m, w);
    let kp = k_of_parameter(&(m.one() - m), w);
    let mut tau = kp.div(&kk, w);
    // SAFETY: initialised; aliasing allowed.
    unsafe { acb_mul_onei(&mut tau.0, &tau.0) };
    let two_k = kk.mul(&Acb::real(&Ball::exact(2.0, w)), w);
    let z = Acb::real(u).div(&two_k, w);
    let [t1, t2, t3, t4] = thetas(&z, &tau, w);
    let [_, z2, z3, z4] = thetas(&Acb::zero(), &tau, w);
    let sn = z3.mul(&t1, w).div(&z2.mul(&t4, w), w);
    let cn = z4.mul(&t2, w).div(&z2.mul(&t4, w), w);
    let dn = z4.mul(&t3, w).div(&z3.mul(&t4, w), w);
    Ok((sn.re(prec), cn.re(prec), dn.re(prec)))
}

/// `F(φ, k)` (see the module).
pub(super) fn ellipf(phi: &Ball, k: &Ball) -> Result<Ball, String> {
    let prec = phi.prec_bits().max(k.prec_bits());
    if k.is_zero() {
        return Ok(phi.clone());
    }
    let m = parameter(k)?;
    let mut r = Acb::zero();
    // SAFETY: every value is initialised.
    unsafe {
        acb_elliptic_f(
            &mut r.0,
            &Acb::real(phi).0,
            &Acb::real(&m).0,
            0,
            i64::from(prec + GUARD),
        )
    };
    Ok(r.re(prec))
}

/// The real `u ∈ (−2K, 2K]` with `(sn, cn, dn)(u, k) = (s, c, d)`: `F(atan2(s, c), k)`.
/// The balls must be consistent (`s² + c² − 1` and `d² + k²s² − 1` contain 0) and
/// `d > 0` decided; otherwise the values are not sn, cn, dn of one real argument.
pub(super) fn jacobi_inverse(s: &Ball, c: &Ball, d: &Ball, k: &Ball) -> Result<Ball, String> {
    let one = s.one();
    let r1 = s.clone() * s.clone() + c.clone() * c.clone() - one.clone();
    let r2 = d.clone() * d.clone() + k.clone() * k.clone() * s.clone() * s.clone() - one;
    if !r1.contains_zero() || !r2.contains_zero() || !d.gt(&d.zero()) {
        return Err(format!(
            "inconsistent input: ({}, {}, {}) are not sn, cn, dn of one real argument with dn > 0",
            s.show(10),
            c.show(10),
            d.show(10)
        ));
    }
    ellipf(&Real::atan2(s, c), k)
}

#[cfg(test)]
mod tests {
    use super::*;

    // mpmath (30 digits): ellipfun('sn'/'cn'/'dn', 0.7, m=0.64), ellipk(0.64),
    // ellipf(1.2, 0.64)
    #[test]
    fn enclosures_hold_the_reference_values() {
        let (u, k) = (Ball::exact(0.7, 200), Ball::exact(0.8, 200));
        let (s, c, d) = sncndn(&u, &k).unwrap();
        for (b, x) in [
            (&s, 0.618_755_648_952_545_3_f64),
            (&c, 0.785_583_507_266_614_2),
            (&d, 0.868_890_399_307_738_5),
        ] {
            assert!(
                (b.mid_f64() - x).abs() < 2e-16 && b.rad_f64() < 1e-50,
                "{b:?}"
            );
        }
        // mpmath (30 digits), at other moduli and arguments
        for (u, k, want) in [
            (
                -3.3,
                0.3,
                [
                    0.083_795_537_590_535_4,
                    -0.996_482_969_187_087_1,
                    0.999_683_973_918_354,
                ],
            ),
            (
                5.0,
                0.99,
                [
                    0.940_610_080_751_535_3,
                    -0.339_488_845_160_765_6,
                    0.364_498_487_975_488_5,
                ],
            ),
            (
                0.001,
                0.05,
                [
                    0.000_999_999_832_916_675_3,
                    0.999_999_500_000_042_1,
                    0.999_999_998_750_000_4,
                ],
            ),
        ] {
            let (s, c, d) = sncndn(&Ball::exact(u, 200), &Ball::exact(k, 200)).unwrap();
            for (b, x) in [s, c, d].iter().zip(want) {
                assert!((b.mid_f64() - x).abs() <= 4e-16 * x.abs(), "{u} {k}: {b:?}");
                assert!(b.rad_f64() < 1e-20 * x.abs(), "{u} {k}: {b:?}");
            }
        }
        let kk = ellipk(&k, false).unwrap();
        assert!((kk.mid_f64() - 1.995_302_777_664_729_4).abs() < 4e-16);
        let f = ellipf(&Ball::exact(1.2, 200), &k).unwrap();
        assert!((f.mid_f64() - 1.399_520_505_737_465_5).abs() < 4e-16);
    }

    #[test]
    fn inverse_returns_the_argument_and_refuses_inconsistent_values() {
        let k = Ball::exact(0.8, 200);
        for x in [-2.5, -0.3, 0.0, 1.1, 3.9] {
            let (s, c, d) = sncndn(&Ball::exact(x, 200), &k).unwrap();
            let u = jacobi_inverse(&s, &c, &d, &k).unwrap();
            assert!(
                u.contains_f64(x) || (u.mid_f64() - x).abs() < 1e-40,
                "{x}: {u:?}"
            );
        }
        let (s, c) = (Ball::exact(0.6, 200), Ball::exact(0.6, 200));
        assert!(jacobi_inverse(&s, &c, &Ball::exact(0.9, 200), &k).is_err());
        assert!(parameter(&Ball::exact(1.0, 200)).is_err());
    }
}
