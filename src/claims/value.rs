//! Values of the expression language: real, complex, vec3, mat3, cmat2, bool, over any
//! scalar backend, with the arithmetic of the language (type errors are `Err`, never
//! panics).  Vectors and matrices are the [`crate::linalg`] types, so products,
//! determinants and commutators are written once, there.

use super::backend::{Num, RealFn2};
use super::cmath;
use crate::linalg::{Mat2, Mat3, Vec3};
use crate::numbers::Cplx;

/// A value of the language.
#[derive(Clone, Debug, PartialEq)]
pub enum Value<T> {
    /// A real number.
    Real(T),
    /// A complex number.
    Complex(Cplx<T>),
    /// A real 3-vector.
    Vec3(Vec3<T>),
    /// A real 3×3 matrix (row-major).
    Mat3(Mat3<T>),
    /// A complex 2×2 matrix (row-major).
    CMat2(Mat2<Cplx<T>>),
    /// A truth value.
    Bool(bool),
}

impl<T> Value<T> {
    /// The type name, for messages.
    pub fn type_name(&self) -> &'static str {
        match self {
            Value::Real(_) => "real",
            Value::Complex(_) => "complex",
            Value::Vec3(_) => "vec3",
            Value::Mat3(_) => "mat3",
            Value::CMat2(_) => "cmat2",
            Value::Bool(_) => "bool",
        }
    }
}

/// How [`Value::render`] lays out vectors and matrices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layout {
    /// One line: vectors as `(a, b, c)`, matrices as `[[…], […]]` (evidence in reports).
    Inline,
    /// Vectors as `[a, b, c]`, matrices one row per line (the `eval` command).
    Rows,
}

/// The largest integer magnitude [`Value::as_int`] accepts.
pub const MAX_INT: f64 = 1e15;

impl<T: Num> Value<T> {
    /// Decimal rendering with `digits` significant digits in the given layout.
    pub fn render(&self, digits: usize, layout: Layout) -> String {
        let d = |x: &T| x.to_decimal(digits);
        // a − bi for a negative imaginary part (not a + -bi)
        let c = |z: &Cplx<T>| {
            let im = d(&z.im);
            match im.strip_prefix('-') {
                Some(b) => format!("{} - {b}i", d(&z.re)),
                None => format!("{} + {im}i", d(&z.re)),
            }
        };
        let rows = |rs: Vec<String>| match layout {
            Layout::Inline => format!("[{}]", rs.join(", ")),
            Layout::Rows => rs.join("\n"),
        };
        match self {
            Value::Real(x) => d(x),
            Value::Bool(b) => b.to_string(),
            Value::Complex(z) => c(z),
            Value::Vec3(Vec3(a)) => {
                let (open, close) = match layout {
                    Layout::Inline => ("(", ")"),
                    Layout::Rows => ("[", "]"),
                };
                format!("{open}{}, {}, {}{close}", d(&a[0]), d(&a[1]), d(&a[2]))
            }
            Value::Mat3(Mat3(m)) => rows(
                m.iter()
                    .map(|r| format!("[{}, {}, {}]", d(&r[0]), d(&r[1]), d(&r[2])))
                    .collect(),
            ),
            Value::CMat2(Mat2(m)) => rows(
                m.iter()
                    .map(|r| format!("[{}, {}]", c(&r[0]), c(&r[1])))
                    .collect(),
            ),
        }
    }

