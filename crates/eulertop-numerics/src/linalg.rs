//! Small dense linear algebra over any [`Scalar`]: 3-vectors, 3×3 matrices and 2×2
//! matrices (used with complex scalars for su(2)), and in [`newton`] Gaussian elimination
//! and Newton's method for small square systems.  Part of the numbers layer: it knows
//! nothing about the Euler top.

#[cfg(feature = "arb")]
pub mod krawczyk;
pub mod newton;

use crate::numbers::{ComplexScalar, Real, Scalar};
use std::ops::{Add, Mul, Neg, Sub};

/// The ring operations that sums, products, determinants and commutators need.  Every
/// [`Scalar`] has them, and so has [`crate::numbers::Cplx`] over any ordered scalar
/// (exact rationals included), so a `Mat2<Cplx<T>>` works for every backend.
pub trait Ring:
    Clone + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
}

impl<T> Ring for T where
    T: Clone + Add<Output = T> + Sub<Output = T> + Mul<Output = T> + Neg<Output = T>
{
}

/// A column 3-vector.
#[derive(Clone, Debug, PartialEq)]
pub struct Vec3<S>(pub [S; 3]);

/// A 3×3 matrix, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct Mat3<S>(pub [[S; 3]; 3]);

/// A 2×2 matrix, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct Mat2<S>(pub [[S; 2]; 2]);

/// A value whose components are rounded to a given precision: a real scalar or a
/// [`Vec3`] of them (and, downstream, anything built of them).
///
/// ```
/// use eulertop_numerics::linalg::{AtPrec, Vec3};
/// let f = |x: f64| rug::Float::with_val(256, x);
/// let v = Vec3::new(f(1.0), f(2.0), f(3.0));
/// assert!(v.at_prec(64).0.iter().all(|x| x.prec() == 64));
/// assert_eq!(0.5_f64.at_prec(64), 0.5);
/// ```
pub trait AtPrec {
    /// The same value with each component rounded to `bits` bits (a fixed-precision
    /// type such as `f64` is unchanged).
    fn at_prec(&self, bits: u32) -> Self;
}

impl<R: Real> AtPrec for R {
    fn at_prec(&self, bits: u32) -> Self {
        self.with_prec(bits)
    }
}

impl<R: Real> AtPrec for Vec3<R> {
    fn at_prec(&self, bits: u32) -> Self {
        Vec3(std::array::from_fn(|i| self.0[i].with_prec(bits)))
    }
}

impl<S: Scalar> Vec3<S> {
    /// `(x, y, z)`.
    pub fn new(x: S, y: S, z: S) -> Self {
        Vec3([x, y, z])
    }
    /// The zero vector with the precision of `like`.
    pub fn zeros(like: &S) -> Self {
        Vec3([like.zero(), like.zero(), like.zero()])
    }
    /// Component `i` (0-based).
    pub fn get(&self, i: usize) -> &S {
        &self.0[i]
    }
    /// Euclidean inner product ⟨self, o⟩.
    pub fn dot(&self, o: &Self) -> S {
        let [a, b, c] = &self.0;
        let [x, y, z] = &o.0;
        S::dot3([a, b, c], [x, y, z])
    }
    /// The standard (right-handed) cross product: `(a×b)₁ = a₂b₃ − a₃b₂`, cyclic.
    pub fn cross(&self, o: &Self) -> Self {
        let [a1, a2, a3] = &self.0;
        let [b1, b2, b3] = &o.0;
        Vec3([
            S::det2(a2, b3, a3, b2),
            S::det2(a3, b1, a1, b3),
            S::det2(a1, b2, a2, b1),
        ])
    }
    /// `s · self`.
    pub fn scale(&self, s: &S) -> Self {
        Vec3(self.0.clone().map(|x| x * s.clone()))
    }
    /// Componentwise product.
    pub fn hadamard(&self, o: &Self) -> Self {
        let [a, b, c] = self.0.clone();
        let [x, y, z] = o.0.clone();
        Vec3([a * x, b * y, c * z])
    }
    /// Squared Euclidean norm.
    pub fn norm2(&self) -> S {
        self.dot(self)
    }
    /// Largest component magnitude (∞-norm), as f64.
    pub fn max_magnitude(&self) -> f64 {
        self.0.iter().map(|x| x.magnitude()).fold(0.0, f64::max)
    }
}

impl<S: Scalar> Add for Vec3<S> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        let [a, b, c] = self.0;
        let [x, y, z] = o.0;
        Vec3([a + x, b + y, c + z])
    }
}
impl<S: Scalar> Sub for Vec3<S> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        let [a, b, c] = self.0;
        let [x, y, z] = o.0;
        Vec3([a - x, b - y, c - z])
    }
}
impl<S: Scalar> Neg for Vec3<S> {
    type Output = Self;
    fn neg(self) -> Self {
        Vec3(self.0.map(|x| -x))
    }
}

