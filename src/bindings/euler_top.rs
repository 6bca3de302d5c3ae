//! The Euler-top model's functions in the claim catalogue, declared once in
//! [`ModelFn`]: name, arguments, value and the paper's label.  [`registry`] registers
//! them all; `identities/README.md` lists them from the same declaration
//! ([`readme_table`]).
//!
//! Arguments: moments of inertia `A, B, C` (validated A > B > C > 0), `M` a vec3, `h` the
//! step, `Msq = M²`, `E` the energy.  The field-only functions (`Omega`, `energy`,
//! `msq`, `hatM`, `OmegaM`, `Jdiag`) run the model's own generic code in every backend,
//! the exact one included.
//!
//! ```
//! use eulertop::bindings::euler_top::registry;
//! use eulertop::claims::eval::Evaluator;
//! use eulertop::claims::parser::parse_expr;
//! let reg = registry().unwrap();
//! let ev = Evaluator::new(&reg, 0.0f64);
//! let e = ev.eval(&parse_expr("energy(vec(1, 2, 3), 3, 2, 1)").unwrap()).unwrap();
//! assert!((e.as_real().unwrap() - (1.0 / 3.0 + 4.0 / 2.0 + 9.0)).abs() < 1e-15);
//! ```

use crate::claims::backend::{Num, RealNum};
use crate::claims::builtins::table::name_table;
use crate::claims::implicit::Implicit;
use crate::claims::registry::{GenericFunction, Registry, RegistryError};
use crate::claims::value::Value;
use crate::linalg::Vec3;
use crate::model::discretization::{Gamma, step};
use crate::model::elliptic_coords::{m_to_phase, phi_to_m_signed};
use crate::model::params::EllipticParams;
use crate::model::phase::delta;
use crate::model::veselov_moser::{hat, j_diag, omega_matrix, vm_step};
use crate::model::{Inertia, ModelError, lax};
use crate::numbers::Cplx;

/// The declaration of a model function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ModelSpec {
    /// The name in the catalogue.
    pub name: &'static str,
    /// The argument list.
    pub args: &'static str,
    /// What the value is.
    pub doc: &'static str,
    /// The paper's `\label`s it implements, comma-separated.
    pub labels: &'static str,
    /// Is it computed with field operations only (so also exactly)?
    pub algebraic: bool,
}

