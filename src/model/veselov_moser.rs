//! The Veselov–Moser discretization in matrix form (Section 8): the hat map (M m),
//! (Omega m), `J` from (J)/(Js), the relation (M thru omega) solved for `ω ∈ SO(3)` on
//! the branch (omega as), the step (VM), the six roots of
//! `det(I − hλM − λ²J²)` and their split into `S₊`/`S₋`.
//!
//! # Branch choice
//! `ω` is parametrized by the Cayley transform `ω = (I+V)(I−V)⁻¹`, `V = V̌` skew
//! (the (M m) hat of a vector `v`), which is in SO(3) for every real `v`.  Newton's
//! method on the three components of the skew residual `ωJ − Jωᵀ − hM` starts from
//! `v = ½hΩ(M)` (because `ω = I + 2V + O(V²)` and (omega as) `ω = I + hΩ + O(h²)`), so
//! for small `h` it converges to the unique solution with `V = O(h)`, i.e. the branch
//! (omega as) whose `S₋` roots are close to `1/J₁, 1/J₂, 1/J₃`.  Jacobians are
//! computed with [`Dual`] numbers.  Stopping rule and errors as in
//! [`discretization`](super::discretization): relative residual (scaled by
//! `max(‖J‖, h‖M‖)`) at most `16·2^(−p)`, otherwise [`ModelError::NewtonFailed`].

use super::discretization::inf_norm;
use super::ladder::{AtPrec, ladder};
use super::{Inertia, ModelError};
use crate::linalg::{Mat3, Vec3};
use crate::numbers::{ComplexScalar, Cplx, Dual, Real, Scalar};

/// The hat map (M m): `v ↦ [[0, v₃, −v₂], [−v₃, 0, v₁], [v₂, −v₁, 0]]` — minus the
/// usual hat map, so that `[v̌, w̌] = (w ×_std v)ˇ` (see the [module note](super)).
pub fn hat<S: Scalar>(v: &Vec3<S>) -> Mat3<S> {
    let [v1, v2, v3] = v.0.clone();
    let z = v1.zero();
    Mat3([
        [z.clone(), v3.clone(), -v2.clone()],
        [-v3, z.clone(), v1.clone()],
        [v2, -v1, z],
    ])
}

/// Inverse of [`hat`] on skew matrices: `(M₂₃, M₃₁, M₁₂)` (1-based).
pub fn vee<S: Scalar>(m: &Mat3<S>) -> Vec3<S> {
    Vec3::new(m.0[1][2].clone(), m.0[2][0].clone(), m.0[0][1].clone())
}

/// (Omega m): `Ω(M)` as a skew matrix, the [`hat`] of (Omega).
pub fn omega_matrix<R: Scalar + PartialOrd>(inertia: &Inertia<R>, m: &Vec3<R>) -> Mat3<R> {
    hat(&inertia.omega(m))
}

/// The diagonal of `J` (J) from (Js): `J₁ = (B+C−A)/2`, `J₂ = (C+A−B)/2`,
/// `J₃ = (A+B−C)/2`.  (`J₁` may be ≤ 0 when `A ≥ B + C`.)
pub fn j_diag<R: Scalar + PartialOrd>(inertia: &Inertia<R>) -> Vec3<R> {
    let (a, b, c) = (&inertia.a, &inertia.b, &inertia.c);
    let half = a.from_ratio(1, 2);
    Vec3::new(
        (b.clone() + c.clone() - a.clone()) * half.clone(),
        (c.clone() + a.clone() - b.clone()) * half.clone(),
        (a.clone() + b.clone() - c.clone()) * half,
    )
}