impl<S: Scalar> Mat3<S> {
    /// Build from a function of (row, column).
    pub fn from_fn(mut f: impl FnMut(usize, usize) -> S) -> Self {
        Mat3(std::array::from_fn(|i| std::array::from_fn(|j| f(i, j))))
    }
    /// The zero matrix.
    pub fn zeros(like: &S) -> Self {
        Self::from_fn(|_, _| like.zero())
    }
    /// The identity matrix.
    pub fn identity(like: &S) -> Self {
        Self::from_fn(|i, j| if i == j { like.one() } else { like.zero() })
    }
    /// `diag(d₁, d₂, d₃)`.
    pub fn diag(d: &Vec3<S>) -> Self {
        let z = d.0[0].zero();
        Self::from_fn(|i, j| if i == j { d.0[i].clone() } else { z.clone() })
    }
    /// Entry (i, j), 0-based.
    pub fn at(&self, i: usize, j: usize) -> &S {
        &self.0[i][j]
    }
    /// Transpose.
    pub fn transpose(&self) -> Self {
        Self::from_fn(|i, j| self.0[j][i].clone())
    }
    /// `s · self`.
    pub fn scale(&self, s: &S) -> Self {
        Self::from_fn(|i, j| self.0[i][j].clone() * s.clone())
    }
    /// Matrix–vector product.
    pub fn mul_vec(&self, v: &Vec3<S>) -> Vec3<S> {
        Vec3(std::array::from_fn(|i| {
            self.0[i][0].clone() * v.0[0].clone()
                + self.0[i][1].clone() * v.0[1].clone()
                + self.0[i][2].clone() * v.0[2].clone()
        }))
    }
    /// Determinant (cofactor expansion).
    pub fn det(&self) -> S {
        let m = &self.0;
        let c = |i: usize, j: usize| m[i][j].clone();
        c(0, 0) * (c(1, 1) * c(2, 2) - c(1, 2) * c(2, 1))
            - c(0, 1) * (c(1, 0) * c(2, 2) - c(1, 2) * c(2, 0))
            + c(0, 2) * (c(1, 0) * c(2, 1) - c(1, 1) * c(2, 0))
    }
    /// Inverse by the adjugate; `None` when the determinant is exactly zero.
    pub fn inverse(&self) -> Option<Self> {
        let d = self.det();
        if d.is_zero() {
            return None;
        }
        // adj(A) = cof(A)ᵀ
        let cof = self.cofactors();
        Some(Self::from_fn(|j, i| cof.0[i][j].clone() / d.clone()))
    }
    /// The matrix of cofactors, `cof(A)ᵢⱼ = (−1)^(i+j)·Mᵢⱼ`: row `i` is the cross product
    /// of rows `i+1` and `i+2` (indices mod 3), each entry one [`Scalar::det2`].
    ///
    /// ```
    /// use eulertop_numerics::linalg::Mat3;
    /// let a = Mat3([[2.0, 0.0, 1.0], [1.0, 3.0, 0.0], [0.0, 1.0, 4.0]]);
    /// // adj(A) = cof(A)ᵀ, and A·adj(A) = det(A)·I
    /// let p = a.clone() * a.cofactors().transpose();
    /// assert_eq!(p, Mat3::identity(&1.0).scale(&a.det()));
    /// ```
    pub fn cofactors(&self) -> Self {
        let m = &self.0;
        let c = |i: usize, j: usize| &m[i % 3][j % 3];
        Self::from_fn(|i, j| {
            S::det2(
                c(i + 1, j + 1),
                c(i + 2, j + 2),
                c(i + 1, j + 2),
                c(i + 2, j + 1),
            )
        })
    }
    /// `self·P·selfᵀ` for an exactly antisymmetric `P`, by the identity
    /// `A·[p]ₓ·Aᵀ = [cof(A)·p]ₓ`, where `[p]ₓ` is the matrix of `v ↦ p × v`
    /// (`p = (P₃₂, P₁₃, P₂₁)`).  Row `k` of `cof(A)` is `aᵢ × aⱼ` for the rows `aᵢ`, `aⱼ`
    /// of `A` with `(i, j, k)` cyclic, so `(cof(A)·p)ₖ = aᵢ·(aⱼ × p)`: 9 [`Scalar::det2`]
    /// and 3 [`Scalar::dot3`] instead of two matrix products, and the diagonal is
    /// exactly 0.  `None` when `P` is not antisymmetric ([`Scalar::is_zero`] of `Pᵢᵢ` and
    /// of `Pᵢⱼ + Pⱼᵢ`).
    ///
    /// ```
    /// use eulertop_numerics::linalg::Mat3;
    /// let a = Mat3([[2.0, 0.0, 1.0], [1.0, 3.0, 0.0], [0.0, 1.0, 4.0]]);
    /// let p = Mat3([[0.0, -3.0, 2.0], [3.0, 0.0, -1.0], [-2.0, 1.0, 0.0]]);
    /// let plain = a.clone() * p.clone() * a.transpose();
    /// assert_eq!(a.congruence_antisymmetric(&p), Some(plain));
    /// assert_eq!(a.congruence_antisymmetric(&a), None);
    /// ```
    pub fn congruence_antisymmetric(&self, p: &Self) -> Option<Self> {
        let e = &p.0;
        let antisymmetric = (0..3).all(|i| {
            e[i][i].is_zero() && (i + 1..3).all(|j| (e[i][j].clone() + e[j][i].clone()).is_zero())
        });
        if !antisymmetric {
            return None;
        }
        let p = Vec3([e[2][1].clone(), e[0][2].clone(), e[1][0].clone()]);
        let row = |i: usize| Vec3(self.0[i % 3].clone());
        // q_k = (a_i × a_j)·p = a_i·(a_j × p), (i, j, k) cyclic
        let q: [S; 3] = std::array::from_fn(|k| row(k + 1).dot(&row(k + 2).cross(&p)));
        let z = q[0].zero();
        Some(Mat3([
            [z.clone(), -q[2].clone(), q[1].clone()],
            [q[2].clone(), z.clone(), -q[0].clone()],
            [-q[1].clone(), q[0].clone(), z],
        ]))
    }
    /// Commutator `[self, o] = self·o − o·self`.
    pub fn commutator(&self, o: &Self) -> Self {
        self.clone() * o.clone() - o.clone() * self.clone()
    }
    /// Largest entry magnitude, as f64.
    pub fn max_magnitude(&self) -> f64 {
        self.0
            .iter()
            .flat_map(|r| r.iter())
            .map(|x| x.magnitude())
            .fold(0.0, f64::max)
    }
    /// Trace.
    pub fn trace(&self) -> S {
        self.0[0][0].clone() + self.0[1][1].clone() + self.0[2][2].clone()
    }
}

