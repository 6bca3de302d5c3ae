//! Seeded, domain-aware sampling.  Variables are drawn in f64 by evaluating their sampler
//! expressions, in which the random primitives `uniform`, `normal`, `randint`, `sign` and
//! `choice` are replaced by draws from a ChaCha20 generator seeded from the claim's seed
//! and id (FNV-1a, stable across platforms and versions).  Constraints (`where`) are
//! enforced by rejection with a cap; a too-thin domain is an error naming the constraint.

use super::ast::{Expr, ExprKind};
use super::builtins::{Arity, Primitive};
use super::catalogue::{Catalogue, Claim, PExpr};
use super::eval::{EvalError, Evaluator};
use super::registry::Registry;
use super::value::Value;
use crate::linalg::Vec3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha20Rng;

/// Rejection cap: draws per accepted point.
pub const MAX_DRAWS: usize = 2000;
/// Grid size of `uniform`: a + (b−a)·j/2^24, j ∈ 0..=2^24.
pub const UNIFORM_GRID: u64 = 1 << 24;

/// A sampled point: variable values in f64 (dyadic rationals, used exactly everywhere).
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// Variables in draw order.
    pub vars: Vec<(String, Value<f64>)>,
}

impl Point {
    /// Largest modulus of any scalar component (the default residual scale), at least
    /// the smallest positive normal f64.
    pub fn size(&self) -> f64 {
        self.vars
            .iter()
            .map(|(_, v)| v.magnitude())
            .fold(0.0, f64::max)
            .max(f64::MIN_POSITIVE)
    }
    /// Value of a variable.
    pub fn get(&self, name: &str) -> Option<&Value<f64>> {
        self.vars
            .iter()
            .rev()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v)
    }
    /// Human rendering `name = value, ...` with round-trip f64 digits.
    pub fn render(&self) -> Vec<(String, String)> {
        self.vars
            .iter()
            .map(|(n, v)| (n.clone(), render_f64_value(v)))
            .collect()
    }
}

/// Renders an f64 value with round-trip digits.
pub fn render_f64_value(v: &Value<f64>) -> String {
    match v {
        Value::Real(x) => format!("{x:e}"),
        Value::Bool(b) => b.to_string(),
        Value::Complex(z) => format!("{:e} + {:e}i", z.re, z.im),
        Value::Vec3(Vec3(a)) => format!("({:e}, {:e}, {:e})", a[0], a[1], a[2]),
        v => format!("{:?}", v.components()),
    }
}

/// Statistics of the primitives used, for Schwartz–Zippel bounds.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DrawStats {
    /// Candidate points drawn.
    pub draws: usize,
    /// Points accepted by the constraints.
    pub accepted: usize,
    /// Smallest finite set size among the primitives used.
    pub min_set: Option<u64>,
    /// Was a non-uniform primitive (normal) used?
    pub nonuniform: bool,
}

/// FNV-1a 64-bit hash (stable).
pub fn fnv1a(s: &str) -> u64 {
    let mut h: u64 = 0xcbf29ce484222325;
    for b in s.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x100000001b3);
    }
    h
}

/// The independent random streams of one claim: different purposes never share draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stream {
    /// The float samples of the ladder.
    Samples,
    /// The rational points of the exact evaluation.
    Exact,
    /// The redrawn values of an independence claim.
    Redraws,
    /// The Newton starts of an existence claim.
    Starts,
    /// The domain points at which the prover's symbols carry numeric values.
    Proof,
}

impl Stream {
    /// The ChaCha20 stream number (fixed: reports depend on it).
    pub fn id(self) -> u64 {
        match self {
            Stream::Samples => 0,
            Stream::Exact => 1,
            Stream::Redraws => 2,
            Stream::Starts => 3,
            Stream::Proof => 4,
        }
    }
}

/// Samples points of one claim's domain.
pub struct Sampler<'c> {
    rng: ChaCha20Rng,
    reg: &'c Registry,
    vars: Vec<(String, &'c PExpr)>,
    wheres: Vec<&'c PExpr>,
    /// Draw `uniform(a, b)` next to its ends (see [`Sampler::toward_boundary`]).
    boundary: bool,
    /// Primitive statistics.
    pub stats: DrawStats,
}