/// The Cayley transform `ω = (I+V)(I−V)⁻¹` with `V = hat(v)`; always in SO(3).
///
/// Computed in the closed form `ω = I + 2(V + V²)/(1 + |v|²)` with
/// `V² = v vᵀ − |v|² I`: for a skew `V`, `V³ = −|v|²V`, so multiplying the right side
/// by `I − V` gives `I − V + 2(V − V³)/(1 + |v|²) = I + V`.  One division and products
/// only, no matrix inverse; `1 + |v|² ≥ 1` for real `v` (a complex `v` with
/// `1 + v·v = 0`, where `I − V` is singular, gives the identity).
///
/// ```
/// use eulertop::linalg::Vec3;
/// use eulertop::model::veselov_moser::cayley;
/// let w = cayley(&Vec3::new(0.3, -0.2, 0.5));
/// let id = w.clone() * w.transpose();
/// for i in 0..3 {
///     for j in 0..3 {
///         let e: f64 = if i == j { 1.0 } else { 0.0 };
///         assert!((id.0[i][j] - e).abs() < 1e-15);
///     }
/// }
/// ```
pub fn cayley<S: Scalar>(v: &Vec3<S>) -> Mat3<S> {
    let vm = hat(v);
    let one = v.0[0].one();
    let [v1, v2, v3] = &v.0;
    let n2 = v1.clone() * v1.clone() + v2.clone() * v2.clone() + v3.clone() * v3.clone();
    let den = one.clone() + n2.clone();
    if den.is_zero() {
        return Mat3::identity(&one);
    }
    let c = (one.clone() + one.clone()) / den;
    Mat3::from_fn(|i, j| {
        let outer = v.0[i].clone() * v.0[j].clone();
        let square = if i == j { outer - n2.clone() } else { outer };
        let e = c.clone() * (vm.0[i][j].clone() + square);
        if i == j { one.clone() + e } else { e }
    })
}

/// The skew residual `vee(ωJ − Jωᵀ − hM̌)` of (M thru omega) at `ω = cayley(v)`, with
/// `j = J` and `hm = hM̌`: the equations [`vm_step`] solves for `v`, and that the prover
/// uses as the definition of `ω`.
pub fn omega_residual<S: Scalar>(v: &Vec3<S>, j: &Mat3<S>, hm: &Mat3<S>) -> Vec3<S> {
    let w = cayley(v);
    vee(&(w.clone() * j.clone() - j.clone() * w.transpose() - hm.clone()))
}

/// [`omega_residual`] for a diagonal `J`, given by its diagonal `j`: the three entries
/// `(ωJ − Jωᵀ − hM̌)ᵢₖ = ωᵢₖJₖ − Jᵢωₖᵢ − hM̌ᵢₖ` that [`vee`] reads, from the six
/// off-diagonal entries `ωᵢₖ = c(Vᵢₖ + vᵢvₖ)`, `c = 2/(1 + |v|²)`, of `ω = cayley(v)`.
///
/// ```
/// use eulertop::linalg::{Mat3, Vec3};
/// use eulertop::model::veselov_moser::{hat, omega_residual, omega_residual_diag};
/// let (v, j) = (Vec3::new(0.1, -0.2, 0.3), Vec3::new(0.5, 1.5, 2.5));
/// let hm = hat(&Vec3::new(0.7, 0.1, -0.4));
/// let full = omega_residual(&v, &Mat3::diag(&j), &hm);
/// let diag = omega_residual_diag(&v, &j, &hm);
/// assert!((full - diag).max_magnitude() < 1e-15);
/// ```
pub fn omega_residual_diag<S: Scalar>(v: &Vec3<S>, j: &Vec3<S>, hm: &Mat3<S>) -> Vec3<S> {
    let [v1, v2, v3] = &v.0;
    let one = v1.one();
    let n2 = v1.clone() * v1.clone() + v2.clone() * v2.clone() + v3.clone() * v3.clone();
    let c = (one.clone() + one.clone()) / (one + n2);
    let vm = hat(v);
    let w = |i: usize, k: usize| c.clone() * (vm.0[i][k].clone() + v.0[i].clone() * v.0[k].clone());
    let x = |i: usize, k: usize| {
        w(i, k) * j.0[k].clone() - j.0[i].clone() * w(k, i) - hm.0[i][k].clone()
    };
    Vec3::new(x(1, 2), x(2, 0), x(0, 1))
}