impl<S: Scalar> Add for Mat3<S> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self::from_fn(|i, j| self.0[i][j].clone() + o.0[i][j].clone())
    }
}
impl<S: Scalar> Sub for Mat3<S> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self::from_fn(|i, j| self.0[i][j].clone() - o.0[i][j].clone())
    }
}
impl<S: Scalar> Neg for Mat3<S> {
    type Output = Self;
    fn neg(self) -> Self {
        Self::from_fn(|i, j| -self.0[i][j].clone())
    }
}
/// The matrix product, each entry one [`Scalar::dot3`]: numbers round as `a·b + c·d + e·f`
/// always did, and the prover forms each entry over one common denominator.
impl<S: Scalar> Mul for Mat3<S> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Self::from_fn(|i, j| {
            S::dot3(
                [&self.0[i][0], &self.0[i][1], &self.0[i][2]],
                [&o.0[0][j], &o.0[1][j], &o.0[2][j]],
            )
        })
    }
}

impl<S: Ring> Mat2<S> {
    /// Build from a function of (row, column).
    pub fn from_fn(mut f: impl FnMut(usize, usize) -> S) -> Self {
        Mat2(std::array::from_fn(|i| std::array::from_fn(|j| f(i, j))))
    }
    /// `s · self`.
    pub fn scale(&self, s: &S) -> Self {
        Self::from_fn(|i, j| self.0[i][j].clone() * s.clone())
    }
    /// Determinant.
    pub fn det(&self) -> S {
        let m = &self.0;
        m[0][0].clone() * m[1][1].clone() - m[0][1].clone() * m[1][0].clone()
    }
    /// Transpose.
    pub fn transpose(&self) -> Self {
        Self::from_fn(|i, j| self.0[j][i].clone())
    }
    /// Trace.
    pub fn trace(&self) -> S {
        self.0[0][0].clone() + self.0[1][1].clone()
    }
    /// Commutator `[self, o]`.
    pub fn commutator(&self, o: &Self) -> Self {
        self.clone() * o.clone() - o.clone() * self.clone()
    }
}

impl<S: Scalar> Mat2<S> {
    /// The zero matrix.
    pub fn zeros(like: &S) -> Self {
        Self::from_fn(|_, _| like.zero())
    }
    /// The identity matrix.
    pub fn identity(like: &S) -> Self {
        Self::from_fn(|i, j| if i == j { like.one() } else { like.zero() })
    }
    /// Inverse; `None` when the determinant is exactly zero.
    pub fn inverse(&self) -> Option<Self> {
        let d = self.det();
        if d.is_zero() {
            return None;
        }
        let m = &self.0;
        Some(Mat2([
            [m[1][1].clone() / d.clone(), -m[0][1].clone() / d.clone()],
            [-m[1][0].clone() / d.clone(), m[0][0].clone() / d],
        ]))
    }
    /// Largest entry magnitude, as f64.
    pub fn max_magnitude(&self) -> f64 {
        self.0
            .iter()
            .flat_map(|r| r.iter())
            .map(|x| x.magnitude())
            .fold(0.0, f64::max)
    }
}

