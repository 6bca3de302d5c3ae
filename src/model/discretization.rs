//! Special discretizations (Section 5): the implicit map (impl spec) /
//! (impl spec 1–3) `M̂ − M = ¼hγ(M, M̂, h)·(M+M̂) × Ω(M+M̂)` for the four functions γ
//! of the paper — γ₀ ≡ 1 (Section 7), γ₁ (gamma1), γ₂ (gamma2) and γ_VM (gammaMV) —
//! and a Newton solver for `M̂` at the working precision of the scalar.
//!
//! The cross product is the paper's, i.e. the component form (impl spec 1–3):
//! `M̂₁ − M₁ = ¼hγ(1/B − 1/C)(M₂+M̂₂)(M₃+M̂₃)` and cyclic (see the
//! [module-level note](super)).
//!
//! # Newton solver
//! Unknown `X = M̂`, residual `F(X) = X − M − ¼hγ(M, X, h)·f(M+X)` with `f` the (ET)
//! field [`Inertia::field_et`].  The 3×3 Jacobian is analytic (`∂γ/∂M̂` included;
//! checked against [`Dual`](crate::numbers::Dual) numbers in the tests).  Predictor: the explicit midpoint
//! step `M + h f(M + ½h f(M))`, which is `O(h³)` from the solution.  Iteration stops
//! when the update is below `4·ε·‖X‖∞` (ε = `2^(1−p)`) or stops decreasing; the result
//! is accepted only if the relative residual `‖F(X)‖∞ / max(‖M‖∞, ‖X‖∞)` is at most
//! `16·2^(−p)`, otherwise [`ModelError::NewtonFailed`] is returned (also on a
//! singular Jacobian, non-finite values or when the iteration cap is reached).  Above
//! [`LADDER_BITS`](super::ladder::LADDER_BITS) bits the iteration starts instead at the
//! solution at about half the precision (module [`ladder`](super::ladder)), and
//! [`StepReport::iterations`] counts the steps at full precision.
//! γ_VM returns [`ModelError::ImaginarySqrt`] when its radicand is negative.
//!
//! For small `h` the Newton iterate is the solution branch with `M̂ → M` as `h → 0`
//! (Proposition 1).  For large `h` (impl spec) may have several solutions; a returned
//! `M̂` always satisfies (impl spec) to working precision (and so preserves `M²`, `E`),
//! but it need not lie on the branch continuous in `h`.

use super::ladder::{AtPrec, ladder};
use super::{Inertia, ModelError};
use crate::linalg::{Mat3, Vec3};
use crate::numbers::Real;

/// The function γ(M, M̂, h) of (impl spec).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Gamma {
    /// γ₀ ≡ 1 (Section 7, non-Poisson).
    G0,
    /// γ₁ = 4M² / ⟨M+M̂, M+M̂⟩ (gamma1).
    G1,
    /// γ₂ = 4E / ⟨M+M̂, Ω(M+M̂)⟩ (gamma2).
    G2,
    /// γ_VM = 2 / (1 + √(1 − ¼h²‖Ω(M+M̂)‖²)) (gammaMV).
    Vm,
}

impl Gamma {
    /// Parses `0`, `1`, `2` or `vm`.
    pub fn parse(s: &str) -> Option<Gamma> {
        match s.trim().to_ascii_lowercase().as_str() {
            "0" => Some(Gamma::G0),
            "1" => Some(Gamma::G1),
            "2" => Some(Gamma::G2),
            "vm" => Some(Gamma::Vm),
            _ => None,
        }
    }

