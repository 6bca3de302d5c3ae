//! The model's implicit maps as the prover sees them ([`crate::claims::implicit`]).
//!
//! Every parametrization is built from the model's own code: the residual of
//! (impl spec 1–3) ([`discretization::residual`]), the skew residual of
//! (M thru omega) ([`omega_residual`]), and the master equations ([`master12_equation`],
//! [`mv_master_equation`]) that the Newton solvers use.  The prover proves these
//! equations at the parametrization together with the claim.
//!
//! * **(impl spec) with γ₀, γ₁, γ₂** (`step_gamma0/1/2`): with `S = M + M̂` and
//!   `M̂ − M = g·f(S)` (`f` the (ET) field), `M = (S − g f)/2`, `M̂ = (S + g f)/2`; the
//!   residual is `f(S)·(g − hγ/4)`, affine in `h` (γ₀, γ₁, γ₂ do not depend on `h`), and
//!   `h` is solved from it.  New symbols: `S1, S2, S3, g`; eliminated: `M`, `h`.
//! * **Veselov–Moser** (`step_vm`, `vm_omega`): `ω = cayley(v)` as in the solver; (M thru
//!   omega) `hM̌ = ωJ − Jωᵀ` is linear in `M`, so `M = vee(ωJ − Jωᵀ)/h`.  New symbols:
//!   `v1, v2, v3`; eliminated: `M`.
//! * **Phase steps** (`delta1`, `delta2`, `delta_vm`): `δ` is a new symbol (an
//!   elliptic base argument with its own `sn`, `cn`, `dn`); the master equation is
//!   affine in `h`, which is solved from it.  Eliminated: `h`.

use super::euler_top::{ModelFn, err, inertia, params, v3};
use crate::algebra::Sym;
use crate::claims::implicit::{Implicit, Parametrized};
use crate::claims::registry::GenericFunction;
use crate::claims::value::Value;
use crate::linalg::{Mat3, Vec3};
use crate::model::Inertia;
use crate::model::discretization::{Gamma, residual, residual_cleared, residual_vm_squared};
use crate::model::elliptic_coords::sncndn_params;
use crate::model::params::EllipticParams;
use crate::model::phase::{master12_equation, mv_master_equation};
use crate::model::veselov_moser::{cayley, hat, j_diag, omega_residual, vm_conjugate, vm_step};
use crate::numbers::Scalar;
use rug::{Complex, Float};

/// The numeric arguments at domain point `p` (the real parts of the shadows).
fn numeric_args(args: &[Value<Sym>], p: usize, prec: u32) -> Vec<Value<Float>> {
    args.iter()
        .map(|a| a.map(&mut |s: &Sym| Float::with_val(prec, s.shadow(p).real())))
        .collect()
}

/// The function's numeric value at every domain point, at the shadows' precision.
fn numeric_values(f: ModelFn, args: &[Value<Sym>]) -> Result<Vec<Value<Float>>, String> {
    let ring = args
        .iter()
        .flat_map(|a| a.components())
        .next()
        .map(|c| c.ring().clone())
        .ok_or("an implicit call without arguments")?;
    (0..ring.points())
        .map(|p| {
            let at = numeric_args(args, p, ring.precision());
            f.call::<Float>(&at)
                .map_err(|e| format!("{} at domain point {}: {e}", f.name(), p + 1))
        })
        .collect()
}

fn shadow_of(x: &Float) -> Complex {
    Complex::with_val(x.prec(), (x, 0))
}

/// A new indeterminate named after `base` with the given values.
fn fresh(like: &Sym, base: &str, values: &[Float]) -> Result<Sym, String> {
    let ring = like.ring();
    let name = ring.fresh_name(base);
    let sh: Vec<Complex> = values.iter().map(shadow_of).collect();
    ring.indeterminate(&name, &sh).map_err(|e| e.to_string())
}

fn gamma_of(f: ModelFn) -> Option<Gamma> {
    match f {
        ModelFn::StepGamma0 => Some(Gamma::G0),
        ModelFn::StepGamma1 => Some(Gamma::G1),
        ModelFn::StepGamma2 => Some(Gamma::G2),
        _ => None,
    }
}

/// Solves `r(x) = 0` for `x`, where every component of `r` is affine in `x`: from the
/// first component whose coefficient is not 0.
fn solve_affine(r0: &[Sym], r1: &[Sym], what: &str) -> Result<Sym, String> {
    for (a, b) in r0.iter().zip(r1) {
        let slope = b.clone() - a.clone();
        if !slope.is_exact_zero() {
            return Ok(-(a.clone()) / slope);
        }
    }
    Err(format!(
        "{what} does not depend on the variable to solve for"
    ))
}

