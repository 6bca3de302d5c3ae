//! The model's implicit maps as power series in `h` ([`crate::algebra::series`]): the
//! solution of each map's own equations that is continuous at `h = 0`, coefficient by
//! coefficient.
//!
//! Every map is `E(x, h) = 0` with a known solution `x₀` at `h = 0` and an invertible
//! linearization `L = ∂E/∂x (x₀, 0)`: (impl spec 1–3) with `x = M̂`, `x₀ = M`, `L = I`;
//! (M thru omega) with `ω = cayley(v)`, `x = v`, `x₀ = 0`; the master equations with
//! `x = δ`, `x₀ = 0`.  The iteration `x ← x − L⁻¹E(x, h)` gains at least one order of
//! `h` per step; it stops when `x` no longer changes at the working precision, so
//! `E(x, h) = O(h^n)` there and `x` is the unique power-series solution with
//! `x(0) = x₀` (implicit function theorem): the Taylor series of the map's branch.
//! `E(x₀, 0) = 0` is checked exactly, and `L`'s determinant has a proved sign.

use super::euler_top::{ModelFn, err, inertia, params, v3};
use crate::algebra::AssumptionKind;
use crate::algebra::series::Series;
use crate::algebra::series_solve::{Equations, solve_at};
use crate::claims::implicit::Implicit;
use crate::claims::value::Value;
use crate::linalg::{Mat3, Vec3};
use crate::model::discretization::{Gamma, residual};
use crate::model::elliptic_coords::sncndn_params;
use crate::model::phase::{master12_equation, mv_master_equation};
use crate::model::veselov_moser::{cayley, hat, j_diag, omega_residual, vm_conjugate};
use crate::numbers::Scalar;

/// `f(args)` as a power series (see the module doc).
pub(super) fn series(f: ModelFn, args: &[Value<Series>]) -> Result<Value<Series>, String> {
    let at = match f {
        ModelFn::Delta1 | ModelFn::Delta2 | ModelFn::DeltaVm => 5,
        _ => 1,
    };
    let h = args.get(at).ok_or("too few arguments")?.as_real()?;
    if h.valuation() < 1 {
        return Err("the step size does not tend to 0 with h".into());
    }
    let constant = args
        .iter()
        .enumerate()
        .filter(|(j, _)| *j != at && (at == 5 || *j != 0))
        .flat_map(|(_, a)| a.components())
        .all(|c| c.is_constant());
    if !constant {
        return Err("the map's parameters depend on h".into());
    }
    let ring = h.ring().clone();
    ring.assume(
        AssumptionKind::Branch(f.name().to_string()),
        format!("{}: {}", f.name(), f.branch()),
    );
    ring.note(format!(
        "{}: the power series in h of the solution of {} continuous at h = 0",
        f.name(),
        f.equations()
    ));
    let out = match f {
        ModelFn::StepVm | ModelFn::VmOmega => vm(f, args, &h),
        ModelFn::Delta1 | ModelFn::Delta2 | ModelFn::DeltaVm => phase(f, args, &h),
        ModelFn::StepGamma0 => midpoint(Gamma::G0, args, &h),
        ModelFn::StepGamma1 => midpoint(Gamma::G1, args, &h),
        ModelFn::StepGamma2 => midpoint(Gamma::G2, args, &h),
        _ => Err("not an implicit map".into()),
    }?;
    let argv: Vec<Vec<Series>> = args.iter().map(Value::components).collect();
    Series::record_chart(f.name(), &argv, &out.components());
    Ok(out)
}

