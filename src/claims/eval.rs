//! The evaluator: one generic tree walker over every scalar backend ([`Num`]).
//!
//! A scope is a list of bindings (sampled variables, `let` values, function parameters).
//! `let` bindings remember their defining expression, so `d(expr, x)` can lift the scope
//! into dual numbers, seed `x`, and recompute every later binding that may depend on it.

use super::ast::{BinOp, Binding, Expr, ExprKind, Span, UnOp};
use super::backend::Num;
use super::builtins;
use super::registry::{Registry, UserFn};
use super::value::{Cx, Value};
use crate::numbers::Dual;
use std::any::Any;
use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;
use std::sync::Arc;

/// An evaluation error: a one-line message and, when known, the span of the expression.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct EvalError {
    /// What went wrong.
    pub message: String,
    /// Where (in the expression's source string), if known.
    pub span: Option<Span>,
}

impl EvalError {
    fn at(message: impl Into<String>, span: Span) -> Self {
        EvalError {
            message: message.into(),
            span: Some(span),
        }
    }
}

#[derive(Clone)]
struct Bind<T> {
    name: String,
    value: Value<T>,
    def: Option<Rc<Expr>>,
}

/// Cache of lifted dual scopes for `d()`, keyed by (variable position, component,
/// recomputed bindings); cleared whenever the scope changes, empty in clones.
#[derive(Default)]
struct DCache(RefCell<HashMap<String, Rc<dyn Any>>>);

impl Clone for DCache {
    fn clone(&self) -> Self {
        DCache::default()
    }
}

/// Evaluates expressions over the backend `T`.
#[derive(Clone)]
pub struct Evaluator<'r, T> {
    reg: &'r Registry,
    like: T,
    scope: Vec<Bind<T>>,
    local_fns: Vec<Arc<UserFn>>,
    depth: usize,
    dcache: DCache,
}

const MAX_CALL_DEPTH: usize = 64;

