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
//! [`Sym::derivative`] is defined here for that reason: the chain rule through the
//! coordinates once they are declared, else the derivation of module [`super::derive`].

use super::error::{AlgResult, AlgebraError};
use super::ring::{Coordinates, Ring, Stored};
use super::sym::Sym;

/// The coordinates `x` as values in the parameters `p`, and `D⁻¹` once computed.
struct ChangeOfVariables {
    coords: Vec<Sym>,
    params: Vec<Sym>,
    inverse: Option<Vec<Vec<Sym>>>,
}

impl Ring {
    /// Declares that the claim's variables have the values `coords`, which are
    /// expressions in the indeterminates `params` (as many as `coords`): from now on
    /// [`Sym::derivative`] with respect to a coordinate uses the chain rule.
    pub fn set_coordinates(&self, coords: Vec<Sym>, params: Vec<Sym>) -> AlgResult<()> {
        self.set_named_coordinates(coords, Vec::new(), params)
    }

    /// [`Ring::set_coordinates`] with the claim's name of each coordinate, which a
    /// certificate states with the coordinate's value in the parameters (a `coord` line).
    pub fn set_named_coordinates(
        &self,
        coords: Vec<Sym>,
        names: Vec<String>,
        params: Vec<Sym>,
    ) -> AlgResult<()> {
        if coords.len() != params.len() {
            return Err(AlgebraError::Derivative(format!(
                "{} coordinates for {} parameters",
                coords.len(),
                params.len()
            )));
        }
        self.state().coordinates = Some(Coordinates {
            coords: coords.iter().map(Sym::stored).collect(),
            names,
            params: params.iter().map(Sym::stored).collect(),
            inverse: None,
        });
        Ok(())
    }

    /// The declared coordinates, parameters and `D⁻¹` (once computed) as values.
    fn change_of_variables(&self) -> Option<ChangeOfVariables> {
        let c = self.state().coordinates.clone()?;
        let values = |v: Vec<Stored>| -> Vec<Sym> {
            v.into_iter().map(|s| Sym::restored(self, s)).collect()
        };
        Some(ChangeOfVariables {
            coords: values(c.coords),
            params: values(c.params),
            inverse: c.inverse.map(|m| m.into_iter().map(values).collect()),
        })
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
    /// Can derivatives be taken with respect to this value: an indeterminate of the
    /// claim, or one of the declared coordinates or parameters?  (Otherwise it is a
    /// value, such as a function parameter bound to an expression.)
    pub fn is_symbol_of_claim(&self) -> bool {
        let same = |y: &Sym| y.try_sub(self).map(|d| d.is_exact_zero()).unwrap_or(false);
        if let Some(c) = self.ring.change_of_variables()
            && (c.coords.iter().any(same) || c.params.iter().any(same))
        {
            return true;
        }
        self.as_field_var().is_some_and(|j| {
            matches!(
                self.ring.state().vars[j].kind,
                super::ring::VarKind::Indeterminate
            )
        })
    }

    /// The exact derivative with respect to an indeterminate `x`.
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// let ring = Ring::new(RingOptions { points: 2, ..Default::default() });
    /// let u = ring.indeterminate_f64("u", &[0.3, 0.9]).unwrap();
    /// let k = ring.indeterminate_f64("k", &[0.6, 0.3]).unwrap();
    /// let (s, c, d) = u.sncndn(&k).unwrap();
    /// let ds = s.derivative(&u).unwrap();
    /// assert!(ring.prove(&ds, &(c * d)).is_proved()); // DLMF 22.13.1
    /// ```
    pub fn derivative(&self, x: &Sym) -> AlgResult<Sym> {
        if let Some(c) = self.ring.change_of_variables() {
            return self.derivative_in_coordinates(x, c);
        }
        self.derivative_plain(x)
    }

    /// `∂self/∂x` by the chain rule through the ring's declared coordinates, where `x`
    /// is one of them (or, if `x` is one of the parameters, at fixed other parameters).
    fn derivative_in_coordinates(&self, x: &Sym, c: ChangeOfVariables) -> AlgResult<Sym> {
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
        // x is also a parameter and no other coordinate depends on it: the Jacobian is
        // the identity in x's row and column, so the derivative at fixed other
        // coordinates is the one at fixed other parameters
        if c.params.iter().any(same) {
            let mut alone = true;
            for (j, xj) in c.coords.iter().enumerate() {
                if j != i && !xj.derivative_plain(x)?.is_exact_zero() {
                    alone = false;
                    break;
                }
            }
            if alone {
                return self.derivative_plain(x);
            }
        }
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
                    st.inverse = Some(
                        inv.iter()
                            .map(|r| r.iter().map(Sym::stored).collect())
                            .collect(),
                    );
                }
                inv
            }
        };
        // Σⱼ ∂self/∂pⱼ · (J⁻¹)ⱼᵢ, over one common denominator
        let mut parts = Vec::new();
        for (j, p) in c.params.iter().enumerate() {
            if !inv[j][i].is_exact_zero() {
                parts.push((self.derivative_plain(p)?, &inv[j][i]));
            }
        }
        if parts.is_empty() {
            return Ok(self.zero_like());
        }
        let terms: Vec<(&Sym, &Sym, bool)> = parts.iter().map(|(d, m)| (d, *m, false)).collect();
        Sym::try_sum_of_products(&terms)
    }

    fn zero_like(&self) -> Sym {
        self.ring().integer(0)
    }

    fn one_like(&self) -> Sym {
        self.ring().integer(1)
    }
}