    /// Name as in the paper.
    pub fn name(&self) -> &'static str {
        match self {
            Gamma::G0 => "gamma0",
            Gamma::G1 => "gamma1",
            Gamma::G2 => "gamma2",
            Gamma::Vm => "gammaVM",
        }
    }

    /// γ(M, M̂, h) exactly as printed in (gamma1), (gamma2), (gammaMV) (γ₀ ≡ 1).
    /// `M²` and `E` in (gamma1), (gamma2) are those of `M`.
    pub fn eval<R: Real>(
        &self,
        inertia: &Inertia<R>,
        m: &Vec3<R>,
        mhat: &Vec3<R>,
        h: &R,
    ) -> Result<R, ModelError> {
        let (num, den) = self.fraction(inertia, m, mhat, h)?;
        Ok(num / den)
    }

    /// γ as printed, as a numerator and a denominator: `(4M², ⟨S, S⟩)`,
    /// `(4E, ⟨S, ΩS⟩)`, `(2, 1 + √(1 − h²|ΩS|²/4))` with `S = M + M̂`, and `(1, 1)` for γ₀.
    pub fn fraction<R: Real>(
        &self,
        inertia: &Inertia<R>,
        m: &Vec3<R>,
        mhat: &Vec3<R>,
        h: &R,
    ) -> Result<(R, R), ModelError> {
        let one = h.one();
        let s = m.clone() + mhat.clone();
        let four = one.from_i64(4);
        Ok(match self {
            Gamma::G0 => (one.clone(), one),
            Gamma::G1 => (four * m.norm2(), s.norm2()),
            Gamma::G2 => (four * inertia.energy(m), s.dot(&inertia.omega(&s))),
            Gamma::Vm => (one.from_i64(2), one + vm_root(inertia, &s, h)?),
        })
    }

    /// γ and its gradient with respect to `M̂` (γ alone is [`Gamma::eval`], which the
    /// symbolic backend uses: it spares the gradient's divisions).
    pub fn eval_grad<R: Real>(
        &self,
        inertia: &Inertia<R>,
        m: &Vec3<R>,
        mhat: &Vec3<R>,
        h: &R,
    ) -> Result<(R, Vec3<R>), ModelError> {
        let one = h.one();
        let s = m.clone() + mhat.clone();
        let g = self.eval(inertia, m, mhat, h)?;
        let two = one.from_i64(2);
        let grad = match self {
            Gamma::G0 => Vec3::zeros(&one),
            Gamma::G1 => s.scale(&(-(g.clone() * two) / s.norm2())),
            Gamma::G2 => {
                let om = inertia.omega(&s);
                let n = s.dot(&om);
                om.scale(&(-(g.clone() * two) / n))
            }
            Gamma::Vm => {
                let r = vm_root(inertia, &s, h)?;
                if r.is_zero() {
                    Vec3::zeros(&one)
                } else {
                    let om2 = inertia.omega(&inertia.omega(&s));
                    om2.scale(&(g.sqr() * h.sqr() / (one.from_i64(8) * r)))
                }
            }
        };
        Ok((g, grad))
    }
}

/// `√(1 − h²|ΩS|²/4)`, the root in (gammaMV); an error where the radicand is negative.
fn vm_root<R: Real>(inertia: &Inertia<R>, s: &Vec3<R>, h: &R) -> Result<R, ModelError> {
    let one = h.one();
    let q = one.clone() - h.sqr() * inertia.omega(s).norm2() / one.from_i64(4);
    if q < one.zero() || !q.is_finite() {
        return Err(ModelError::ImaginarySqrt(q.to_f64()));
    }
    Ok(q.sqrt())
}

/// The residual of (impl spec 1–3): `M̂ − M − ¼hγ(M,M̂,h)·f(M+M̂)`, with `f` the
/// (ET) component field.
pub fn residual<R: Real>(
    inertia: &Inertia<R>,
    gamma: Gamma,
    m: &Vec3<R>,
    mhat: &Vec3<R>,
    h: &R,
) -> Result<Vec3<R>, ModelError> {
    let g = gamma.eval(inertia, m, mhat, h)?;
    let s = m.clone() + mhat.clone();
    let f = inertia.field_et(&s);
    let coef = h.clone() * g / h.from_i64(4);
    Ok(mhat.clone() - m.clone() - f.scale(&coef))
}

/// The residual of (impl spec 1–3) times the denominator `d` of γ = n/d
/// ([`Gamma::fraction`]): `d·(M̂ − M) − ¼h·n·f(M+M̂)`, with `d`.  It vanishes where
/// [`residual`] does, wherever `d ≠ 0`, and needs no division.
pub fn residual_cleared<R: Real>(
    inertia: &Inertia<R>,
    gamma: Gamma,
    m: &Vec3<R>,
    mhat: &Vec3<R>,
    h: &R,
) -> Result<(Vec3<R>, R), ModelError> {
    let (n, d) = gamma.fraction(inertia, m, mhat, h)?;
    let s = m.clone() + mhat.clone();
    let f = inertia.field_et(&s);
    let coef = h.clone() * n / h.from_i64(4);
    Ok(((mhat.clone() - m.clone()).scale(&d) - f.scale(&coef), d))
}

