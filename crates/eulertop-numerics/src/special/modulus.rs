//! The modulus as the caller gave it ([`Spec`]), which modulus of the pair `(k, k')` is
//! evaluated ([`Modulus`]), the transformations of DLMF §22.17 that take any real modulus
//! to `κ ∈ [0, 1]` ([`Form`]), and the quadrant of an argument.

use super::{SpecialError, show};
use crate::numbers::Real;

/// Which modulus of the pair `(k, k')` an evaluation is for: `k` itself, or its
/// complement `k'` (Jacobi's imaginary transformation, DLMF Table 22.6.1, needs the
/// functions of `k'` for the imaginary part of a complex argument).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Modulus {
    /// The modulus `k`.
    K,
    /// The complementary modulus `k' = √(1 − k²)`, with `k` the exactly given value.
    Complement,
}

/// A real modulus as the caller gave it.
#[derive(Debug)]
pub(crate) enum Spec<'a, R> {
    /// The modulus `k ≥ 0` (`k > 1` by DLMF 22.17.2–4), or its complement.
    Modulus(&'a R, Modulus),
    /// The parameter `m = k²`, any real (`m < 0`: imaginary modulus, DLMF 22.17.6–8).
    Parameter(&'a R),
}

impl<R> Clone for Spec<'_, R> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<R> Copy for Spec<'_, R> {}

impl<R: Real> Spec<'_, R> {
    /// Runs `f` on the same spec with its value rounded to `f64` (exact when
    /// [`Real::PLAIN_F64`]).
    #[inline(always)]
    pub(crate) fn with_f64<T>(self, f: impl FnOnce(Spec<'_, f64>) -> T) -> T {
        match self {
            Spec::Modulus(k, modulus) => f(Spec::Modulus(&k.to_f64(), modulus)),
            Spec::Parameter(m) => f(Spec::Parameter(&m.to_f64())),
        }
    }

    /// A key that tells specs apart: the bits of the value rounded to `f64` and the kind.
    #[inline(always)]
    pub(crate) fn key(self) -> [u64; 2] {
        match self {
            Spec::Modulus(k, Modulus::K) => [k.to_f64().to_bits(), 0],
            Spec::Modulus(k, Modulus::Complement) => [k.to_f64().to_bits(), 1],
            Spec::Parameter(m) => [m.to_f64().to_bits(), 2],
        }
    }
}

/// How the evaluated modulus `κ ∈ [0, 1]` relates to the given one (DLMF §22.17):
/// with `v = f·u`, `Direct`: `(sn, cn, dn)(u) = (s, c, d)(v)`; `Reciprocal` (`k > 1`,
/// `κ = 1/k`, `f = k`): `(s/k, d, c)`; `Imaginary` (`m < 0`, `κ² = −m/(1−m)`,
/// `f = √(1−m)`): `(s/(f d), c/d, 1/d)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Form {
    Direct,
    Reciprocal,
    Imaginary,
}

/// `(sn, cn, dn)` of the evaluated modulus back to the given one (see [`Form`]); `f` is
/// the argument factor.
#[inline(always)]
pub(crate) fn untransform<R: Real>(form: Form, f: &R, (s, c, d): (R, R, R)) -> (R, R, R) {
    match form {
        Form::Direct => (s, c, d),
        Form::Reciprocal => (s / f.clone(), d, c),
        Form::Imaginary => {
            let rd = d.recip();
            (s * rd.clone() / f.clone(), c * rd.clone(), rd)
        }
    }
}

/// Multi-precision: `(κ, modulus, f, form)` of a [`Spec`] at `w` bits.
pub(crate) fn mp_modulus<R: Real>(spec: Spec<'_, R>, w: u32) -> (R, Modulus, R, Form) {
    match spec {
        Spec::Modulus(k, modulus) if *k <= k.one() => (k.clone(), modulus, k.one(), Form::Direct),
        Spec::Modulus(k, _) => {
            let kw = k.with_prec(w);
            (kw.recip(), Modulus::K, kw, Form::Reciprocal)
        }
        Spec::Parameter(m) => {
            let mw = m.with_prec(w);
            let one = mw.one();
            if mw < mw.zero() {
                let opm = one.clone() - mw.clone();
                (
                    (-mw / opm.clone()).sqrt(),
                    Modulus::K,
                    opm.sqrt(),
                    Form::Imaginary,
                )
            } else if mw <= one {
                (mw.sqrt(), Modulus::K, one, Form::Direct)
            } else {
                let f = mw.sqrt();
                (f.recip(), Modulus::K, f, Form::Reciprocal)
            }
        }
    }
}

/// The quadrant `j = round(u/K)` (half away from zero) from `ratio = u/K` in `f64`.
#[inline(always)]
pub(crate) fn quadrant<R: Real>(ratio: f64, u: &R) -> Result<i64, SpecialError> {
    if ratio.is_nan() || ratio.abs() >= 2f64.powi(50) {
        return Err(too_large(ratio, u));
    }
    Ok(if ratio >= 0.0 {
        (ratio + 0.5) as i64
    } else {
        (ratio - 0.5) as i64
    })
}

#[cold]
fn too_large<R: Real>(ratio: f64, u: &R) -> SpecialError {
    SpecialError::ArgumentTooLarge(format!(
        "|u|/K = {:e} >= 2^50 (u = {})",
        ratio.abs(),
        show(u)
    ))
}