impl<'r, T: Num> Evaluator<'r, T> {
    /// A new evaluator; `like` fixes the precision of constants and literals.
    pub fn new(reg: &'r Registry, like: T) -> Self {
        Evaluator {
            reg,
            like,
            scope: Vec::new(),
            local_fns: Vec::new(),
            depth: 0,
            dcache: DCache::default(),
        }
    }
    /// A scalar with the working precision.
    pub fn like(&self) -> &T {
        &self.like
    }
    /// The registry.
    pub fn registry(&self) -> &'r Registry {
        self.reg
    }
    /// Binds a variable (e.g. a sampled input).
    pub fn bind(&mut self, name: &str, value: Value<T>) {
        self.dcache.0.borrow_mut().clear();
        self.scope.push(Bind {
            name: name.to_string(),
            value,
            def: None,
        });
    }
    /// Evaluates a `let` binding and binds it (function bindings become local functions).
    pub fn bind_let(&mut self, b: &Binding) -> Result<(), EvalError> {
        if let Some(ps) = &b.params {
            self.local_fns.push(Arc::new(UserFn {
                params: ps.clone(),
                def: b.clone(),
            }));
            return Ok(());
        }
        let v = self.eval(&b.body).map_err(|e| EvalError {
            message: format!("in '{}': {}", b.name, e.message),
            span: e.span,
        })?;
        self.dcache.0.borrow_mut().clear();
        self.scope.push(Bind {
            name: b.name.clone(),
            value: v,
            def: Some(Rc::new(b.body.clone())),
        });
        Ok(())
    }
    /// The value of a bound name.
    pub fn lookup(&self, name: &str) -> Option<&Value<T>> {
        self.scope
            .iter()
            .rev()
            .find(|b| b.name == name)
            .map(|b| &b.value)
    }

    /// Evaluates an expression.
    pub fn eval(&self, e: &Expr) -> Result<Value<T>, EvalError> {
        let v = self.eval_inner(e)?;
        if !v.is_finite() {
            return Err(EvalError::at(
                "value is not finite (pole or overflow)",
                e.span,
            ));
        }
        Ok(v)
    }

    fn eval_inner(&self, e: &Expr) -> Result<Value<T>, EvalError> {
        let sp = e.span;
        let wrap = |r: Result<Value<T>, String>| r.map_err(|m| EvalError::at(m, sp));
        match &e.kind {
            ExprKind::Num(s) => wrap(self.like.lit(s).map(Value::Real)),
            ExprKind::Name(n) => {
                if let Some(v) = self.lookup(n) {
                    return Ok(v.clone());
                }
                match n.as_str() {
                    "pi" => wrap(self.like.pi_().map(Value::Real)),
                    "i" => Ok(Value::Complex(Cx::new(self.like.zero(), self.like.one()))),
                    "I3" | "I2" => builtins::call(self, n, &[])
                        .unwrap_or_else(|| Err(String::new()))
                        .map_err(|m| EvalError::at(m, sp)),
                    _ => Err(EvalError::at(format!("unknown variable '{n}'"), sp)),
                }
            }
            ExprKind::Unary(UnOp::Neg, a) => wrap(self.eval(a)?.neg()),
            ExprKind::Unary(UnOp::Not, a) => wrap(self.eval(a)?.as_bool().map(|b| Value::Bool(!b))),
            ExprKind::Binary(op, a, b) => {
                if matches!(op, BinOp::And | BinOp::Or) {
                    let x = wrap(self.eval(a)?.as_bool().map(Value::Bool))?;
                    let x = x.as_bool().map_err(|m| EvalError::at(m, sp))?;
                    if (*op == BinOp::And && !x) || (*op == BinOp::Or && x) {
                        return Ok(Value::Bool(x));
                    }
                    return wrap(self.eval(b)?.as_bool().map(Value::Bool));
                }
                let x = self.eval(a)?;
                let y = self.eval(b)?;
                wrap(binary(*op, &x, &y))
            }
            ExprKind::If(c, a, b) => {
                let c = wrap(self.eval(c)?.as_bool().map(Value::Bool))?;
                if c == Value::Bool(true) {
                    self.eval(a)
                } else {
                    self.eval(b)
                }
            }
            ExprKind::Index(a, ix) => {
                let v = self.eval(a)?;
                let mut idx = Vec::new();
                for i in ix {
                    idx.push(
                        self.eval(i)?
                            .as_int()
                            .map_err(|m| EvalError::at(m, i.span))?,
                    );
                }
                wrap(index(&v, &idx))
            }
            ExprKind::List(items) => self.list(items, sp),
            ExprKind::Call(name, args) => self.call(name, args, sp),
            ExprKind::Sum {
                var,
                from,
                to,
                body,
                product,
            } => {
                let a = self
                    .eval(from)?
                    .as_int()
                    .map_err(|m| EvalError::at(m, from.span))?;
                let b = self
                    .eval(to)?
                    .as_int()
                    .map_err(|m| EvalError::at(m, to.span))?;
                if b - a > 100_000 {
                    return Err(EvalError::at("sum range too long", sp));
                }
                let mut acc = Value::Real(if *product {
                    self.like.one()
                } else {
                    self.like.zero()
                });
                let mut inner = self.clone();
                for k in a..=b {
                    inner.scope.push(Bind {
                        name: var.clone(),
                        value: Value::Real(self.like.from_i64(k)),
                        def: None,
                    });
                    inner.dcache.0.borrow_mut().clear();
                    let t = inner.eval(body)?;
                    inner.scope.pop();
                    acc = wrap(if *product { acc.mul(&t) } else { acc.add(&t) })?;
                }
                Ok(acc)
            }
            ExprKind::Deriv {
                body,
                var,
                component,
            } => {
                let comp = match component {
                    Some(c) => Some(
                        self.eval(c)?
                            .as_int()
                            .map_err(|m| EvalError::at(m, c.span))?,
                    ),
                    None => None,
                };
                T::derive_in(self, body, var, comp).map_err(|mut err| {
                    if err.span.is_none() {
                        err.span = Some(sp);
                    }
                    err
                })
            }
            ExprKind::Grad { body, var } => {
                let mut out = Vec::new();
                for j in 1..=3 {
                    let v = T::derive_in(self, body, var, Some(j))?;
                    out.push(v.as_real().map_err(|m| {
                        EvalError::at(format!("grad needs a real expression: {m}"), sp)
                    })?);
                }
                let [a, b, c]: [T; 3] = out.try_into().map_err(|_| EvalError::at("grad", sp))?;
                Ok(Value::Vec3([a, b, c]))
            }
        }
    }

    fn list(&self, items: &[Expr], sp: Span) -> Result<Value<T>, EvalError> {
        let vals: Vec<Value<T>> = items
            .iter()
            .map(|x| self.eval(x))
            .collect::<Result<_, _>>()?;
        let err = || {
            EvalError::at("a list must be [a, b, c] (reals), [[..],[..],[..]] (3×3 real) or [[a, b],[c, d]] (2×2)", sp)
        };
        if vals.len() == 3 && vals.iter().all(|v| matches!(v, Value::Real(_))) {
            let r: Vec<T> = vals.iter().filter_map(|v| v.as_real().ok()).collect();
            return Ok(Value::Vec3([r[0].clone(), r[1].clone(), r[2].clone()]));
        }
        // matrices: rows are lists; a row of reals evaluates to a vec3 for 3×3
        if vals.len() == 3 && vals.iter().all(|v| matches!(v, Value::Vec3(_))) {
            let rows: Vec<[T; 3]> = vals.iter().filter_map(|v| v.as_vec3().ok()).collect();
            return Ok(Value::Mat3([
                rows[0].clone(),
                rows[1].clone(),
                rows[2].clone(),
            ]));
        }
        if vals.len() == 2 {
            // 2×2: evaluate rows entry by entry (rows are lists of 2 scalars)
            let mut rows = Vec::new();
            for it in items {
                let ExprKind::List(r) = &it.kind else {
                    return Err(err());
                };
                if r.len() != 2 {
                    return Err(err());
                }
                let a = self
                    .eval(&r[0])?
                    .as_complex()
                    .map_err(|m| EvalError::at(m, r[0].span))?;
                let b = self
                    .eval(&r[1])?
                    .as_complex()
                    .map_err(|m| EvalError::at(m, r[1].span))?;
                rows.push([a, b]);
            }
            let r1 = rows.pop().ok_or_else(err)?;
            let r0 = rows.pop().ok_or_else(err)?;
            return Ok(Value::CMat2([r0, r1]));
        }
        Err(err())
    }

    fn call(&self, name: &str, args: &[Expr], sp: Span) -> Result<Value<T>, EvalError> {
        if name == "__list2" {
            return Err(EvalError::at("internal", sp));
        }
        let vals: Vec<Value<T>> = args
            .iter()
            .map(|x| self.eval(x))
            .collect::<Result<_, _>>()?;
        if let Some(f) = self.local_fns.iter().rev().find(|f| f.def.name == name) {
            return self.call_user(f, &vals, sp);
        }
        if let Some(r) = builtins::call(self, name, &vals) {
            return r.map_err(|m| EvalError::at(format!("{name}: {m}"), sp));
        }
        if let Some(f) = self.reg.ext(name) {
            if vals.len() != f.arity {
                return Err(EvalError::at(
                    format!("{name} takes {} arguments, got {}", f.arity, vals.len()),
                    sp,
                ));
            }
            let out = T::ext_call(f.f.as_ref(), &vals)
                .map_err(|m| EvalError::at(format!("{name}: {m}"), sp))?;
            return Ok(out);
        }
        if let Some(f) = self.reg.user(name) {
            let f = f.clone();
            return self.call_user(&f, &vals, sp);
        }
        Err(EvalError::at(format!("unknown function '{name}'"), sp))
    }

    fn call_user(&self, f: &UserFn, vals: &[Value<T>], sp: Span) -> Result<Value<T>, EvalError> {
        if vals.len() != f.params.len() {
            return Err(EvalError::at(
                format!(
                    "{} takes {} arguments, got {}",
                    f.def.name,
                    f.params.len(),
                    vals.len()
                ),
                sp,
            ));
        }
        if self.depth >= MAX_CALL_DEPTH {
            return Err(EvalError::at(
                format!("recursion too deep in '{}'", f.def.name),
                sp,
            ));
        }
        let mut inner = Evaluator {
            reg: self.reg,
            like: self.like.clone(),
            scope: Vec::new(),
            local_fns: Vec::new(),
            depth: self.depth + 1,
            dcache: DCache::default(),
        };
        for (p, v) in f.params.iter().zip(vals) {
            inner.bind(p, v.clone());
        }
        inner.eval(&f.def.body).map_err(|e| EvalError {
            message: format!("in function '{}': {}", f.def.name, e.message),
            span: Some(sp),
        })
    }
}

