//! Jacobi functions and quarter periods whose modulus depends on `h`, as power series
//! known to the order at which the modulus starts to move.
//!
//! For a real argument `u₀` and a real parameter `m₀ = k₀²`, `sn`, `cn` and `dn` are
//! analytic in `(u, m)` near `(u₀, m₀)`: they solve `y″ = −(1 + m)·y + 2m·y³`
//! (DLMF 22.13.13 and its companions), whose solutions depend analytically on the
//! parameter `m` on every compact interval of `u` where they stay bounded, and for real
//! `u` and real `m` they have no poles (DLMF 22.2, with the reciprocal-modulus and
//! imaginary-modulus transformations 22.17 for `m > 1` and `m < 0`).  So
//! `sn(u(h), k(h)) = sn(u(h), k₀) + O(|k(h)² − k₀²|)`, and where `k(h) − k₀ = O(hᵛ)`
//! the value is `sn(u(h), k₀)`, computed as for a fixed modulus, cut at `O(hᵛ)`.  Only
//! the coefficients below `hᵛ` are claimed; nothing is extrapolated.  This is what a
//! limit statement needs: at `k₀ = 1`, `sn(u, k) → tanh u` and `cn, dn → sech u` as
//! `k → 1` (DLMF 22.5.ii), at an order in `h` that the proof reads off.
//!
//! `K(k)` is analytic in `m` for `m < 1` (DLMF 19.2.8) and `K′(k) = K(k′)` for `m > 0`;
//! at `m₀ = 1` (respectively `0`) it has a logarithmic singularity (DLMF 19.12.1) and no
//! power series: such a value is refused.
//!
//! ```
//! use eulertop::algebra::series::{Series, with_precision};
//! use eulertop::algebra::{Ring, RingOptions};
//! let ring = Ring::new(RingOptions { points: 1, ..Default::default() });
//! with_precision(4, || {
//!     let h = Series::var(&ring);
//!     let one = Series::constant(&ring.integer(1));
//!     // k(h) = 1 − h: at h = 0 the functions are tanh and sech of u₀ = 0
//!     let (s, c, _) = Series::constant(&ring.integer(0)).sncndn(&(one - h)).unwrap();
//!     assert_eq!(s.precision(), 1);
//!     assert_eq!(c.coefficient(0).unwrap().as_rational(), Some(1.into()));
//! });
//! ```

use super::error::{AlgResult, AlgebraError};
use super::series::Series;
use super::sym::Sym;
use crate::numbers::{Dual, DualTriple};

impl Series {
    /// `(sn, cn, dn)(self, k)` for a modulus `k(h) = k₀ + O(hᵛ)` that depends on `h`:
    /// the values at the fixed modulus `k₀`, cut at `O(hᵛ)` (see the module).  The
    /// argument's constant term and `k₀` must be real by construction.
    pub(crate) fn sncndn_moving(&self, k: &Series) -> AlgResult<(Series, Series, Series)> {
        let (k0, v) = k.split_modulus()?;
        let u0 = self
            .coefficient(0)
            .unwrap_or_else(|| self.ring().integer(0));
        if self.valuation() < 0 || !u0.is_real_by_construction() {
            return Err(AlgebraError::NotAlgebraic(
                "sn, cn, dn with a modulus that depends on h, at an argument not known to be real"
                    .into(),
            ));
        }
        let (s, c, d) = self.sncndn(&Series::constant(&k0))?;
        Ok((
            s.at_moving_modulus(k, v),
            c.at_moving_modulus(k, v),
            d.at_moving_modulus(k, v),
        ))
    }

