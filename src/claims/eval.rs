//! The evaluator: one generic tree walker over every backend ([`Backend`]).
//!
//! A scope is a list of bindings (sampled variables, `let` values, function parameters).
//! `let` bindings remember their defining expression, so `d(expr, x)` can lift the scope
//! into dual numbers, seed `x`, and recompute every later binding that may depend on it.
//!
//! A backend is a scalar type ([`Num`]) that also knows how to call registered functions
//! ([`HostCall`]) and how to differentiate ([`Differentiate`]: `f64` and MPFR by dual
//! numbers; duals and rationals refuse).  Evaluation depth is bounded
//! ([`MAX_NESTING`], [`MAX_CALL_DEPTH`]): a too deep expression or a recursive
//! definition is an error, never a stack overflow.

use super::ast::{BinOp, Binding, Expr, ExprKind, Span, UnOp};
use super::backend::Num;
use super::builtins::apply::{jacobi_pick, jacobi_triple};
use super::builtins::{Builtin, apply};
use super::cmath;
use super::memo::{CallMemo, Callee};
use super::registry::{HostCall, Registry, UserFn};
use super::value::Value;
use crate::algebra::Sym;
use crate::linalg::{Mat2, Mat3, Vec3};
use crate::numbers::{Ball, Dual, Rational};
use rug::Float;
use std::any::Any;
use std::cell::{Cell, RefCell};
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
    /// A depth limit was reached: the message is passed up unchanged (not prefixed by
    /// every enclosing function).
    pub limit: bool,
}

impl EvalError {
    /// An error without a position.
    pub fn new(message: impl Into<String>) -> Self {
        EvalError {
            message: message.into(),
            span: None,
            limit: false,
        }
    }
    fn at(message: impl Into<String>, span: Span) -> Self {
        EvalError {
            message: message.into(),
            span: Some(span),
            limit: false,
        }
    }
    fn limit(message: String, span: Span) -> Self {
        EvalError {
            message,
            span: Some(span),
            limit: true,
        }
    }
}

/// How a backend evaluates `d(body, var[, comp])`.
pub trait Differentiate: Sized {
    /// The derivative of `body` with respect to `var` (component `comp` of a vec3) in
    /// the scope of `ev`.
    fn derive(
        ev: &Evaluator<'_, Self>,
        body: &Expr,
        var: &str,
        comp: Option<i64>,
    ) -> Result<Value<Self>, EvalError>;
}

/// Everything the evaluator needs of a number type.
pub trait Backend: Num + HostCall + Differentiate {}
impl<T: Num + HostCall + Differentiate> Backend for T {}

macro_rules! by_duals {
    ($($t:ty),*) => {$(
        impl Differentiate for $t {
            fn derive(
                ev: &Evaluator<'_, Self>,
                body: &Expr,
                var: &str,
                comp: Option<i64>,
            ) -> Result<Value<Self>, EvalError> {
                derive_with(ev, body, var, comp)
            }
        }
    )*};
}
// a derivative of a derivative: duals of duals (second order, no further)
by_duals!(
    f64,
    Float,
    Dual<f64>,
    Dual<Float>,
    crate::algebra::series::Series,
    crate::numbers::Ball
);

macro_rules! cannot_derive {
    ($($t:ty => $why:expr),* $(,)?) => {$(
        impl Differentiate for $t {
            fn derive(
                _ev: &Evaluator<'_, Self>,
                _body: &Expr,
                var: &str,
                _comp: Option<i64>,
            ) -> Result<Value<Self>, EvalError> {
                Err(EvalError::new(format!("d(..., {var}): {} are not supported", $why)))
            }
        }
    )*};
}
cannot_derive!(
    Dual<Dual<f64>> => "derivatives of order 3 or more",
    Dual<Dual<Float>> => "derivatives of order 3 or more",
    Dual<Sym> => "derivatives inside a function differentiated in its parameter",
    Rational => "derivatives in exact rational arithmetic",
    Dual<crate::algebra::series::Series> => "second derivatives of power series",
    Dual<crate::numbers::Ball> => "second derivatives in ball arithmetic",
);

