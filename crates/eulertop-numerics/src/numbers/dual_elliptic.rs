//! The elliptic functions of dual numbers over an enclosing type that evaluates them by
//! rules ([`Real::BY_RULE`] and [`Real::ENCLOSES`]: balls): the value by the type's rule,
//! the derivative by the exact differentiation formulas, so that a derivative in ball
//! arithmetic encloses the exact derivative.
//!
//! With `k'² = 1 − k²`, `Δ = √(1 − k² sin²φ)` and `E(u) = E(am u, k)`:
//! * `∂(sn, cn, dn)/∂u = (cn dn, −sn dn, −k² sn cn)` (DLMF 22.13.1–3);
//! * `∂ am/∂k = (k sn cn − dn·Z/k)/k'²` with `Z = E(u) − k'²u`, and then
//!   `∂sn/∂k = cn·∂am/∂k`, `∂cn/∂k = −sn·∂am/∂k`, `∂dn/∂k = −(k sn² + k² sn ∂sn/∂k)/dn`;
//! * `dK/dk = E/(k k'²) − K/k`, `dK'/dk = k K'/k'² − E'/(k k'²)` (DLMF 19.4.1);
//! * `∂F/∂φ = 1/Δ`, `∂F/∂k = E(φ, k)/(k k'²) − F/k − k sin φ cos φ/(k'² Δ)` (DLMF 19.4.2
//!   with 19.4.4's notation).
//!
//! The amplitude of `E(u)` is the continuous one: `atan2(sn, cn)` plus the whole turns
//! `2π·round((u − F(atan2(sn, cn), k))/(4K))`.
//!
//! With the feature `arb` (balls):
//!
//! ```
//! # #[cfg(feature = "arb")]
//! # fn main() {
//! use eulertop_numerics::numbers::{Ball, Dual, Real};
//! // d/dk sn(0.7, k) at k = 0.8, against the same derivative of f64 dual numbers
//! let k = Dual::new(Ball::exact(0.8, 128), Ball::exact(1.0, 128));
//! let u = Dual::constant(Ball::exact(0.7, 128));
//! let (s, _, _) = Real::sncndn_by_rule(&u, &k).unwrap();
//! let (sf, _, _) = eulertop_numerics::special::sncndn(&Dual::constant(0.7_f64), &Dual::new(0.8, 1.0)).unwrap();
//! assert!((s.d.mid_f64() - sf.d).abs() < 1e-13);
//! # }
//! # #[cfg(not(feature = "arb"))]
//! # fn main() {}
//! ```

use super::{Dual, Real};

/// The integer `n` in the type of `x`.
fn num<R: Real>(x: &R, n: i64) -> R {
    x.from_i64(n)
}

/// `∂ am/∂k` at `(u, k)`, from `sn, cn, dn` there (see the module).
fn dam_dk<R: Real>(u: &R, k: &R, (s, c, d): (&R, &R, &R)) -> Result<R, String> {
    let phi0 = s.atan2(c);
    let kk = R::quarter_period_by_rule(k, false)?;
    // a whole number up to rounding: floor(x + 1/2) decides it without a sign test
    let x = (u.clone() - R::ellipf_by_rule(&phi0, k)?) / (kk * num(k, 4));
    let turns = (x + k.one().mul_2si(-1)).floor();
    let am = phi0 + turns * k.pi().mul_2si(1);
    let kp2 = k.one() - k.sqr();
    let z = R::ellipeinc_by_rule(&am, k)? - kp2.clone() * u.clone();
    Ok((k.clone() * s.clone() * c.clone() - d.clone() * z / k.clone()) / kp2)
}

/// `(sn, cn, dn)` as dual numbers.
type Triple<R> = (Dual<R>, Dual<R>, Dual<R>);

/// `(sn, cn, dn)(u, k)` of dual numbers (see the module).
pub(super) fn sncndn<R: Real>(u: &Dual<R>, k: &Dual<R>) -> Result<Triple<R>, String> {
    let (s, c, d) = R::sncndn_by_rule(&u.v, &k.v)?;
    let k2 = k.v.sqr();
    // the k-parts are formed even where k's derivative is 0: a test for 0 of a ball
    // would be a decision
    let a = dam_dk(&u.v, &k.v, (&s, &c, &d))?;
    let dsk = c.clone() * a.clone();
    let ddk = -(k.v.clone() * s.sqr() + k2.clone() * s.clone() * dsk.clone()) / d.clone();
    let ds = c.clone() * d.clone() * u.d.clone() + dsk * k.d.clone();
    let dc = -(s.clone() * d.clone()) * u.d.clone() - s.clone() * a * k.d.clone();
    let dd = -(k2 * s.clone() * c.clone()) * u.d.clone() + ddk * k.d.clone();
    Ok((Dual::new(s, ds), Dual::new(c, dc), Dual::new(d, dd)))
}