impl<C: ComplexScalar> Mat2<C> {
    /// Pauli matrix σ_k, k ∈ {1, 2, 3}:
    /// `σ₁ = [[0,1],[1,0]]`, `σ₂ = [[0,−i],[i,0]]`, `σ₃ = [[1,0],[0,−1]]`.
    /// Returns `None` for any other k.
    pub fn pauli(k: usize, like: &C) -> Option<Self> {
        let (o, z, i) = (like.one(), like.zero(), like.i());
        Some(match k {
            1 => Mat2([[z.clone(), o.clone()], [o, z]]),
            2 => Mat2([[z.clone(), -i.clone()], [i, z]]),
            3 => Mat2([[o.clone(), z.clone()], [z, -o]]),
            _ => return None,
        })
    }
}

impl<S: Ring> Add for Mat2<S> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Self::from_fn(|i, j| self.0[i][j].clone() + o.0[i][j].clone())
    }
}
impl<S: Ring> Sub for Mat2<S> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Self::from_fn(|i, j| self.0[i][j].clone() - o.0[i][j].clone())
    }
}
impl<S: Ring> Neg for Mat2<S> {
    type Output = Self;
    fn neg(self) -> Self {
        Self::from_fn(|i, j| -self.0[i][j].clone())
    }
}
impl<S: Ring> Mul for Mat2<S> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        Self::from_fn(|i, j| {
            self.0[i][0].clone() * o.0[0][j].clone() + self.0[i][1].clone() * o.0[1][j].clone()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numbers::C64;
    #[test]
    fn inverse_and_cross() {
        let m = Mat3([[2.0, 1.0, 0.0], [0.0, 3.0, 1.0], [1.0, 0.0, 4.0]]);
        let p = m.clone() * m.inverse().unwrap();
        assert!((p - Mat3::identity(&1.0)).max_magnitude() < 1e-15);
        let e1 = Vec3::new(1.0, 0.0, 0.0);
        let e2 = Vec3::new(0.0, 1.0, 0.0);
        assert_eq!(e1.cross(&e2), Vec3::new(0.0, 0.0, 1.0));
    }
    /// The congruence of an antisymmetric matrix is the two products, exactly (over
    /// the rationals), and a matrix that is not antisymmetric is refused.
    #[test]
    fn congruence_of_an_antisymmetric_matrix_is_the_two_products() {
        use num_bigint::BigInt;
        use num_rational::BigRational;
        use proptest::prelude::*;
        let q = |n: i64, d: i64| BigRational::new(BigInt::from(n), BigInt::from(d));
        let entry = (-50i64..50, 1i64..20);
        let mat = proptest::array::uniform3(proptest::array::uniform3(entry.clone()));
        let vec = proptest::array::uniform3(entry);
        proptest!(ProptestConfig::with_cases(200), |(a in mat, p in vec, off in 1i64..5)| {
            let a = Mat3(a.map(|r| r.map(|(n, d)| q(n, d))));
            let [p1, p2, p3] = p.map(|(n, d)| q(n, d));
            let z = q(0, 1);
            let hat = Mat3([
                [z.clone(), -p3.clone(), p2.clone()],
                [p3, z.clone(), -p1.clone()],
                [-p2, p1, z],
            ]);
            let plain = a.clone() * hat.clone() * a.transpose();
            prop_assert_eq!(a.congruence_antisymmetric(&hat), Some(plain));
            let mut skewed = hat.clone();
            skewed.0[0][1] = skewed.0[0][1].clone() + q(off, 7);
            prop_assert_eq!(a.congruence_antisymmetric(&skewed), None);
            let mut diagonal = hat;
            diagonal.0[2][2] = q(off, 3);
            prop_assert_eq!(a.congruence_antisymmetric(&diagonal), None);
        });
    }
    #[test]
    fn pauli_algebra() {
        let z = C64::new(0.0, 0.0);
        let s1 = Mat2::pauli(1, &z).unwrap();
        let s2 = Mat2::pauli(2, &z).unwrap();
        let s3 = Mat2::pauli(3, &z).unwrap();
        // σ₁σ₂ = iσ₃
        let lhs = s1 * s2;
        let rhs = s3.scale(&C64::new(0.0, 1.0));
        assert!((lhs - rhs).max_magnitude() < 1e-16);
        assert!(Mat2::pauli(4, &z).is_none());
    }
}