/// (impl spec) with γ = γ_VM (gammaMV) for a given pair `(M, M̂)`, free of the square
/// root of (gammaMV).
///
/// With `S = M + M̂`, `D = M̂ − M`, `f = f(S)` the (ET) field, `P = ⟨D, f⟩` and
/// `L = ‖D‖²`: where `P ≠ 0`, `D = ¼hγf` holds for some γ iff `D × f = 0`, and then
/// `D = cf` with `c = P/‖f‖² = L/P`, so `γ = 4L/(hP)`.  That γ is γ_VM = 2/(1 + w),
/// `w = √(1 − ¼h²‖ΩS‖²)`, iff `w = (hP − 2L)/(2L)` is positive and
/// `w² = 1 − ¼h²‖ΩS‖²`, which multiplied by `4L²/h` is
/// `h(P² + ‖ΩS‖²L²) − 4PL = 0` (affine in h).  Only inner products enter the last
/// equation and the conditions, so sign flips of components leave them unchanged, and
/// their degree in `M, M̂` (6) is the lowest this elimination allows.
///
/// Returns the four equations `[D × f, h(P² + ‖ΩS‖²L²) − 4PL]` and the conditions
/// `[P, L, hP − 2L]`: (impl spec) with γ_VM holds iff the equations vanish, `P ≠ 0`,
/// `L > 0` and `hP − 2L > 0`.
///
/// ```
/// use eulertop::linalg::Vec3;
/// use eulertop::model::discretization::{residual_vm_squared, step, Gamma};
/// use eulertop::model::Inertia;
/// let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
/// let (m, h) = (Vec3::new(0.3, -0.7, 1.1), 0.3);
/// let mh = step(&i, Gamma::Vm, &m, &h).unwrap();
/// let (eqs, [_, _, branch]) = residual_vm_squared(&i, &m, &mh, &h);
/// assert!(eqs.iter().all(|e| e.abs() < 1e-15) && branch > 0.0);
/// ```
pub fn residual_vm_squared<R: Real>(
    inertia: &Inertia<R>,
    m: &Vec3<R>,
    mhat: &Vec3<R>,
    h: &R,
) -> ([R; 4], [R; 3]) {
    let s = m.clone() + mhat.clone();
    let d = mhat.clone() - m.clone();
    let f = inertia.field_et(&s);
    let p = d.dot(&f);
    let l = d.norm2();
    let o2 = inertia.omega(&s).norm2();
    let [c1, c2, c3] = d.cross(&f).0;
    let quad = h.clone() * (p.sqr() + o2 * l.sqr()) - h.from_i64(4) * p.clone() * l.clone();
    let branch = h.clone() * p.clone() - l.clone() * h.from_i64(2);
    ([c1, c2, c3, quad], [p, l, branch])
}

/// Residual and its analytic Jacobian with respect to `M̂`.
pub fn residual_jacobian<R: Real>(
    inertia: &Inertia<R>,
    gamma: Gamma,
    m: &Vec3<R>,
    mhat: &Vec3<R>,
    h: &R,
) -> Result<(Vec3<R>, Mat3<R>), ModelError> {
    let (g, dg) = gamma.eval_grad(inertia, m, mhat, h)?;
    let s = m.clone() + mhat.clone();
    let f = inertia.field_et(&s);
    let q = h.clone() / h.from_i64(4);
    let res = mhat.clone() - m.clone() - f.scale(&(q.clone() * g.clone()));
    let (ia, ib, ic) = (inertia.a.recip(), inertia.b.recip(), inertia.c.recip());
    let p = [ib.clone() - ic.clone(), ic - ia.clone(), ia - ib];
    let [s1, s2, s3] = s.0.clone();
    let z = h.zero();
    let df = Mat3([
        [
            z.clone(),
            p[0].clone() * s3.clone(),
            p[0].clone() * s2.clone(),
        ],
        [p[1].clone() * s3, z.clone(), p[1].clone() * s1.clone()],
        [p[2].clone() * s2, p[2].clone() * s1, z],
    ]);
    let jac = Mat3::from_fn(|i, j| {
        let id = if i == j { h.one() } else { h.zero() };
        id - q.clone() * (g.clone() * df.0[i][j].clone() + f.0[i].clone() * dg.0[j].clone())
    });
    Ok((res, jac))
}

