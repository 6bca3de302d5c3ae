//! Elliptic coordinates (Section 4): `Φ: (M², E, φ) ↦ M` (ell coord) with the sign
//! rules for `a, b, c` in the four sectors and on the separatrix half-planes
//! (halfplanes), and the inverse `Φ⁻¹: M ↦ (M², E, φ)`.
//!
//! # Sign rules (the text after (ell coord))
//! * `E/M² > 1/B` (upper): `sign c = sign M₃`, `sign(ab) = sign c`.  The paper leaves
//!   the individual signs of `a, b` free (flipping both is `φ ↦ φ + 2K`); this crate
//!   fixes **`b > 0`**, hence `sign a = sign M₃`.
//! * `E/M² < 1/B` (lower): `sign a = sign M₁`, `sign(bc) = sign a`; again **`b > 0`**,
//!   hence `sign c = sign M₁`.
//! * separatrix: `sign a = sign M₁`, `sign c = sign M₃`, `sign b = sign(ac)`.
//!
//! In all cases `abc > 0`, as the paper requires for (sol) with `ν > 0`.
//! `φ` is returned in `(−2K, 2K]` (via [`jacobi_inverse`]); on the separatrix
//! `φ ∈ ℝ` (no period).  [`phi_near`] unwraps by multiples of `4K` so that `φ` is
//! continuous along an orbit.
//!
//! # Finding about the proof of Proposition 3
//! The printed Jacobian `∂(M₁,M₂,M₃)/∂(M²,E,φ) = −dn²φ/(4ν)` does not hold; computed
//! by AD it is `−1/(4ν(M², E))`, independent of `φ`, which is what (PB in ell)
//! `{E, φ} = −2ν` (confirmed) implies because `det ∂(M²,E,φ)/∂M = 2{E, φ}`.  The
//! conclusion (non-vanishing) is unaffected.  See `tests/model/model_elliptic.rs`.

use super::params::{EllipticParams, Regime};
use super::{Inertia, ModelError};
use crate::linalg::Vec3;
use crate::numbers::Real;
use crate::special::{ellipk, jacobi_inverse, sncndn};

/// The signs of `a, b, c` in one sector (each ±1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Sector {
    /// The regime the sector lies in.
    pub regime: Regime,
    /// sign(a).
    pub sa: i8,
    /// sign(b).
    pub sb: i8,
    /// sign(c).
    pub sc: i8,
}

fn sgn<R: Real>(x: &R) -> i8 {
    x.signum_i() as i8
}

impl Sector {
    /// The sector of the point `m` (whose regime is `regime`), by the sign rules in
    /// the module docs.  Errors where the rule needs a sign that is zero (only at the
    /// fixed points on the axes; for the separatrix, on the `M₂` axis).
    pub fn of<R: Real>(regime: Regime, m: &Vec3<R>) -> Result<Sector, ModelError> {
        let [m1, _, m3] = &m.0;
        let s = match regime {
            Regime::Upper => {
                let sc = sgn(m3);
                Sector {
                    regime,
                    sa: sc,
                    sb: 1,
                    sc,
                }
            }
            Regime::Lower => {
                let sa = sgn(m1);
                Sector {
                    regime,
                    sa,
                    sb: 1,
                    sc: sa,
                }
            }
            Regime::Separatrix => {
                let (sa, sc) = (sgn(m1), sgn(m3));
                Sector {
                    regime,
                    sa,
                    sb: sa * sc,
                    sc,
                }
            }
        };
        if s.sa == 0 || s.sc == 0 {
            return Err(ModelError::Undefined(
                "elliptic coordinate phi undefined: point on a coordinate axis (fixed point)"
                    .into(),
            ));
        }
        Ok(s)
    }
}

/// The signed amplitudes `(a, b, c)` of (abc) for a sector.
pub fn amplitudes<R: Real>(p: &EllipticParams<R>, s: Sector) -> (R, R, R) {
    let sg = |x: &R, sign: i8| if sign < 0 { -x.sqrt() } else { x.sqrt() };
    (sg(&p.a2, s.sa), sg(&p.b2, s.sb), sg(&p.c2, s.sc))
}

