//! The parameters of the explicit solution (sol): modulus (k), amplitudes (abc) and
//! frequency (nu) in both regimes `E/M² ≷ 1/B`, and the hyperbolic formulas on the
//! separatrix `E/M² = 1/B` (the unnumbered display after (nu)); also the
//! coefficients (alphas) of (master12) and (MV alphabeta) of (MV master).

use super::{Inertia, ModelError};
use crate::linalg::Vec3;
use crate::numbers::Real;

/// Which of the three cases of (sol) applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Regime {
    /// `1/B < E/M² ≤ 1/C`: the upper expressions in the curly brackets.
    Upper,
    /// `1/A ≤ E/M² < 1/B`: the lower expressions.
    Lower,
    /// `E/M² = 1/B` exactly: the hyperbolic formulas.
    Separatrix,
}

impl Regime {
    /// The regime of `(M², E)`: the sign of `B·E − M²` (exact comparison).
    pub fn of<R: Real>(inertia: &Inertia<R>, m2: &R, e: &R) -> Regime {
        let d = inertia.b.clone() * e.clone() - m2.clone();
        match d.signum_i() {
            1 => Regime::Upper,
            -1 => Regime::Lower,
            _ => Regime::Separatrix,
        }
    }
}

/// Squares of the parameters of (sol)/(ell coord) for given `(M², E)`: `k²` (k),
/// `a², b², c²` (abc) and `ν²` (nu), or their separatrix counterparts (where `k² = 1`).
#[derive(Clone, Debug, PartialEq)]
pub struct EllipticParams<R> {
    /// The regime.
    pub regime: Regime,
    /// `M²`.
    pub m2: R,
    /// `E`.
    pub e: R,
    /// `k²` (k); exactly 1 on the separatrix.
    pub k2: R,
    /// `a²` (abc).
    pub a2: R,
    /// `b²` (abc).
    pub b2: R,
    /// `c²` (abc).
    pub c2: R,
    /// `ν²` (nu).
    pub nu2: R,
}

impl<R: Real> EllipticParams<R> {
    /// Computes (k), (abc), (nu) — or the separatrix formulas — from `(M², E)`.
    ///
    /// Errors ([`ModelError::Undefined`]) unless `M² > 0` and `1/A ≤ E/M² ≤ 1/C`
    /// (i.e. `AE − M² ≥ 0` and `M² − CE ≥ 0`), the range attained by real `M ≠ 0`.
    pub fn new(inertia: &Inertia<R>, m2: &R, e: &R) -> Result<Self, ModelError> {
        let (a, c) = (&inertia.a, &inertia.c);
        let ae = a.clone() * e.clone() - m2.clone(); // AE − M²
        let ce = m2.clone() - c.clone() * e.clone(); // M² − CE
        let regime = Regime::of(inertia, m2, e);
        Self::rounded_to_regime(inertia, m2, e, ae, ce, regime)
    }

    /// The same parameters for the `(M², E)` of the point `m`, with the differences
    /// `AE − M² = M₂²(A−B)/B + M₃²(A−C)/C`, `M² − CE = M₁²(A−C)/A + M₂²(B−C)/B` and
    /// `BE − M² = M₃²(B−C)/C − M₁²(A−B)/A` (whose sign gives the regime) computed
    /// without cancellation, so that points near the axes keep full relative accuracy.
    pub fn from_point(inertia: &Inertia<R>, m: &Vec3<R>) -> Result<Self, ModelError> {
        let (a, b, c) = (&inertia.a, &inertia.b, &inertia.c);
        let [x, y, z] = &m.0;
        let (x2, y2, z2) = (x.sqr(), y.sqr(), z.sqr());
        let ab = a.clone() - b.clone();
        let bc = b.clone() - c.clone();
        let ac = a.clone() - c.clone();
        let ae = y2.clone() * ab.clone() / b.clone() + z2.clone() * ac.clone() / c.clone();
        let ce = x2.clone() * ac / a.clone() + y2.clone() * bc.clone() / b.clone();
        let be = z2.clone() * bc / c.clone() - x2.clone() * ab / a.clone();
        let regime = match be.signum_i() {
            1 => Regime::Upper,
            -1 => Regime::Lower,
            _ => Regime::Separatrix,
        };
        // (M2) and (E) from the squares already taken (M₁²/A rather than M₁·(M₁/A)):
        // an exact evaluation then squares each component once
        let m2 = x2.clone() + y2.clone() + z2.clone();
        let e = x2 / a.clone() + y2 / b.clone() + z2 / c.clone();
        Self::rounded_to_regime(inertia, &m2, &e, ae, ce, regime)
    }