/// (impl spec) with γ₀, γ₁ or γ₂: `M`, `h` in terms of `S = M + M̂` and `g`.
fn midpoint(f: ModelFn, gamma: Gamma, args: &[Value<Sym>]) -> Result<Parametrized, String> {
    let i = inertia(args, 2)?;
    let h = args[1].as_real()?;
    let num = numeric_values(f, args)?;
    let prec = h.ring().precision();
    let mut s_num: [Vec<Float>; 3] = Default::default();
    let mut g_num = Vec::new();
    for (p, v) in num.iter().enumerate() {
        let at = numeric_args(args, p, prec);
        let (mp, mh) = (at[0].as_vec3()?, v.as_vec3()?);
        let ip = inertia(&at, 2)?;
        let s = mp.clone() + mh.clone();
        let fs = ip.field_et(&s);
        g_num.push((mh - mp).dot(&fs) / fs.norm2());
        for (j, sj) in s.0.into_iter().enumerate() {
            s_num[j].push(sj);
        }
    }
    let (s1, s2, s3) = (
        fresh(&h, "S1", &s_num[0])?,
        fresh(&h, "S2", &s_num[1])?,
        fresh(&h, "S3", &s_num[2])?,
    );
    let s = Vec3::new(s1.clone(), s2.clone(), s3.clone());
    let g = fresh(&h, "g", &g_num)?;
    let fs = i.field_et(&s).scale(&g);
    let half = h.from_ratio(1, 2);
    let m_new = (s.clone() - fs.clone()).scale(&half);
    let m_hat = (s + fs).scale(&half);
    let at_h = |x: &Sym| residual(&i, gamma, &m_new, &m_hat, x).map_err(err);
    let r0 = at_h(&h.zero())?.0.to_vec();
    let r1 = at_h(&h.one())?.0.to_vec();
    let h_new = solve_affine(&r0, &r1, "the residual of (impl spec)")?;
    let checks = at_h(&h_new)?.0.to_vec();
    Ok(Parametrized {
        replace: vec![Value::Vec3(m_new), Value::Real(h_new)],
        value: Value::Vec3(m_hat),
        also: Vec::new(),
        params: vec![s1, s2, s3, g],
        checks,
        note: format!(
            "{}: M = (S − g·f(S))/2 and M̂ = (S + g·f(S))/2 with S = M + M̂ and f the (ET) field; h solved from the residual of (impl spec) with {}, which is affine in h",
            f.name(),
            gamma.name()
        ),
    })
}

/// Veselov–Moser: `ω = cayley(v)` and `M = vee(ωJ − Jωᵀ)/h` from (M thru omega).
fn cayley_param(f: ModelFn, args: &[Value<Sym>]) -> Result<Parametrized, String> {
    let i = inertia(args, 2)?;
    let h = args[1].as_real()?;
    let prec = h.ring().precision();
    let mut v_num: [Vec<Float>; 3] = Default::default();
    for p in 0..h.ring().points() {
        let at = numeric_args(args, p, prec);
        let ip = inertia(&at, 2)?;
        let st = vm_step(&ip, &at[0].as_vec3()?, &at[1].as_real()?).map_err(err)?;
        for (j, vj) in st.v.0.into_iter().enumerate() {
            v_num[j].push(vj);
        }
    }
    let v = Vec3::new(
        fresh(&h, "v1", &v_num[0])?,
        fresh(&h, "v2", &v_num[1])?,
        fresh(&h, "v3", &v_num[2])?,
    );
    let j = Mat3::diag(&j_diag(&i));
    let zero = Mat3::zeros(&h);
    let m_new = omega_residual(&v, &j, &zero).scale(&h.recip());
    let checks = omega_residual(&v, &j, &hat(&m_new).scale(&h)).0.to_vec();
    let w = cayley(&v);
    let step = Value::Vec3(vm_conjugate(&w, &m_new));
    let omega = Value::Mat3(w);
    let (value, also) = match f {
        ModelFn::StepVm => (step, (ModelFn::VmOmega.name(), omega)),
        _ => (omega, (ModelFn::StepVm.name(), step)),
    };
    Ok(Parametrized {
        replace: vec![Value::Vec3(m_new)],
        value,
        also: vec![also],
        params: v.0.to_vec(),
        checks,
        note: format!(
            "{}: ω = cayley(v) = (I + v̌)(I − v̌)⁻¹ and M = vee(ωJ − Jωᵀ)/h, from (M thru omega), which is linear in M",
            f.name()
        ),
    })
}

