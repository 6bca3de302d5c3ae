//! The model's functions in ball arithmetic ([`Ball`]): enclosures of their exact values.
//!
//! * The algebraic functions (field operations only: Ω, the energy, M², the hat matrix,
//!   J) are evaluated as written; every ball operation encloses.
//! * The Veselov–Moser rotation (`vm_omega`, `step_vm`): the solver's Cayley vector `v`
//!   (in `f64`, at the midpoints of the arguments) is certified by the Krawczyk test
//!   ([`crate::linalg::krawczyk`]) on the equations the solver solves, (M thru omega)
//!   with `ω = cayley(v)`: for every argument in the argument balls, exactly one solution
//!   lies in a box of relative half-width 10⁻⁹ around the solver's `v`, and it lies in the
//!   returned enclosure.  That solution is the solver's (the one it converged to lies in
//!   the box): the branch the function selects.
//! * The steps of (impl spec) with γ₀, γ₁, γ₂ (`step_gamma0`, …): the solver's `M̂` is
//!   certified in the same way on the map's own equations ([`residual`]).
//! * The elliptic coordinates (`ell_coords`, `ell_inverse`) and the parameters `k`, `ν`:
//!   evaluated as written; the elliptic functions they call are Arb's enclosures (see
//!   [`Ball`]), and every comparison they make is decided or recorded.
//! * Every other function is refused: its numerical algorithms (iterations stopped at a
//!   tolerance) do not enclose.

use super::euler_top::{ModelFn, err, inertia, v3};
use crate::claims::registry::{GenericFunction, NO_BALLS};
use crate::claims::value::Value;
use crate::linalg::krawczyk::{BallSystem, krawczyk};
use crate::linalg::{Mat3, Vec3};
use crate::model::discretization::{Gamma, residual, step};
use crate::model::veselov_moser::{
    cayley, hat, j_diag, omega_residual_diag, vm_conjugate, vm_step,
};
use crate::numbers::{Ball, Dual, Real, Scalar};

/// (M thru omega) in `v` for a diagonal `J` and `hM̌` given as balls.
struct OmegaSystem {
    jv: Vec3<Ball>,
    hm: Mat3<Ball>,
}

impl BallSystem for OmegaSystem {
    fn residual(&mut self, x: &[Ball]) -> Result<Vec<Ball>, String> {
        let v = Vec3(std::array::from_fn(|k| x[k].clone()));
        Ok(omega_residual_diag(&v, &self.jv, &self.hm).0.to_vec())
    }
    fn jacobian(&mut self, x: &[Ball]) -> Result<Vec<Vec<Ball>>, String> {
        let jd = Vec3(self.jv.0.clone().map(Dual::constant));
        let hmd = Mat3::from_fn(|i, k| Dual::constant(self.hm.0[i][k].clone()));
        let mut jac = vec![vec![x[0].zero(); 3]; 3];
        for col in 0..3 {
            let vd = Vec3(std::array::from_fn(|k| {
                let d = if k == col { x[k].one() } else { x[k].zero() };
                Dual::new(x[k].clone(), d)
            }));
            let r = omega_residual_diag(&vd, &jd, &hmd);
            for (row, j) in jac.iter_mut().enumerate() {
                j[col] = r.0[row].d.clone();
            }
        }
        Ok(jac)
    }
}

/// The certified Cayley vector of the Veselov–Moser rotation at `(M, h, A, B, C)`.
fn vm_cayley(a: &[Value<Ball>]) -> Result<Vec3<Ball>, String> {
    let mid: Vec<Value<f64>> = a
        .iter()
        .map(|v| v.map(&mut |b: &Ball| b.mid_f64()))
        .collect();
    let solved = vm_step(&inertia(&mid, 2)?, &v3(&mid[0])?, &mid[1].as_real()?).map_err(err)?;
    let h = a[1].as_real()?;
    let mut sys = OmegaSystem {
        jv: j_diag(&inertia(a, 2)?),
        hm: hat(&v3(&a[0])?).scale(&h),
    };
    let center = solved.v.0.to_vec();
    let radius: Vec<f64> = center.iter().map(|x| 1e-9 * x.abs().max(1e-3)).collect();
    let cert = krawczyk(&mut sys, &center, &radius, Real::prec(&h))
        .map_err(|e| format!("(M thru omega) is not certified in balls: {e}"))?;
    let [x, y, z]: [Ball; 3] = cert
        .enclosure
        .try_into()
        .map_err(|_| "a Cayley vector of three components".to_string())?;
    Ok(Vec3([x, y, z]))
}

/// (impl spec 1–3) in `M̂` for given `M`, `h` and inertia, as balls.
struct StepSystem {
    inertia: crate::model::Inertia<Ball>,
    gamma: Gamma,
    m: Vec3<Ball>,
    h: Ball,
}