/// The derivative `∂M̂/∂M` of the map defined by (impl spec) at a solved pair
/// `(M, M̂)`, by the implicit function theorem: `−(∂F/∂M̂)⁻¹ ∂F/∂M`, with `∂F/∂M̂`
/// analytic and `∂F/∂M` from three [`Dual`](crate::numbers::Dual) passes.  Errors if
/// `∂F/∂M̂` is singular (Proposition 1 fails).
pub fn step_jacobian<R: Real>(
    inertia: &Inertia<R>,
    gamma: Gamma,
    m: &Vec3<R>,
    mhat: &Vec3<R>,
    h: &R,
) -> Result<Mat3<R>, ModelError> {
    use crate::numbers::Dual;
    let (_, jx) = residual_jacobian(inertia, gamma, m, mhat, h)?;
    let inv = jx.inverse().ok_or_else(|| ModelError::NewtonFailed {
        what: "step Jacobian (singular dF/dM^)".into(),
        iterations: 0,
        residual: f64::NAN,
    })?;
    let id = inertia.to_dual();
    let xd = Vec3(mhat.0.clone().map(Dual::constant));
    let hd = Dual::constant(h.clone());
    let mut jm = Mat3::zeros(h);
    for col in 0..3 {
        let md = Vec3(std::array::from_fn(|k| {
            let v = m.0[k].clone();
            let d = if k == col { v.one() } else { v.zero() };
            Dual::new(v, d)
        }));
        let r = residual(&id, gamma, &md, &xd, &hd)?;
        for row in 0..3 {
            jm.0[row][col] = r.0[row].d.clone();
        }
    }
    Ok(-(inv * jm))
}

/// Options of the Newton solver.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NewtonOptions {
    /// Iteration cap.
    pub max_iter: usize,
}

impl Default for NewtonOptions {
    fn default() -> Self {
        NewtonOptions { max_iter: 100 }
    }
}

/// The result of one step of the implicit map.
#[derive(Clone, Debug, PartialEq)]
pub struct StepReport<R> {
    /// `M̂`.
    pub m: Vec3<R>,
    /// Newton iterations used.
    pub iterations: usize,
    /// Final relative residual `‖F(M̂)‖∞ / max(‖M‖∞, ‖M̂‖∞)`, as f64.
    pub residual: f64,
}

/// Solves `a·x = b` by Cramer's rule with a single division; `None` if `det a = 0`.
fn solve3<R: Real>(a: &Mat3<R>, b: &Vec3<R>) -> Option<Vec3<R>> {
    let det = a.det();
    if det.is_zero() || !det.is_finite() {
        return None;
    }
    let inv = det.recip();
    let col = |j: usize| {
        let mut m = a.clone();
        for i in 0..3 {
            m.0[i][j] = b.0[i].clone();
        }
        m.det() * inv.clone()
    };
    Some(Vec3::new(col(0), col(1), col(2)))
}

/// `‖v‖∞` in the scalar type.
pub fn inf_norm<R: Real>(v: &Vec3<R>) -> R {
    let [a, b, c] = &v.0;
    a.abs().max_of(&b.abs()).max_of(&c.abs())
}

/// The explicit midpoint predictor `M + h f(M + ½h f(M))` with the (ET) field.
pub fn predictor<R: Real>(inertia: &Inertia<R>, m: &Vec3<R>, h: &R) -> Vec3<R> {
    let half = h.clone() / h.from_i64(2);
    let mid = m.clone() + inertia.field_et(m).scale(&half);
    m.clone() + inertia.field_et(&mid).scale(h)
}

/// The start point of a step: not at rest (the stopping rule is relative to `‖M‖`, so at
/// `M = 0` it cannot judge a step), and with a finite `M²` (else every residual is NaN
/// and the failure would be blamed on the step size).
fn check_start<R: Real>(
    m: &Vec3<R>,
    mnorm: &R,
    what: &dyn Fn() -> String,
) -> Result<(), ModelError> {
    if mnorm.is_zero() {
        return Err(ModelError::Undefined(format!(
            "{}: M = 0 (the top at rest) is not a start point; the step needs M ≠ 0",
            what()
        )));
    }
    check_m2_finite(m, mnorm, what)
}

/// `M²` of a start point is finite: else every residual of the step is NaN, and the
/// failure would be blamed on the step size.
pub(super) fn check_m2_finite<R: Real>(
    m: &Vec3<R>,
    mnorm: &R,
    what: &dyn Fn() -> String,
) -> Result<(), ModelError> {
    if m.norm2().is_finite() {
        return Ok(());
    }
    Err(ModelError::Undefined(format!(
        "{}: M² = M₁² + M₂² + M₃² overflows at {} bits (|M_i| up to {:.3e}); rescale M",
        what(),
        mnorm.prec(),
        mnorm.to_f64()
    )))
}