/// Exact derivatives: the derivation of the prover's tower with respect to the
/// indeterminate bound to `var` (every value already depends on it through the
/// indeterminate, so `let` bindings need no re-evaluation).
impl Differentiate for Sym {
    fn derive(
        ev: &Evaluator<'_, Self>,
        body: &Expr,
        var: &str,
        comp: Option<i64>,
    ) -> Result<Value<Self>, EvalError> {
        let bound = ev
            .lookup(var)
            .ok_or_else(|| EvalError::new(format!("d(..., {var}): unknown variable '{var}'")))?;
        let x = match (bound, comp) {
            (Value::Real(x), None) => x.clone(),
            (Value::Vec3(v), Some(j)) if (1..=3).contains(&j) => v.0[(j - 1) as usize].clone(),
            _ => {
                return Err(EvalError::new(format!(
                    "d(..., {var}): not a real variable or a vec3 component"
                )));
            }
        };
        // in a function body `var` is a parameter, and d() is the partial derivative of
        // the body in it (as the numerical backends take it).  That is the derivative in
        // the claim variable that is its value only when no other parameter depends on
        // that variable; otherwise (and for values that are no variable) it is taken by
        // dual numbers over the tower.
        let partial_is_total =
            x.is_symbol_of_claim() && (ev.depth == 0 || others_independent(ev, var, comp, &x));
        if !partial_is_total {
            return derive_with(ev, body, var, comp);
        }
        let value = ev.eval(body)?;
        let mut failure = None;
        let out = value.map(&mut |f: &Sym| match f.derivative(&x) {
            Ok(d) => d,
            Err(e) => {
                failure.get_or_insert_with(|| e.to_string());
                f.clone()
            }
        });
        match failure {
            Some(m) => Err(EvalError::new(format!("d(..., {var}): {m}"))),
            None => Ok(out),
        }
    }
}

/// Do the other bindings of the scope (a function's parameters) not depend on `x`, the
/// value of `var` (component `comp`)?
fn others_independent(ev: &Evaluator<'_, Sym>, var: &str, comp: Option<i64>, x: &Sym) -> bool {
    ev.scope.iter().all(|b| {
        let comps = b.value.components();
        comps.iter().enumerate().all(|(j, c)| {
            let itself = b.name == var && comp.map_or(comps.len() == 1, |k| k as usize == j + 1);
            itself || c.derivative(x).is_ok_and(|d| d.is_exact_zero())
        })
    })
}

/// Nested applications of one catalogue function to its own result (through the first
/// argument), this deep or deeper, are an iteration (such as Newton's method written
/// out): in ball arithmetic its value is its limit ([`Evaluator::fixed_point`]).
const ITERATION_DEPTH: usize = 3;

/// How many times `name` is applied in a chain `name(name(…))` starting at `e`.
fn chain_depth(e: &Expr, name: &str) -> usize {
    match &e.kind {
        ExprKind::Call(n, args) if n == name => {
            1 + args.first().map_or(0, |a| chain_depth(a, name))
        }
        _ => 0,
    }
}

/// Does `e` hold an iteration (a chain of [`ITERATION_DEPTH`] applications)?
fn has_chain(e: &Expr) -> bool {
    let mut found = false;
    e.walk(&mut |x| {
        if let ExprKind::Call(n, _) = &x.kind {
            found |= chain_depth(x, n) >= ITERATION_DEPTH;
        }
    });
    found
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
    nesting: Cell<usize>,
    dcache: DCache,
    /// The calls this evaluation has made (shared with the evaluations of function
    /// bodies at the same precision; `None` for exact backends).
    memo: Option<Rc<dyn Any>>,
    /// How many times the innermost enclosing sum or product evaluates its body in all
    /// (the product of the lengths of the enclosing ranges; 1 outside any).
    loop_terms: u64,
}

/// Most nested calls of catalogue functions (a recursive definition stops here).
pub const MAX_CALL_DEPTH: usize = 64;
/// Most nested sub-expressions being evaluated at once, function bodies included.
pub const MAX_NESTING: usize = 2000;
/// Most terms of one `sum` or `prod`.
pub const MAX_LOOP_TERMS: u64 = 100_000;
/// Most evaluations of the body of nested sums and products, all levels together.
pub const MAX_NESTED_LOOP_TERMS: u64 = 1_000_000;
/// Below this much free stack, evaluation continues on a new segment...
const STACK_RED_ZONE: usize = 128 * 1024;
/// ... of this size.
const STACK_SEGMENT: usize = 2 * 1024 * 1024;

