//! The su(2) Lax representation of Section 5: the elliptic functions `w_k(u)` (ws)
//! with `ρ`, `κ` from (rokappa), the matrices `M(u)` (2x2 M), `V(u)` (2x2 V) and the
//! discrete `𝒱(u)` (2x2 dV), built from the Pauli matrices
//! [`Mat2::pauli`](crate::linalg::Mat2::pauli).
//!
//! # Finding about (u0)
//! For every `u`, (ws) gives `w₁² − w₃² = ρ²(1 − cn²)/sn² = ρ²` and
//! `w₁² − w₂² = ρ²κ²`.  The conditions (u0) `w₁(u₀) = A^{−1/2}`, `w₂(u₀) = B^{−1/2}`,
//! `w₃(u₀) = C^{−1/2}` need `w₁² − w₃² = 1/A − 1/C < 0` and
//! `w₁² − w₂² = 1/A − 1/B < 0`, whereas (rokappa) gives `ρ² = 1/C − 1/A > 0`,
//! `ρ²κ² = 1/B − 1/A > 0`: **(u0) has no solution, not even a complex one, with `ρ²` as
//! printed.**  With `ρ² = −(A−C)/(AC)` (i.e. `ρ = i·√((A−C)/(AC))`), it is solved by
//! the purely imaginary `u₀ = i·F(asin √((A−C)/A), κ')`, `κ' = √(1−κ²)`
//! ([`u0_corrected`]).  [`u0_defects`] returns the two printed mismatches.

use super::{Inertia, ModelError};
use crate::linalg::{Mat2, Vec3};
use crate::numbers::{ComplexScalar, Cplx, Real, Scalar};
use crate::special::{ellipf, sncndn_complex};

/// `(ρ², κ²)` exactly as printed in (rokappa): `ρ² = (A−C)/(AC)`,
/// `κ² = C(A−B)/(B(A−C))`.
pub fn rho2_kappa2<R: Real>(inertia: &Inertia<R>) -> (R, R) {
    let (a, b, c) = (&inertia.a, &inertia.b, &inertia.c);
    let ac = a.clone() - c.clone();
    (
        ac.clone() / (a.clone() * c.clone()),
        c.clone() * (a.clone() - b.clone()) / (b.clone() * ac),
    )
}

/// `[w₁(u), w₂(u), w₃(u)]` of (ws): `ρ/sn`, `ρ dn/sn`, `ρ cn/sn` with modulus `κ`, for
/// complex `u` and a (possibly complex) `ρ`.  Errors at poles (`sn(u) = 0`).
pub fn w<R: Real>(u: &Cplx<R>, rho: &Cplx<R>, kappa: &R) -> Result<[Cplx<R>; 3], ModelError> {
    let (sn, cn, dn) = sncndn_complex(u, kappa)?;
    if ComplexScalar::abs(&sn).is_zero() {
        return Err(ModelError::Undefined("w_k(u): pole at sn(u) = 0".into()));
    }
    let r = rho.clone() / sn;
    Ok([r.clone(), r.clone() * dn, r * cn])
}

/// `(1/2i) Σ_k X_k w_k σ_k` — (2x2 M) with `X = M`, `w = w(u)`, and (2x2 V) with
/// `X = V`, `w = w(u − u₀)`.
pub fn su2_matrix<R: Real>(x: &Vec3<R>, w: &[Cplx<R>; 3]) -> Mat2<Cplx<R>> {
    let like = &w[0];
    let z = like.zero();
    let two_i = Cplx::new(z.re.clone(), z.re.from_i64(2));
    let mut acc = Mat2::zeros(like);
    for (k, wk) in w.iter().enumerate() {
        let s = Mat2::pauli(k + 1, like).unwrap_or_else(|| Mat2::zeros(like));
        let coef = Cplx::from_real(x.0[k].clone()) * wk.clone() / two_i.clone();
        acc = acc + s.scale(&coef);
    }
    acc
}

/// (2x2 M): `M(u) = (1/2i) Σ M_k w_k(u) σ_k`.
pub fn lax_m<R: Real>(
    m: &Vec3<R>,
    u: &Cplx<R>,
    rho: &Cplx<R>,
    kappa: &R,
) -> Result<Mat2<Cplx<R>>, ModelError> {
    Ok(su2_matrix(m, &w(u, rho, kappa)?))
}