/// `K(k)`, or `K'(k)` when `complementary`, of a dual number (see the module).
pub(super) fn quarter_period<R: Real>(k: &Dual<R>, complementary: bool) -> Result<Dual<R>, String> {
    let kk = R::quarter_period_by_rule(&k.v, complementary)?;
    let e = R::ellipe_by_rule(&k.v, complementary)?;
    let kp2 = k.v.one() - k.v.sqr();
    let dk = match complementary {
        false => e / (k.v.clone() * kp2) - kk.clone() / k.v.clone(),
        true => k.v.clone() * kk.clone() / kp2.clone() - e / (k.v.clone() * kp2),
    };
    Ok(Dual::new(kk, dk * k.d.clone()))
}

/// `F(φ, k)` of dual numbers (see the module).
pub(super) fn ellipf<R: Real>(phi: &Dual<R>, k: &Dual<R>) -> Result<Dual<R>, String> {
    let f = R::ellipf_by_rule(&phi.v, &k.v)?;
    let (sn, cs) = phi.v.sin_cos();
    let delta = (k.v.one() - k.v.sqr() * sn.sqr()).sqrt();
    let kp2 = k.v.one() - k.v.sqr();
    let e = R::ellipeinc_by_rule(&phi.v, &k.v)?;
    let dk = e / (k.v.clone() * kp2.clone())
        - f.clone() / k.v.clone()
        - k.v.clone() * sn * cs / (kp2 * delta.clone());
    Ok(Dual::new(f, phi.d.clone() / delta + dk * k.d.clone()))
}

/// The real `u ∈ (−2K, 2K]` with the given `sn, cn, dn` of dual numbers:
/// `F(atan2(sn, cn), k)`, after the type's own check of the values.
pub(super) fn jacobi_inverse<R: Real>(
    s: &Dual<R>,
    c: &Dual<R>,
    d: &Dual<R>,
    k: &Dual<R>,
) -> Result<Dual<R>, String> {
    R::jacobi_inverse_by_rule(&s.v, &c.v, &d.v, &k.v)?;
    ellipf(&s.atan2(c), k)
}

#[cfg(all(test, feature = "arb"))]
mod tests {
    use super::*;
    use crate::numbers::Ball;

    fn ball_dual(v: f64, d: f64) -> Dual<Ball> {
        Dual::new(Ball::exact(v, 160), Ball::exact(d, 160))
    }

    /// The derivatives in balls against those of `f64` dual numbers, which run the
    /// numerical algorithms of `special` on duals (an independent computation).
    #[test]
    fn derivatives_agree_with_dual_numbers_through_the_numerical_algorithms() {
        use crate::special;
        for (u, k) in [(0.7, 0.8), (-2.9, 0.35), (5.3, 0.95)] {
            for (du, dk) in [(1.0, 0.0), (0.0, 1.0), (0.3, -0.7)] {
                let (s, c, d) = sncndn(&ball_dual(u, du), &ball_dual(k, dk)).unwrap();
                let (sf, cf, df) = special::sncndn(&Dual::new(u, du), &Dual::new(k, dk)).unwrap();
                for (b, f) in [(s, sf), (c, cf), (d, df)] {
                    assert!(
                        (b.d.mid_f64() - f.d).abs() < 1e-12,
                        "{u} {k}: {:?} {}",
                        b.d,
                        f.d
                    );
                }
            }
            for comp in [false, true] {
                let kk = quarter_period(&ball_dual(k, 1.0), comp).unwrap();
                let f = match comp {
                    false => special::ellipk(&Dual::new(k, 1.0)).unwrap(),
                    true => special::ellipkp(&Dual::new(k, 1.0)).unwrap(),
                };
                assert!(
                    (kk.d.mid_f64() - f.d).abs() < 1e-12,
                    "K' {comp}: {:?} {}",
                    kk.d,
                    f.d
                );
            }
            let phi = ball_dual(u / 2.0, 0.6);
            let fb = ellipf(&phi, &ball_dual(k, -0.4)).unwrap();
            let ff = special::ellipf(&Dual::new(u / 2.0, 0.6), &Dual::new(k, -0.4)).unwrap();
            assert!(
                (fb.d.mid_f64() - ff.d).abs() < 1e-12,
                "F: {:?} {}",
                fb.d,
                ff.d
            );
        }
    }
}
