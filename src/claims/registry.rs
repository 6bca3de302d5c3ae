//! The function table through which other layers register named functions for the
//! catalogue (the Euler-top model does, from [`crate::bindings`]), and the catalogue's own
//! `definition` functions.  The engine itself knows nothing about the Euler top.
//!
//! A layer implements [`GenericFunction`] (one generic method over every [`RealNum`]
//! backend, optionally one over every backend with field operations only) and calls
//! [`Registry::register`].  How a backend reaches the right method of a registered
//! function is [`HostCall`], implemented here for every backend.

use super::ast::Binding;
use super::backend::{Num, RealNum};
use super::builtins::Builtin;
use super::implicit::Implicit;
use super::value::Value;
use crate::algebra::Sym;
use crate::algebra::series::Series;
use crate::numbers::{Ball, Dual, Rational};
use rug::Float;
use std::collections::BTreeMap;
use std::sync::Arc;

/// A function callable on every backend: one method per backend type, so that it can be
/// stored as a trait object.  Implemented automatically for every [`GenericFunction`].
pub trait ExtFunction: Send + Sync {
    /// On f64.
    fn call_f64(&self, args: &[Value<f64>]) -> Result<Value<f64>, String>;
    /// On MPFR.
    fn call_mpfr(&self, args: &[Value<Float>]) -> Result<Value<Float>, String>;
    /// On f64 duals (derivatives).
    fn call_dual_f64(&self, args: &[Value<Dual<f64>>]) -> Result<Value<Dual<f64>>, String>;
    /// On MPFR duals (derivatives).
    fn call_dual_mpfr(&self, args: &[Value<Dual<Float>>]) -> Result<Value<Dual<Float>>, String>;
    /// On duals of f64 duals (second derivatives).
    fn call_dual2_f64(
        &self,
        args: &[Value<Dual<Dual<f64>>>],
    ) -> Result<Value<Dual<Dual<f64>>>, String>;
    /// On duals of MPFR duals (second derivatives).
    fn call_dual2_mpfr(
        &self,
        args: &[Value<Dual<Dual<Float>>>],
    ) -> Result<Value<Dual<Dual<Float>>>, String>;
    /// On exact rationals.
    fn call_exact(&self, args: &[Value<Rational>]) -> Result<Value<Rational>, String>;
    /// On exact symbolic values (the prover's backend).
    fn call_sym(&self, args: &[Value<Sym>]) -> Result<Value<Sym>, String>;
    /// On dual numbers over the prover's values (partial derivatives in a function
    /// parameter).
    fn call_dual_sym(&self, args: &[Value<Dual<Sym>>]) -> Result<Value<Dual<Sym>>, String>;
    /// On power series in `h` over the prover's values (asymptotic claims).
    fn call_series(&self, args: &[Value<Series>]) -> Result<Value<Series>, String>;
    /// On dual numbers over power series (derivatives in a function parameter of an
    /// asymptotic claim's functions).
    fn call_dual_series(&self, args: &[Value<Dual<Series>>])
    -> Result<Value<Dual<Series>>, String>;
    /// How the prover handles the function when its value is defined implicitly (by
    /// equations the numerical backends solve); `None` for explicit functions.
    fn implicit(&self) -> Option<&dyn Implicit> {
        None
    }
    /// On real balls (rigorous enclosures): refused by default, since a function's
    /// numerical algorithms (iterations stopped at a tolerance) are not enclosures.
    fn call_ball(&self, _args: &[Value<Ball>]) -> Result<Value<Ball>, String> {
        Err(NO_BALLS.into())
    }
    /// On duals over real balls: refused by default, as [`ExtFunction::call_ball`].
    fn call_dual_ball(&self, _args: &[Value<Dual<Ball>>]) -> Result<Value<Dual<Ball>>, String> {
        Err(NO_BALLS.into())
    }
}

/// Why a registered function gives no enclosure in ball arithmetic.
pub const NO_BALLS: &str = "a model function is not evaluated in ball arithmetic (its numerical algorithms are not enclosures)";

/// A function written once, generically over the backends.
pub trait GenericFunction: Send + Sync {
    /// Evaluates on any real backend; errors are one-line messages.
    fn call<R: RealNum>(&self, args: &[Value<R>]) -> Result<Value<R>, String>;
    /// Evaluates in ball arithmetic, as an enclosure of the exact value for every
    /// argument in the argument balls; by default refused (see [`NO_BALLS`]).
    fn call_ball(&self, _args: &[Value<Ball>]) -> Result<Value<Ball>, String> {
        Err(NO_BALLS.into())
    }
    /// Evaluates on duals over balls (a derivative enclosed as well as the value); by
    /// default refused (see [`NO_BALLS`]).
    fn call_dual_ball(&self, _args: &[Value<Dual<Ball>>]) -> Result<Value<Dual<Ball>>, String> {
        Err(NO_BALLS.into())
    }
    /// Evaluates with field operations only, on any backend (exact rationals, and any
    /// backend without transcendental functions); by default an error (the function is
    /// not rational).
    fn call_algebraic<S: Num>(&self, _args: &[Value<S>]) -> Result<Value<S>, String> {
        Err("not available in exact rational arithmetic".into())
    }
    /// The prover's view of an implicitly defined function (see
    /// [`ExtFunction::implicit`]); `None` for explicit functions.
    fn implicit(&self) -> Option<&dyn Implicit> {
        None
    }
    /// The function's name, for the prover's records of implicit values.
    fn name_for_proofs(&self) -> &str {
        ""
    }
}

