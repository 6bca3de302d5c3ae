//! Numeric shadows: the value of a symbolic quantity at a few domain points, in MPFR
//! (complex, the ring's precision), with a running bound of the rounding error.
//!
//! Every [`super::Sym`] carries its shadow, computed by the same operations as its
//! exact normal form but independently of it.  Shadows decide signs, branches and
//! comparisons, and check the normal form (an exact zero with a non-zero shadow is an
//! internal error).
//!
//! The error bound is kept as `lscale`: the absolute rounding error at a point is about
//! `2^(lscale − prec)`.  A value is *numerically zero* when it is below
//! `2^(lscale − prec + MARGIN)`.

use rug::{Complex, Float};

/// Bits of slack between the tracked rounding-error bound and what counts as zero.
const MARGIN: f64 = 48.0;

/// Values at the domain points with their error scales.
#[derive(Clone, Debug)]
pub struct Shadow {
    /// The value at each point.
    pub v: Vec<Complex>,
    /// log₂ of the magnitude scale of the rounding error at each point.
    pub lscale: Vec<f64>,
}

/// log₂ |z| (−∞ for 0).
pub fn log2_abs(z: &Complex) -> f64 {
    let a = Float::with_val(64, z.abs_ref());
    if a.is_zero() {
        f64::NEG_INFINITY
    } else if a.is_finite() {
        // exponent-based, exact enough for scales, no overflow
        let (m, e) = a.to_f64_exp();
        m.abs().log2() + e as f64
    } else {
        f64::INFINITY
    }
}

impl Shadow {
    /// Exact leaf values (the scale of each value is its magnitude).
    pub fn leaf(v: Vec<Complex>) -> Shadow {
        let lscale = v.iter().map(|z| log2_abs(z).max(0.0)).collect();
        Shadow { v, lscale }
    }

    /// Leaf values whose own error scale is given.
    pub fn with_scale(v: Vec<Complex>, lscale: Vec<f64>) -> Shadow {
        Shadow { v, lscale }
    }

    /// Number of points.
    pub fn len(&self) -> usize {
        self.v.len()
    }

    /// Are there no points?
    pub fn is_empty(&self) -> bool {
        self.v.is_empty()
    }

    fn zip(
        &self,
        o: &Shadow,
        f: impl Fn(&Complex, &Complex) -> Complex,
        s: impl Fn(f64, f64, &Complex, &Complex) -> f64,
    ) -> Shadow {
        let v: Vec<Complex> = self.v.iter().zip(&o.v).map(|(a, b)| f(a, b)).collect();
        let lscale = (0..v.len())
            .map(|i| s(self.lscale[i], o.lscale[i], &self.v[i], &o.v[i]))
            .collect();
        Shadow { v, lscale }
    }

    /// Pointwise sum.
    pub fn add(&self, o: &Shadow) -> Shadow {
        self.zip(
            o,
            |a, b| Complex::with_val(a.prec(), a + b),
            |x, y, _, _| x.max(y) + 1.0,
        )
    }

    /// Pointwise difference.
    pub fn sub(&self, o: &Shadow) -> Shadow {
        self.zip(
            o,
            |a, b| Complex::with_val(a.prec(), a - b),
            |x, y, _, _| x.max(y) + 1.0,
        )
    }

    /// Pointwise product.
    pub fn mul(&self, o: &Shadow) -> Shadow {
        self.zip(
            o,
            |a, b| Complex::with_val(a.prec(), a * b),
            |x, y, _, _| x + y + 1.0,
        )
    }

    /// Pointwise quotient (an exact zero divisor gives NaN, never a panic).
    pub fn div(&self, o: &Shadow) -> Shadow {
        self.zip(
            o,
            |a, b| Complex::with_val(a.prec(), a / b),
            |x, y, _, b| {
                let lb = log2_abs(b);
                x - lb + (y - lb).max(0.0) + 1.0
            },
        )
    }

    /// Pointwise negation.
    pub fn neg(&self) -> Shadow {
        Shadow {
            v: self
                .v
                .iter()
                .map(|a| Complex::with_val(a.prec(), -a))
                .collect(),
            lscale: self.lscale.clone(),
        }
    }