    /// The real number, or a type error.
    pub fn as_real(&self) -> Result<T, String> {
        match self {
            Value::Real(x) => Ok(x.clone()),
            v => Err(format!("expected a real, got a {}", v.type_name())),
        }
    }
    /// The value as a complex number (reals promoted).
    pub fn as_complex(&self) -> Result<Cplx<T>, String> {
        match self {
            Value::Real(x) => Ok(cmath::real(x.clone())),
            Value::Complex(z) => Ok(z.clone()),
            v => Err(format!(
                "expected a complex number, got a {}",
                v.type_name()
            )),
        }
    }
    /// The 3-vector, or a type error.
    pub fn as_vec3(&self) -> Result<Vec3<T>, String> {
        match self {
            Value::Vec3(v) => Ok(v.clone()),
            v => Err(format!("expected a vec3, got a {}", v.type_name())),
        }
    }
    /// The 3×3 matrix, or a type error.
    pub fn as_mat3(&self) -> Result<Mat3<T>, String> {
        match self {
            Value::Mat3(m) => Ok(m.clone()),
            v => Err(format!("expected a mat3, got a {}", v.type_name())),
        }
    }
    /// The complex 2×2 matrix, or a type error.
    pub fn as_cmat2(&self) -> Result<Mat2<Cplx<T>>, String> {
        match self {
            Value::CMat2(m) => Ok(m.clone()),
            v => Err(format!("expected a cmat2, got a {}", v.type_name())),
        }
    }
    /// The truth value, or a type error.
    pub fn as_bool(&self) -> Result<bool, String> {
        match self {
            Value::Bool(b) => Ok(*b),
            v => Err(format!("expected a bool, got a {}", v.type_name())),
        }
    }
    /// An exact integer of magnitude at most [`MAX_INT`] (for indices, loop bounds,
    /// integer powers).
    pub fn as_int(&self) -> Result<i64, String> {
        let x = self.as_real()?;
        let f = x.to_f64();
        let exact = f.is_finite() && f.fract() == 0.0 && (x.clone() - x.from_f64(f)).is_zero();
        if !exact {
            return Err(format!("expected an integer, got {f}"));
        }
        if f.abs() > MAX_INT {
            return Err(format!(
                "integer {f:e} is too large (at most {MAX_INT:e} in magnitude)"
            ));
        }
        Ok(f as i64)
    }
    /// All scalar components (complex as two), for magnitudes and finiteness.
    pub fn components(&self) -> Vec<T> {
        match self {
            Value::Real(x) => vec![x.clone()],
            Value::Complex(z) => vec![z.re.clone(), z.im.clone()],
            Value::Vec3(v) => v.0.to_vec(),
            Value::Mat3(m) => m.0.iter().flatten().cloned().collect(),
            Value::CMat2(m) => {
                m.0.iter()
                    .flatten()
                    .flat_map(|z| [z.re.clone(), z.im.clone()])
                    .collect()
            }
            Value::Bool(_) => vec![],
        }
    }
    /// Largest component modulus (complex entries by modulus), as f64.
    pub fn magnitude(&self) -> f64 {
        match self {
            Value::Complex(z) => cmath::magnitude(z),
            Value::CMat2(m) => {
                m.0.iter()
                    .flatten()
                    .map(cmath::magnitude)
                    .fold(0.0, f64::max)
            }
            Value::Bool(b) => f64::from(u8::from(*b)),
            v => v
                .components()
                .iter()
                .map(|x| x.magnitude())
                .fold(0.0, f64::max),
        }
    }
    /// `max log2 |component|` (−∞ when every component is zero): the size of a value at
    /// any precision, without underflow.
    pub fn log2_magnitude(&self) -> f64 {
        self.components()
            .iter()
            .map(|c| c.log2_abs())
            .fold(f64::NEG_INFINITY, f64::max)
    }
    /// Are all components finite?
    pub fn is_finite(&self) -> bool {
        self.all_components(&mut |x: &T| x.is_finite())
    }
    /// Does `f` hold for every scalar component (complex parts included)?  Stops at
    /// the first that fails; copies nothing, unlike [`Value::components`].
    pub fn all_components(&self, f: &mut dyn FnMut(&T) -> bool) -> bool {
        match self {
            Value::Real(x) => f(x),
            Value::Complex(z) => f(&z.re) && f(&z.im),
            Value::Vec3(v) => v.0.iter().all(&mut *f),
            Value::Mat3(m) => m.0.iter().flatten().all(&mut *f),
            Value::CMat2(m) => m.0.iter().flatten().all(|z| f(&z.re) && f(&z.im)),
            Value::Bool(_) => true,
        }
    }
    /// Maps every scalar component (complex parts included).
    pub fn map<U: Num>(&self, f: &mut dyn FnMut(&T) -> U) -> Value<U> {
        let mut cx = |z: &Cplx<T>| Cplx::new(f(&z.re), f(&z.im));
        match self {
            Value::Real(x) => Value::Real(f(x)),
            Value::Complex(z) => Value::Complex(cx(z)),
            Value::Vec3(v) => Value::Vec3(Vec3([f(&v.0[0]), f(&v.0[1]), f(&v.0[2])])),
            Value::Mat3(m) => Value::Mat3(Mat3(std::array::from_fn(|i| {
                std::array::from_fn(|j| f(&m.0[i][j]))
            }))),
            Value::CMat2(m) => {
                let a = cx(&m.0[0][0]);
                let b = cx(&m.0[0][1]);
                let c = cx(&m.0[1][0]);
                let d = cx(&m.0[1][1]);
                Value::CMat2(Mat2([[a, b], [c, d]]))
            }
            Value::Bool(b) => Value::Bool(*b),
        }
    }