/// The master equation of a phase step at `delta`, as a function of `h`.
fn master<'a>(
    f: ModelFn,
    i: &'a Inertia<Sym>,
    p: &'a EllipticParams<Sym>,
    delta: &Sym,
) -> Result<impl Fn(&Sym) -> Sym + 'a + use<'a>, String> {
    let (sn, cn, dn) = sncndn_params(delta, p).map_err(err)?;
    let (a, b) = match f {
        ModelFn::Delta1 => (p.alpha1(), delta.zero()),
        ModelFn::Delta2 => (p.alpha2(i), delta.zero()),
        _ => p
            .alpha_beta_vm(i)
            .ok_or("(MV alphabeta) is not given on the separatrix")?,
    };
    let nu2 = p.nu() * delta.from_ratio(1, 2);
    let vm = f == ModelFn::DeltaVm;
    Ok(move |h: &Sym| {
        let hn = h.clone() * nu2.clone();
        if vm {
            mv_master_equation(&a, &b, &hn, &sn, &cn, &dn)
        } else {
            master12_equation(&a, &hn, &sn, &cn, &dn)
        }
    })
}

/// A phase step: `δ` a new elliptic base argument, `h` solved from the master equation.
fn phase_param(f: ModelFn, args: &[Value<Sym>]) -> Result<Parametrized, String> {
    let (i, p) = params(args)?;
    let h = args[5].as_real()?;
    let num = numeric_values(f, args)?;
    let d_num: Vec<Complex> = num
        .iter()
        .map(|v| v.as_real().map(|x| shadow_of(&x)))
        .collect::<Result<_, _>>()?;
    let ring = h.ring().clone();
    let name = ring.fresh_name("delta");
    let delta = ring
        .opaque(&name, &d_num, false)
        .map_err(|e| e.to_string())?;
    // the chart's parameter: δ ranges over real values, and h is solved from it
    ring.declare_real(&delta);
    let eq = master(f, &i, &p, &delta)?;
    let h_new = solve_affine(&[eq(&h.zero())], &[eq(&h.one())], "the master equation")?;
    let checks = vec![eq(&h_new)];
    Ok(Parametrized {
        replace: vec![Value::Real(h_new)],
        value: Value::Real(delta.clone()),
        also: Vec::new(),
        params: vec![delta],
        checks,
        note: format!(
            "{}: δ is a new base argument {name} with its own sn, cn, dn; h solved from {}, which is affine in h",
            f.name(),
            f.implicit_equations()
        ),
    })
}

impl ModelFn {
    fn implicit_equations(self) -> &'static str {
        match self {
            ModelFn::StepGamma0 => "(impl spec 1–3) with γ₀ ≡ 1",
            ModelFn::StepGamma1 => "(impl spec 1–3) with (gamma1)",
            ModelFn::StepGamma2 => "(impl spec 1–3) with (gamma2)",
            ModelFn::StepVm | ModelFn::VmOmega => "(M thru omega) with ω = cayley(v), and (VM)",
            ModelFn::Delta1 => "(master12) with α₁",
            ModelFn::Delta2 => "(master12) with α₂",
            _ => "(MV master) with (MV alphabeta)",
        }
    }
}

impl Implicit for ModelFn {
    fn series(
        &self,
        args: &[Value<crate::algebra::series::Series>],
    ) -> Result<Value<crate::algebra::series::Series>, String> {
        super::implicit_series::series(*self, args)
    }

