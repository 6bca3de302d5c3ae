//! The Krawczyk test: existence and uniqueness of a zero of a square system in a box,
//! certified in ball arithmetic ([`Ball`]).
//!
//! For `f: ℝⁿ → ℝⁿ` continuously differentiable on the box `X`, a point `x̃ ∈ X` and any
//! real matrix `Y`, the Krawczyk operator is
//!
//! `K(X) = x̃ − Y·f(x̃) + (I − Y·J(X))·(X − x̃)`
//!
//! where `J(X)` encloses the Jacobian of `f` at every point of `X`.  If `K(X)` lies in
//! the interior of `X`, then `f` has exactly one zero in `X` (and it lies in `K(X)`): the
//! theorem of Krawczyk in the form of Rump, *Verification methods* (Acta Numerica 2010),
//! Theorem 13.1.  Here `f(x̃)` and `J(X)` are evaluated by the caller in balls (every
//! value an enclosure), `Y` is the inverse of the midpoint Jacobian in `f64` (any `Y` is
//! sound; a good one makes `K(X)` small), and the products are formed in balls.
//!
//! ```
//! use eulertop_numerics::linalg::krawczyk::{krawczyk, BallSystem};
//! use eulertop_numerics::numbers::{Ball, Scalar};
//! // x² − 2 = 0
//! struct Root2;
//! impl BallSystem for Root2 {
//!     fn residual(&mut self, x: &[Ball]) -> Result<Vec<Ball>, String> {
//!         Ok(vec![x[0].clone() * x[0].clone() - x[0].from_i64(2)])
//!     }
//!     fn jacobian(&mut self, x: &[Ball]) -> Result<Vec<Vec<Ball>>, String> {
//!         Ok(vec![vec![x[0].from_i64(2) * x[0].clone()]])
//!     }
//! }
//! // a box around the root: certified, and the enclosure holds √2
//! let c = krawczyk(&mut Root2, &[1.4142135], &[1e-6], 128).unwrap();
//! assert!(c.enclosure[0].contains_f64(std::f64::consts::SQRT_2));
//! // a box without a root: no certificate
//! assert!(krawczyk(&mut Root2, &[1.5], &[0.01], 128).is_err());
//! ```

use super::newton::solve;
use crate::numbers::{Ball, Decisions, Scalar};

/// A square system evaluated in balls: every returned ball must enclose the exact value
/// for every argument inside the argument balls.
pub trait BallSystem {
    /// `f(x)` for the balls `x`.
    fn residual(&mut self, x: &[Ball]) -> Result<Vec<Ball>, String>;
    /// An enclosure of the Jacobian `∂fᵢ/∂xⱼ` over the balls `x`.
    fn jacobian(&mut self, x: &[Ball]) -> Result<Vec<Vec<Ball>>, String>;
}

/// A certified zero: the box `center ± radius` holds exactly one zero of the system, and
/// it lies in `enclosure`.
#[derive(Clone, Debug)]
pub struct Certificate {
    /// The box's center (exact).
    pub center: Vec<f64>,
    /// The box's half-widths.
    pub radius: Vec<f64>,
    /// The Krawczyk image `K(X)`, inside the box, which holds the zero.
    pub enclosure: Vec<Ball>,
}