/// The residual of (M thru omega) at `v` and its Jacobian in `v`, by [`Dual`] numbers
/// (one pass per column), for a diagonal `J` (see [`omega_residual_diag`]).
fn residual_and_jacobian<R: Real>(
    v: &Vec3<R>,
    jd: &Vec3<Dual<R>>,
    hmd: &Mat3<Dual<R>>,
) -> (Vec3<R>, Mat3<R>) {
    let mut jac = Mat3::zeros(&v.0[0]);
    let mut res = Vec3::zeros(&v.0[0]);
    for col in 0..3 {
        let vd = Vec3(std::array::from_fn(|k| {
            let x = v.0[k].clone();
            let d = if k == col { x.one() } else { x.zero() };
            Dual::new(x, d)
        }));
        let r = omega_residual_diag(&vd, jd, hmd);
        for row in 0..3 {
            jac.0[row][col] = r.0[row].d.clone();
        }
        res = Vec3(r.0.map(|x| x.v));
    }
    (res, jac)
}

/// One Veselov–Moser step with its by-products.
#[derive(Clone, Debug, PartialEq)]
pub struct VmStep<R> {
    /// `ω ∈ SO(3)` solving (M thru omega) on the branch (omega as).
    pub omega: Mat3<R>,
    /// `M̂` from (VM) `M̂ = ωᵀMω`, as a vector.
    pub m_hat: Vec3<R>,
    /// The Cayley vector `v` of `ω = cayley(v)`.
    pub v: Vec3<R>,
    /// Newton iterations used (at full precision: above
    /// [`LADDER_BITS`](super::ladder::LADDER_BITS) bits the iteration starts at the
    /// solution at about half the precision, module [`ladder`](super::ladder)).
    pub iterations: usize,
}

/// Solves (M thru omega) `hM = ωJ − Jωᵀ` for `ω` (branch: see module docs) and
/// returns the (VM) step `M̂ = ωᵀMω`.
pub fn vm_step<R: Real>(inertia: &Inertia<R>, m: &Vec3<R>, h: &R) -> Result<VmStep<R>, ModelError> {
    super::discretization::check_m2_finite(m, &inf_norm(m), &|| "(M thru omega)".into())?;
    let jv = j_diag(inertia);
    let jm = Mat3::diag(&jv);
    let mm = hat(m);
    let hm = mm.scale(h);
    let half = h.from_ratio(1, 2);
    let mut v = ladder(h, |q| {
        vm_step(&inertia.at_prec(q), &m.at_prec(q), &h.at_prec(q)).map(|s| s.v)
    })
    .unwrap_or_else(|| inertia.omega(m).scale(&(h.clone() * half)));
    let jd = Vec3(jv.0.clone().map(Dual::constant));
    let hmd = Mat3::from_fn(|i, k| Dual::constant(hm.0[i][k].clone()));
    let eps = h.epsilon();
    let scale = inf_norm(&jv).max_of(&(h.abs() * inf_norm(m)));
    let fail = |it: usize, r: f64| ModelError::NewtonFailed {
        what: "(M thru omega)".into(),
        iterations: it,
        residual: r,
    };
    let max_iter = 100;
    let mut prev: Option<R> = None;
    let mut it = 0;
    loop {
        if it >= max_iter {
            return Err(fail(it, f64::NAN));
        }
        let (res, jac) = residual_and_jacobian(&v, &jd, &hmd);
        let inv = jac.inverse().ok_or_else(|| fail(it, f64::NAN))?;
        let dv = inv.mul_vec(&res);
        v = v - dv.clone();
        it += 1;
        let dn = inf_norm(&dv);
        if !dn.is_finite() {
            return Err(fail(it, f64::NAN));
        }
        let vs = inf_norm(&v).max_of(&h.abs());
        if dn <= eps.clone() * vs.from_i64(4) * vs.clone() {
            break;
        }
        if let Some(p) = &prev
            && dn >= *p
            && dn <= eps.sqrt() * vs
        {
            break;
        }
        prev = Some(dn);
    }
    let r = omega_residual(&v, &jm, &hm);
    let rel = inf_norm(&r) / scale;
    if rel > eps.mul_2si(3) || !rel.is_finite() {
        return Err(fail(it, rel.to_f64()));
    }
    let w = cayley(&v);
    let m_hat = vm_conjugate(&w, m);
    Ok(VmStep {
        omega: w,
        m_hat,
        v,
        iterations: it,
    })
}