    fn eliminates(&self) -> &'static [usize] {
        match self {
            ModelFn::StepVm | ModelFn::VmOmega => &[0],
            ModelFn::Delta1 | ModelFn::Delta2 | ModelFn::DeltaVm => &[5],
            _ => &[0, 1],
        }
    }

    fn parametrize(&self, args: &[Value<Sym>]) -> Result<Parametrized, String> {
        match self {
            ModelFn::StepVm | ModelFn::VmOmega => cayley_param(*self, args),
            ModelFn::Delta1 | ModelFn::Delta2 | ModelFn::DeltaVm => phase_param(*self, args),
            f => midpoint(*f, gamma_of(*f).ok_or("not an implicit map")?, args),
        }
    }

    fn residual(&self, args: &[Value<Sym>], value: &Value<Sym>) -> Result<Vec<Sym>, String> {
        match self {
            ModelFn::Delta1 | ModelFn::Delta2 | ModelFn::DeltaVm => {
                let (i, p) = params(args)?;
                let eq = master(*self, &i, &p, &value.as_real()?)?;
                Ok(vec![eq(&args[5].as_real()?)])
            }
            ModelFn::VmOmega => {
                let i = inertia(args, 2)?;
                let (m, h) = (v3(&args[0])?, args[1].as_real()?);
                let w = value.as_mat3()?;
                let j = Mat3::diag(&j_diag(&i));
                let skew = w.clone() * j.clone() - j * w.transpose() - hat(&m).scale(&h);
                let orth = w.transpose() * w.clone() - Mat3::identity(&h.one());
                Ok(skew.0.into_iter().chain(orth.0).flatten().collect())
            }
            ModelFn::StepVm => Err(
                "the equations of step_vm are in ω, so a stated value of M̂ is not substituted into them"
                    .into(),
            ),
            f => {
                let gamma = gamma_of(*f).ok_or("not an implicit map")?;
                let i = inertia(args, 2)?;
                let (m, h) = (v3(&args[0])?, args[1].as_real()?);
                let r = residual(&i, gamma, &m, &value.as_vec3()?, &h).map_err(err)?;
                Ok(r.0.to_vec())
            }
        }
    }

    fn stated_residual(
        &self,
        args: &[Value<Sym>],
        value: &Value<Sym>,
    ) -> Result<(Vec<Sym>, Option<Sym>), String> {
        if *self == ModelFn::StepVm {
            return stated_vm(args, value).map(|e| (e, None));
        }
        let Some(gamma) = gamma_of(*self) else {
            return Ok((self.residual(args, value)?, None));
        };
        // (impl spec) times the denominator of γ: no division by ⟨S, S⟩ or ⟨S, ΩS⟩
        let i = inertia(args, 2)?;
        let (m, h) = (v3(&args[0])?, args[1].as_real()?);
        let (r, d) = residual_cleared(&i, gamma, &m, &value.as_vec3()?, &h).map_err(err)?;
        Ok((r.0.to_vec(), Some(d)))
    }

    fn equations(&self) -> String {
        self.implicit_equations().to_string()
    }

    fn stated_equations(&self) -> String {
        match self {
            ModelFn::StepVm => "(impl spec) with γ_VM, which is the VM map by Theorem 2 (claim sec8.thm2.gammaMV), with the root of (gammaMV) eliminated: D × f = 0 and h(P² + ‖ΩS‖²L²) − 4PL = 0 for D = M̂ − M, S = M + M̂, f = f(S), P = ⟨D, f⟩ and L = ‖D‖², where P ≠ 0, L > 0 and hP − 2L > 0 on the domain".into(),
            _ => self.equations(),
        }
    }

    fn branch(&self) -> String {
        match self {
            ModelFn::StepVm | ModelFn::VmOmega => {
                "the solution ω of (M thru omega) with ω → I as h → 0 (omega as), as the Newton solver selects it".into()
            }
            ModelFn::Delta1 | ModelFn::Delta2 | ModelFn::DeltaVm => {
                "the root δ ∈ (0, K) of the master equation continuous at h = 0 (δ ≈ hν/2), as the Newton solver selects it".into()
            }
            _ => "the solution M̂ of (impl spec) with M̂ → M as h → 0 (Proposition 1), as the Newton solver selects it".into(),
        }
    }
}

/// The equations of a stated value `M̂` of `step_vm(M, h, A, B, C)`: by Theorem 2 the VM
/// map is (impl spec) with γ_VM, whose square root [`residual_vm_squared`] eliminates;
/// its conditions are decided on the domain (and recorded as assumptions).
fn stated_vm(args: &[Value<Sym>], value: &Value<Sym>) -> Result<Vec<Sym>, String> {
    let i = inertia(args, 2)?;
    let (m, h) = (v3(&args[0])?, args[1].as_real()?);
    let (eqs, [p, l, branch]) = residual_vm_squared(&i, &m, &value.as_vec3()?, &h);
    let decided = |x: &Sym, what: &str| x.sign().map_err(|e| format!("{what}: {e}"));
    decided(&p, "P = ⟨D, f(S)⟩")?;
    decided(&l, "L = ‖D‖²")?;
    if decided(&branch, "the root of (gammaMV)")? < 0 {
        return Err("the stated value gives the negative root of (gammaMV), not γ_VM".into());
    }
    Ok(eqs.to_vec())
}