impl<'c> Sampler<'c> {
    /// A sampler for `claim` (domain variables then the claim's own) on `stream`.
    pub fn new(cat: &'c Catalogue, claim: &'c Claim, stream: Stream) -> Result<Self, String> {
        let mut vars = Vec::new();
        let mut wheres = Vec::new();
        if let Some(d) = &claim.domain {
            let dom = cat
                .domains
                .get(&d.value)
                .ok_or_else(|| format!("unknown domain '{}'", d.value))?;
            vars.extend(dom.vars.iter().map(|(n, p)| (n.clone(), p)));
            wheres.extend(dom.wheres.iter());
        }
        vars.extend(claim.vars.iter().map(|(n, p)| (n.clone(), p)));
        wheres.extend(claim.wheres.iter());
        let seed = fnv1a(&claim.id) ^ claim.seed.wrapping_mul(0x9e3779b97f4a7c15);
        let mut rng = ChaCha20Rng::seed_from_u64(seed);
        rng.set_stream(stream.id());
        Ok(Sampler {
            rng,
            reg: &cat.registry,
            vars,
            wheres,
            boundary: false,
            stats: DrawStats::default(),
        })
    }

    /// The same sampler drawing toward the boundary of the domain: every
    /// `uniform(a, b)` takes a grid value next to `a` or to `b` (the distance to the end
    /// a fourth power of a uniform fraction of the width, so the ends themselves and the
    /// vertices where several meet are reached often).  For searching a part of the
    /// domain that the uniform draws miss, such as a thin corner.
    ///
    /// ```
    /// use eulertop::bindings::euler_top::registry;
    /// use eulertop::claims::catalogue::load_sources;
    /// use eulertop::claims::sampler::{Sampler, Stream};
    /// let toml = r#"
    /// [[claim]]
    /// id = "corner"
    /// environment = "Section 2"
    /// role = "statement"
    /// location = "a doc example"
    /// printed = 'x'
    /// kind = "identity"
    /// expect = "proved"
    /// vars = [["x", "uniform(0, 1)"]]
    /// lhs = "x"
    /// rhs = "x"
    /// "#;
    /// let cat = load_sources(&[("doc.toml".into(), toml.into())], registry().unwrap()).unwrap();
    /// let mut s = Sampler::new(&cat, &cat.claims[0], Stream::Proof).unwrap().toward_boundary();
    /// let near = (0..100)
    ///     .filter(|_| {
    ///         let p = s.draw().unwrap();
    ///         let x = p.get("x").unwrap().as_real().unwrap();
    ///         x < 1e-3 || x > 1.0 - 1e-3
    ///     })
    ///     .count();
    /// assert!(near > 20, "{near}");
    /// ```
    pub fn toward_boundary(mut self) -> Self {
        self.boundary = true;
        self
    }

