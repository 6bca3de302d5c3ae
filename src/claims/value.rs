//! Values of the expression language: real, complex, vec3, mat3, cmat2, bool, over any
//! scalar backend, with the arithmetic of the language (type errors are `Err`, never
//! panics).

use super::backend::{Num, RealFn};

/// A complex number over a backend scalar (exact for rationals).
#[derive(Clone, Debug, PartialEq)]
pub struct Cx<T> {
    /// Real part.
    pub re: T,
    /// Imaginary part.
    pub im: T,
}

impl<T: Num> Cx<T> {
    /// `re + i·im`.
    pub fn new(re: T, im: T) -> Self {
        Cx { re, im }
    }
    /// A real number as complex.
    pub fn real(re: T) -> Self {
        let im = re.zero();
        Cx { re, im }
    }
    /// Sum.
    pub fn add(&self, o: &Self) -> Self {
        Cx::new(
            self.re.clone() + o.re.clone(),
            self.im.clone() + o.im.clone(),
        )
    }
    /// Difference.
    pub fn sub(&self, o: &Self) -> Self {
        Cx::new(
            self.re.clone() - o.re.clone(),
            self.im.clone() - o.im.clone(),
        )
    }
    /// Product.
    pub fn mul(&self, o: &Self) -> Self {
        Cx::new(
            self.re.clone() * o.re.clone() - self.im.clone() * o.im.clone(),
            self.re.clone() * o.im.clone() + self.im.clone() * o.re.clone(),
        )
    }
    /// Quotient; error when dividing by an exact zero.
    pub fn div(&self, o: &Self) -> Result<Self, String> {
        let den = o.re.clone() * o.re.clone() + o.im.clone() * o.im.clone();
        if den.is_zero() {
            return Err("division by zero".into());
        }
        let n = self.mul(&o.conj());
        Ok(Cx::new(n.re / den.clone(), n.im / den))
    }
    /// Negation.
    pub fn neg(&self) -> Self {
        Cx::new(-self.re.clone(), -self.im.clone())
    }
    /// Conjugate.
    pub fn conj(&self) -> Self {
        Cx::new(self.re.clone(), -self.im.clone())
    }
    /// Real scaling.
    pub fn scale(&self, s: &T) -> Self {
        Cx::new(self.re.clone() * s.clone(), self.im.clone() * s.clone())
    }
    /// Modulus.
    pub fn abs(&self) -> Result<T, String> {
        (self.re.clone() * self.re.clone() + self.im.clone() * self.im.clone())
            .real_fn(RealFn::Sqrt)
    }
    /// Largest part magnitude, as f64.
    pub fn magnitude(&self) -> f64 {
        self.re.magnitude().hypot(self.im.magnitude())
    }
    /// Principal square root.
    pub fn sqrt(&self) -> Result<Self, String> {
        let r = self.abs()?;
        if r.is_zero() {
            return Ok(self.clone());
        }
        let two = r.from_i64(2);
        let t = ((r + self.re.real_fn(RealFn::Abs)?) / two.clone()).real_fn(RealFn::Sqrt)?;
        if self.re >= self.re.zero() {
            let im = self.im.clone() / (t.clone() * two);
            Ok(Cx::new(t, im))
        } else {
            let re = self.im.real_fn(RealFn::Abs)? / (t.clone() * two);
            let im = if self.im < self.im.zero() { -t } else { t };
            Ok(Cx::new(re, im))
        }
    }
    /// Exponential.
    pub fn exp(&self) -> Result<Self, String> {
        let e = self.re.real_fn(RealFn::Exp)?;
        Ok(Cx::new(
            e.clone() * self.im.real_fn(RealFn::Cos)?,
            e * self.im.real_fn(RealFn::Sin)?,
        ))
    }
    /// Principal logarithm.
    pub fn ln(&self) -> Result<Self, String> {
        Ok(Cx::new(self.abs()?.real_fn(RealFn::Ln)?, self.arg()?))
    }
    /// Argument in (−π, π].
    pub fn arg(&self) -> Result<T, String> {
        self.im.atan2_(&self.re)
    }
}