/// (VM) `M̂ = ωᵀMω` (on hat matrices), as a vector.
pub fn vm_conjugate<S: Scalar>(w: &Mat3<S>, m: &Vec3<S>) -> Vec3<S> {
    vee(&(w.transpose() * hat(m) * w.clone()))
}

/// Coefficients (constant term first) of `det P(λ)` for a 3×3 matrix polynomial
/// given entrywise by coefficient lists.
pub fn det_poly<S: Scalar>(p: &[[Vec<S>; 3]; 3], like: &S) -> Vec<S> {
    fn mul<S: Scalar>(a: &[S], b: &[S], like: &S) -> Vec<S> {
        let mut out = vec![like.zero(); a.len() + b.len() - 1];
        for (i, x) in a.iter().enumerate() {
            for (j, y) in b.iter().enumerate() {
                out[i + j] = out[i + j].clone() + x.clone() * y.clone();
            }
        }
        out
    }
    fn add<S: Scalar>(a: &[S], b: &[S], sign: bool, like: &S) -> Vec<S> {
        let n = a.len().max(b.len());
        (0..n)
            .map(|i| {
                let x = a.get(i).cloned().unwrap_or_else(|| like.zero());
                let y = b.get(i).cloned().unwrap_or_else(|| like.zero());
                if sign { x + y } else { x - y }
            })
            .collect()
    }
    let perms: [([usize; 3], bool); 6] = [
        ([0, 1, 2], true),
        ([1, 2, 0], true),
        ([2, 0, 1], true),
        ([0, 2, 1], false),
        ([2, 1, 0], false),
        ([1, 0, 2], false),
    ];
    let mut acc = vec![like.zero()];
    for (s, sign) in perms {
        let t = mul(&mul(&p[0][s[0]], &p[1][s[1]], like), &p[2][s[2]], like);
        acc = add(&acc, &t, sign, like);
    }
    acc
}

/// Coefficients of `det(I − hλM − λ²J²)` (constant term first, degree 6), with `M`
/// the (M m) matrix of `m`.
pub fn lambda_poly<R: Real>(inertia: &Inertia<R>, m: &Vec3<R>, h: &R) -> Vec<R> {
    let jv = j_diag(inertia);
    let mm = hat(m);
    let z = h.zero();
    let p: [[Vec<R>; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|k| {
            let c0 = if i == k { h.one() } else { z.clone() };
            let c1 = -(h.clone() * mm.0[i][k].clone());
            let c2 = if i == k { -jv.0[i].sqr() } else { z.clone() };
            vec![c0, c1, c2]
        })
    });
    det_poly(&p, h)
}

