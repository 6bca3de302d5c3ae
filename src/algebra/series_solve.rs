//! The power-series root of a system `E(x, h) = 0` continuous at `h = 0`: the
//! implicit function theorem, coefficient by coefficient.
//!
//! Given `x₀` with `E(x₀(0), 0) = 0` (checked exactly) and `L = ∂E/∂x (x₀(0), 0)` with a
//! determinant of proved sign, the iteration `x ← x − L⁻¹E(x, h)` gains at least one
//! order of `h` per step.  It stops when `x` no longer changes at the working precision
//! ([`super::series::with_precision`]); then `E(x, h) = O(hⁿ)` and `x` is the unique
//! power-series solution with `x(0) = x₀(0)`, the Taylor series of the analytic solution
//! that the implicit function theorem gives for small `h`.
//!
//! ```
//! use eulertop::algebra::series::{Series, with_precision};
//! use eulertop::algebra::series_solve::solve;
//! use eulertop::algebra::{Ring, RingOptions};
//! use eulertop::numbers::Scalar;
//! let ring = Ring::new(RingOptions { points: 1, ..Default::default() });
//! with_precision(4, || {
//!     let h = Series::var(&ring);
//!     // x² + h·x − 1 = 0 from x = 1: x = 1 − h/2 + h²/8 + O(h⁴)
//!     let e = |x: &[Series], hh: &Series| Ok(vec![x[0].clone() * x[0].clone() + hh.clone() * x[0].clone() - h.one()]);
//!     let x = solve(vec![h.one()], &e, &h).unwrap();
//!     assert_eq!(x[0].coefficient(1).unwrap().as_rational(), Some(rug::Rational::from((-1, 2))));
//!     assert_eq!(x[0].coefficient(2).unwrap().as_rational(), Some(rug::Rational::from((1, 8))));
//! });
//! ```

use super::series::Series;
use super::sym::Sym;
use crate::linalg::Mat3;
use crate::numbers::Scalar;

/// The equations `E(x, h)` of a system, as components.
pub type Equations<'a> = dyn Fn(&[Series], &Series) -> Result<Vec<Series>, String> + 'a;

/// The power-series root of `e(x, h) = 0` with `x(0) = x0(0)` (see the module doc), for
/// equations whose other arguments do not depend on `h`.
pub fn solve(x0: Vec<Series>, e: &Equations<'_>, h: &Series) -> Result<Vec<Series>, String> {
    solve_at(x0, e, e, h)
}

/// [`solve`] where the equations' other arguments may depend on `h`: `at_zero` is `e`
/// with those arguments at `h = 0` (their constant terms), from which the linearization
/// `L = ∂E/∂x (x₀(0), 0)` is taken (with `e` itself, the perturbation of `x` and the
/// arguments' own `h` would share one series variable).
pub fn solve_at(
    x0: Vec<Series>,
    e: &Equations<'_>,
    at_zero: &Equations<'_>,
    h: &Series,
) -> Result<Vec<Series>, String> {
    let inv = linearization_inverse(&x0, at_zero, h)?;
    let mut x = x0;
    let rounds = h.precision().max(1) + 2;
    for _ in 0..rounds {
        let r = e(&x, h)?;
        let next: Vec<Series> = (0..x.len())
            .map(|i| {
                let step = (0..x.len()).fold(h.zero(), |acc, j| {
                    acc + Series::constant(&inv[i][j]) * r[j].clone()
                });
                x[i].clone() - step
            })
            .collect();
        failed(h)?;
        if next == x {
            return Ok(x);
        }
        x = next;
    }
    Err(format!(
        "the power series of the map's root did not settle in {rounds} steps"
    ))
}

/// `L⁻¹` for `L = ∂E/∂x (x₀(0), 0)`, after checking `E(x₀(0), 0) = 0` exactly and that
/// `det L` has a proved sign.
fn linearization_inverse(
    x0: &[Series],
    e: &Equations<'_>,
    h: &Series,
) -> Result<Vec<Vec<Sym>>, String> {
    let n = x0.len();
    if n != 1 && n != 3 {
        return Err(format!(
            "a system of {n} unknowns (1 or 3 are solved as series)"
        ));
    }
    let base: Vec<Series> = x0
        .iter()
        .map(|x| Series::constant(&x.coefficient(0).unwrap_or_else(|| x.ring().integer(0))))
        .collect();
    let t = Series::var(h.ring());
    let zero = h.zero();
    let mut cols = Vec::new();
    for j in 0..n {
        let mut xj = base.clone();
        xj[j] = xj[j].clone() + t.clone();
        let r = e(&xj, &zero)?;
        failed(h)?;
        if r.iter().any(|c| c.valuation() < 1) {
            return Err("the map's equations do not hold at h = 0 at the starting value".into());
        }
        cols.push(
            r.iter()
                .map(|c| c.coefficient(1).ok_or("no linear term"))
                .collect::<Result<Vec<Sym>, _>>()?,
        );
    }
    let l = |i: usize, j: usize| cols[j][i].clone();
    if n == 1 {
        nonzero(&l(0, 0))?;
        return Ok(vec![vec![l(0, 0).one() / l(0, 0)]]);
    }
    let m = Mat3::from_fn(l);
    nonzero(&m.det())?;
    let inv = m
        .inverse()
        .ok_or("the linearization at h = 0 is singular")?;
    Ok(inv.0.iter().map(|row| row.to_vec()).collect())
}

/// A proved nonzero sign on the whole domain.
fn nonzero(d: &Sym) -> Result<(), String> {
    match d.sign() {
        Ok(0) => Err("the linearization at h = 0 is singular".into()),
        Ok(_) => Ok(()),
        Err(e) => Err(format!("the linearization at h = 0: {e}")),
    }
}

/// The ring's first error, if any.
fn failed(h: &Series) -> Result<(), String> {
    match h.ring().error() {
        Some(e) => Err(e.to_string()),
        None => Ok(()),
    }
}
