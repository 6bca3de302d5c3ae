//! Small square systems over any ordered [`Scalar`]: Gaussian elimination with partial
//! pivoting ([`solve`]) and Newton's method ([`newton`]) with the stopping rule the claim
//! engine uses (two consecutive steps at working precision, or an exact zero).
//!
//! ```
//! use eulertop_numerics::linalg::newton::{newton, Limits, System};
//! // x² − 2 = 0 from x = 1
//! struct Root2;
//! impl System<f64> for Root2 {
//!     type Error = String;
//!     fn residual(&mut self, x: &[f64]) -> Result<Vec<f64>, String> {
//!         Ok(vec![x[0] * x[0] - 2.0])
//!     }
//!     fn jacobian(&mut self, x: &[f64]) -> Result<Vec<Vec<f64>>, String> {
//!         Ok(vec![vec![2.0 * x[0]]])
//!     }
//! }
//! let run = newton(&mut Root2, vec![1.0], Limits::default()).unwrap();
//! assert!((run.x[0] - 2f64.sqrt()).abs() < 1e-15);
//! assert!(run.best_log2 < -50.0);
//! ```

use crate::numbers::Scalar;

/// `|x|` from the order alone (exact for every ordered scalar).
fn abs<T: Scalar + PartialOrd>(x: &T) -> T {
    if *x < x.zero() { -x.clone() } else { x.clone() }
}

/// Solves `a·x = b` by Gaussian elimination with partial pivoting; `None` when a pivot
/// is exactly zero (a singular matrix).
///
/// ```
/// use eulertop_numerics::linalg::newton::solve;
/// let x = solve(vec![vec![2.0, 1.0], vec![1.0, 3.0]], vec![3.0, 5.0]).unwrap();
/// assert_eq!(x, vec![0.8, 1.4]);
/// ```
pub fn solve<T: Scalar + PartialOrd>(mut a: Vec<Vec<T>>, mut b: Vec<T>) -> Option<Vec<T>> {
    let n = b.len();
    for c in 0..n {
        let mut piv = c;
        for r in c + 1..n {
            if abs(&a[r][c]) > abs(&a[piv][c]) {
                piv = r;
            }
        }
        if a[piv][c].is_zero() {
            return None;
        }
        a.swap(c, piv);
        b.swap(c, piv);
        for r in c + 1..n {
            let f = a[r][c].clone() / a[c][c].clone();
            let pivot_row = a[c].clone();
            for (k, pk) in pivot_row.iter().enumerate().skip(c) {
                let t = pk.clone() * f.clone();
                a[r][k] = a[r][k].clone() - t;
            }
            let t = b[c].clone() * f;
            b[r] = b[r].clone() - t;
        }
    }
    let mut x = b.clone();
    for c in (0..n).rev() {
        let mut s = b[c].clone();
        for k in c + 1..n {
            s = s - a[c][k].clone() * x[k].clone();
        }
        x[c] = s / a[c][c].clone();
    }
    Some(x)
}

/// A square system `F(x) = 0` for [`newton`].
pub trait System<T> {
    /// Why `F` or its Jacobian could not be evaluated.
    type Error;
    /// `F(x)`.
    fn residual(&mut self, x: &[T]) -> Result<Vec<T>, Self::Error>;
    /// The Jacobian `∂F_i/∂x_j` at `x` (called right after [`System::residual`] at the
    /// same `x`).
    fn jacobian(&mut self, x: &[T]) -> Result<Vec<Vec<T>>, Self::Error>;
}

/// Limits of [`newton`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    /// Most iterations.
    pub max_iter: usize,
    /// Working precision in bits: a step below `2^(4 − bits)` relative to `max(|x|, 1)`
    /// is "at working precision".
    pub bits: u32,
    /// Stop after this many steps at working precision.
    pub small_steps: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_iter: 100,
            bits: 53,
            small_steps: 2,
        }
    }
}

/// The last iterate and the smallest residual seen.
#[derive(Clone, Debug, PartialEq)]
pub struct Run<T> {
    /// The last iterate.
    pub x: Vec<T>,
    /// min over iterations of `max_i log2 |F_i(x)|` (−∞: an exact zero).
    pub best_log2: f64,
}

/// Why [`newton`] stopped without an iterate.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum NewtonError<E> {
    /// A Jacobian with an exactly zero pivot.
    #[error("singular Jacobian in Newton's method")]
    Singular,
    /// The system could not be evaluated.
    #[error("{0}")]
    System(E),
}

/// Newton's method from `x0`: iterates `x ← x − J⁻¹F(x)` until `F` is exactly zero,
/// [`Limits::small_steps`] steps were at working precision, or [`Limits::max_iter`]
/// iterations were done.  The caller judges convergence from [`Run::best_log2`].
pub fn newton<T, S>(
    system: &mut S,
    x0: Vec<T>,
    limits: Limits,
) -> Result<Run<T>, NewtonError<S::Error>>
where
    T: Scalar + PartialOrd,
    S: System<T>,
{
    let prec = f64::from(limits.bits);
    let mut x = x0;
    let mut best = f64::INFINITY;
    let mut small_steps = 0;
    for _ in 0..limits.max_iter {
        let f = system.residual(&x).map_err(NewtonError::System)?;
        let r = f
            .iter()
            .map(|v| v.log2_abs())
            .fold(f64::NEG_INFINITY, f64::max);
        best = best.min(r);
        if r == f64::NEG_INFINITY || small_steps >= limits.small_steps {
            break;
        }
        let a = system.jacobian(&x).map_err(NewtonError::System)?;
        let dx = solve(a, f).ok_or(NewtonError::Singular)?;
        let mut step = f64::NEG_INFINITY;
        let mut size = 0.0f64;
        for (xi, di) in x.iter_mut().zip(&dx) {
            *xi = xi.clone() - di.clone();
            step = step.max(di.log2_abs());
            size = size.max(xi.log2_abs());
        }
        if step <= size.max(0.0) - prec + 4.0 {
            small_steps += 1;
        }
    }
    Ok(Run { x, best_log2: best })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numbers::Rational;

    #[test]
    fn solve_is_exact_over_rationals_and_detects_singularity() {
        let q = |n: i64| Rational::from_integer(n.into());
        // [[1, 2], [3, 4]] x = [5, 6]  ⇒  x = (−4, 9/2)
        let x = solve(vec![vec![q(1), q(2)], vec![q(3), q(4)]], vec![q(5), q(6)]).unwrap();
        assert_eq!(x, vec![q(-4), Rational::new(9.into(), 2.into())]);
        assert!(solve(vec![vec![q(1), q(2)], vec![q(2), q(4)]], vec![q(1), q(1)]).is_none());
    }

    struct Line;
    impl System<f64> for Line {
        type Error = ();
        fn residual(&mut self, x: &[f64]) -> Result<Vec<f64>, ()> {
            Ok(vec![x[0] - 3.0])
        }
        fn jacobian(&mut self, _x: &[f64]) -> Result<Vec<Vec<f64>>, ()> {
            Ok(vec![vec![0.0]])
        }
    }

    #[test]
    fn singular_jacobian_is_an_error() {
        assert_eq!(
            newton(&mut Line, vec![1.0], Limits::default()),
            Err(NewtonError::Singular)
        );
    }
}