/// `(sn, cn, dn)(u, k)` for the parameters' modulus; on the separatrix (`k = 1`)
/// `(tanh u, sech u, sech u)`.
pub fn sncndn_params<R: Real>(u: &R, p: &EllipticParams<R>) -> Result<(R, R, R), ModelError> {
    match p.regime {
        Regime::Separatrix => {
            let sech = u.cosh().recip();
            Ok((u.tanh(), sech.clone(), sech))
        }
        _ => Ok(sncndn(u, &p.k())?),
    }
}

/// `Φ(M², E, φ)` (ell coord) in the given sector (hyperbolic formulas on the
/// separatrix).
pub fn phi_to_m<R: Real>(p: &EllipticParams<R>, s: Sector, phi: &R) -> Result<Vec3<R>, ModelError> {
    point_of(p, amplitudes(p, s), phi)
}

/// [`phi_to_m`] with the sector given by the signs of `M₁` and `M₃` as values
/// (`s₁`, `s₃`, each ±1, or for the prover a sign symbol): upper regime
/// `(a, b, c) = s₃·(|a|, |b|/s₃, |c|)`, lower `s₁·(|a|, |b|/s₁, |c|)`, separatrix
/// `(s₁|a|, s₁s₃|b|, s₃|c|)`, as [`Sector::of`] reads them off a point.
///
/// ```
/// use eulertop::model::elliptic_coords::{phi_to_m, phi_to_m_signed};
/// use eulertop::model::{EllipticParams, Inertia, Sector};
/// let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
/// let p = EllipticParams::new(&i, &1.0, &0.6).unwrap();
/// let s = Sector { regime: p.regime, sa: -1, sb: 1, sc: -1 };
/// let m = phi_to_m_signed(&p, &1.0, &-1.0, &0.4).unwrap();
/// assert_eq!(m, phi_to_m(&p, s, &0.4).unwrap());
/// ```
pub fn phi_to_m_signed<R: Real>(
    p: &EllipticParams<R>,
    s1: &R,
    s3: &R,
    phi: &R,
) -> Result<Vec3<R>, ModelError> {
    point_of(p, signed_amplitudes(p, s1.clone(), s3.clone()), phi)
}

/// The point of phase `φ` with the signed amplitudes `(a, b, c)`.
fn point_of<R: Real>(
    p: &EllipticParams<R>,
    (a, b, c): (R, R, R),
    phi: &R,
) -> Result<Vec3<R>, ModelError> {
    let (sn, cn, dn) = sncndn_params(phi, p)?;
    Ok(match p.regime {
        Regime::Upper | Regime::Separatrix => Vec3::new(a * cn, b * sn, c * dn),
        Regime::Lower => Vec3::new(a * dn, b * sn, c * cn),
    })
}

/// A point in elliptic coordinates with the data needed to map it back.
#[derive(Clone, Debug, PartialEq)]
pub struct EllCoords<R> {
    /// Parameters (k), (abc), (nu) of `(M², E)`.
    pub params: EllipticParams<R>,
    /// The sector.
    pub sector: Sector,
    /// `φ`, in `(−2K, 2K]` (any real on the separatrix).
    pub phi: R,
}

/// `Φ⁻¹(M) = (M², E, φ)`.
///
/// Upper regime: `(cn φ, sn φ) = (M₁/a, M₂/b)` normalized to the unit circle; lower:
/// `(cn φ, sn φ) = (M₃/c, M₂/b)`; then `φ` = [`jacobi_inverse`].  Separatrix:
/// `φ = asinh((M₂/b)/(M₁/a))`.  Errors ([`ModelError::Undefined`]) at `M = 0` and on
/// the coordinate axes, where `φ` is undefined.  The phase is [`m_to_phase`]'s.
pub fn m_to_phi<R: Real>(inertia: &Inertia<R>, m: &Vec3<R>) -> Result<EllCoords<R>, ModelError> {
    let (params, phi) = m_to_phase(inertia, m)?;
    let sector = Sector::of(params.regime, m)?;
    Ok(EllCoords {
        params,
        sector,
        phi,
    })
}

fn undefined() -> ModelError {
    ModelError::Undefined(
        "elliptic coordinate phi undefined: point on a coordinate axis (fixed point)".into(),
    )
}