impl<G: GenericFunction> ExtFunction for G {
    fn call_f64(&self, a: &[Value<f64>]) -> Result<Value<f64>, String> {
        self.call(a)
    }
    fn call_mpfr(&self, a: &[Value<Float>]) -> Result<Value<Float>, String> {
        self.call(a)
    }
    fn call_dual_f64(&self, a: &[Value<Dual<f64>>]) -> Result<Value<Dual<f64>>, String> {
        self.call(a)
    }
    fn call_dual_mpfr(&self, a: &[Value<Dual<Float>>]) -> Result<Value<Dual<Float>>, String> {
        self.call(a)
    }
    fn call_dual2_f64(
        &self,
        a: &[Value<Dual<Dual<f64>>>],
    ) -> Result<Value<Dual<Dual<f64>>>, String> {
        self.call(a)
    }
    fn call_dual2_mpfr(
        &self,
        a: &[Value<Dual<Dual<Float>>>],
    ) -> Result<Value<Dual<Dual<Float>>>, String> {
        self.call(a)
    }
    fn call_exact(&self, a: &[Value<Rational>]) -> Result<Value<Rational>, String> {
        self.call_algebraic(a)
    }
    fn call_ball(&self, a: &[Value<Ball>]) -> Result<Value<Ball>, String> {
        GenericFunction::call_ball(self, a)
    }
    fn call_dual_ball(&self, a: &[Value<Dual<Ball>>]) -> Result<Value<Dual<Ball>>, String> {
        GenericFunction::call_dual_ball(self, a)
    }
    fn call_sym(&self, a: &[Value<Sym>]) -> Result<Value<Sym>, String> {
        if self.implicit().is_some()
            && let Some(v) = super::implicit::recall(self.name_for_proofs(), a)
        {
            return Ok(v);
        }
        // after the prover's first error the values are meaningless (and the model's
        // checks would misname them): that error is the reason
        self.call(a).map_err(|m| {
            a.iter()
                .flat_map(|v| v.components())
                .find_map(|x| crate::numbers::Real::failure(&x))
                .unwrap_or(m)
        })
    }
    fn call_dual_sym(&self, a: &[Value<Dual<Sym>>]) -> Result<Value<Dual<Sym>>, String> {
        if self.implicit().is_some() {
            return Err(format!(
                "{}: the derivative of an implicit map in a function parameter is not supported",
                self.name_for_proofs()
            ));
        }
        self.call(a)
    }
    fn call_series(&self, a: &[Value<Series>]) -> Result<Value<Series>, String> {
        match self.implicit() {
            Some(imp) => imp.series(a),
            None => self.call(a).map_err(|m| {
                a.iter()
                    .flat_map(|v| v.components())
                    .find_map(|x| crate::numbers::Real::failure(&x))
                    .unwrap_or(m)
            }),
        }
    }
    fn call_dual_series(&self, a: &[Value<Dual<Series>>]) -> Result<Value<Dual<Series>>, String> {
        if self.implicit().is_some() {
            return Err(format!(
                "{}: the derivative of an implicit map in a function parameter is not supported",
                self.name_for_proofs()
            ));
        }
        self.call(a)
    }
    fn implicit(&self) -> Option<&dyn Implicit> {
        GenericFunction::implicit(self)
    }
}

/// How a backend calls a registered function: it picks its method of [`ExtFunction`].
pub trait HostCall: Num {
    /// Calls `f` on `args`.
    fn host_call(f: &dyn ExtFunction, args: &[Value<Self>]) -> Result<Value<Self>, String>;
}

macro_rules! host_call {
    ($($t:ty => $method:ident),* $(,)?) => {
        $(impl HostCall for $t {
            fn host_call(f: &dyn ExtFunction, args: &[Value<Self>]) -> Result<Value<Self>, String> {
                f.$method(args)
            }
        })*
    };
}

host_call!(
    f64 => call_f64,
    Float => call_mpfr,
    Dual<f64> => call_dual_f64,
    Dual<Float> => call_dual_mpfr,
    Dual<Dual<f64>> => call_dual2_f64,
    Dual<Dual<Float>> => call_dual2_mpfr,
    Rational => call_exact,
    Sym => call_sym,
    Dual<Sym> => call_dual_sym,
    Series => call_series,
    Dual<Series> => call_dual_series,
    Ball => call_ball,
    Dual<Ball> => call_dual_ball,
);