impl ModelSpec {
    const fn new(
        name: &'static str,
        args: &'static str,
        doc: &'static str,
        labels: &'static str,
        algebraic: bool,
    ) -> Self {
        ModelSpec {
            name,
            args,
            doc,
            labels,
            algebraic,
        }
    }
    /// The number of arguments.
    pub fn arity(&self) -> usize {
        self.args.split(',').count()
    }
    /// `name(args)`.
    pub fn signature(&self) -> String {
        format!("{}({})", self.name, self.args)
    }
    /// The paper labels as written in the README: `(Omega), (gamma1)`.
    pub fn label_list(&self) -> String {
        self.labels
            .split(", ")
            .map(|l| format!("({l})"))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

name_table! {
    /// A function of the Euler-top model, callable from the catalogue.
    pub enum ModelFn: ModelSpec {
        /// vec3 Ω(M) = (M1/A, M2/B, M3/C)
        Omega = "Omega"("M, A, B, C"): "Omega", true;
        /// the energy E(M) = ⟨M, Ω(M)⟩
        Energy = "energy"("M, A, B, C"): "E", true;
        /// M² = ⟨M, M⟩
        Msq = "msq"("M"): "M2", true;
        /// mat3 [[0, M3, −M2], [−M3, 0, M1], [M2, −M1, 0]] (the paper's hat)
        HatM = "hatM"("M"): "M m", true;
        /// mat3 hatM(Ω(M))
        OmegaM = "OmegaM"("M, A, B, C"): "Omega m", true;
        /// vec3 (J1, J2, J3) = ((B+C−A)/2, (C+A−B)/2, (A+B−C)/2)
        Jdiag = "Jdiag"("A, B, C"): "Js", true;
        /// the modulus k (not k²)
        Kmod = "kmod"("A, B, C, Msq, E"): "k", false;
        /// ν > 0
        Nu = "nu"("A, B, C, Msq, E"): "nu", false;
        /// vec3 (|a|, |b|, |c|)
        Abc = "abc"("A, B, C, Msq, E"): "abc", false;
        /// vec3 (M², E, φ) with φ ∈ (−2K, 2K]: Φ⁻¹
        EllCoords = "ell_coords"("M, A, B, C"): "ell coord", false;
        /// vec3 M = Φ(M², E, φ) in the sector sign M3 = s3 (upper regime) or sign M1 = s1 (lower)
        EllInverse = "ell_inverse"("Msq, E, phi, s1, s3, A, B, C"): "ell coord", false;
        /// vec3 M̂ of (impl spec 1–3) with γ0 ≡ 1
        StepGamma0 = "step_gamma0"("M, h, A, B, C"): "impl spec, gamma0", false;
        /// vec3 M̂ of (impl spec 1–3) with γ1
        StepGamma1 = "step_gamma1"("M, h, A, B, C"): "impl spec, gamma1", false;
        /// vec3 M̂ of (impl spec 1–3) with γ2
        StepGamma2 = "step_gamma2"("M, h, A, B, C"): "impl spec, gamma2", false;
        /// vec3 M̂ = ωᵀMω (Veselov–Moser, on the branch (omega as))
        StepVm = "step_vm"("M, h, A, B, C"): "VM", false;
        /// mat3 ω solving (M thru omega) on the branch (omega as)
        VmOmega = "vm_omega"("M, h, A, B, C"): "M thru omega", false;
        /// γ_VM(M, M̂, h)
        GammaVm = "gamma_vm"("M, Mh, h, A, B, C"): "gammaMV", false;
        /// the phase step δ solving (master12) with α1
        Delta1 = "delta1"("A, B, C, Msq, E, h"): "master12", false;
        /// the phase step δ solving (master12) with α2
        Delta2 = "delta2"("A, B, C, Msq, E, h"): "master12", false;
        /// the phase step δ solving (MV master)
        DeltaVm = "delta_vm"("A, B, C, Msq, E, h"): "MV master", false;
        /// the positive root of the printed ρ²
        Rho = "rho"("A, B, C"): "rokappa", false;
        /// the positive root of the printed κ²
        Kappa = "kappa"("A, B, C"): "rokappa", false;
        /// complex w_j(u) with the printed ρ, κ (u real or complex, j = 1, 2, 3)
        W = "w"("j, u, A, B, C"): "ws", false;
    }
}

impl ModelFn {
    /// The one-line description kept in the registry: `name(args): value (label)`.
    pub fn registry_doc(self) -> String {
        let s = self.spec();
        format!("{}: {} {}", s.signature(), s.doc.trim(), s.label_list())
    }
}

/// The function table of the catalogue: every [`ModelFn`] registered.  The only error is
/// a name clash with a built-in (a programming error, which the tests catch).
pub fn registry() -> Result<Registry, RegistryError> {
    let mut reg = Registry::new();
    for f in ModelFn::ALL {
        let s = f.spec();
        reg.register(s.name, s.arity(), &f.registry_doc(), *f)?;
    }
    Ok(reg)
}

/// The model-function table of `identities/README.md`.
pub fn readme_table() -> String {
    let mut s = String::from("| function | value | paper |\n|---|---|---|\n");
    for f in ModelFn::ALL {
        let sp = f.spec();
        s.push_str(&format!(
            "| `{}` | {} | {} |\n",
            sp.signature(),
            sp.doc.trim().replace('|', "\\|"),
            sp.label_list()
        ));
    }
    s
}

pub(super) fn v3<R: Num>(v: &Value<R>) -> Result<Vec3<R>, String> {
    v.as_vec3()
}
pub(super) fn inertia<R: Num>(a: &[Value<R>], at: usize) -> Result<Inertia<R>, String> {
    Inertia::new(a[at].as_real()?, a[at + 1].as_real()?, a[at + 2].as_real()?)
        .map_err(|e| e.to_string())
}
pub(super) fn params<R: RealNum>(
    a: &[Value<R>],
) -> Result<(Inertia<R>, EllipticParams<R>), String> {
    let i = inertia(a, 0)?;
    let p =
        EllipticParams::new(&i, &a[3].as_real()?, &a[4].as_real()?).map_err(|e| e.to_string())?;
    Ok((i, p))
}
/// (ell coord) inverted: `(M², E, φ)` of the point `a[0]` for the moments `a[1..4]`.
///
/// For a symbolic scalar whose proof has not decided the regime of the point (the sign
/// of `BE − M²`), `M²` and `E` are the polynomials they are and `φ` is an opaque symbol
/// with the numeric phase as its values: a claim about `M²` and `E` alone needs no
/// regime, and one that uses `φ` is proved only where it holds for every `φ`.  The
/// undecided sign stays noted, so that a proof can still split the domain by it.
fn ell_coords<R: RealNum>(a: &[Value<R>]) -> Result<Value<R>, String> {
    let i = inertia(a, 1)?;
    let m = v3(&a[0])?;
    if R::BY_RULE {
        let [x, y, z] = &m.0;
        let (x2, y2, z2) = (x.sqr(), y.sqr(), z.sqr());
        let be = z2.clone() * (i.b.clone() - i.c.clone()) / i.c.clone()
            - x2.clone() * (i.a.clone() - i.b.clone()) / i.a.clone();
        if be.stated_sign().is_err() {
            let m2 = x2.clone() + y2.clone() + z2.clone();
            let e = x2 / i.a.clone() + y2 / i.b.clone() + z2 / i.c.clone();
            let phi = R::opaque_by_rule("ellphi", &[x, y, z, &i.a, &i.b, &i.c], &|v| {
                let at = Inertia::new(v[3].clone(), v[4].clone(), v[5].clone()).ok()?;
                let point = Vec3::new(v[0].clone(), v[1].clone(), v[2].clone());
                m_to_phase(&at, &point).ok().map(|(_, phi)| phi)
            })?;
            return Ok(Value::Vec3(Vec3::new(m2, e, phi)));
        }
    }
    let (p, phi) = m_to_phase(&i, &m).map_err(err)?;
    Ok(Value::Vec3(Vec3::new(p.m2, p.e, phi)))
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
pub(super) fn err(e: ModelError) -> String {
    e.to_string()
}

impl GenericFunction for ModelFn {
    fn call<R: RealNum>(&self, a: &[Value<R>]) -> Result<Value<R>, String> {
        use ModelFn as F;
        if R::BY_RULE && self.is_implicit() {
            return Err(format!(
                "uses the implicit map {}: its value is a root of the map's equations, which the prover parametrizes only where the replaced arguments are free variables of the claim, or substitutes a stated value into",
                self.name()
            ));
        }
        match self {
            f if f.spec().algebraic => self.call_algebraic(a),
            F::Kmod => Ok(Value::Real(params(a)?.1.k())),
            F::Nu => Ok(Value::Real(params(a)?.1.nu())),
            F::Abc => {
                let p = params(a)?.1;
                Ok(Value::Vec3(Vec3::new(
                    p.a2.sqrt(),
                    p.b2.sqrt(),
                    p.c2.sqrt(),
                )))
            }
            F::EllCoords => ell_coords(a),
            F::EllInverse => ell_inverse(a),
            F::StepGamma0 | F::StepGamma1 | F::StepGamma2 | F::StepVm | F::VmOmega => self.step(a),
            F::GammaVm => {
                let i = inertia(a, 3)?;
                let g = Gamma::Vm.eval(&i, &v3(&a[0])?, &v3(&a[1])?, &a[2].as_real()?);
                Ok(Value::Real(g.map_err(err)?))
            }
            F::Delta1 | F::Delta2 | F::DeltaVm => {
                let (i, p) = params(a)?;
                let g = match self {
                    F::Delta1 => Gamma::G1,
                    F::Delta2 => Gamma::G2,
                    _ => Gamma::Vm,
                };
                Ok(Value::Real(
                    delta(&i, &p, g, &a[5].as_real()?).map_err(err)?,
                ))
            }
            F::Rho | F::Kappa => {
                let (r2, k2) = lax::rho2_kappa2(&inertia(a, 0)?);
                Ok(Value::Real(if *self == F::Rho {
                    r2.sqrt()
                } else {
                    k2.sqrt()
                }))
            }
            _ => w(a),
        }
    }

    fn implicit(&self) -> Option<&dyn Implicit> {
        self.is_implicit().then_some(self as &dyn Implicit)
    }

    fn call_ball(
        &self,
        a: &[Value<crate::numbers::Ball>],
    ) -> Result<Value<crate::numbers::Ball>, String> {
        super::ball::call(*self, a)
    }

    fn call_dual_ball(
        &self,
        a: &[Value<crate::numbers::Dual<crate::numbers::Ball>>],
    ) -> Result<Value<crate::numbers::Dual<crate::numbers::Ball>>, String> {
        super::ball::call_dual(*self, a)
    }

    fn name_for_proofs(&self) -> &str {
        self.name()
    }

    fn call_algebraic<S: Num>(&self, a: &[Value<S>]) -> Result<Value<S>, String> {
        use ModelFn as F;
        Ok(match self {
            F::Omega => Value::Vec3(inertia(a, 1)?.omega(&v3(&a[0])?)),
            F::Energy => Value::Real(inertia(a, 1)?.energy(&v3(&a[0])?)),
            F::Msq => Value::Real(v3(&a[0])?.norm2()),
            F::HatM => Value::Mat3(hat(&v3(&a[0])?)),
            F::OmegaM => Value::Mat3(omega_matrix(&inertia(a, 1)?, &v3(&a[0])?)),
            F::Jdiag => Value::Vec3(j_diag(&inertia(a, 0)?)),
            other => {
                return Err(format!(
                    "{} is not available in {}",
                    other.name(),
                    S::ARITHMETIC
                ));
            }
        })
    }
}

impl ModelFn {
    /// Is the value defined implicitly (by Newton's method on the map's equations)?
    pub fn is_implicit(self) -> bool {
        use ModelFn as F;
        matches!(
            self,
            F::StepGamma0
                | F::StepGamma1
                | F::StepGamma2
                | F::StepVm
                | F::VmOmega
                | F::Delta1
                | F::Delta2
                | F::DeltaVm
        )
    }

    /// One step of a discretization: `(M, h, A, B, C)`.
    fn step<R: RealNum>(&self, a: &[Value<R>]) -> Result<Value<R>, String> {
        let i = inertia(a, 2)?;
        let (m, h) = (v3(&a[0])?, a[1].as_real()?);
        let gamma = match self {
            ModelFn::StepGamma0 => Gamma::G0,
            ModelFn::StepGamma1 => Gamma::G1,
            ModelFn::StepGamma2 => Gamma::G2,
            ModelFn::StepVm => return Ok(Value::Vec3(vm_step(&i, &m, &h).map_err(err)?.m_hat)),
            _ => return Ok(Value::Mat3(vm_step(&i, &m, &h).map_err(err)?.omega)),
        };
        Ok(Value::Vec3(step(&i, gamma, &m, &h).map_err(err)?))
    }
}

/// `ell_inverse(Msq, E, phi, s1, s3, A, B, C)`.
fn ell_inverse<R: RealNum>(a: &[Value<R>]) -> Result<Value<R>, String> {
    let i = inertia(a, 5)?;
    let (m2, en, phi) = (a[0].as_real()?, a[1].as_real()?, a[2].as_real()?);
    let (s1, s3) = (sign_value_of(&a[3])?, sign_value_of(&a[4])?);
    let p = EllipticParams::new(&i, &m2, &en).map_err(err)?;
    Ok(Value::Vec3(
        phi_to_m_signed(&p, &s1, &s3, &phi).map_err(err)?,
    ))
}

/// The sign of a sector argument as a value: ±1, or for the prover a sign symbol
/// ([`Real::signum_value`]).
fn sign_value_of<R: RealNum>(v: &Value<R>) -> Result<R, String> {
    let x = v.as_real()?;
    if !x.is_finite() {
        return Ok(x.from_i64(i64::from(sign_of(v)?)));
    }
    let s = x.signum_value();
    if s.is_zero() {
        return Err("sign argument must be nonzero".into());
    }
    Ok(s)
}

/// `w(j, u, A, B, C)`.
fn w<R: RealNum>(a: &[Value<R>]) -> Result<Value<R>, String> {
    let j = a[0].as_int()?;
    if !(1..=3).contains(&j) {
        return Err(format!("w(j, ...): j = {j} must be 1, 2 or 3"));
    }
    let i = inertia(a, 2)?;
    let (r2, k2) = lax::rho2_kappa2(&i);
    let u = a[1].as_complex()?;
    let z = r2.zero();
    let ws = lax::w(&u, &Cplx::new(r2.sqrt(), z), &k2.sqrt()).map_err(err)?;
    Ok(Value::Complex(ws[(j - 1) as usize].clone()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_function_registers_with_its_arity() {
        let reg = registry().unwrap();
        for f in ModelFn::ALL {
            let r = reg.ext(f.name()).unwrap();
            assert_eq!(r.arity, f.spec().arity(), "{}", f.name());
        }
        assert_eq!(reg.registered().len(), ModelFn::ALL.len());
    }

    #[test]
    fn the_readme_table_is_this_declaration() {
        let readme = include_str!("../../identities/README.md");
        assert!(readme.contains(&readme_table()), "{}", readme_table());
    }

    #[test]
    fn labels_are_labels_of_the_paper() {
        let table: toml::Table = toml::from_str(include_str!("../../identities/paper.toml"))
            .expect("identities/paper.toml parses");
        let paper: Vec<&str> = table["paper"]["labels"]
            .as_array()
            .expect("the paper's labels")
            .iter()
            .filter_map(|l| l.as_str())
            .collect();
        assert_eq!(paper.len(), 96);
        for f in ModelFn::ALL {
            for l in f.spec().labels.split(", ") {
                assert!(
                    paper.contains(&l),
                    "{}: '{l}' is not a paper label",
                    f.name()
                );
            }
        }
    }
}
