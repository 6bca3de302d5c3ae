//! Registers the model's functions in the claim catalogue's function table
//! ([`crate::claims::registry::Registry`]), under the names listed in
//! `identities/README.md`.  Arguments: moments of inertia `A, B, C` (validated
//! A > B > C > 0), `M` a vec3, `h` the step, `Msq = M²`, `E` the energy.
//!
//! | name | value | paper |
//! |---|---|---|
//! | `Omega(M, A, B, C)` | vec3 Ω(M) | (Omega) |
//! | `energy(M, A, B, C)` | E(M) | (E) |
//! | `msq(M)` | M² | (M2) |
//! | `hatM(M)` | mat3, the paper's hat map | (M m) |
//! | `OmegaM(M, A, B, C)` | mat3 Ω of M | (Omega m) |
//! | `Jdiag(A, B, C)` | vec3 (J₁, J₂, J₃) | (Js) |
//! | `kmod(A, B, C, Msq, E)` | modulus k (not k²) | (k) |
//! | `nu(A, B, C, Msq, E)` | ν > 0 | (nu) |
//! | `abc(A, B, C, Msq, E)` | vec3 (|a|, |b|, |c|) | (abc) |
//! | `ell_coords(M, A, B, C)` | vec3 (M², E, φ), φ ∈ (−2K, 2K] | Φ⁻¹, (ell coord) |
//! | `ell_inverse(Msq, E, phi, s1, s3, A, B, C)` | vec3 M with sign(M₁)=s1 (lower regime) / sign(M₃)=s3 (upper) | Φ, (ell coord) |
//! | `step_gamma0/1/2(M, h, A, B, C)` | vec3 M̂ of (impl spec) with γ₀, γ₁, γ₂ | (impl spec 1–3), (gamma1), (gamma2) |
//! | `step_vm(M, h, A, B, C)` | vec3 M̂ = ωᵀMω (Veselov–Moser) | (VM), (M thru omega) |
//! | `vm_omega(M, h, A, B, C)` | mat3 ω on the branch ω = I + hΩ + O(h²) | (M thru omega), (omega as) |
//! | `gamma_vm(M, Mh, h, A, B, C)` | γ_VM(M, M̂, h) | (gammaMV) |
//! | `delta1/delta2/delta_vm(A, B, C, Msq, E, h)` | phase step δ | (master12), (MV master) |
//! | `rho(A, B, C)`, `kappa(A, B, C)` | √ of the printed ρ², κ² | (rokappa) |
//! | `w(j, u, A, B, C)` | w_j(u) with the printed ρ, κ (u real or complex) | (ws) |
//!
//! The simple polynomial / rational functions (`Omega`, `energy`, `msq`, `hatM`,
//! `OmegaM`, `Jdiag`) are also available in the exact backend.

use super::discretization::{step, Gamma};
use super::elliptic_coords::{m_to_phi, phi_to_m, Sector};
use super::params::{EllipticParams, Regime};
use super::phase::delta;
use super::veselov_moser::{hat, j_diag, omega_matrix, vm_step};
use super::{lax, Inertia};
use crate::claims::backend::Num;
use crate::claims::registry::{GenericFunction, Registry};
use crate::claims::value::{Cx, Value};
use crate::linalg::Vec3;
use crate::numbers::{Cplx, Rational, Real};