/// All complex roots of a real polynomial (constant term first) by the
/// Weierstrass–Durand–Kerner iteration in `Cplx<R>`, iterated until the largest
/// correction is below `4ε` relative (cap 1000 sweeps; then
/// [`ModelError::NewtonFailed`]).  Errors if the leading coefficient is zero.
pub fn poly_roots<R: Real>(coef: &[R]) -> Result<Vec<Cplx<R>>, ModelError> {
    if coef.len() < 2 {
        return Err(ModelError::Undefined(
            "polynomial of degree < 1 has no roots to find".into(),
        ));
    }
    let n = coef.len() - 1;
    let lead = coef[n].clone();
    if lead.is_zero() {
        return Err(ModelError::Undefined(
            "polynomial has zero leading coefficient".into(),
        ));
    }
    let like = lead.zero();
    let c: Vec<Cplx<R>> = coef
        .iter()
        .map(|x| Cplx::new(x.clone() / lead.clone(), like.clone()))
        .collect();
    // Cauchy bound for the root radius
    let mut rad = like.one();
    for x in &c[..n] {
        rad = rad.max_of(&(x.re.abs() + like.one()));
    }
    let seed = Cplx::new(like.from_f64(0.4), like.from_f64(0.9));
    let mut z: Vec<Cplx<R>> = (0..n)
        .map(|k| seed.powi(k as i32 + 1) * Cplx::new(rad.clone(), like.clone()))
        .collect();
    let eval = |x: &Cplx<R>| {
        let mut acc = c[n].clone();
        for k in (0..n).rev() {
            acc = acc * x.clone() + c[k].clone();
        }
        acc
    };
    let eps = like.epsilon().mul_2si(2);
    for _ in 0..1000 {
        let mut maxrel = like.zero();
        for i in 0..n {
            let mut den = Cplx::new(like.one(), like.clone());
            for (j, zj) in z.iter().enumerate() {
                if j != i {
                    den = den * (z[i].clone() - zj.clone());
                }
            }
            let corr = eval(&z[i]) / den;
            let rel = ComplexScalar::abs(&corr) / ComplexScalar::abs(&z[i]).max_of(&like.one());
            if !rel.is_finite() {
                return Err(ModelError::NewtonFailed {
                    what: "polynomial roots".into(),
                    iterations: 0,
                    residual: f64::NAN,
                });
            }
            maxrel = maxrel.max_of(&rel);
            z[i] = z[i].clone() - corr;
        }
        if maxrel <= eps {
            return Ok(z);
        }
    }
    Err(ModelError::NewtonFailed {
        what: "polynomial roots".into(),
        iterations: 1000,
        residual: f64::NAN,
    })
}

/// The set `S` of the six roots of `det(I − hλM − λ²J²) = 0`.
pub fn lambda_roots<R: Real>(
    inertia: &Inertia<R>,
    m: &Vec3<R>,
    h: &R,
) -> Result<Vec<Cplx<R>>, ModelError> {
    poly_roots(&lambda_poly(inertia, m, h))
}

/// `(S₊, S₋)`: the roots of `det(ω + λJ) = 0` and of `det(ωᵀ − λJ) = 0`.
#[allow(clippy::type_complexity)]
pub fn split_roots<R: Real>(
    inertia: &Inertia<R>,
    omega: &Mat3<R>,
) -> Result<(Vec<Cplx<R>>, Vec<Cplx<R>>), ModelError> {
    let jv = j_diag(inertia);
    let like = jv.0[0].clone();
    let z = like.zero();
    let build = |w: &Mat3<R>, s: R| -> [[Vec<R>; 3]; 3] {
        std::array::from_fn(|i| {
            std::array::from_fn(|k| {
                let c1 = if i == k {
                    s.clone() * jv.0[i].clone()
                } else {
                    z.clone()
                };
                vec![w.0[i][k].clone(), c1]
            })
        })
    };
    let plus = det_poly(&build(omega, like.one()), &like);
    let minus = det_poly(&build(&omega.transpose(), -like.one()), &like);
    Ok((poly_roots(&plus)?, poly_roots(&minus)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hat_is_minus_usual_and_brackets() {
        let a = Vec3::new(0.3, -0.7, 1.1);
        let b = Vec3::new(-0.2, 0.5, 0.9);
        let lhs = hat(&a).commutator(&hat(&b));
        let rhs = hat(&b.cross(&a));
        assert!((lhs - rhs).max_magnitude() < 1e-15);
        assert_eq!(vee(&hat(&a)), a);
    }

    #[test]
    fn m_thru_omega_identity() {
        // (M thru Omega): M = JΩ + ΩJ
        let i = Inertia::new(3.0, 2.0, 1.5).unwrap();
        let m = Vec3::new(0.3, -0.7, 1.1);
        let j = Mat3::diag(&j_diag(&i));
        let om = omega_matrix(&i, &m);
        let r = j.clone() * om.clone() + om * j - hat(&m);
        assert!(r.max_magnitude() < 1e-15);
    }
}