    /// `self + o`.
    pub fn add(&self, o: &Self) -> Result<Self, String> {
        self.zip(o, "+", false)
    }
    /// `self - o`.
    pub fn sub(&self, o: &Self) -> Result<Self, String> {
        self.zip(o, "-", true)
    }
    fn zip(&self, o: &Self, op: &str, minus: bool) -> Result<Self, String> {
        fn pm<X: std::ops::Add<Output = X> + std::ops::Sub<Output = X>>(
            a: X,
            b: X,
            minus: bool,
        ) -> X {
            if minus { a - b } else { a + b }
        }
        Ok(match (self, o) {
            (Value::Real(a), Value::Real(b)) => Value::Real(pm(a.clone(), b.clone(), minus)),
            (Value::Real(_) | Value::Complex(_), Value::Real(_) | Value::Complex(_)) => {
                Value::Complex(pm(self.as_complex()?, o.as_complex()?, minus))
            }
            (Value::Vec3(a), Value::Vec3(b)) => Value::Vec3(pm(a.clone(), b.clone(), minus)),
            (Value::Mat3(a), Value::Mat3(b)) => Value::Mat3(pm(a.clone(), b.clone(), minus)),
            (Value::CMat2(a), Value::CMat2(b)) => Value::CMat2(pm(a.clone(), b.clone(), minus)),
            _ => {
                return Err(format!(
                    "cannot apply '{op}' to a {} and a {}",
                    self.type_name(),
                    o.type_name()
                ));
            }
        })
    }
    /// `-self`.
    pub fn neg(&self) -> Result<Self, String> {
        match self {
            Value::Bool(_) => Err("cannot negate a bool".into()),
            v => Ok(v.map(&mut |x: &T| -x.clone())),
        }
    }
    fn scale_complex(&self, s: &Cplx<T>) -> Result<Self, String> {
        match self {
            Value::Real(x) => Ok(Value::Complex(cmath::scale(s, x))),
            Value::Complex(z) => Ok(Value::Complex(s.clone() * z.clone())),
            Value::CMat2(m) => Ok(Value::CMat2(Mat2::from_fn(|i, j| {
                s.clone() * m.0[i][j].clone()
            }))),
            v => Err(format!(
                "cannot multiply a {} by a complex number",
                v.type_name()
            )),
        }
    }
    /// `self * o`: scalar·anything, matrix·matrix, matrix·vector.
    pub fn mul(&self, o: &Self) -> Result<Self, String> {
        match (self, o) {
            (Value::Real(s), v) | (v, Value::Real(s)) if !matches!(v, Value::Bool(_)) => {
                Ok(v.map(&mut |x: &T| s.clone() * x.clone()))
            }
            (Value::Complex(s), v) | (v, Value::Complex(s)) => v.scale_complex(s),
            (Value::Mat3(a), Value::Mat3(b)) => Ok(Value::Mat3(a.clone() * b.clone())),
            (Value::Mat3(a), Value::Vec3(v)) => Ok(Value::Vec3(a.mul_vec(v))),
            (Value::CMat2(a), Value::CMat2(b)) => Ok(Value::CMat2(a.clone() * b.clone())),
            _ => Err(format!(
                "cannot multiply a {} by a {} (use dot/cross for vectors)",
                self.type_name(),
                o.type_name()
            )),
        }
    }
    /// `self / o` for a real or complex scalar `o`.
    pub fn div(&self, o: &Self) -> Result<Self, String> {
        match o {
            Value::Real(s) => {
                if s.is_zero() {
                    return Err("division by zero".into());
                }
                match self {
                    Value::Bool(_) => Err("cannot divide a bool".into()),
                    v => Ok(v.map(&mut |x: &T| x.clone() / s.clone())),
                }
            }
            Value::Complex(s) => {
                let inv = cmath::div(&cmath::real(s.re.one()), s)?;
                self.scale_complex(&inv)
            }
            _ => Err(format!("cannot divide by a {}", o.type_name())),
        }
    }
    /// The multiplicative identity of this value's type (scalars and square matrices).
    fn one(&self) -> Result<Self, String> {
        Ok(match self {
            Value::Real(x) => Value::Real(x.one()),
            Value::Complex(z) => Value::Complex(cmath::real(z.re.one())),
            Value::Mat3(m) => Value::Mat3(Mat3::identity(&m.0[0][0])),
            Value::CMat2(m) => {
                let z = &m.0[0][0].re;
                Value::CMat2(Mat2::from_fn(|i, j| {
                    cmath::real(if i == j { z.one() } else { z.zero() })
                }))
            }
            v => return Err(format!("cannot raise a {} to a power", v.type_name())),
        })
    }
    /// `self ^ o`: integer powers of scalars and square matrices by repeated
    /// multiplication (negative powers of scalars invert); real powers of positive reals.
    pub fn pow(&self, o: &Self) -> Result<Self, String> {
        if let Ok(n) = o.as_int() {
            if n.unsigned_abs() > 1 << 20 {
                return Err(format!("exponent {n} too large"));
            }
            let one = self.one()?;
            let mut base = self.clone();
            if n < 0 {
                base = match &base {
                    Value::Real(_) | Value::Complex(_) => one.div(&base)?,
                    _ => return Err("negative powers of matrices: use inv".into()),
                };
            }
            let mut e = n.unsigned_abs();
            let mut acc = one;
            while e > 0 {
                if e & 1 == 1 {
                    acc = acc.mul(&base)?;
                }
                e >>= 1;
                if e > 0 {
                    base = base.mul(&base)?;
                }
            }
            return Ok(acc);
        }
        match (self, o) {
            (Value::Real(x), Value::Real(y)) => Ok(Value::Real(x.real_fn2(RealFn2::Pow, y)?)),
            _ => Err(format!(
                "cannot raise a {} to a non-integer {} power",
                self.type_name(),
                o.type_name()
            )),
        }
    }
    /// `self[idx]` with 1-based indices: a vec3 component, a matrix entry or row.
    pub fn index(&self, idx: &[i64]) -> Result<Self, String> {
        let chk = |i: i64, n: i64| -> Result<usize, String> {
            if i < 1 || i > n {
                Err(format!("index {i} out of range 1..{n}"))
            } else {
                Ok((i - 1) as usize)
            }
        };
        match (self, idx) {
            (Value::Vec3(a), [i]) => Ok(Value::Real(a.0[chk(*i, 3)?].clone())),
            (Value::Mat3(m), [i, j]) => Ok(Value::Real(m.0[chk(*i, 3)?][chk(*j, 3)?].clone())),
            (Value::Mat3(m), [i]) => Ok(Value::Vec3(Vec3(m.0[chk(*i, 3)?].clone()))),
            (Value::CMat2(m), [i, j]) => Ok(Value::Complex(m.0[chk(*i, 2)?][chk(*j, 2)?].clone())),
            _ => Err(format!(
                "cannot index a {} with {} indices",
                self.type_name(),
                idx.len()
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every value of each type with one component replaced by NaN or ∞.
    fn values_with(bad: f64) -> Vec<Value<f64>> {
        let mut out = Vec::new();
        out.push(Value::Real(bad));
        for j in 0..2 {
            let p = [1.0, 2.0].map(|x| if j == 0 { bad } else { x });
            let q = [1.0, 2.0].map(|x| if j == 1 { bad } else { x });
            out.push(Value::Complex(Cplx::new(p[0], q[1])));
        }
        for j in 0..3 {
            out.push(Value::Vec3(Vec3(std::array::from_fn(|i| {
                if i == j { bad } else { 1.0 }
            }))));
        }
        for j in 0..9 {
            out.push(Value::Mat3(Mat3(std::array::from_fn(|r| {
                std::array::from_fn(|c| if 3 * r + c == j { bad } else { 1.0 })
            }))));
        }
        for j in 0..8 {
            out.push(Value::CMat2(Mat2(std::array::from_fn(|r| {
                std::array::from_fn(|c| {
                    let at = |part: usize| if 4 * r + 2 * c + part == j { bad } else { 0.5 };
                    Cplx::new(at(0), at(1))
                })
            }))));
        }
        out
    }

    #[test]
    fn is_finite_sees_every_component_as_components_lists_them() {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 3.0] {
            for v in values_with(bad) {
                let listed = v.components().iter().all(|x| x.is_finite());
                assert_eq!(v.is_finite(), listed, "{v:?}");
                assert_eq!(listed, bad.is_finite(), "{v:?}");
            }
        }
        assert!(Value::<f64>::Bool(true).is_finite());
    }
}
