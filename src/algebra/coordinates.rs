//! Derivatives after a change of variables.
//!
//! When a proof replaces a claim's variables `x = (x₁ … xₙ)` by expressions in new
//! indeterminates `p = (p₁ … pₙ)` (a parametrization of an implicit map's solutions),
//! a derivative `∂f/∂xᵢ` at fixed other `x` is no longer the derivation with respect
//! to one indeterminate.  With the Jacobian `Dᵢⱼ = ∂xᵢ/∂pⱼ`, the chain rule gives
//! `∂f/∂xᵢ = Σⱼ ∂f/∂pⱼ · (D⁻¹)ⱼᵢ`.  The ring keeps the coordinates and `D⁻¹` (computed
//! once, by Gaussian elimination in the tower); once coordinates are declared, every
//! derivative goes through them, so a derivative with respect to an indeterminate that
//! a replacement depends on is never taken at fixed parameters by mistake.

use super::error::{AlgResult, AlgebraError};
use super::ring::Ring;
use super::sym::Sym;

/// The coordinates `x` as values in the parameters `p`, and `D⁻¹` once computed.
#[derive(Clone, Default)]
pub(crate) struct Coordinates {
    pub coords: Vec<Sym>,
    pub params: Vec<Sym>,
    pub inverse: Option<Vec<Vec<Sym>>>,
}

impl Ring {
    /// Declares that the claim's variables have the values `coords`, which are
    /// expressions in the indeterminates `params` (as many as `coords`): from now on
    /// [`Sym::derivative`] with respect to a coordinate uses the chain rule.
    pub fn set_coordinates(&self, coords: Vec<Sym>, params: Vec<Sym>) -> AlgResult<()> {
        if coords.len() != params.len() {
            return Err(AlgebraError::Derivative(format!(
                "{} coordinates for {} parameters",
                coords.len(),
                params.len()
            )));
        }
        self.state().coordinates = Some(Coordinates {
            coords,
            params,
            inverse: None,
        });
        Ok(())
    }

    pub(crate) fn change_of_variables(&self) -> Option<Coordinates> {
        self.state().coordinates.clone()
    }
}

/// The inverse of a square matrix of tower elements, by Gauss–Jordan elimination with
/// pivots that are not 0 (exactly).
fn inverse(m: &[Vec<Sym>]) -> AlgResult<Vec<Vec<Sym>>> {
    let n = m.len();
    let zero = m[0][0].zero_like();
    let one = m[0][0].one_like();
    let mut a: Vec<Vec<Sym>> = m
        .iter()
        .enumerate()
        .map(|(i, row)| {
            let mut r = row.clone();
            r.extend((0..n).map(|j| if i == j { one.clone() } else { zero.clone() }));
            r
        })
        .collect();
    for col in 0..n {
        let pivot = (col..n)
            .find(|&r| !a[r][col].is_exact_zero())
            .ok_or_else(|| {
                AlgebraError::Derivative(
                    "the change of variables is singular (its Jacobian determinant is 0)".into(),
                )
            })?;
        a.swap(col, pivot);
        let p = a[col][col].clone();
        a[col] = a[col]
            .iter()
            .map(|x| x.try_div(&p))
            .collect::<AlgResult<_>>()?;
        for r in 0..n {
            if r != col && !a[r][col].is_exact_zero() {
                let f = a[r][col].clone();
                let pivot_row = a[col].clone();
                for (x, y) in a[r].iter_mut().zip(&pivot_row) {
                    *x = x.try_sub(&f.try_mul(y)?)?;
                }
            }
        }
    }
    Ok(a.into_iter().map(|r| r[n..].to_vec()).collect())
}

impl Sym {
    /// `∂self/∂x` by the chain rule through the ring's declared coordinates, where `x`
    /// is one of them (or, if `x` is one of the parameters, at fixed other parameters).
    pub(crate) fn derivative_in_coordinates(&self, x: &Sym, c: Coordinates) -> AlgResult<Sym> {
        let ring = self.ring().clone();
        let same = |y: &Sym| y.try_sub(x).map(|d| d.is_exact_zero()).unwrap_or(false);
        let Some(i) = c.coords.iter().position(same) else {
            // a parameter itself: the derivative at fixed other parameters
            if c.params.iter().any(same) {
                return self.derivative_plain(x);
            }
            return Err(AlgebraError::Derivative(format!(
                "{} is not one of the claim's variables after the change of variables",
                x.render_short(60)
            )));
        };
        let inv = match c.inverse {
            Some(inv) => inv,
            None => {
                let jac: Vec<Vec<Sym>> = c
                    .coords
                    .iter()
                    .map(|xi| {
                        c.params
                            .iter()
                            .map(|p| xi.derivative_plain(p))
                            .collect::<AlgResult<_>>()
                    })
                    .collect::<AlgResult<_>>()?;
                let inv = inverse(&jac)?;
                if let Some(st) = ring.state().coordinates.as_mut() {
                    st.inverse = Some(inv.clone());
                }
                inv
            }
        };
        let mut out = self.zero_like();
        for (j, p) in c.params.iter().enumerate() {
            if !inv[j][i].is_exact_zero() {
                out = out.try_add(&self.derivative_plain(p)?.try_mul(&inv[j][i])?)?;
            }
        }
        Ok(out)
    }

    fn zero_like(&self) -> Sym {
        self.ring().integer(0)
    }

    fn one_like(&self) -> Sym {
        self.ring().integer(1)
    }
}
