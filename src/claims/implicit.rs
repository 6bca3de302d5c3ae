//! Implicitly defined functions in symbolic proofs.
//!
//! A registered function whose value is a root of equations (a step of an implicit
//! map, a phase step solving a master equation) has no expression the prover could
//! expand.  It can still take part in a proof in two ways, which the function offers
//! through [`Implicit`]:
//!
//! * **Parametrization.**  Some of its arguments (those at [`Implicit::eliminates`])
//!   are free variables of the claim.  The function replaces them by expressions in
//!   new indeterminates for which its value is an expression too, such that the
//!   defining equations hold identically.  Every solution of the equations is of
//!   this form, so an identity proved after the replacement holds for every
//!   solution, the one the numerical solver selects included.  The equations at the
//!   replaced arguments ([`Parametrized::checks`]) are proved together with the claim:
//!   the parametrization is checked against the function's own equations, not
//!   trusted.
//! * **A stated value.**  When one side of a claim is the call itself, the other side
//!   is substituted into the defining equations ([`Implicit::residual`]); the claim is
//!   proved when every component vanishes identically.
//!
//! Either way the proof shows that a solution of the equations has the property; that
//! the solution is the one the function selects (its branch) is an assumption of the
//! proof, recorded with [`Implicit::branch`], and the claim's numerical evidence checks
//! it at the sampled points.

use crate::algebra::Sym;
use crate::algebra::series::Series;
use crate::claims::value::Value;
use crate::linalg::{Mat3, Vec3};

/// The replacement of a function's eliminated arguments by a parametrization.
pub struct Parametrized {
    /// Values replacing the eliminated arguments, in the order of
    /// [`Implicit::eliminates`].
    pub replace: Vec<Value<Sym>>,
    /// The function's value at the replaced arguments.
    pub value: Value<Sym>,
    /// Values of companion functions at the same arguments (such as the rotation that
    /// defines a step), by name: the same parametrization gives them too.
    pub also: Vec<(&'static str, Value<Sym>)>,
    /// The components of the defining equations at the replaced arguments and the
    /// value: each must be 0 identically.
    pub checks: Vec<Sym>,
    /// The new indeterminates, as many as the eliminated arguments have components
    /// (for derivatives with respect to the claim's variables, by the chain rule).
    pub params: Vec<Sym>,
    /// What the parametrization is, for the reader.
    pub note: String,
}

/// A function defined implicitly, as seen by the prover.
pub trait Implicit: Send + Sync {
    /// Positions of the arguments that [`Implicit::parametrize`] replaces; each must be
    /// a free variable of the claim.
    fn eliminates(&self) -> &'static [usize];
    /// The parametrization at `args` (the eliminated ones are the claim's
    /// indeterminates, whose values at the domain points serve to place the new
    /// symbols).
    fn parametrize(&self, args: &[Value<Sym>]) -> Result<Parametrized, String>;
    /// The components of the defining equations at `args` with the stated `value`.
    fn residual(&self, args: &[Value<Sym>], value: &Value<Sym>) -> Result<Vec<Sym>, String>;
    /// [`Implicit::residual`] for a stated value, possibly multiplied through by a
    /// factor to spare divisions: the components and the factor, which the prover shows
    /// to be nonzero on the domain (`None`: no factor).
    fn stated_residual(
        &self,
        args: &[Value<Sym>],
        value: &Value<Sym>,
    ) -> Result<(Vec<Sym>, Option<Sym>), String> {
        Ok((self.residual(args, value)?, None))
    }
    /// The defining equations, as the paper labels them.
    fn equations(&self) -> String;
    /// The equations that [`Implicit::residual`] substitutes a stated value into, with
    /// the reason they hold (the defining ones unless a proved theorem supplies others).
    fn stated_equations(&self) -> String {
        self.equations()
    }
    /// Which solution the function selects.
    fn branch(&self) -> String;
    /// The value as a power series in `h` at power-series arguments: the solution of
    /// the defining equations continuous at `h = 0` (the branch of
    /// [`Implicit::branch`]), coefficient by coefficient.  By default not available.
    fn series(&self, _args: &[Value<Series>]) -> Result<Value<Series>, String> {
        Err("no power-series solution of its equations".into())
    }
}

/// The key under which the value of `name(args)` is remembered in the prover's ring.
pub fn key(name: &str, args: &[Value<Sym>]) -> String {
    let parts: Vec<String> = args
        .iter()
        .map(|a| {
            a.components()
                .iter()
                .map(|c| c.render())
                .collect::<Vec<_>>()
                .join(", ")
        })
        .collect();
    format!("{name}({})", parts.join("; "))
}

fn shape(v: &Value<Sym>) -> &'static str {
    v.type_name()
}

/// Remembers `value` as the value of `name(args)` in the ring of `value`.
pub fn remember(name: &str, args: &[Value<Sym>], value: &Value<Sym>) -> Result<(), String> {
    let comps = value.components();
    let ring = comps
        .first()
        .map(|c| c.ring().clone())
        .ok_or_else(|| format!("{name}: an implicit value without components"))?;
    ring.remember(&key(name, args), shape(value), &comps);
    Ok(())
}

/// The remembered value of `name(args)`, if a parametrization put one there.
pub fn recall(name: &str, args: &[Value<Sym>]) -> Option<Value<Sym>> {
    let ring = args
        .iter()
        .flat_map(|a| a.components())
        .next()?
        .ring()
        .clone();
    let (shape, c) = ring.recall(&key(name, args))?;
    let at = |j: usize| c.get(j).cloned();
    Some(match (shape.as_str(), c.len()) {
        ("real", 1) => Value::Real(at(0)?),
        ("vec3", 3) => Value::Vec3(Vec3::new(at(0)?, at(1)?, at(2)?)),
        ("mat3", 9) => Value::Mat3(Mat3(std::array::from_fn(|i| {
            std::array::from_fn(|j| c[3 * i + j].clone())
        }))),
        _ => return None,
    })
}