/// (impl spec 1–3): `M̂ − M − ¼hγ f(M + M̂) = 0` from `M̂ = M`.
fn midpoint(gamma: Gamma, args: &[Value<Series>], h: &Series) -> Result<Value<Series>, String> {
    let i = inertia(args, 2)?;
    let m = v3(&args[0])?;
    let m0 = Vec3::new(at_zero(&m.0[0]), at_zero(&m.0[1]), at_zero(&m.0[2]));
    let e = |x: &[Series], hh: &Series| -> Result<Vec<Series>, String> {
        let mh = Vec3::new(x[0].clone(), x[1].clone(), x[2].clone());
        Ok(residual(&i, gamma, &m, &mh, hh).map_err(err)?.0.to_vec())
    };
    let e0 = |x: &[Series], hh: &Series| -> Result<Vec<Series>, String> {
        let mh = Vec3::new(x[0].clone(), x[1].clone(), x[2].clone());
        Ok(residual(&i, gamma, &m0, &mh, hh).map_err(err)?.0.to_vec())
    };
    let x = solve_at(m.0.to_vec(), &e, &e0, h)?;
    Ok(Value::Vec3(Vec3::new(
        x[0].clone(),
        x[1].clone(),
        x[2].clone(),
    )))
}

/// (M thru omega): `vee(ωJ − Jωᵀ − hM̌) = 0` with `ω = cayley(v)`, from `v = 0`.
fn vm(f: ModelFn, args: &[Value<Series>], h: &Series) -> Result<Value<Series>, String> {
    let i = inertia(args, 2)?;
    let m = v3(&args[0])?;
    let j = Mat3::diag(&j_diag(&i));
    let m0 = Vec3::new(at_zero(&m.0[0]), at_zero(&m.0[1]), at_zero(&m.0[2]));
    let e = |x: &[Series], hh: &Series| -> Result<Vec<Series>, String> {
        let v = Vec3::new(x[0].clone(), x[1].clone(), x[2].clone());
        Ok(omega_residual(&v, &j, &hat(&m).scale(hh)).0.to_vec())
    };
    let e0 = |x: &[Series], hh: &Series| -> Result<Vec<Series>, String> {
        let v = Vec3::new(x[0].clone(), x[1].clone(), x[2].clone());
        Ok(omega_residual(&v, &j, &hat(&m0).scale(hh)).0.to_vec())
    };
    let zero = h.zero();
    let x = solve_at(vec![zero.clone(), zero.clone(), zero], &e, &e0, h)?;
    let w = cayley(&Vec3::new(x[0].clone(), x[1].clone(), x[2].clone()));
    Ok(match f {
        ModelFn::VmOmega => Value::Mat3(w),
        _ => Value::Vec3(vm_conjugate(&w, &m)),
    })
}

/// The master equation of a phase step in `δ`, from `δ = 0`.
fn phase(f: ModelFn, args: &[Value<Series>], h: &Series) -> Result<Value<Series>, String> {
    let args0: Vec<Value<Series>> = args
        .iter()
        .map(|a| a.map(&mut |x: &Series| at_zero(x)))
        .collect();
    let eq = |args: &[Value<Series>]| phase_equation(f, args, h);
    let (e, e0) = (eq(args)?, eq(&args0)?);
    let x = solve_at(vec![h.zero()], &e, &e0, h)?;
    Ok(Value::Real(x[0].clone()))
}

/// The value at `h = 0` (the constant term) of a series.
fn at_zero(x: &Series) -> Series {
    Series::constant(&x.coefficient(0).unwrap_or_else(|| x.ring().integer(0)))
}

/// The master equation of a phase step in `δ` at the arguments `args`.
fn phase_equation<'a>(
    f: ModelFn,
    args: &[Value<Series>],
    h: &Series,
) -> Result<Box<Equations<'a>>, String> {
    let (i, p) = params(args)?;
    let (a, b) = match f {
        ModelFn::Delta1 => (p.alpha1(), h.zero()),
        ModelFn::Delta2 => (p.alpha2(&i), h.zero()),
        _ => p
            .alpha_beta_vm(&i)
            .ok_or("(MV alphabeta) is not given on the separatrix")?,
    };
    let nu2 = p.nu() * h.from_ratio(1, 2);
    Ok(Box::new(
        move |x: &[Series], hh: &Series| -> Result<Vec<Series>, String> {
            let (sn, cn, dn) = sncndn_params(&x[0], &p).map_err(err)?;
            let hn = hh.clone() * nu2.clone();
            Ok(vec![match f {
                ModelFn::DeltaVm => mv_master_equation(&a, &b, &hn, &sn, &cn, &dn),
                _ => master12_equation(&a, &hn, &sn, &cn, &dn),
            }])
        },
    ))
}