impl<'r, T: Backend> Evaluator<'r, T> {
    /// A new evaluator; `like` fixes the precision of constants and literals.
    pub fn new(reg: &'r Registry, like: T) -> Self {
        Evaluator {
            reg,
            like,
            scope: Vec::new(),
            local_fns: Vec::new(),
            depth: 0,
            nesting: Cell::new(0),
            dcache: DCache::default(),
            memo: CallMemo::<T>::for_backend(T::EXACT),
            loop_terms: 1,
        }
    }
    /// An empty evaluator over another backend that continues this one's depth counts.
    fn child<U: Backend>(&self, like: U, depth: usize) -> Evaluator<'r, U> {
        Evaluator {
            reg: self.reg,
            scope: Vec::new(),
            local_fns: Vec::new(),
            depth,
            nesting: Cell::new(self.nesting.get()),
            loop_terms: self.loop_terms,
            dcache: DCache::default(),
            memo: match CallMemo::<U>::of(&self.memo) {
                Some(_) if self.like.precision() == like.precision() => self.memo.clone(),
                _ => CallMemo::<U>::for_backend(U::EXACT),
            },
            like,
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
            ..e
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

    /// Evaluates an expression; a value that is not finite is an error.
    ///
    /// ```
    /// use eulertop::claims::eval::Evaluator;
    /// use eulertop::claims::parser::parse_expr;
    /// use eulertop::claims::registry::Registry;
    /// use eulertop::claims::value::Value;
    ///
    /// let reg = Registry::new();
    /// let mut ev = Evaluator::new(&reg, 0.0f64);
    /// ev.bind("x", Value::Real(0.5));
    /// let v = ev.eval(&parse_expr("sn(x, 0)^2 + cos(x)^2").unwrap()).unwrap();
    /// assert!((v.as_real().unwrap() - 1.0).abs() < 1e-15);
    /// // the same expression exactly: sn is not rational
    /// let q = eulertop::numbers::Rational::from_integer(0.into());
    /// assert!(Evaluator::new(&reg, q).eval(&parse_expr("sn(0, 0)").unwrap()).is_err());
    /// ```
    pub fn eval(&self, e: &Expr) -> Result<Value<T>, EvalError> {
        let n = self.nesting.get();
        if n >= MAX_NESTING {
            return Err(EvalError::limit(
                format!(
                    "expression nested too deeply to evaluate (more than {MAX_NESTING} levels, function bodies included)"
                ),
                e.span,
            ));
        }
        self.nesting.set(n + 1);
        // deep (but bounded) nesting runs on heap-allocated stack segments when the
        // thread's own stack runs low
        let v = stacker::maybe_grow(STACK_RED_ZONE, STACK_SEGMENT, || self.eval_inner(e));
        self.nesting.set(n);
        let v = v?;
        if !v.is_finite() {
            let why = v.components().iter().find_map(|c| c.failure());
            let msg = why.unwrap_or_else(|| "value is not finite (pole or overflow)".into());
            return Err(EvalError::at(msg, e.span));
        }
        Ok(v)
    }

    fn eval_inner(&self, e: &Expr) -> Result<Value<T>, EvalError> {
        let sp = e.span;
        let wrap = |r: Result<Value<T>, String>| r.map_err(|m| EvalError::at(m, sp));
        match &e.kind {
            ExprKind::Num(s) => wrap(self.like.lit(s).map(Value::Real)),
            ExprKind::Name(n) => self.name(n, sp),
            ExprKind::Unary(UnOp::Neg, a) => wrap(self.eval(a)?.neg()),
            ExprKind::Unary(UnOp::Not, a) => wrap(self.eval(a)?.as_bool().map(|b| Value::Bool(!b))),
            ExprKind::Binary(op, a, b) => self.binary(*op, a, b, sp),
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
                    idx.push(self.int(i)?);
                }
                wrap(v.index(&idx))
            }
            ExprKind::List(items) => self.list(items, sp),
            ExprKind::Call(name, args) => self.call(name, args, sp),
            ExprKind::Sum {
                var,
                from,
                to,
                body,
                product,
            } => self.sum(var, from, to, body, *product, sp),
            ExprKind::Deriv {
                body,
                var,
                component,
            } => {
                let comp = match component {
                    Some(c) => Some(self.int(c)?),
                    None => None,
                };
                T::derive(self, body, var, comp).map_err(|mut err| {
                    if err.span.is_none() {
                        err.span = Some(sp);
                    }
                    err
                })
            }
            ExprKind::Grad { body, var } => self.grad(body, var, sp),
        }
    }

    fn int(&self, e: &Expr) -> Result<i64, EvalError> {
        self.eval(e)?.as_int().map_err(|m| EvalError::at(m, e.span))
    }

    #[inline(never)]
    fn name(&self, n: &str, sp: Span) -> Result<Value<T>, EvalError> {
        if let Some(v) = self.lookup(n) {
            return Ok(v.clone());
        }
        let r = match n {
            "pi" => cmath::pi(&self.like).map(Value::Real),
            "i" => Ok(Value::Complex(cmath::i(&self.like))),
            "I3" => apply(Builtin::I3, &self.like, &[]),
            "I2" => apply(Builtin::I2, &self.like, &[]),
            _ => Err(format!("unknown variable '{n}'")),
        };
        r.map_err(|m| EvalError::at(m, sp))
    }

    #[inline(never)]
    fn binary(&self, op: BinOp, a: &Expr, b: &Expr, sp: Span) -> Result<Value<T>, EvalError> {
        let wrap = |r: Result<Value<T>, String>| r.map_err(|m| EvalError::at(m, sp));
        if matches!(op, BinOp::And | BinOp::Or) {
            let x = wrap(self.eval(a)?.as_bool().map(Value::Bool))?;
            let x = x.as_bool().map_err(|m| EvalError::at(m, sp))?;
            if (op == BinOp::And && !x) || (op == BinOp::Or && x) {
                return Ok(Value::Bool(x));
            }
            return wrap(self.eval(b)?.as_bool().map(Value::Bool));
        }
        if op == BinOp::Mul
            && let Some(v) = self.congruence(a, b)?
        {
            return Ok(Value::Mat3(v));
        }
        if let Some(v) = self.extremum_comparison(op, a, b, sp)? {
            return Ok(v);
        }
        let x = self.eval(a)?;
        let y = self.eval(b)?;
        match (x, y) {
            (Value::Real(p), Value::Real(q)) => wrap(real_binary(op, p, q)),
            (x, y) => wrap(binary(op, &x, &y)),
        }
    }

    /// A comparison of `min(x₁, …)` or `max(x₁, …)` with `b`, argument by argument:
    /// `min(xs) > b` iff every `xᵢ > b`, `min(xs) < b` iff some `xᵢ < b` (and the same
    /// with `max`, the quantifiers exchanged).  The value is that of the comparison as
    /// written, but no argument is compared with another: an exact backend need not
    /// decide which argument is the least, only how each compares with `b`.  `None`
    /// when `a` is not such a call (or the operator is not `<`, `<=`, `>`, `>=`).
    fn extremum_comparison(
        &self,
        op: BinOp,
        a: &Expr,
        b: &Expr,
        sp: Span,
    ) -> Result<Option<Value<T>>, EvalError> {
        let ExprKind::Call(f, xs) = &a.kind else {
            return Ok(None);
        };
        let is_min = f == "min";
        let comparison = matches!(op, BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge);
        if !comparison || !(is_min || f == "max") || xs.len() < 2 || self.shadowed(f) {
            return Ok(None);
        }
        // min > b, max < b: all; min < b, max > b: some
        let above = matches!(op, BinOp::Gt | BinOp::Ge);
        let all = above == is_min;
        let y = self.eval(b)?;
        for x in xs {
            let v = binary(op, &self.eval(x)?, &y).map_err(|m| EvalError::at(m, sp))?;
            let t = v.as_bool().map_err(|m| EvalError::at(m, sp))?;
            if t != all {
                return Ok(Some(Value::Bool(t)));
            }
        }
        Ok(Some(Value::Bool(all)))
    }

    /// Is `name` a function of the catalogue or of a `let` (which a built-in's name
    /// would then stand for)?
    fn shadowed(&self, name: &str) -> bool {
        self.local_fns.iter().any(|f| f.def.name == name) || self.reg.user(name).is_some()
    }

    /// `X * P * transpose(X)` or `transpose(X) * P * X` (`a * b`), with `X` a name and
    /// `P` an exactly antisymmetric matrix, evaluated as one congruence
    /// ([`Mat3::congruence_antisymmetric`]): the same matrix as the two products, with
    /// fewer operations, the cancellation of its symmetric part left out.  `None` when
    /// the product has another form (it is then evaluated as written).
    fn congruence(&self, a: &Expr, b: &Expr) -> Result<Option<Mat3<T>>, EvalError> {
        let ExprKind::Binary(BinOp::Mul, left, p) = &a.kind else {
            return Ok(None);
        };
        let transposed = |e: &Expr| match &e.kind {
            ExprKind::Call(f, args) if f == "transpose" && args.len() == 1 => match &args[0].kind {
                ExprKind::Name(n) => Some(n.clone()),
                _ => None,
            },
            _ => None,
        };
        let name = |e: &Expr| match &e.kind {
            ExprKind::Name(n) => Some(n.clone()),
            _ => None,
        };
        // `transpose` must be the built-in, not a function of the claim
        if self.local_fns.iter().any(|f| f.def.name == "transpose") {
            return Ok(None);
        }
        let (outer, first_transposed) = match (name(left), transposed(b), transposed(left), name(b))
        {
            (Some(x), Some(y), _, _) if x == y => (left.as_ref(), false),
            (_, _, Some(x), Some(y)) if x == y => (b, true),
            _ => return Ok(None),
        };
        let (Value::Mat3(x), Value::Mat3(m)) = (self.eval(outer)?, self.eval(p)?) else {
            return Ok(None);
        };
        let x = if first_transposed { x.transpose() } else { x };
        Ok(x.congruence_antisymmetric(&m))
    }

    #[inline(never)]
    fn sum(
        &self,
        var: &str,
        from: &Expr,
        to: &Expr,
        body: &Expr,
        product: bool,
        sp: Span,
    ) -> Result<Value<T>, EvalError> {
        let a = self.int(from)?;
        let b = self.int(to)?;
        let what = if product { "prod" } else { "sum" };
        // the number of terms, without overflow (0 for an empty range)
        let n = (i128::from(b) - i128::from(a) + 1).max(0);
        if n > MAX_LOOP_TERMS as i128 {
            return Err(EvalError::at(
                format!(
                    "{what} range too long: {a}..{b} has {n} terms, more than {MAX_LOOP_TERMS} terms"
                ),
                sp,
            ));
        }
        // nested sums and products multiply their lengths: the body is evaluated
        // loop_terms·n times in all
        let total = self.loop_terms.saturating_mul(n as u64);
        if total > MAX_NESTED_LOOP_TERMS {
            return Err(EvalError::at(
                format!(
                    "nested sums and products would evaluate their bodies {total} times, more than {MAX_NESTED_LOOP_TERMS} in all"
                ),
                sp,
            ));
        }
        let mut inner = self.clone();
        inner.loop_terms = total.max(1);
        let mut term = |k: i64| -> Result<Value<T>, EvalError> {
            inner.scope.push(Bind {
                name: var.to_string(),
                value: Value::Real(self.like.from_i64(k)),
                def: None,
            });
            inner.dcache.0.borrow_mut().clear();
            let t = inner.eval(body);
            inner.scope.pop();
            t
        };
        if n == 0 {
            // the empty product is 1; the empty sum is the zero of the body's type
            // (taken at k = a), or the real 0 where the body has no value there
            if product {
                return Ok(Value::Real(self.like.one()));
            }
            return Ok(match term(a) {
                Ok(t) => t.map(&mut |_| self.like.zero()),
                Err(_) => Value::Real(self.like.zero()),
            });
        }
        let mut acc = term(a)?;
        for j in 1..n as i64 {
            // a + j ≤ b: no overflow
            let t = term(a + j)?;
            acc = (if product { acc.mul(&t) } else { acc.add(&t) })
                .map_err(|m| EvalError::at(m, sp))?;
        }
        Ok(acc)
    }

    #[inline(never)]
    fn grad(&self, body: &Expr, var: &str, sp: Span) -> Result<Value<T>, EvalError> {
        let mut out = Vec::new();
        for j in 1..=3 {
            let v = T::derive(self, body, var, Some(j))?;
            out.push(
                v.as_real()
                    .map_err(|m| EvalError::at(format!("grad needs a real expression: {m}"), sp))?,
            );
        }
        let [a, b, c]: [T; 3] = out.try_into().map_err(|_| EvalError::at("grad", sp))?;
        Ok(Value::Vec3(Vec3([a, b, c])))
    }

    #[inline(never)]
    fn list(&self, items: &[Expr], sp: Span) -> Result<Value<T>, EvalError> {
        let err = || {
            EvalError::at(
                "a list must be [a, b, c] (reals), [[..],[..],[..]] (3×3 real) or [[a, b],[c, d]] (2×2)",
                sp,
            )
        };
        // 2×2: the rows are lists of two scalars, which are not values on their own, so
        // the entries are evaluated one by one
        let pair = |e: &Expr| matches!(&e.kind, ExprKind::List(r) if r.len() == 2);
        if items.len() == 2 && items.iter().all(pair) {
            let mut rows = Vec::new();
            for it in items {
                let ExprKind::List(r) = &it.kind else {
                    return Err(err());
                };
                if r.len() != 2 {
                    return Err(err());
                }
                let entry = |x: &Expr| {
                    self.eval(x)?
                        .as_complex()
                        .map_err(|m| EvalError::at(m, x.span))
                };
                rows.push([entry(&r[0])?, entry(&r[1])?]);
            }
            let r1 = rows.pop().ok_or_else(err)?;
            let r0 = rows.pop().ok_or_else(err)?;
            return Ok(Value::CMat2(Mat2([r0, r1])));
        }
        let vals: Vec<Value<T>> = items
            .iter()
            .map(|x| self.eval(x))
            .collect::<Result<_, _>>()?;
        if vals.len() == 3 && vals.iter().all(|v| matches!(v, Value::Real(_))) {
            let r: Vec<T> = vals.iter().filter_map(|v| v.as_real().ok()).collect();
            return Ok(Value::Vec3(Vec3([
                r[0].clone(),
                r[1].clone(),
                r[2].clone(),
            ])));
        }
        // matrices: rows are lists; a row of reals evaluates to a vec3 for 3×3
        if vals.len() == 3 && vals.iter().all(|v| matches!(v, Value::Vec3(_))) {
            let rows: Vec<[T; 3]> = vals
                .iter()
                .filter_map(|v| v.as_vec3().ok())
                .map(|v| v.0)
                .collect();
            return Ok(Value::Mat3(Mat3([
                rows[0].clone(),
                rows[1].clone(),
                rows[2].clone(),
            ])));
        }
        Err(err())
    }

    #[inline(never)]
    fn call(&self, name: &str, args: &[Expr], sp: Span) -> Result<Value<T>, EvalError> {
        if T::ENCLOSES
            && args
                .first()
                .is_some_and(|a| 1 + chain_depth(a, name) >= ITERATION_DEPTH)
        {
            let local = self.local_fns.iter().rev().find(|f| f.def.name == name);
            // a chain of a step (a function without an iteration of its own); a chain of
            // iterations is evaluated as written, each iteration inside certified
            if let Some(f) = local.or_else(|| self.reg.user(name)).cloned()
                && !has_chain(&f.def.body)
            {
                return self.fixed_point(&f, args, sp);
            }
        }
        let vals: Vec<Value<T>> = args
            .iter()
            .map(|x| self.eval(x))
            .collect::<Result<_, _>>()?;
        if let Some(f) = self.local_fns.iter().rev().find(|f| f.def.name == name) {
            return self.call_user(f, &vals, sp);
        }
        if let Some(b) = Builtin::from_name(name) {
            if b.is_jacobi() {
                return self
                    .jacobi(b, &vals)
                    .map_err(|m| EvalError::at(format!("{name}: {m}"), sp));
            }
            return apply(b, &self.like, &vals)
                .map_err(|m| EvalError::at(format!("{name}: {m}"), sp));
        }
        if let Some(f) = self.reg.ext(name) {
            if vals.len() != f.arity {
                return Err(EvalError::at(
                    format!("{name} takes {} arguments, got {}", f.arity, vals.len()),
                    sp,
                ));
            }
            return T::host_call(f.f.as_ref(), &vals)
                .map_err(|m| EvalError::at(format!("{name}: {m}"), sp));
        }
        if let Some(f) = self.reg.user(name) {
            let f = f.clone();
            return self.call_user(&f, &vals, sp);
        }
        Err(EvalError::at(format!("unknown function '{name}'"), sp))
    }

    /// In ball arithmetic, an iteration `g(g(g(x₀, …), …), …)` of a catalogue function
    /// `g` (Newton's method written out) stands for its limit, the fixed point of `g`
    /// near the iterate: the iterate `r` is computed, and the Krawczyk test on
    /// `x − g(x, …)` in the box `r ± 10⁻⁹·max(|r|, 10⁻³)` certifies exactly one fixed
    /// point there, whose enclosure is the value.  A value that is not real and a
    /// derivative through the iteration are refused.  (A chain of a function that holds
    /// an iteration itself is evaluated as written, its inner iterations certified.)
    fn fixed_point(&self, f: &Arc<UserFn>, args: &[Expr], sp: Span) -> Result<Value<T>, EvalError> {
        let name = f.def.name.clone();
        let fail =
            |m: &str| EvalError::at(format!("{name}: the iteration is not enclosed: {m}"), sp);
        let Some(like) = self.like.as_ball() else {
            return Err(fail("a derivative through an iteration has no enclosure"));
        };
        let (prec, one) = (like.prec_bits(), crate::numbers::Scalar::one(like));
        let vals: Vec<Value<T>> = args
            .iter()
            .map(|x| self.eval(x))
            .collect::<Result<_, _>>()?;
        let r = self
            .call_user(f, &vals, sp)?
            .as_real()
            .map_err(|m| fail(&m))?;
        let c = r.as_ball().map_or(f64::NAN, Ball::mid_f64);
        if !c.is_finite() {
            return Err(fail("the iterate is not finite"));
        }
        let rad = 1e-9 * c.abs().max(1e-3);
        let ball = |x: Ball| Value::Real(T::from_ball(x).expect("the evaluator's type is Ball"));
        // the step g(x, …) with x and the other arguments bound to names no catalogue
        // name can take (they contain spaces)
        let names: Vec<String> = (0..vals.len())
            .map(|i| format!("fixed point {i}"))
            .collect();
        let mut ev = self.clone();
        for (n, v) in names.iter().zip(&vals).skip(1) {
            ev.bind(n, v.clone());
        }
        let name_expr = |n: &String| Expr {
            kind: ExprKind::Name(n.clone()),
            span: sp,
        };
        let step = Expr {
            kind: ExprKind::Call(name.clone(), names.iter().map(name_expr).collect()),
            span: sp,
        };
        let real = |v: Value<T>| -> Result<Ball, EvalError> {
            let x = v.as_real().map_err(|m| fail(&m))?;
            x.as_ball().cloned().ok_or_else(|| fail("not a ball"))
        };
        ev.bind(&names[0], ball(Ball::exact(c, prec)));
        let fc = Ball::exact(c, prec) - real(ev.eval(&step)?)?;
        let bx = Ball::with_radius(c, rad, prec);
        ev.bind(&names[0], ball(bx.clone()));
        let d = Expr {
            kind: ExprKind::Deriv {
                body: Box::new(step),
                var: names[0].clone(),
                component: None,
            },
            span: sp,
        };
        let dfx = one.clone() - real(ev.eval(&d)?)?;
        let y = Ball::exact(1.0 / dfx.mid_f64(), prec);
        let k = Ball::exact(c, prec) - y.clone() * fc
            + (one - y * dfx) * (bx.clone() - Ball::exact(c, prec));
        if !bx.contains_interior(&k) {
            return Err(fail(&format!(
                "the Krawczyk image {} is not inside the box",
                k.show(10)
            )));
        }
        Ok(ball(k))
    }

    /// A Jacobi built-in, its triple `[sn, cn, dn](u, k)` remembered (see [`CallMemo`]).
    fn jacobi(&self, b: Builtin, vals: &[Value<T>]) -> Result<Value<T>, String> {
        let memo = CallMemo::<T>::of(&self.memo);
        let known = memo.and_then(|m| m.get(&Callee::Jacobi, vals));
        let triple: [Value<T>; 3] = match known.map(<[Value<T>; 3]>::try_from) {
            Some(Ok(t)) => t,
            _ => {
                let t = jacobi_triple(vals)?;
                if let Some(m) = memo {
                    m.put(Callee::Jacobi, vals, t.to_vec());
                }
                t
            }
        };
        jacobi_pick(b, vals, &triple)
    }

    /// A catalogue function, its result remembered (see [`CallMemo`]).
    fn call_user(
        &self,
        f: &Arc<UserFn>,
        vals: &[Value<T>],
        sp: Span,
    ) -> Result<Value<T>, EvalError> {
        let memo = CallMemo::<T>::of(&self.memo);
        let callee = Callee::User(f.clone());
        if let Some(mut r) = memo.and_then(|m| m.get(&callee, vals))
            && let Some(v) = r.pop()
        {
            return Ok(v);
        }
        let v = self.call_user_body(f, vals, sp)?;
        if let Some(m) = memo {
            m.put(callee, vals, vec![v.clone()]);
        }
        Ok(v)
    }

    #[inline(never)]
    fn call_user_body(
        &self,
        f: &UserFn,
        vals: &[Value<T>],
        sp: Span,
    ) -> Result<Value<T>, EvalError> {
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
            return Err(EvalError::limit(
                format!(
                    "recursion too deep in '{}' (more than {MAX_CALL_DEPTH} nested calls)",
                    f.def.name
                ),
                sp,
            ));
        }
        let mut inner = self.child(self.like.clone(), self.depth + 1);
        for (p, v) in f.params.iter().zip(vals) {
            inner.bind(p, v.clone());
        }
        inner.eval(&f.def.body).map_err(|e| {
            if e.limit {
                return e;
            }
            EvalError::at(format!("in function '{}': {}", f.def.name, e.message), sp)
        })
    }
}