/// (2x2 V): `V(u) = (1/2i) Σ V_k w_k(u − u₀) σ_k`.
pub fn lax_v<R: Real>(
    v: &Vec3<R>,
    u: &Cplx<R>,
    u0: &Cplx<R>,
    rho: &Cplx<R>,
    kappa: &R,
) -> Result<Mat2<Cplx<R>>, ModelError> {
    Ok(su2_matrix(v, &w(&(u.clone() - u0.clone()), rho, kappa)?))
}

/// (2x2 dV): `𝒱(u) = I + (h/2i) Σ V_k w_k(u − u₀) σ_k = I + h·V(u)`.
pub fn lax_dv<R: Real>(
    v: &Vec3<R>,
    u: &Cplx<R>,
    u0: &Cplx<R>,
    h: &R,
    rho: &Cplx<R>,
    kappa: &R,
) -> Result<Mat2<Cplx<R>>, ModelError> {
    let vm = lax_v(v, u, u0, rho, kappa)?;
    let like = Cplx::from_real(h.clone());
    Ok(Mat2::identity(&like) + vm.scale(&like))
}

/// `Ω^{1/2}(V) = (V₁/√A, V₂/√B, V₃/√C)` as used in (gET 1), (gET 2), (dgET aux).
pub fn omega_half<R: Real>(inertia: &Inertia<R>, v: &Vec3<R>) -> Vec3<R> {
    let [v1, v2, v3] = v.0.clone();
    Vec3::new(
        v1 / inertia.a.sqrt(),
        v2 / inertia.b.sqrt(),
        v3 / inertia.c.sqrt(),
    )
}

/// The two identities (u0) would need, minus what (ws)/(rokappa) force:
/// `((1/A − 1/C) − ρ², (1/A − 1/B) − ρ²κ²)`; both are nonzero for A > B > C > 0.
pub fn u0_defects<R: Real>(inertia: &Inertia<R>) -> (R, R) {
    let (r2, k2) = rho2_kappa2(inertia);
    let (ia, ib, ic) = (inertia.a.recip(), inertia.b.recip(), inertia.c.recip());
    (ia.clone() - ic - r2.clone(), ia - ib - r2 * k2)
}

/// The corrected data `(ρ, u₀)` with `ρ = i·√((A−C)/(AC))` and
/// `u₀ = i·F(asin √((A−C)/A), κ')`, which satisfy (u0) (see the module docs).
pub fn u0_corrected<R: Real>(inertia: &Inertia<R>) -> Result<(Cplx<R>, Cplx<R>), ModelError> {
    let (r2, k2) = rho2_kappa2(inertia);
    let z = r2.zero();
    let kp = (z.one() - k2).sqrt();
    let s = ((inertia.a.clone() - inertia.c.clone()) / inertia.a.clone()).sqrt();
    let v = ellipf(&s.asin(), &kp)?;
    Ok((Cplx::new(z.clone(), r2.sqrt()), Cplx::new(z, v)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn printed_u0_inconsistent_corrected_works() {
        let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
        let (d1, d2) = u0_defects(&i);
        assert!(d1.abs() > 0.1 && d2.abs() > 0.1);
        let (r2, k2) = rho2_kappa2(&i);
        let kappa = k2.sqrt();
        // identity w1² − w3² = ρ² at an arbitrary complex u, with the printed ρ
        let rho = Cplx::new(r2.sqrt(), 0.0);
        let u = Cplx::new(0.37, 0.21);
        let [w1, w2, w3] = w(&u, &rho, &kappa).unwrap();
        let e = w1.clone() * w1.clone() - w3.clone() * w3 - Cplx::new(r2, 0.0);
        assert!(ComplexScalar::abs(&e) < 1e-13);
        let e2 = w1.clone() * w1 - w2.clone() * w2 - Cplx::new(r2 * k2, 0.0);
        assert!(ComplexScalar::abs(&e2) < 1e-13);
        // corrected (ρ, u₀) satisfies (u0)
        let (rho_c, u0) = u0_corrected(&i).unwrap();
        let ws = w(&u0, &rho_c, &kappa).unwrap();
        let target = [1.0 / 3.0f64.sqrt(), 1.0 / 2.0f64.sqrt(), 1.0];
        for k in 0..3 {
            assert!((ws[k].re - target[k]).abs() < 1e-12, "{k}: {:?}", ws[k]);
            assert!(ws[k].im.abs() < 1e-12);
        }
    }
}