/// Applies a binary operator.
pub fn binary<T: Num>(op: BinOp, x: &Value<T>, y: &Value<T>) -> Result<Value<T>, String> {
    match op {
        BinOp::Add => x.add(y),
        BinOp::Sub => x.sub(y),
        BinOp::Mul => x.mul(y),
        BinOp::Div => x.div(y),
        BinOp::Pow => x.pow(y),
        BinOp::Eq | BinOp::Ne => {
            let eq = match (x, y) {
                (Value::Bool(a), Value::Bool(b)) => a == b,
                _ => x.sub(y)?.components().iter().all(|c| c.is_zero()),
            };
            Ok(Value::Bool(eq == (op == BinOp::Eq)))
        }
        BinOp::Lt | BinOp::Gt | BinOp::Le | BinOp::Ge => {
            let (a, b) = (x.as_real()?, y.as_real()?);
            Ok(Value::Bool(match op {
                BinOp::Lt => a < b,
                BinOp::Gt => a > b,
                BinOp::Le => a <= b,
                _ => a >= b,
            }))
        }
        BinOp::And | BinOp::Or => {
            let (a, b) = (x.as_bool()?, y.as_bool()?);
            Ok(Value::Bool(if op == BinOp::And { a && b } else { a || b }))
        }
    }
}