#[derive(Clone, Copy)]
struct ModelFn(&'static str);

const TABLE: &[(&str, usize, &str)] = &[
    ("Omega", 4, "Omega(M, A, B, C): angular velocity (Omega)"),
    ("energy", 4, "energy(M, A, B, C): E(M) (E)"),
    ("msq", 1, "msq(M): M^2 (M2)"),
    ("hatM", 1, "hatM(M): the paper's hat map (M m)"),
    ("OmegaM", 4, "OmegaM(M, A, B, C): (Omega m)"),
    ("Jdiag", 3, "Jdiag(A, B, C): (J1, J2, J3) of (Js)"),
    ("kmod", 5, "kmod(A, B, C, Msq, E): modulus k of (k)"),
    ("nu", 5, "nu(A, B, C, Msq, E): positive root of (nu)"),
    ("abc", 5, "abc(A, B, C, Msq, E): (|a|, |b|, |c|) of (abc)"),
    ("ell_coords", 4, "ell_coords(M, A, B, C): (M^2, E, phi)"),
    (
        "ell_inverse",
        8,
        "ell_inverse(Msq, E, phi, s1, s3, A, B, C): Phi",
    ),
    (
        "step_gamma0",
        5,
        "step_gamma0(M, h, A, B, C): (impl spec) with gamma0 = 1",
    ),
    (
        "step_gamma1",
        5,
        "step_gamma1(M, h, A, B, C): (impl spec) with (gamma1)",
    ),
    (
        "step_gamma2",
        5,
        "step_gamma2(M, h, A, B, C): (impl spec) with (gamma2)",
    ),
    ("step_vm", 5, "step_vm(M, h, A, B, C): Veselov-Moser (VM)"),
    (
        "vm_omega",
        5,
        "vm_omega(M, h, A, B, C): omega of (M thru omega)",
    ),
    ("gamma_vm", 6, "gamma_vm(M, Mh, h, A, B, C): (gammaMV)"),
    (
        "delta1",
        6,
        "delta1(A, B, C, Msq, E, h): (master12) with alpha1",
    ),
    (
        "delta2",
        6,
        "delta2(A, B, C, Msq, E, h): (master12) with alpha2",
    ),
    ("delta_vm", 6, "delta_vm(A, B, C, Msq, E, h): (MV master)"),
    (
        "rho",
        3,
        "rho(A, B, C): sqrt of the printed rho^2 (rokappa)",
    ),
    (
        "kappa",
        3,
        "kappa(A, B, C): sqrt of the printed kappa^2 (rokappa)",
    ),
    (
        "w",
        5,
        "w(j, u, A, B, C): w_j(u) of (ws) with the printed rho, kappa",
    ),
];

/// Registers every model function (see the module table).  Errors only on a name
/// clash with a built-in (a programming error reported as a message).
pub fn register(reg: &mut Registry) -> Result<(), String> {
    for (name, arity, doc) in TABLE {
        reg.register(name, *arity, doc, ModelFn(name))?;
    }
    Ok(())
}

fn v3<R: Num>(v: &Value<R>) -> Result<Vec3<R>, String> {
    Ok(Vec3(v.as_vec3()?))
}
fn out3<R>(v: Vec3<R>) -> Value<R> {
    Value::Vec3(v.0)
}
fn inertia<R: Real + Num>(a: &[Value<R>], at: usize) -> Result<Inertia<R>, String> {
    Inertia::new(a[at].as_real()?, a[at + 1].as_real()?, a[at + 2].as_real()?)
        .map_err(|e| e.to_string())
}
fn params<R: Real + Num>(a: &[Value<R>]) -> Result<(Inertia<R>, EllipticParams<R>), String> {
    let i = inertia(a, 0)?;
    let p =
        EllipticParams::new(&i, &a[3].as_real()?, &a[4].as_real()?).map_err(|e| e.to_string())?;
    Ok((i, p))
}
fn sign_of<R: Num>(v: &Value<R>) -> Result<i8, String> {
    let x = v.as_real()?;
    if x > x.zero() {
        Ok(1)
    } else if x < x.zero() {
        Ok(-1)
    } else {
        Err("sign argument must be nonzero".into())
    }
}

impl GenericFunction for ModelFn {
    fn call<R: Real + Num>(&self, a: &[Value<R>]) -> Result<Value<R>, String> {
        let e = |x: super::ModelError| x.to_string();
        Ok(match self.0 {
            "Omega" => out3(inertia(a, 1)?.omega(&v3(&a[0])?)),
            "energy" => Value::Real(inertia(a, 1)?.energy(&v3(&a[0])?)),
            "msq" => Value::Real(v3(&a[0])?.norm2()),
            "hatM" => Value::Mat3(hat(&v3(&a[0])?).0),
            "OmegaM" => Value::Mat3(omega_matrix(&inertia(a, 1)?, &v3(&a[0])?).0),
            "Jdiag" => out3(j_diag(&inertia(a, 0)?)),
            "kmod" => Value::Real(params(a)?.1.k()),
            "nu" => Value::Real(params(a)?.1.nu()),
            "abc" => {
                let p = params(a)?.1;
                Value::Vec3([p.a2.sqrt(), p.b2.sqrt(), p.c2.sqrt()])
            }
            "ell_coords" => {
                let i = inertia(a, 1)?;
                let c = m_to_phi(&i, &v3(&a[0])?).map_err(e)?;
                Value::Vec3([c.params.m2, c.params.e, c.phi])
            }
            "ell_inverse" => {
                let i = inertia(a, 5)?;
                let (m2, en, phi) = (a[0].as_real()?, a[1].as_real()?, a[2].as_real()?);
                let (s1, s3) = (sign_of(&a[3])?, sign_of(&a[4])?);
                let p = EllipticParams::new(&i, &m2, &en).map_err(e)?;
                let sector = match p.regime {
                    Regime::Upper => Sector {
                        regime: p.regime,
                        sa: s3,
                        sb: 1,
                        sc: s3,
                    },
                    Regime::Lower => Sector {
                        regime: p.regime,
                        sa: s1,
                        sb: 1,
                        sc: s1,
                    },
                    Regime::Separatrix => Sector {
                        regime: p.regime,
                        sa: s1,
                        sb: s1 * s3,
                        sc: s3,
                    },
                };
                out3(phi_to_m(&p, sector, &phi).map_err(e)?)
            }
            "step_gamma0" | "step_gamma1" | "step_gamma2" => {
                let g = match self.0 {
                    "step_gamma0" => Gamma::G0,
                    "step_gamma1" => Gamma::G1,
                    _ => Gamma::G2,
                };
                let i = inertia(a, 2)?;
                out3(step(&i, g, &v3(&a[0])?, &a[1].as_real()?).map_err(e)?)
            }
            "step_vm" => {
                let i = inertia(a, 2)?;
                out3(vm_step(&i, &v3(&a[0])?, &a[1].as_real()?).map_err(e)?.m_hat)
            }
            "vm_omega" => {
                let i = inertia(a, 2)?;
                Value::Mat3(
                    vm_step(&i, &v3(&a[0])?, &a[1].as_real()?)
                        .map_err(e)?
                        .omega
                        .0,
                )
            }
            "gamma_vm" => {
                let i = inertia(a, 3)?;
                Value::Real(
                    Gamma::Vm
                        .eval(&i, &v3(&a[0])?, &v3(&a[1])?, &a[2].as_real()?)
                        .map_err(e)?,
                )
            }
            "delta1" | "delta2" | "delta_vm" => {
                let (i, p) = params(a)?;
                let g = match self.0 {
                    "delta1" => Gamma::G1,
                    "delta2" => Gamma::G2,
                    _ => Gamma::Vm,
                };
                Value::Real(delta(&i, &p, g, &a[5].as_real()?).map_err(e)?)
            }
            "rho" | "kappa" => {
                let (r2, k2) = lax::rho2_kappa2(&inertia(a, 0)?);
                Value::Real(if self.0 == "rho" {
                    r2.sqrt()
                } else {
                    k2.sqrt()
                })
            }
            "w" => {
                let j = a[0].as_int()?;
                if !(1..=3).contains(&j) {
                    return Err(format!("w(j, ...): j = {j} must be 1, 2 or 3"));
                }
                let i = inertia(a, 2)?;
                let (r2, k2) = lax::rho2_kappa2(&i);
                let u = a[1].as_complex()?;
                let z = r2.zero();
                let ws = lax::w(&Cplx::new(u.re, u.im), &Cplx::new(r2.sqrt(), z), &k2.sqrt())
                    .map_err(e)?;
                let wj = ws[(j - 1) as usize].clone();
                Value::Complex(Cx::new(wj.re, wj.im))
            }
            other => return Err(format!("unknown model function '{other}'")),
        })
    }

    fn call_exact(&self, a: &[Value<Rational>]) -> Result<Value<Rational>, String> {
        let abc = |at: usize| -> Result<[Rational; 3], String> {
            let (x, y, z) = (a[at].as_real()?, a[at + 1].as_real()?, a[at + 2].as_real()?);
            let zero = Rational::from_integer(0.into());
            if !(x > y && y > z && z > zero) {
                return Err("moments of inertia must satisfy A > B > C > 0".into());
            }
            Ok([x, y, z])
        };
        match self.0 {
            "Omega" | "energy" | "OmegaM" => {
                let m = a[0].as_vec3()?;
                let [x, y, z] = abc(1)?;
                let om = [m[0].clone() / x, m[1].clone() / y, m[2].clone() / z];
                Ok(match self.0 {
                    "Omega" => Value::Vec3(om),
                    "energy" => Value::Real(
                        m[0].clone() * om[0].clone()
                            + m[1].clone() * om[1].clone()
                            + m[2].clone() * om[2].clone(),
                    ),
                    _ => Value::Mat3(hat(&Vec3(om)).0),
                })
            }
            "msq" => {
                let m = Vec3(a[0].as_vec3()?);
                Ok(Value::Real(m.norm2()))
            }
            "hatM" => Ok(Value::Mat3(hat(&Vec3(a[0].as_vec3()?)).0)),
            "Jdiag" => {
                let [x, y, z] = abc(0)?;
                let two = Rational::from_integer(2.into());
                Ok(Value::Vec3([
                    (y.clone() + z.clone() - x.clone()) / two.clone(),
                    (z.clone() + x.clone() - y.clone()) / two.clone(),
                    (x + y - z) / two,
                ]))
            }
            other => Err(format!(
                "{other} is not available in exact rational arithmetic"
            )),
        }
    }
}