/// A registered function.
#[derive(Clone)]
pub struct Registered {
    /// Number of arguments.
    pub arity: usize,
    /// One-line description (shown in `identities/README.md` and errors).
    pub doc: String,
    /// The implementation.
    pub f: Arc<dyn ExtFunction>,
}

/// A user function from a `define` claim or a `let` block.
#[derive(Clone, Debug)]
pub struct UserFn {
    /// Parameter names.
    pub params: Vec<String>,
    /// The defining binding.
    pub def: Binding,
}

/// Why a name could not be added to a [`Registry`].
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum RegistryError {
    /// The name is a built-in function.
    #[error("'{0}' is a built-in function")]
    Builtin(String),
    /// A host function of this name is registered already.
    #[error("function '{0}' registered twice")]
    RegisteredTwice(String),
    /// A definition would shadow a built-in or registered function.
    #[error("'{0}' is already a built-in or registered function")]
    Shadows(String),
    /// A catalogue function of this name is defined already.
    #[error("function '{0}' defined twice")]
    DefinedTwice(String),
}

/// The function table: registered (host) functions and catalogue-defined functions.
#[derive(Clone, Default)]
pub struct Registry {
    ext: BTreeMap<String, Registered>,
    user: BTreeMap<String, Arc<UserFn>>,
}

impl std::fmt::Debug for Registry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Registry")
            .field("registered", &self.ext.keys().collect::<Vec<_>>())
            .field("defined", &self.user.keys().collect::<Vec<_>>())
            .finish()
    }
}

impl Registry {
    /// An empty table (built-ins are always available; they are not stored here).
    pub fn new() -> Self {
        Self::default()
    }
    /// Registers a host function under `name`.  Errors if the name is a built-in or
    /// taken.
    ///
    /// ```
    /// use eulertop::claims::eval::Evaluator;
    /// use eulertop::claims::parser::parse_expr;
    /// use eulertop::claims::registry::{GenericFunction, Registry};
    /// use eulertop::claims::value::Value;
    /// use eulertop::claims::backend::RealNum;
    ///
    /// /// cube(x) = x³
    /// struct Cube;
    /// impl GenericFunction for Cube {
    ///     fn call<R: RealNum>(&self, a: &[Value<R>]) -> Result<Value<R>, String> {
    ///         let x = a[0].as_real()?;
    ///         Ok(Value::Real(x.clone() * x.clone() * x))
    ///     }
    /// }
    ///
    /// let mut reg = Registry::new();
    /// reg.register("cube", 1, "cube(x): x^3", Cube).unwrap();
    /// assert!(reg.register("sin", 1, "clash", Cube).is_err());
    /// let v = Evaluator::new(&reg, 0.0f64).eval(&parse_expr("cube(2)").unwrap()).unwrap();
    /// assert_eq!(v, Value::Real(8.0));
    /// ```
    pub fn register(
        &mut self,
        name: &str,
        arity: usize,
        doc: &str,
        f: impl ExtFunction + 'static,
    ) -> Result<(), RegistryError> {
        if Builtin::from_name(name).is_some() {
            return Err(RegistryError::Builtin(name.into()));
        }
        if self.ext.contains_key(name) {
            return Err(RegistryError::RegisteredTwice(name.into()));
        }
        self.ext.insert(
            name.to_string(),
            Registered {
                arity,
                doc: doc.to_string(),
                f: Arc::new(f),
            },
        );
        Ok(())
    }
    /// Adds a catalogue-defined function.  Errors if the name is taken.
    pub fn define(&mut self, def: Binding) -> Result<(), RegistryError> {
        let name = def.name.clone();
        if Builtin::from_name(&name).is_some() || self.ext.contains_key(&name) {
            return Err(RegistryError::Shadows(name));
        }
        if self.user.contains_key(&name) {
            return Err(RegistryError::DefinedTwice(name));
        }
        let params = def.params.clone().unwrap_or_default();
        self.user.insert(name, Arc::new(UserFn { params, def }));
        Ok(())
    }
    /// A host function by name.
    pub fn ext(&self, name: &str) -> Option<&Registered> {
        self.ext.get(name)
    }
    /// A catalogue function by name.
    pub fn user(&self, name: &str) -> Option<&Arc<UserFn>> {
        self.user.get(name)
    }
    /// Is `name` callable (built-in, registered or defined)?
    pub fn knows(&self, name: &str) -> bool {
        Builtin::from_name(name).is_some()
            || self.ext.contains_key(name)
            || self.user.contains_key(name)
    }
    /// Names, arities and docs of the registered host functions, sorted by name.
    pub fn registered(&self) -> Vec<(String, usize, String)> {
        self.ext
            .iter()
            .map(|(n, r)| (n.clone(), r.arity, r.doc.clone()))
            .collect()
    }
    /// The catalogue-defined functions, sorted by name.
    pub fn defined(&self) -> impl Iterator<Item = &Arc<UserFn>> {
        self.user.values()
    }
}