/// A binary operator on two reals, consuming them (the left operand's storage holds the
/// result): the same values as [`binary`], with no copies of the operands.
fn real_binary<T: Num>(op: BinOp, p: T, q: T) -> Result<Value<T>, String> {
    match op {
        BinOp::Add => Ok(Value::Real(p + q)),
        BinOp::Sub => Ok(Value::Real(p - q)),
        BinOp::Mul => Ok(Value::Real(p * q)),
        BinOp::Div if q.is_zero() => Err("division by zero".into()),
        BinOp::Div => Ok(Value::Real(p / q)),
        _ => binary(op, &Value::Real(p), &Value::Real(q)),
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
                _ => x.sub(y)?.components().iter().all(|c| c.test_zero()),
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

/// `d(body, var[, comp])` evaluated with dual numbers over `T` (the f64 and MPFR
/// backends).  Only the bindings after `var` that the body needs (transitively) are
/// recomputed; the lifted scope is cached per evaluator.
pub fn derive_with<'r, T>(
    ev: &Evaluator<'r, T>,
    body: &Expr,
    var: &str,
    comp: Option<i64>,
) -> Result<Value<T>, EvalError>
where
    T: Backend,
    Dual<T>: Backend,
{
    let Some(pos) = ev.scope.iter().rposition(|b| b.name == var) else {
        return Err(EvalError::new(format!(
            "d(): '{var}' is not a variable in scope"
        )));
    };
    let mut dev: Evaluator<'r, Dual<T>> = ev.child(Dual::constant(ev.like.clone()), ev.depth);
    dev.local_fns = ev.local_fns.clone();
    let recompute = needed_bindings(ev, body, pos);
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
        lift_scope(ev, &mut dev, pos, comp, &recompute)?;
        let stored: Rc<dyn Any> = Rc::new(dev.scope.clone());
        ev.dcache.0.borrow_mut().insert(key, stored);
    }
    let out = dev.eval(body)?;
    Ok(out.map(&mut |x: &Dual<T>| x.d.clone()))
}

