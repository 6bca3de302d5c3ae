//! The continuous Euler top (Section 2): moments of inertia (ABC), angular velocity
//! (Omega), energy (E), Casimir (M2), the equations of motion (ET) / (ET v) and the
//! Poisson bracket (PB).  See the [module-level note](super) on the sign of (ET v).

use super::ModelError;
use crate::linalg::Vec3;
use crate::numbers::{Dual, Real, Scalar};

/// Principal moments of inertia `A > B > C > 0` (ABC).
#[derive(Clone, Debug, PartialEq)]
pub struct Inertia<R> {
    /// A, the largest moment.
    pub a: R,
    /// B, the middle moment.
    pub b: R,
    /// C, the smallest moment.
    pub c: R,
}

/// The field-only part: every ordered scalar (exact rationals included) computes
/// (Omega), (E) and (M2) with this same code.
impl<R: Scalar + PartialOrd> Inertia<R> {
    /// Validates (ABC) `A > B > C > 0`; otherwise [`ModelError::InvalidInertia`].
    pub fn new(a: R, b: R, c: R) -> Result<Self, ModelError> {
        let z = a.zero();
        let ok = a.is_finite() && b.is_finite() && c.is_finite() && a > b && b > c && c > z;
        if ok {
            Ok(Inertia { a, b, c })
        } else {
            Err(ModelError::InvalidInertia {
                a: a.to_decimal(17),
                b: b.to_decimal(17),
                c: c.to_decimal(17),
            })
        }
    }

    /// `(A, B, C)` as a vector.
    pub fn as_vec(&self) -> Vec3<R> {
        Vec3::new(self.a.clone(), self.b.clone(), self.c.clone())
    }

    /// Angular velocity (Omega): `Ω(M) = (M₁/A, M₂/B, M₃/C)`.
    pub fn omega(&self, m: &Vec3<R>) -> Vec3<R> {
        let [m1, m2, m3] = m.0.clone();
        Vec3::new(
            m1 / self.a.clone(),
            m2 / self.b.clone(),
            m3 / self.c.clone(),
        )
    }

    /// Energy (E): `E(M) = M₁²/A + M₂²/B + M₃²/C = ⟨M, Ω(M)⟩`.
    pub fn energy(&self, m: &Vec3<R>) -> R {
        m.dot(&self.omega(m))
    }

    /// Casimir (M2): `M² = M₁² + M₂² + M₃²`.
    pub fn m2(&self, m: &Vec3<R>) -> R {
        m.norm2()
    }
}

impl<R: Real> Inertia<R> {
    /// Converts every moment with `f` (e.g. to [`Dual`] constants or another
    /// precision); the order A > B > C > 0 is preserved by monotone conversions.
    pub fn map<S: Real>(&self, f: impl Fn(&R) -> S) -> Inertia<S> {
        Inertia {
            a: f(&self.a),
            b: f(&self.b),
            c: f(&self.c),
        }
    }

    /// The same moments as [`Dual`] constants.
    pub fn to_dual(&self) -> Inertia<Dual<R>> {
        self.map(|x| Dual::constant(x.clone()))
    }

    /// The right-hand side of (ET) in components:
    /// `((1/B − 1/C)M₂M₃, (1/C − 1/A)M₃M₁, (1/A − 1/B)M₁M₂)`, which equals
    /// `Ω(M) ×_std M` (standard cross product).  This is the convention the solution
    /// (sol), the bracket (PB) and (impl spec 1–3) follow.
    pub fn field_et(&self, m: &Vec3<R>) -> Vec3<R> {
        let (ia, ib, ic) = (self.a.recip(), self.b.recip(), self.c.recip());
        let [m1, m2, m3] = &m.0;
        Vec3::new(
            (ib.clone() - ic.clone()) * m2.clone() * m3.clone(),
            (ic - ia.clone()) * m3.clone() * m1.clone(),
            (ia - ib) * m1.clone() * m2.clone(),
        )
    }

    /// The printed vector form (ET v) `M × Ω(M)` evaluated with the *standard*
    /// right-handed cross product; it equals `−`[`field_et`](Self::field_et).
    pub fn field_cross_std(&self, m: &Vec3<R>) -> Vec3<R> {
        m.cross(&self.omega(m))
    }

    /// The Lie–Poisson bracket (PB) `{F, G}(M) = ⟨M, ∇F × ∇G⟩` (standard cross
    /// product), which gives `{M₁, M₂} = M₃` and cyclic as printed.  Gradients are
    /// computed exactly by forward-mode AD ([`Dual`]), one pass per coordinate.
    pub fn poisson_bracket<F, G>(&self, m: &Vec3<R>, f: F, g: G) -> R
    where
        F: Fn(&Vec3<Dual<R>>) -> Dual<R>,
        G: Fn(&Vec3<Dual<R>>) -> Dual<R>,
    {
        let gf = gradient(m, f);
        let gg = gradient(m, g);
        m.dot(&gf.cross(&gg))
    }

    /// The Hamiltonian vector field `Ṁᵢ = {Mᵢ, H}` with `H = E/2` and the bracket
    /// (PB), computed through [`poisson_bracket`](Self::poisson_bracket) with AD.
    /// Mathematically equal to [`field_et`](Self::field_et).
    pub fn hamiltonian_field(&self, m: &Vec3<R>) -> Vec3<R> {
        let id = self.to_dual();
        let half = m.0[0].from_ratio(1, 2);
        let h = |x: &Vec3<Dual<R>>| id.energy(x) * Dual::constant(half.clone());
        Vec3(std::array::from_fn(|i| {
            self.poisson_bracket(m, |x: &Vec3<Dual<R>>| x.0[i].clone(), h)
        }))
    }
}

/// The gradient of `f` at `m` by three forward-mode AD passes.
pub fn gradient<R: Real, F>(m: &Vec3<R>, f: F) -> Vec3<R>
where
    F: Fn(&Vec3<Dual<R>>) -> Dual<R>,
{
    Vec3(std::array::from_fn(|i| {
        let x = Vec3(std::array::from_fn(|j| {
            let v = m.0[j].clone();
            let d = if i == j { v.one() } else { v.zero() };
            Dual::new(v, d)
        }));
        f(&x).d
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_bad_order() {
        assert!(Inertia::new(1.0, 2.0, 3.0).is_err());
        assert!(Inertia::new(3.0, 2.0, 0.0).is_err());
        assert!(Inertia::new(3.0, 3.0, 1.0).is_err());
        assert!(Inertia::new(3.0, 2.0, 1.0).is_ok());
    }

    #[test]
    fn bracket_of_coordinates_is_pb() {
        let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
        let m = Vec3::new(0.3, -0.7, 1.1);
        let c = |k: usize| move |x: &Vec3<Dual<f64>>| x.0[k].clone();
        assert!((i.poisson_bracket(&m, c(0), c(1)) - m.0[2]).abs() < 1e-15);
        assert!((i.poisson_bracket(&m, c(1), c(2)) - m.0[0]).abs() < 1e-15);
        assert!((i.poisson_bracket(&m, c(2), c(0)) - m.0[1]).abs() < 1e-15);
    }

    #[test]
    fn et_is_minus_standard_cross_and_hamiltonian() {
        let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
        let m = Vec3::new(0.3, -0.7, 1.1);
        let s = i.field_et(&m) + i.field_cross_std(&m);
        assert!(s.max_magnitude() < 1e-15);
        let d = i.field_et(&m) - i.hamiltonian_field(&m);
        assert!(d.max_magnitude() < 1e-15);
        assert!(i.field_et(&m).max_magnitude() > 0.1);
    }
}