    /// `K(k)` (or `K′(k)` when `complementary`) for a modulus `k(h) = k₀ + O(hᵛ)`:
    /// the value at `k₀` cut at `O(hᵛ)`, where it is analytic in `m = k²` (`m₀ < 1` for
    /// `K`, `m₀ > 0` for `K′`, both proved).
    pub(crate) fn quarter_period_moving(k: &Series, complementary: bool) -> AlgResult<Series> {
        let (k0, v) = k.split_modulus()?;
        let ring = k.ring().clone();
        let m0 = k0.try_mul(&k0)?;
        let (margin, what) = if complementary {
            (m0.clone(), "K'(k) at k^2 = 0")
        } else {
            (ring.integer(1).try_sub(&m0)?, "K(k) at k^2 = 1")
        };
        if !matches!(margin.sign(), Ok(1)) {
            return Err(AlgebraError::NotAlgebraic(format!(
                "{what} or where that is not excluded, for a modulus that depends on h (a logarithmic singularity, no power series)"
            )));
        }
        let q = if complementary {
            ring.quarter_period_prime(&k0)?
        } else {
            ring.quarter_period(&k0)?
        };
        Ok(Series::constant(&q).cut(v))
    }

    /// The constant term `k₀` of a modulus, real by construction, and the exponent `v`
    /// of the first power of `h` at which `k(h) − k₀` may be nonzero.
    fn split_modulus(&self) -> AlgResult<(Sym, i32)> {
        if self.valuation() < 0 || self.precision() <= 0 {
            return Err(AlgebraError::Pole(
                "a modulus with a pole at h = 0 or no known constant term".into(),
            ));
        }
        let k0 = self
            .coefficient(0)
            .unwrap_or_else(|| self.ring().integer(0));
        if !k0.is_real_by_construction() {
            return Err(AlgebraError::NotAlgebraic(
                "a modulus that depends on h whose value at h = 0 is not known to be real".into(),
            ));
        }
        let v = (1..self.precision())
            .find(|&e| self.coefficient(e).is_some_and(|c| !c.is_exact_zero()))
            .unwrap_or(self.precision());
        Ok((k0, v))
    }
}

impl Series {
    /// `(sn, cn, dn)(u, k)` of dual numbers over power series: the `u`-derivatives by
    /// DLMF 22.13.1–3, the `k`-derivatives `2k·∂/∂m` by [`Series::sncndn_dm`] (so only
    /// at moduli tending to 0 or 1 when `k` carries a derivative).
    pub(crate) fn sncndn_dual(u: &Dual<Series>, k: &Dual<Series>) -> AlgResult<DualTriple<Series>> {
        let (s, c, d) = u.v.sncndn(&k.v)?;
        let k2 = k.v.try_mul(&k.v)?;
        let minus = Series::constant(&k.v.ring().integer(-1));
        let mut ds = c.try_mul(&d)?.try_mul(&u.d)?;
        let mut dc = s.try_mul(&d)?.try_mul(&u.d)?.try_mul(&minus)?;
        let mut dd = k2
            .try_mul(&s)?
            .try_mul(&c)?
            .try_mul(&u.d)?
            .try_mul(&minus)?;
        if !k.d.known_zero() {
            let (gs, gc, gd) = u.v.sncndn_dm(&k.v)?;
            let dm = k.v.try_mul(&k.d)?.try_add(&k.v.try_mul(&k.d)?, false)?;
            ds = ds.try_add(&gs.try_mul(&dm)?, false)?;
            dc = dc.try_add(&gc.try_mul(&dm)?, false)?;
            dd = dd.try_add(&gd.try_mul(&dm)?, false)?;
        }
        Ok((Dual::new(s, ds), Dual::new(c, dc), Dual::new(d, dd)))
    }