impl Certificate {
    /// The box and the enclosure, one line: "x ∈ [1.41421356237309 +/- 5.1e-20]".
    pub fn describe(&self, names: &[String]) -> String {
        (names.iter().zip(&self.enclosure))
            .map(|(n, b)| format!("{n} ∈ {}", b.show(15)))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// The inverse of the midpoint of `a`, in `f64` (`None` if singular).
fn mid_inverse(a: &[Vec<Ball>]) -> Option<Vec<Vec<f64>>> {
    let n = a.len();
    let m: Vec<Vec<f64>> = a
        .iter()
        .map(|r| r.iter().map(Ball::mid_f64).collect())
        .collect();
    let mut cols = Vec::with_capacity(n);
    for j in 0..n {
        let e = (0..n).map(|i| f64::from(u8::from(i == j))).collect();
        let c = solve(m.clone(), e)?;
        if c.iter().any(|v| !v.is_finite()) {
            return None;
        }
        cols.push(c);
    }
    Some(
        (0..n)
            .map(|i| (0..n).map(|j| cols[j][i]).collect())
            .collect(),
    )
}

/// The Krawczyk test on the box `center ± radius` at `prec` bits: the certificate, or
/// why the test fails (then nothing is claimed: the box may or may not hold a zero).
pub fn krawczyk<S: BallSystem>(
    sys: &mut S,
    center: &[f64],
    radius: &[f64],
    prec: u32,
) -> Result<Certificate, String> {
    let n = center.len();
    let span = Decisions::start();
    let xm: Vec<Ball> = center.iter().map(|&c| Ball::exact(c, prec)).collect();
    let boxes: Vec<Ball> = (center.iter().zip(radius))
        .map(|(&c, &r)| Ball::with_radius(c, r, prec))
        .collect();
    let fm = sys.residual(&xm)?;
    let jx = sys.jacobian(&boxes)?;
    if !span.all_decided() {
        return Err("a comparison could not be decided in balls on the box".into());
    }
    if fm.len() != n || jx.len() != n || jx.iter().any(|r| r.len() != n) {
        return Err("the system is not square".into());
    }
    let y = mid_inverse(&jx).ok_or("the midpoint Jacobian is singular")?;
    let zero = xm[0].zero();
    let mut k = Vec::with_capacity(n);
    for i in 0..n {
        let yb = |j: usize| xm[0].from_f64(y[i][j]);
        let mut ki = xm[i].clone();
        for (j, f) in fm.iter().enumerate() {
            ki = ki - yb(j) * f.clone();
        }
        for j in 0..n {
            // (I − Y·J(X))ᵢⱼ
            let mut c = if i == j { zero.one() } else { zero.clone() };
            for (l, row) in jx.iter().enumerate() {
                c = c - yb(l) * row[j].clone();
            }
            ki = ki + c * (boxes[j].clone() - xm[j].clone());
        }
        k.push(ki);
    }
    if let Some(i) = (0..n).find(|&i| !boxes[i].contains_interior(&k[i])) {
        return Err(format!(
            "K(X) is not inside the box (component {}: {} against radius {:e})",
            i + 1,
            k[i].show(10),
            radius[i]
        ));
    }
    Ok(Certificate {
        center: center.to_vec(),
        radius: radius.to_vec(),
        enclosure: k,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The circle x² + y² = 4 and the line y = x: zeros (±√2, ±√2).
    struct CircleLine;
    impl BallSystem for CircleLine {
        fn residual(&mut self, x: &[Ball]) -> Result<Vec<Ball>, String> {
            let (a, b) = (x[0].clone(), x[1].clone());
            Ok(vec![
                a.clone() * a.clone() + b.clone() * b.clone() - a.from_i64(4),
                b - a,
            ])
        }
        fn jacobian(&mut self, x: &[Ball]) -> Result<Vec<Vec<Ball>>, String> {
            let two = x[0].from_i64(2);
            Ok(vec![
                vec![two.clone() * x[0].clone(), two * x[1].clone()],
                vec![-x[0].one(), x[0].one()],
            ])
        }
    }

    #[test]
    fn a_box_with_a_zero_is_certified_and_one_without_is_not() {
        let s = std::f64::consts::SQRT_2;
        let c = krawczyk(&mut CircleLine, &[s, s], &[1e-9, 1e-9], 128).expect("certified");
        for e in &c.enclosure {
            // the zero is √2: its square holds 2, and the enclosure is far inside the
            // box (radius about the box's radius squared)
            assert!((e.clone() * e.clone()).contains_f64(2.0), "{e:?}");
            assert!(e.rad_f64() < 1e-15, "{e:?}");
        }
        // a box of the same size one thousandth away holds no zero
        assert!(krawczyk(&mut CircleLine, &[s + 1e-3, s], &[1e-9, 1e-9], 128).is_err());
        // a box far too wide to contract: not certified (though it holds a zero)
        assert!(krawczyk(&mut CircleLine, &[s, s], &[2.0, 2.0], 128).is_err());
    }
}
