//! The function table through which other layers (the Euler-top model) register named
//! functions for the catalogue.  The engine itself knows nothing about the Euler top.
//!
//! A layer implements [`GenericFunction`] (one generic method over every [`Real`]
//! backend, optionally an exact one) and calls [`Registry::register`].

use super::ast::Binding;
use super::value::Value;
use crate::numbers::{Dual, Rational, Real};
use rug::Float;
use std::collections::BTreeMap;
use std::sync::Arc;

/// A function callable on every backend.  Implemented automatically for every
/// [`GenericFunction`].
pub trait ExtFunction: Send + Sync {
    /// On f64.
    fn call_f64(&self, args: &[Value<f64>]) -> Result<Value<f64>, String>;
    /// On MPFR.
    fn call_mpfr(&self, args: &[Value<Float>]) -> Result<Value<Float>, String>;
    /// On f64 duals (derivatives).
    fn call_dual_f64(&self, args: &[Value<Dual<f64>>]) -> Result<Value<Dual<f64>>, String>;
    /// On MPFR duals (derivatives).
    fn call_dual_mpfr(&self, args: &[Value<Dual<Float>>]) -> Result<Value<Dual<Float>>, String>;
    /// On exact rationals.
    fn call_exact(&self, args: &[Value<Rational>]) -> Result<Value<Rational>, String>;
}

/// A function written once, generically over the real backends.
pub trait GenericFunction: Send + Sync {
    /// Evaluates on any real backend; errors are one-line messages.
    fn call<R: Real + super::backend::Num>(&self, args: &[Value<R>]) -> Result<Value<R>, String>;
    /// Evaluates exactly; by default an error (the function is not rational).
    fn call_exact(&self, _args: &[Value<Rational>]) -> Result<Value<Rational>, String> {
        Err("not available in exact rational arithmetic".into())
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
    fn call_exact(&self, a: &[Value<Rational>]) -> Result<Value<Rational>, String> {
        GenericFunction::call_exact(self, a)
    }
}

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
    /// Registers a host function.  Errors if the name is a built-in or taken.
    pub fn register(
        &mut self,
        name: &str,
        arity: usize,
        doc: &str,
        f: impl ExtFunction + 'static,
    ) -> Result<(), String> {
        if super::builtins::is_builtin(name) {
            return Err(format!("'{name}' is a built-in function"));
        }
        if self.ext.contains_key(name) {
            return Err(format!("function '{name}' registered twice"));
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
    pub fn define(&mut self, def: Binding) -> Result<(), String> {
        let name = def.name.clone();
        if super::builtins::is_builtin(&name) || self.ext.contains_key(&name) {
            return Err(format!(
                "'{name}' is already a built-in or registered function"
            ));
        }
        if self.user.contains_key(&name) {
            return Err(format!("function '{name}' defined twice"));
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
        super::builtins::is_builtin(name)
            || self.ext.contains_key(name)
            || self.user.contains_key(name)
    }
    /// Names and docs of the registered host functions, sorted.
    pub fn registered(&self) -> Vec<(String, usize, String)> {
        self.ext
            .iter()
            .map(|(n, r)| (n.clone(), r.arity, r.doc.clone()))
            .collect()
    }
}