    /// `∂(sn, cn, dn)/∂m` at `(self, k)` with `m = k²`, for a modulus `k₀ + O(hᵛ)` with
    /// `k₀² = 0` or `1`: the first-order terms of DLMF 22.10.4–6 and 22.10.7–9, in
    /// `s, c = sn, cn(u, 0)` and `T, S = tanh u, sech u`:
    /// * `m₀ = 0`: `(−(u − sc)c/4, (u − sc)s/4, −s²/2)`;
    /// * `m₀ = 1`: `(−(T − uS²)/4, (T²/S − uTS)/4, −(T²/S + uTS)/4)`;
    ///
    /// at `m(h)` they are these plus `O(hᵛ)`, and so cut there.
    pub(crate) fn sncndn_dm(&self, k: &Series) -> AlgResult<(Series, Series, Series)> {
        let (k0, v) = k.split_modulus()?;
        let u0 = self
            .coefficient(0)
            .unwrap_or_else(|| self.ring().integer(0));
        let m0 = k0.try_mul(&k0)?.as_rational();
        let limit = m0.filter(|m| *m == 0 || *m == 1);
        let (Some(m0), true) = (limit, self.valuation() >= 0 && u0.is_real_by_construction())
        else {
            return Err(AlgebraError::NotAlgebraic(
                "the derivative in the modulus of sn, cn, dn of a power series, known only at real arguments and at moduli 0 and 1"
                    .into(),
            ));
        };
        let ring = self.ring().clone();
        let q = |n: i64| Series::constant(&ring.rational(&rug::Rational::from((1, n))));
        let (s, c, _) = self.sncndn(&Series::constant(&ring.integer(i64::from(m0 == 1))))?;
        let out = if m0 == 0 {
            let w = self.try_add_neg(&s.try_mul(&c)?)?;
            (
                w.try_mul(&c)?.try_mul(&q(-4))?,
                w.try_mul(&s)?.try_mul(&q(4))?,
                s.try_mul(&s)?.try_mul(&q(-2))?,
            )
        } else {
            // s = tanh u, c = sech u
            let t2s = s.try_mul(&s)?.try_div(&c)?;
            let uts = self.try_mul(&s)?.try_mul(&c)?;
            let us2 = self.try_mul(&c)?.try_mul(&c)?;
            (
                s.try_add_neg(&us2)?.try_mul(&q(-4))?,
                t2s.try_add_neg(&uts)?.try_mul(&q(4))?,
                t2s.try_add(&uts, false)?.try_mul(&q(-4))?,
            )
        };
        Ok((out.0.cut(v), out.1.cut(v), out.2.cut(v)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::series::with_precision;
    use crate::algebra::{Ring, RingOptions};

    /// `∂(sn, cn, dn)/∂m` at `m₀ ∈ {0, 1}`, against mpmath (`mp.diff` of
    /// `ellipfun(f, u, m)` in `m`, one-sided into `[0, 1]`, 30 digits).
    #[test]
    #[allow(clippy::excessive_precision)]
    fn derivatives_in_the_parameter_agree_with_mpmath() {
        let table: [(i64, f64, [f64; 3]); 4] = [
            (
                0,
                0.7,
                [
                    -0.039633191906875173,
                    0.033382577023824317,
                    -0.20750821427493977,
                ],
            ),
            (
                0,
                -1.3,
                [
                    0.069700117663414711,
                    0.25106696445904224,
                    -0.46422218834223681,
                ],
            ),
            (
                1,
                0.7,
                [
                    -0.040012516032360621,
                    0.030352842531741804,
                    -0.19887893028729219,
                ],
            ),
            (
                1,
                -1.3,
                [
                    0.13176500089982103,
                    0.22378736337810176,
                    -0.50798037641491140,
                ],
            ),
        ];
        for (m0, u, want) in table {
            let ring = Ring::new(RingOptions {
                points: 1,
                ..Default::default()
            });
            let u = ring.indeterminate_f64("u", &[u]).unwrap();
            let k = Series::constant(&ring.integer(m0));
            let got = with_precision(3, || Series::constant(&u).sncndn_dm(&k).unwrap());
            for (g, w) in [got.0, got.1, got.2].iter().zip(want) {
                let g = g.coefficient(0).unwrap().shadows()[0].real().to_f64();
                assert!((g - w).abs() < 1e-14, "m0 = {m0}: {g} against {w}");
            }
        }
    }

    /// A modulus that depends on `h` at a generic `k₀` has no derivative rule here.
    #[test]
    fn a_generic_moving_modulus_has_no_derivative() {
        let ring = Ring::new(RingOptions {
            points: 1,
            ..Default::default()
        });
        let u = ring.indeterminate_f64("u", &[0.3]).unwrap();
        with_precision(3, || {
            let half = Series::constant(&ring.rational(&rug::Rational::from((1, 2))));
            let k = half.try_add(&Series::var(&ring), false).unwrap();
            assert!(Series::constant(&u).sncndn_dm(&k).is_err());
        });
    }
}