fn index<T: Num>(v: &Value<T>, idx: &[i64]) -> Result<Value<T>, String> {
    let chk = |i: i64, n: i64| -> Result<usize, String> {
        if i < 1 || i > n {
            Err(format!("index {i} out of range 1..{n}"))
        } else {
            Ok((i - 1) as usize)
        }
    };
    match (v, idx) {
        (Value::Vec3(a), [i]) => Ok(Value::Real(a[chk(*i, 3)?].clone())),
        (Value::Mat3(m), [i, j]) => Ok(Value::Real(m[chk(*i, 3)?][chk(*j, 3)?].clone())),
        (Value::Mat3(m), [i]) => Ok(Value::Vec3(m[chk(*i, 3)?].clone())),
        (Value::CMat2(m), [i, j]) => Ok(Value::Complex(m[chk(*i, 2)?][chk(*j, 2)?].clone())),
        _ => Err(format!(
            "cannot index a {} with {} indices",
            v.type_name(),
            idx.len()
        )),
    }
}

/// `d(body, var[, comp])` evaluated with dual numbers over `T` (used by the f64 and MPFR
/// backends).  Bindings after `var` that have a defining expression are recomputed.
pub fn derive_with<'r, T>(
    ev: &Evaluator<'r, T>,
    body: &Expr,
    var: &str,
    comp: Option<i64>,
) -> Result<Value<T>, EvalError>
where
    T: Num,
    Dual<T>: Num,
{
    let Some(pos) = ev.scope.iter().rposition(|b| b.name == var) else {
        return Err(EvalError {
            message: format!("d(): '{var}' is not a variable in scope"),
            span: None,
        });
    };
    let lift = |v: &Value<T>| v.map(&mut |x: &T| Dual::constant(x.clone()));
    let mut dev: Evaluator<'r, Dual<T>> = Evaluator {
        reg: ev.reg,
        like: Dual::constant(ev.like.clone()),
        scope: Vec::new(),
        local_fns: ev.local_fns.clone(),
        depth: ev.depth,
        dcache: DCache::default(),
    };
    // Only bindings after `var` that the body needs (transitively) are recomputed.
    let mut needed = std::collections::BTreeSet::new();
    collect_names(body, &mut needed);
    let mut recompute = vec![false; ev.scope.len()];
    for j in (pos + 1..ev.scope.len()).rev() {
        let b = &ev.scope[j];
        if let (true, Some(d)) = (needed.contains(&b.name), &b.def) {
            recompute[j] = true;
            collect_names(d, &mut needed);
        }
    }
    let key = format!(
        "{pos}|{comp:?}|{}",
        recompute
            .iter()
            .map(|&r| if r { '1' } else { '0' })
            .collect::<String>()
    );
    let cached = ev
        .dcache
        .0
        .borrow()
        .get(&key)
        .and_then(|c| c.clone().downcast::<Vec<Bind<Dual<T>>>>().ok());
    if let Some(scope) = cached {
        dev.scope = (*scope).clone();
    } else {
        for (j, b) in ev.scope.iter().enumerate() {
            let value = if j == pos {
                seed(&b.value, comp).map_err(|m| EvalError {
                    message: m,
                    span: None,
                })?
            } else if recompute[j] {
                let d = b.def.as_ref().map(|d| d.as_ref().clone());
                match d {
                    Some(d) => dev.eval(&d)?,
                    None => lift(&b.value),
                }
            } else {
                lift(&b.value)
            };
            dev.scope.push(Bind {
                name: b.name.clone(),
                value,
                def: b.def.clone(),
            });
        }
        let stored: Rc<dyn Any> = Rc::new(dev.scope.clone());
        ev.dcache.0.borrow_mut().insert(key, stored);
    }
    let out = dev.eval(body)?;
    Ok(out.map(&mut |x: &Dual<T>| x.d.clone()))
}