    /// The sampled variables in draw order, with their defining expressions.
    pub fn variables(&self) -> &[(String, &'c PExpr)] {
        &self.vars
    }

    /// Draws one point satisfying every constraint.
    pub fn draw(&mut self) -> Result<Point, String> {
        let mut last_fail = String::new();
        for _ in 0..MAX_DRAWS {
            self.stats.draws += 1;
            let p = self.candidate()?;
            match self.accepts(&p) {
                Ok(true) => {
                    self.stats.accepted += 1;
                    return Ok(p);
                }
                Ok(false) => {}
                Err(m) => last_fail = m,
            }
            if last_fail.is_empty() {
                last_fail = "constraints".into();
            }
        }
        Err(format!(
            "domain too thin: no point satisfied the constraints in {MAX_DRAWS} draws (last rejection: {last_fail})"
        ))
    }

    /// Does the point satisfy every `where` constraint?  `Err` names the failing one.
    pub fn accepts(&self, p: &Point) -> Result<bool, String> {
        let mut ev = Evaluator::new(self.reg, 0.0f64);
        for (n, v) in &p.vars {
            ev.bind(n, v.clone());
        }
        for w in &self.wheres {
            match ev
                .eval(&w.expr)
                .and_then(|v| v.as_bool().map_err(EvalError::new))
            {
                Ok(true) => {}
                Ok(false) => return Err(format!("'{}' is false", w.text)),
                Err(e) => return Err(format!("'{}' cannot be evaluated: {}", w.text, e.message)),
            }
        }
        Ok(true)
    }

    fn candidate(&mut self) -> Result<Point, String> {
        let mut ev = Evaluator::new(self.reg, 0.0f64);
        let mut vars = Vec::new();
        let list = self.vars.clone();
        for (n, p) in list {
            let v = self
                .eval_sampling(&p.expr, &ev)
                .map_err(|m| format!("sampling '{n}' = '{}': {m}", p.text))?;
            ev.bind(&n, v.clone());
            vars.push((n, v));
        }
        Ok(Point { vars })
    }

    /// Evaluates a sampler expression in f64 with the random primitives drawn and the
    /// given evaluator's bindings.
    pub fn eval_sampling(
        &mut self,
        e: &Expr,
        ev: &Evaluator<'_, f64>,
    ) -> Result<Value<f64>, String> {
        let sub = self.substitute(e, ev)?;
        ev.eval(&sub).map_err(|e| e.message)
    }

    /// One draw of the primitive `p` with (f64) arguments `a`.
    fn draw_primitive(&mut self, p: Primitive, a: &[f64]) -> Result<f64, String> {
        Ok(match p {
            Primitive::Uniform => {
                if a.len() != 2 || a[0] >= a[1] || !a[0].is_finite() || !a[1].is_finite() {
                    return Err(format!(
                        "uniform(a, b) needs finite a < b, got {}",
                        bounds(a)
                    ));
                }
                let mut j = self.rng.gen_range(0..=UNIFORM_GRID);
                if self.boundary {
                    let t: f64 = self.rng.r#gen::<f64>().powi(4);
                    let off = (t * UNIFORM_GRID as f64) as u64;
                    j = if self.rng.r#gen::<bool>() {
                        off
                    } else {
                        UNIFORM_GRID - off
                    };
                }
                self.set_size(UNIFORM_GRID + 1);
                a[0] + (a[1] - a[0]) * (j as f64 / UNIFORM_GRID as f64)
            }
            Primitive::Normal => {
                self.stats.nonuniform = true;
                // Box–Muller
                let u1: f64 = 1.0 - self.rng.r#gen::<f64>();
                let u2: f64 = self.rng.r#gen::<f64>();
                (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
            }
            Primitive::Randint => {
                if a.len() != 2 || a[0].fract() != 0.0 || a[1].fract() != 0.0 || a[0] > a[1] {
                    return Err(format!(
                        "randint(a, b) needs integers a <= b, got {}",
                        bounds(a)
                    ));
                }
                if a[1] - a[0] > MAX_RANDINT_SPAN {
                    return Err(format!(
                        "randint(a, b) draws from at most 10^12 + 1 integers (b - a <= 10^12), got {}",
                        bounds(a)
                    ));
                }
                self.set_size((a[1] - a[0]) as u64 + 1);
                self.rng.gen_range(a[0] as i64..=a[1] as i64) as f64
            }
            Primitive::Sign => {
                self.set_size(2);
                if self.rng.r#gen::<bool>() { 1.0 } else { -1.0 }
            }
            Primitive::Choice => {
                if a.is_empty() {
                    return Err("choice(...) needs at least one value".into());
                }
                self.set_size(a.len() as u64);
                a[self.rng.gen_range(0..a.len())]
            }
        })
    }

    fn set_size(&mut self, n: u64) {
        self.stats.min_set = Some(self.stats.min_set.map_or(n, |m| m.min(n)));
    }

    fn substitute(&mut self, e: &Expr, ev: &Evaluator<'_, f64>) -> Result<Expr, String> {
        let mut out = e.clone();
        self.subst_in(&mut out, ev)?;
        Ok(out)
    }

    fn subst_in(&mut self, e: &mut Expr, ev: &Evaluator<'_, f64>) -> Result<(), String> {
        // children first
        match &mut e.kind {
            ExprKind::Call(_, args) | ExprKind::List(args) => {
                for a in args.iter_mut() {
                    self.subst_in(a, ev)?;
                }
            }
            ExprKind::Unary(_, a) => self.subst_in(a, ev)?,
            ExprKind::Binary(_, a, b) => {
                self.subst_in(a, ev)?;
                self.subst_in(b, ev)?;
            }
            ExprKind::If(a, b, c) => {
                self.subst_in(a, ev)?;
                self.subst_in(b, ev)?;
                self.subst_in(c, ev)?;
            }
            ExprKind::Index(a, ix) => {
                self.subst_in(a, ev)?;
                for i in ix.iter_mut() {
                    self.subst_in(i, ev)?;
                }
            }
            _ => {}
        }
        let ExprKind::Call(name, args) = &e.kind else {
            return Ok(());
        };
        let reals = |args: &[Expr]| -> Result<Vec<f64>, String> {
            args.iter()
                .map(|a| ev.eval(a).map_err(|e| e.message)?.as_real())
                .collect()
        };
        let Some(p) = Primitive::from_name(name) else {
            return Ok(());
        };
        if p.spec().arity == Arity::Exact(0) && !args.is_empty() {
            return Err(format!("{}() takes no arguments in a sampler", p.name()));
        }
        let x = self.draw_primitive(p, &reals(args)?)?;
        e.kind = ExprKind::Num(format!("{x:e}"));
        Ok(())
    }
}

/// The widest range `randint(a, b)` draws from: `b - a` at most 10¹².
const MAX_RANDINT_SPAN: f64 = 1e12;

/// `a = …, b = …` for a message about the bounds of a primitive.
fn bounds(a: &[f64]) -> String {
    match a {
        [x, y] => format!("a = {x}, b = {y}"),
        _ => format!("{} arguments", a.len()),
    }
}
