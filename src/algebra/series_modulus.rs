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

impl Series {
    /// `(sn, cn, dn)(self, k)` for a modulus `k(h) = k₀ + O(hᵛ)` that depends on `h`:
    /// the values at the fixed modulus `k₀`, cut at `O(hᵛ)` (see the module).  The
    /// argument's constant term and `k₀` must be real by construction.
    pub(crate) fn sncndn_moving(&self, k: &Series) -> AlgResult<(Series, Series, Series)> {
        let (k0, v) = k.split_modulus()?;
        let u0 = self.coefficient(0).unwrap_or_else(|| self.ring().integer(0));
        if self.valuation() < 0 || !u0.is_real_by_construction() {
            return Err(AlgebraError::NotAlgebraic(
                "sn, cn, dn with a modulus that depends on h, at an argument not known to be real"
                    .into(),
            ));
        }
        let (s, c, d) = self.sncndn(&Series::constant(&k0))?;
        Ok((s.cut(v), c.cut(v), d.cut(v)))
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