impl StepSystem {
    fn at<R: Real>(&self, x: &[R], lift: impl Fn(&Ball) -> R) -> Result<Vec3<R>, String> {
        let i = crate::model::Inertia::new(
            lift(&self.inertia.a),
            lift(&self.inertia.b),
            lift(&self.inertia.c),
        )
        .map_err(err)?;
        let m = Vec3(self.m.0.clone().map(|c| lift(&c)));
        let mh = Vec3(std::array::from_fn(|k| x[k].clone()));
        residual(&i, self.gamma, &m, &mh, &lift(&self.h)).map_err(err)
    }
}

impl BallSystem for StepSystem {
    fn residual(&mut self, x: &[Ball]) -> Result<Vec<Ball>, String> {
        Ok(self.at(x, Ball::clone)?.0.to_vec())
    }
    fn jacobian(&mut self, x: &[Ball]) -> Result<Vec<Vec<Ball>>, String> {
        let mut jac = vec![vec![x[0].zero(); 3]; 3];
        for col in 0..3 {
            let xd: Vec<Dual<Ball>> = (0..3)
                .map(|k| {
                    let d = if k == col { x[k].one() } else { x[k].zero() };
                    Dual::new(x[k].clone(), d)
                })
                .collect();
            let r = self.at(&xd, |b| Dual::constant(b.clone()))?;
            for (row, j) in jac.iter_mut().enumerate() {
                j[col] = r.0[row].d.clone();
            }
        }
        Ok(jac)
    }
}

/// The certified step `M̂` of (impl spec) with `gamma` at `(M, h, A, B, C)`: the solver's
/// `M̂` (in `f64`, at the midpoints) certified by the Krawczyk test on [`residual`].
fn certified_step(gamma: Gamma, a: &[Value<Ball>]) -> Result<Vec3<Ball>, String> {
    let mid: Vec<Value<f64>> = a
        .iter()
        .map(|v| v.map(&mut |b: &Ball| b.mid_f64()))
        .collect();
    let solved = step(&inertia(&mid, 2)?, gamma, &v3(&mid[0])?, &mid[1].as_real()?).map_err(err)?;
    let h = a[1].as_real()?;
    let mut sys = StepSystem {
        inertia: inertia(a, 2)?,
        gamma,
        m: v3(&a[0])?,
        h: h.clone(),
    };
    let center = solved.0.to_vec();
    let radius: Vec<f64> = center.iter().map(|x| 1e-9 * x.abs().max(1e-3)).collect();
    let cert = krawczyk(&mut sys, &center, &radius, Real::prec(&h))
        .map_err(|e| format!("(impl spec) is not certified in balls: {e}"))?;
    let [x, y, z]: [Ball; 3] = cert
        .enclosure
        .try_into()
        .map_err(|_| "a step of three components".to_string())?;
    Ok(Vec3([x, y, z]))
}

/// The functions evaluated as written in ball arithmetic (see the module).
fn as_written(f: ModelFn) -> bool {
    f.spec().algebraic
        || matches!(
            f,
            ModelFn::EllCoords | ModelFn::EllInverse | ModelFn::Kmod | ModelFn::Nu
        )
}

/// A model function on duals over balls: the functions evaluated as written (their
/// derivatives by the rules of [`Dual`], the elliptic ones by the exact formulas), or
/// why it has no enclosure (the implicit steps are certified as values only).
pub(super) fn call_dual(f: ModelFn, a: &[Value<Dual<Ball>>]) -> Result<Value<Dual<Ball>>, String> {
    match f {
        f if f.spec().algebraic => f.call_algebraic(a),
        f if as_written(f) => f.call(a),
        _ => Err(format!("{}: {NO_BALLS}", f.name())),
    }
}

/// A model function in ball arithmetic (see the module), or why it has no enclosure.
pub(super) fn call(f: ModelFn, a: &[Value<Ball>]) -> Result<Value<Ball>, String> {
    if f.spec().algebraic {
        return f.call_algebraic(a);
    }
    match f {
        f if as_written(f) => f.call(a),
        ModelFn::StepGamma0 => Ok(Value::Vec3(certified_step(Gamma::G0, a)?)),
        ModelFn::StepGamma1 => Ok(Value::Vec3(certified_step(Gamma::G1, a)?)),
        ModelFn::StepGamma2 => Ok(Value::Vec3(certified_step(Gamma::G2, a)?)),
        ModelFn::VmOmega => Ok(Value::Mat3(cayley(&vm_cayley(a)?))),
        ModelFn::StepVm => {
            let w = cayley(&vm_cayley(a)?);
            Ok(Value::Vec3(vm_conjugate(&w, &v3(&a[0])?)))
        }
        _ => Err(format!("{}: {NO_BALLS}", f.name())),
    }
}