/// Which bindings after position `pos` must be recomputed for `body`.
fn needed_bindings<T>(ev: &Evaluator<'_, T>, body: &Expr, pos: usize) -> Vec<bool> {
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
    recompute
}

/// Fills `dev`'s scope: `var` seeded, recomputed bindings evaluated in duals, the rest
/// lifted as constants.
fn lift_scope<T>(
    ev: &Evaluator<'_, T>,
    dev: &mut Evaluator<'_, Dual<T>>,
    pos: usize,
    comp: Option<i64>,
    recompute: &[bool],
) -> Result<(), EvalError>
where
    T: Backend,
    Dual<T>: Backend,
{
    let lift = |v: &Value<T>| v.map(&mut |x: &T| Dual::constant(x.clone()));
    for (j, b) in ev.scope.iter().enumerate() {
        let value = if j == pos {
            seed(&b.value, comp).map_err(EvalError::new)?
        } else if recompute[j] {
            match &b.def {
                Some(d) => dev.eval(d)?,
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
    Ok(())
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
            Ok(Value::Vec3(Vec3(std::array::from_fn(|i| {
                if i as i64 == j - 1 {
                    Dual::var(a.0[i].clone())
                } else {
                    Dual::constant(a.0[i].clone())
                }
            }))))
        }
        (Value::Vec3(_), None) => Err(
            "d(): differentiate a vec3 variable by component: d(expr, v, j) or grad(expr, v)"
                .into(),
        ),
        (Value::Real(_), Some(j)) => Err(format!(
            "d(): component {j} of a real variable (a component index needs a vec3 variable)"
        )),
        (Value::Vec3(_), Some(j)) => Err(format!(
            "d(): component {j} of a vec3 variable (components are 1, 2 and 3)"
        )),
        (v, _) => Err(format!(
            "d(): cannot differentiate with respect to a {}",
            v.type_name()
        )),
    }
}