    /// [`from_differences`](Self::from_differences), except that at a finite precision a
    /// modulus that rounds to 1 or beyond (the point lies within rounding of the
    /// separatrix) takes the separatrix formulas, with which `k² = 1` is consistent;
    /// exact arithmetic keeps the regime of the sign.
    fn rounded_to_regime(
        inertia: &Inertia<R>,
        m2: &R,
        e: &R,
        ae: R,
        ce: R,
        regime: Regime,
    ) -> Result<Self, ModelError> {
        let p = Self::from_differences(inertia, m2, e, ae.clone(), ce.clone(), regime)?;
        if p.regime == Regime::Separatrix || m2.precision().is_none() || p.k2 < m2.one() {
            return Ok(p);
        }
        // only within rounding of 1: a modulus that overflows or lies far beyond 1 is
        // an error of the input, reported as before
        let excess = p.k2.clone() - m2.one();
        let rounding = m2.epsilon() * m2.from_i64(64);
        if !excess.is_finite() || excess > rounding {
            return Ok(p);
        }
        Self::from_differences(inertia, m2, e, ae, ce, Regime::Separatrix)
    }

    fn from_differences(
        inertia: &Inertia<R>,
        m2: &R,
        e: &R,
        ae: R,
        ce: R,
        regime: Regime,
    ) -> Result<Self, ModelError> {
        let (a, b, c) = (&inertia.a, &inertia.b, &inertia.c);
        let z = m2.zero();
        if *m2 <= z || !m2.is_finite() {
            return Err(ModelError::Undefined(
                "elliptic parameters undefined at M = 0 (M^2 must be > 0)".into(),
            ));
        }
        if ae < z || ce < z {
            return Err(ModelError::Undefined(format!(
                "E/M^2 outside [1/A, 1/C] (M^2={}, E={})",
                m2.to_decimal(17),
                e.to_decimal(17)
            )));
        }
        let ab = a.clone() - b.clone();
        let bc = b.clone() - c.clone();
        let ac = a.clone() - c.clone();
        let abc = a.clone() * b.clone() * c.clone();
        let (k2, a2, b2, c2, nu2) = match regime {
            Regime::Upper => (
                ab.clone() * ce.clone() / (bc.clone() * ae.clone()),
                a.clone() * ce.clone() / ac.clone(),
                b.clone() * ce.clone() / bc.clone(),
                c.clone() * ae.clone() / ac.clone(),
                bc * ae / abc,
            ),
            Regime::Lower => (
                bc.clone() * ae.clone() / (ab.clone() * ce.clone()),
                a.clone() * ce.clone() / ac.clone(),
                b.clone() * ae.clone() / ab.clone(),
                c.clone() * ae / ac.clone(),
                ab * ce / abc,
            ),
            Regime::Separatrix => (
                m2.one(),
                a.clone() * bc.clone() / (b.clone() * ac.clone()) * m2.clone(),
                m2.clone(),
                c.clone() * ab.clone() / (b.clone() * ac) * m2.clone(),
                ab * bc / (a.clone() * b.sqr() * c.clone()) * m2.clone(),
            ),
        };
        Ok(EllipticParams {
            regime,
            m2: m2.clone(),
            e: e.clone(),
            k2,
            a2,
            b2,
            c2,
            nu2,
        })
    }

    /// Converts every parameter with `f` (e.g. to [`Dual`](crate::numbers::Dual) constants).
    pub fn map<S: Real>(&self, f: impl Fn(&R) -> S) -> EllipticParams<S> {
        EllipticParams {
            regime: self.regime,
            m2: f(&self.m2),
            e: f(&self.e),
            k2: f(&self.k2),
            a2: f(&self.a2),
            b2: f(&self.b2),
            c2: f(&self.c2),
            nu2: f(&self.nu2),
        }
    }

    /// The modulus `k = √k²` (k).
    pub fn k(&self) -> R {
        self.k2.sqrt()
    }

    /// `ν(M², E)`, the positive square root of (nu).
    pub fn nu(&self) -> R {
        self.nu2.sqrt()
    }

    /// `α₁ = b²/M²` (alphas), the coefficient in (master12) for γ₁.
    pub fn alpha1(&self) -> R {
        self.b2.clone() / self.m2.clone()
    }

    /// `α₂ = b²/(BE)` (alphas), the coefficient in (master12) for γ₂.
    pub fn alpha2(&self, inertia: &Inertia<R>) -> R {
        self.b2.clone() / (inertia.b.clone() * self.e.clone())
    }

    /// `(α, β)` of (MV alphabeta), coefficients of (MV master); `None` on the
    /// separatrix, where (MV alphabeta) is not printed.
    pub fn alpha_beta_vm(&self, inertia: &Inertia<R>) -> Option<(R, R)> {
        let (a, b, c) = (&inertia.a, &inertia.b, &inertia.c);
        let e = &self.e;
        let m2 = &self.m2;
        let ae = a.clone() * e.clone() - m2.clone();
        let ce = m2.clone() - c.clone() * e.clone();
        let num = a.from_i64(2) * a.clone() * c.clone() * e.clone()
            - (a.clone() + c.clone() - b.clone()) * m2.clone();
        let ac = a.clone() * c.clone();
        match self.regime {
            Regime::Upper => {
                let bc = b.clone() - c.clone();
                Some((num / (bc.clone() * ae.clone()), ac / bc.sqr() * (ce / ae)))
            }
            Regime::Lower => {
                let ab = a.clone() - b.clone();
                Some((num / (ab.clone() * ce.clone()), ac / ab.sqr() * (ae / ce)))
            }
            Regime::Separatrix => None,
        }
    }
}