fn collect_names(e: &Expr, out: &mut std::collections::BTreeSet<String>) {
    e.walk(&mut |x| match &x.kind {
        ExprKind::Name(n) => {
            out.insert(n.clone());
        }
        ExprKind::Deriv { var, .. } | ExprKind::Grad { var, .. } => {
            out.insert(var.clone());
        }
        _ => {}
    });
}

fn seed<T: Num>(v: &Value<T>, comp: Option<i64>) -> Result<Value<Dual<T>>, String>
where
    Dual<T>: Num,
{
    match (v, comp) {
        (Value::Real(x), None) => Ok(Value::Real(Dual::var(x.clone()))),
        (Value::Vec3(a), Some(j)) if (1..=3).contains(&j) => {
            Ok(Value::Vec3(std::array::from_fn(|i| {
                if i as i64 == j - 1 {
                    Dual::var(a[i].clone())
                } else {
                    Dual::constant(a[i].clone())
                }
            })))
        }
        (Value::Vec3(_), None) => Err(
            "d(): differentiate a vec3 variable by component: d(expr, v, j) or grad(expr, v)"
                .into(),
        ),
        (v, _) => Err(format!(
            "d(): cannot differentiate with respect to a {} (component {:?})",
            v.type_name(),
            comp
        )),
    }
}