/// A value of the language.
#[derive(Clone, Debug, PartialEq)]
pub enum Value<T> {
    /// A real number.
    Real(T),
    /// A complex number.
    Complex(Cx<T>),
    /// A real 3-vector.
    Vec3([T; 3]),
    /// A real 3×3 matrix (row-major).
    Mat3([[T; 3]; 3]),
    /// A complex 2×2 matrix (row-major).
    CMat2([[Cx<T>; 2]; 2]),
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

impl<T: Num> Value<T> {
    /// Decimal rendering with `digits` significant digits in the given layout.
    pub fn render(&self, digits: usize, layout: Layout) -> String {
        let d = |x: &T| x.to_decimal(digits);
        let c = |z: &Cx<T>| format!("{} + {}i", d(&z.re), d(&z.im));
        let rows = |rs: Vec<String>| match layout {
            Layout::Inline => format!("[{}]", rs.join(", ")),
            Layout::Rows => rs.join("\n"),
        };
        match self {
            Value::Real(x) => d(x),
            Value::Bool(b) => b.to_string(),
            Value::Complex(z) => c(z),
            Value::Vec3(a) => {
                let (open, close) = match layout {
                    Layout::Inline => ("(", ")"),
                    Layout::Rows => ("[", "]"),
                };
                format!("{open}{}, {}, {}{close}", d(&a[0]), d(&a[1]), d(&a[2]))
            }
            Value::Mat3(m) => rows(
                m.iter()
                    .map(|r| format!("[{}, {}, {}]", d(&r[0]), d(&r[1]), d(&r[2])))
                    .collect(),
            ),
            Value::CMat2(m) => rows(
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
    pub fn as_complex(&self) -> Result<Cx<T>, String> {
        match self {
            Value::Real(x) => Ok(Cx::real(x.clone())),
            Value::Complex(z) => Ok(z.clone()),
            v => Err(format!(
                "expected a complex number, got a {}",
                v.type_name()
            )),
        }
    }
    /// The 3-vector, or a type error.
    pub fn as_vec3(&self) -> Result<[T; 3], String> {
        match self {
            Value::Vec3(v) => Ok(v.clone()),
            v => Err(format!("expected a vec3, got a {}", v.type_name())),
        }
    }
    /// The 3×3 matrix, or a type error.
    pub fn as_mat3(&self) -> Result<[[T; 3]; 3], String> {
        match self {
            Value::Mat3(m) => Ok(m.clone()),
            v => Err(format!("expected a mat3, got a {}", v.type_name())),
        }
    }
    /// The complex 2×2 matrix, or a type error.
    pub fn as_cmat2(&self) -> Result<[[Cx<T>; 2]; 2], String> {
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
    /// An exact integer (for indices, loop bounds, integer powers).
    pub fn as_int(&self) -> Result<i64, String> {
        let x = self.as_real()?;
        let f = x.to_f64_();
        if !f.is_finite()
            || f.abs() > 1e15
            || f.fract() != 0.0
            || !(x.clone() - x.from_f64(f)).is_zero()
        {
            return Err(format!("expected an integer, got {f}"));
        }
        Ok(f as i64)
    }
    /// All scalar components (complex as two), for magnitudes and finiteness.
    pub fn components(&self) -> Vec<T> {
        match self {
            Value::Real(x) => vec![x.clone()],
            Value::Complex(z) => vec![z.re.clone(), z.im.clone()],
            Value::Vec3(v) => v.to_vec(),
            Value::Mat3(m) => m.iter().flatten().cloned().collect(),
            Value::CMat2(m) => m
                .iter()
                .flatten()
                .flat_map(|z| [z.re.clone(), z.im.clone()])
                .collect(),
            Value::Bool(_) => vec![],
        }
    }
    /// Largest component modulus (complex entries by modulus), as f64.
    pub fn magnitude(&self) -> f64 {
        match self {
            Value::Complex(z) => z.magnitude(),
            Value::CMat2(m) => m
                .iter()
                .flatten()
                .map(|z| z.magnitude())
                .fold(0.0, f64::max),
            Value::Bool(b) => f64::from(u8::from(*b)),
            v => v
                .components()
                .iter()
                .map(|x| x.magnitude())
                .fold(0.0, f64::max),
        }
    }
    /// Are all components finite?
    pub fn is_finite(&self) -> bool {
        self.components().iter().all(|x| x.finite())
    }
    /// Maps every scalar component (complex parts included).
    pub fn map<U: Num>(&self, f: &mut dyn FnMut(&T) -> U) -> Value<U> {
        let cx = |z: &Cx<T>, f: &mut dyn FnMut(&T) -> U| Cx::new(f(&z.re), f(&z.im));
        match self {
            Value::Real(x) => Value::Real(f(x)),
            Value::Complex(z) => Value::Complex(cx(z, f)),
            Value::Vec3(v) => Value::Vec3([f(&v[0]), f(&v[1]), f(&v[2])]),
            Value::Mat3(m) => Value::Mat3(std::array::from_fn(|i| {
                std::array::from_fn(|j| f(&m[i][j]))
            })),
            Value::CMat2(m) => {
                let a = cx(&m[0][0], f);
                let b = cx(&m[0][1], f);
                let c = cx(&m[1][0], f);
                let d = cx(&m[1][1], f);
                Value::CMat2([[a, b], [c, d]])
            }
            Value::Bool(b) => Value::Bool(*b),
        }
    }

    /// `self + o`.
    pub fn add(&self, o: &Self) -> Result<Self, String> {
        self.zip(o, "+", |a, b| a + b, |a, b| a.add(b))
    }
    /// `self - o`.
    pub fn sub(&self, o: &Self) -> Result<Self, String> {
        self.zip(o, "-", |a, b| a - b, |a, b| a.sub(b))
    }
    fn zip(
        &self,
        o: &Self,
        op: &str,
        f: impl Fn(T, T) -> T,
        g: impl Fn(&Cx<T>, &Cx<T>) -> Cx<T>,
    ) -> Result<Self, String> {
        Ok(match (self, o) {
            (Value::Real(a), Value::Real(b)) => Value::Real(f(a.clone(), b.clone())),
            (Value::Real(_) | Value::Complex(_), Value::Real(_) | Value::Complex(_)) => {
                Value::Complex(g(&self.as_complex()?, &o.as_complex()?))
            }
            (Value::Vec3(a), Value::Vec3(b)) => {
                Value::Vec3(std::array::from_fn(|i| f(a[i].clone(), b[i].clone())))
            }
            (Value::Mat3(a), Value::Mat3(b)) => Value::Mat3(std::array::from_fn(|i| {
                std::array::from_fn(|j| f(a[i][j].clone(), b[i][j].clone()))
            })),
            (Value::CMat2(a), Value::CMat2(b)) => Value::CMat2(std::array::from_fn(|i| {
                std::array::from_fn(|j| g(&a[i][j], &b[i][j]))
            })),
            _ => {
                return Err(format!(
                    "cannot apply '{op}' to a {} and a {}",
                    self.type_name(),
                    o.type_name()
                ))
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
    fn scale_complex(&self, s: &Cx<T>) -> Result<Self, String> {
        match self {
            Value::Real(x) => Ok(Value::Complex(s.scale(x))),
            Value::Complex(z) => Ok(Value::Complex(s.mul(z))),
            Value::CMat2(m) => Ok(Value::CMat2(std::array::from_fn(|i| {
                std::array::from_fn(|j| s.mul(&m[i][j]))
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
            (Value::Mat3(a), Value::Mat3(b)) => Ok(Value::Mat3(std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    a[i][0].clone() * b[0][j].clone()
                        + a[i][1].clone() * b[1][j].clone()
                        + a[i][2].clone() * b[2][j].clone()
                })
            }))),
            (Value::Mat3(a), Value::Vec3(v)) => Ok(Value::Vec3(std::array::from_fn(|i| {
                a[i][0].clone() * v[0].clone()
                    + a[i][1].clone() * v[1].clone()
                    + a[i][2].clone() * v[2].clone()
            }))),
            (Value::CMat2(a), Value::CMat2(b)) => Ok(Value::CMat2(std::array::from_fn(|i| {
                std::array::from_fn(|j| a[i][0].mul(&b[0][j]).add(&a[i][1].mul(&b[1][j])))
            }))),
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
                let inv = Cx::real(s.re.one()).div(s)?;
                self.scale_complex(&inv)
            }
            _ => Err(format!("cannot divide by a {}", o.type_name())),
        }
    }
    /// `self ^ o`: integer powers of scalars and square matrices by repeated
    /// multiplication (negative powers of scalars invert); real powers of positive reals.
    pub fn pow(&self, o: &Self) -> Result<Self, String> {
        if let Ok(n) = o.as_int() {
            if n.unsigned_abs() > 1 << 20 {
                return Err(format!("exponent {n} too large"));
            }
            let one: Self = match self {
                Value::Real(x) => Value::Real(x.one()),
                Value::Complex(z) => Value::Complex(Cx::real(z.re.one())),
                Value::Mat3(m) => {
                    let z = &m[0][0];
                    Value::Mat3(std::array::from_fn(|i| {
                        std::array::from_fn(|j| if i == j { z.one() } else { z.zero() })
                    }))
                }
                Value::CMat2(m) => {
                    let z = &m[0][0].re;
                    Value::CMat2(std::array::from_fn(|i| {
                        std::array::from_fn(|j| Cx::real(if i == j { z.one() } else { z.zero() }))
                    }))
                }
                v => return Err(format!("cannot raise a {} to a power", v.type_name())),
            };
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
            (Value::Real(x), Value::Real(y)) => Ok(Value::Real(x.powf_(y)?)),
            _ => Err(format!(
                "cannot raise a {} to a non-integer {} power",
                self.type_name(),
                o.type_name()
            )),
        }
    }
}