/// The signed amplitudes `(a, b, c)` of the point's sector (the sign rules of the
/// module docs), with the signs as values ([`Real::signum_value`]).  For numbers this
/// is [`amplitudes`] of [`Sector::of`]; the prover's values may carry a sign symbol,
/// so that one normal form covers the sectors of all its sign cases.
fn point_amplitudes<R: Real>(p: &EllipticParams<R>, m: &Vec3<R>) -> Result<(R, R, R), ModelError> {
    let [m1, _, m3] = &m.0;
    // only the signs the regime's sector depends on are taken
    let (s1, s3) = match p.regime {
        Regime::Upper => {
            let s = m3.signum_value();
            (s.clone(), s)
        }
        Regime::Lower => {
            let s = m1.signum_value();
            (s.clone(), s)
        }
        Regime::Separatrix => (m1.signum_value(), m3.signum_value()),
    };
    if s1.is_zero() || s3.is_zero() {
        return Err(undefined());
    }
    Ok(signed_amplitudes(p, s1, s3))
}

/// The amplitudes `(a, b, c)` of the sector with the signs `s₁`, `s₃` of `M₁`, `M₃`
/// (see [`phi_to_m_signed`]).
fn signed_amplitudes<R: Real>(p: &EllipticParams<R>, s1: R, s3: R) -> (R, R, R) {
    let (sa, sb, sc) = match p.regime {
        Regime::Upper => (s3.clone(), s3.one(), s3),
        Regime::Lower => (s1.clone(), s1.one(), s1),
        Regime::Separatrix => (s1.clone(), s1 * s3.clone(), s3),
    };
    (sa * p.a2.sqrt(), sb * p.b2.sqrt(), sc * p.c2.sqrt())
}

/// The parameters and the phase `φ` of [`m_to_phi`], without the sector as signs
/// (so that a value standing for several sectors at once has a phase).
pub fn m_to_phase<R: Real>(
    inertia: &Inertia<R>,
    m: &Vec3<R>,
) -> Result<(EllipticParams<R>, R), ModelError> {
    let params = EllipticParams::from_point(inertia, m)?;
    let (a, b, c) = point_amplitudes(&params, m)?;
    let [m1, m2c, m3] = m.0.clone();
    let phi = match params.regime {
        Regime::Separatrix => {
            if b.is_zero() || a.is_zero() {
                return Err(undefined());
            }
            ((m2c / b) / (m1 / a)).asinh()
        }
        _ => {
            // upper: M = (a cn, b sn, c dn); lower: M = (a dn, b sn, c cn)
            let (x, y, z, amp, amp_z) = match params.regime {
                Regime::Upper => (m1, m2c, m3, a, c),
                _ => (m3, m2c, m1, c, a),
            };
            if amp.is_zero() || b.is_zero() || amp_z.is_zero() {
                return Err(undefined());
            }
            let (x, y) = (x / amp, y / b);
            let r = (x.sqr() + y.sqr()).sqrt();
            if r.is_zero() || !r.is_finite() {
                return Err(undefined());
            }
            let (cn, sn) = (x / r.clone(), y / r.clone());
            let k = params.k();
            // dn from its own coordinate, so that an exact evaluation has it as a rational
            // function of M (the inverse checks dn² + k² sn² = 1)
            let dn = z / amp_z;
            jacobi_inverse(&sn, &cn, &dn, &k)?
        }
    };
    Ok((params, phi))
}

/// The complete elliptic integral `K(k)` for the parameters (`None` on the
/// separatrix, where the motion is not periodic).
pub fn quarter_period<R: Real>(p: &EllipticParams<R>) -> Result<Option<R>, ModelError> {
    match p.regime {
        Regime::Separatrix => Ok(None),
        _ => Ok(Some(ellipk(&p.k())?)),
    }
}

/// `Φ⁻¹(M)` with `φ` shifted by a multiple of `4K` to be closest to `prev` (so that
/// `φ` is continuous along an orbit).
pub fn phi_near<R: Real>(
    inertia: &Inertia<R>,
    m: &Vec3<R>,
    prev: &R,
) -> Result<EllCoords<R>, ModelError> {
    let mut c = m_to_phi(inertia, m)?;
    if let Some(k) = quarter_period(&c.params)? {
        let per = k * c.phi.from_i64(4);
        let n = ((prev.clone() - c.phi.clone()) / per.clone()).round();
        c.phi = c.phi.clone() + n * per;
    }
    Ok(c)
}