/// Solves (impl spec 1–3) for `M̂` by Newton's method (see the module docs for the
/// stopping rule and error behaviour).
pub fn step_report<R: Real>(
    inertia: &Inertia<R>,
    gamma: Gamma,
    m: &Vec3<R>,
    h: &R,
    opts: NewtonOptions,
) -> Result<StepReport<R>, ModelError> {
    let what = || format!("(impl spec) with {}", gamma.name());
    let eps = h.epsilon();
    let mnorm = inf_norm(m);
    check_start(m, &mnorm, &what)?;
    let mut x = ladder(h, |q| {
        let (i, m, h) = (inertia.at_prec(q), m.at_prec(q), h.at_prec(q));
        step_report(&i, gamma, &m, &h, opts).map(|r| r.m)
    })
    .unwrap_or_else(|| predictor(inertia, m, h));
    let mut prev: Option<R> = None;
    let mut iterations = 0;
    let fail = |it: usize, r: f64| ModelError::NewtonFailed {
        what: what(),
        iterations: it,
        residual: r,
    };
    loop {
        if iterations >= opts.max_iter {
            let r = residual(inertia, gamma, m, &x, h)?;
            return Err(fail(iterations, inf_norm(&r).to_f64()));
        }
        let (res, jac) = residual_jacobian(inertia, gamma, m, &x, h)?;
        let dx = solve3(&jac, &res).ok_or_else(|| fail(iterations, f64::NAN))?;
        x = x - dx.clone();
        iterations += 1;
        let dn = inf_norm(&dx);
        if !dn.is_finite() || !inf_norm(&x).is_finite() {
            return Err(fail(iterations, f64::NAN));
        }
        let scale = mnorm.max_of(&inf_norm(&x));
        if dn <= eps.clone() * scale.from_i64(4) * scale.clone() {
            break;
        }
        if let Some(p) = &prev {
            // stalled: the update no longer decreases once near rounding level
            if dn >= *p && dn <= eps.sqrt() * scale {
                break;
            }
        }
        prev = Some(dn);
    }
    let r = residual(inertia, gamma, m, &x, h)?;
    let scale = mnorm.max_of(&inf_norm(&x));
    let rel = if scale.is_zero() {
        inf_norm(&r)
    } else {
        inf_norm(&r) / scale.clone()
    };
    let tol = eps.mul_2si(3); // 16·2^(−p)
    if rel > tol || !rel.is_finite() {
        return Err(fail(iterations, rel.to_f64()));
    }
    Ok(StepReport {
        m: x,
        iterations,
        residual: rel.to_f64(),
    })
}

/// One step `M ↦ M̂` of the special discretization (impl spec) with default options.
pub fn step<R: Real>(
    inertia: &Inertia<R>,
    gamma: Gamma,
    m: &Vec3<R>,
    h: &R,
) -> Result<Vec3<R>, ModelError> {
    Ok(step_report(inertia, gamma, m, h, NewtonOptions::default())?.m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numbers::Dual;

    #[test]
    fn analytic_jacobian_matches_ad() {
        let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
        let m = Vec3::new(0.3, -0.7, 1.1);
        let x = Vec3::new(0.35, -0.6, 1.12);
        let h = 0.2;
        let id = i.to_dual();
        for g in [Gamma::G0, Gamma::G1, Gamma::G2, Gamma::Vm] {
            let (_, jac) = residual_jacobian(&i, g, &m, &x, &h).unwrap();
            for j in 0..3 {
                let md = Vec3(m.0.map(Dual::constant));
                let xd = Vec3(std::array::from_fn(|k| {
                    Dual::new(x.0[k], if k == j { 1.0 } else { 0.0 })
                }));
                let r = residual(&id, g, &md, &xd, &Dual::constant(h)).unwrap();
                for k in 0..3 {
                    assert!((r.0[k].d - jac.0[k][j]).abs() < 1e-13, "{g:?} {k} {j}");
                }
            }
        }
    }

    /// The square-free form of (impl spec) with γ_VM vanishes, with the conditions'
    /// signs, exactly at a solution of (impl spec) with γ_VM; a perturbed M̂, or the
    /// solution of another γ, fails it.
    #[test]
    fn the_square_free_vm_equations_hold_at_the_vm_step_only() {
        let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
        let m = Vec3::new(0.3, -0.7, 1.1);
        let h = 0.3;
        let x = step(&i, Gamma::Vm, &m, &h).unwrap();
        let (eqs, [q, n, branch]) = residual_vm_squared(&i, &m, &x, &h);
        for e in eqs {
            assert!(e.abs() < 1e-15, "{e}");
        }
        assert!(q.abs() > 1e-6 && n > 1e-6 && branch > 1e-6);
        let y = x.clone() + Vec3::new(1e-6, 0.0, 0.0);
        let (eqs, _) = residual_vm_squared(&i, &m, &y, &h);
        assert!(eqs.iter().any(|e| e.abs() > 1e-9));
        let z = step(&i, Gamma::G1, &m, &h).unwrap();
        let (eqs, _) = residual_vm_squared(&i, &m, &z, &h);
        assert!(eqs.iter().any(|e| e.abs() > 1e-9));
    }
}