    /// Pointwise principal square root.
    pub fn sqrt(&self) -> Shadow {
        let v: Vec<Complex> = self
            .v
            .iter()
            .map(|a| Complex::with_val(a.prec(), a.sqrt_ref()))
            .collect();
        let lscale = self
            .lscale
            .iter()
            .zip(&self.v)
            .map(|(&s, a)| {
                let la = log2_abs(a);
                if la.is_finite() {
                    (s - la / 2.0).max(la / 2.0) + 1.0
                } else {
                    s / 2.0
                }
            })
            .collect();
        Shadow { v, lscale }
    }

    /// Scales each point's value by `c` (exactly representable factors keep the scale).
    pub fn scale_by(&self, c: &[Complex]) -> Shadow {
        let v: Vec<Complex> = self
            .v
            .iter()
            .zip(c)
            .map(|(a, b)| Complex::with_val(a.prec(), a * b))
            .collect();
        let lscale = self
            .lscale
            .iter()
            .zip(c)
            .map(|(&s, b)| s + log2_abs(b).max(0.0))
            .collect();
        Shadow { v, lscale }
    }

    /// Is the value at point `i` numerically zero for precision `prec`?
    pub fn is_small(&self, i: usize, prec: u32) -> bool {
        let l = log2_abs(&self.v[i]);
        l == f64::NEG_INFINITY || l < self.lscale[i] - prec as f64 + MARGIN
    }

    /// Are the values numerically zero at every point?
    pub fn all_small(&self, prec: u32) -> bool {
        (0..self.len()).all(|i| self.is_small(i, prec))
    }

    /// Is the value NaN or infinite at some point?
    pub fn has_non_finite(&self) -> bool {
        self.v
            .iter()
            .any(|z| !z.real().is_finite() || !z.imag().is_finite())
    }

    /// Is the value numerically real at point `i` (imaginary part numerically zero)?
    pub fn is_real_at(&self, i: usize, prec: u32) -> bool {
        let im = self.v[i].imag();
        if im.is_zero() {
            return true;
        }
        let l = log2_abs(&Complex::with_val(64, (im, 0)));
        l < self.lscale[i] - prec as f64 + MARGIN
    }

    /// The sign of the real value at point `i`: `Some(±1)`, or `None` when it is
    /// numerically zero or not real.
    pub fn real_sign(&self, i: usize, prec: u32) -> Option<i32> {
        if self.is_small(i, prec) || !self.is_real_at(i, prec) {
            return None;
        }
        let re = self.v[i].real();
        if re.is_sign_negative() {
            Some(-1)
        } else {
            Some(1)
        }
    }

    /// Do the values agree with `o` numerically at every point (relative to the larger
    /// of the two error scales)?
    pub fn agrees(&self, o: &Shadow, prec: u32) -> bool {
        let d = self.sub(o);
        d.all_small(prec)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(x: f64) -> Complex {
        Complex::with_val(256, (x, 0))
    }

    #[test]
    fn arithmetic_and_zero_test() {
        let a = Shadow::leaf(vec![c(1.5), c(-2.0)]);
        let b = Shadow::leaf(vec![c(0.5), c(4.0)]);
        let s = a.add(&b).sub(&b).sub(&a);
        assert!(s.all_small(256));
        let p = a.mul(&b).div(&b);
        assert!(p.agrees(&a, 256));
        assert!(!a.agrees(&b, 256));
        assert_eq!(a.real_sign(0, 256), Some(1));
        assert_eq!(a.real_sign(1, 256), Some(-1));
        let z = a.sub(&a);
        assert_eq!(z.real_sign(0, 256), None);
    }

    #[test]
    fn square_root_and_imaginary_values() {
        let a = Shadow::leaf(vec![c(-4.0)]);
        let r = a.sqrt();
        assert!(!r.is_real_at(0, 256));
        assert_eq!(r.real_sign(0, 256), None);
        let back = r.mul(&r);
        assert!(back.agrees(&a, 256));
    }

    #[test]
    fn a_tiny_but_exact_difference_is_not_zero() {
        // 1 + 2^-100 − 1 is far above the 256-bit rounding level
        let one = c(1.0);
        let mut x = Complex::with_val(256, 1);
        x += Float::with_val(256, Float::u_exp(1, -100));
        let d = Shadow::leaf(vec![x]).sub(&Shadow::leaf(vec![one]));
        assert!(!d.is_small(0, 256));
        assert_eq!(d.real_sign(0, 256), Some(1));
    }
}
