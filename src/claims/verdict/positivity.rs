//! The claim's domain as a parametrization by positive parameters, with which the
//! prover proves signs (see [`crate::algebra::positivity`]).
//!
//! Each sampled variable whose definition is built from numbers, earlier variables,
//! `+ − × ÷`, integer powers, `vec(…)` and `uniform(lo, hi)` becomes a rational function
//! of parameters.  Each `uniform(lo, hi)` is relaxed to a range that contains it:
//!
//! | drawn from | relaxed to | as |
//! |---|---|---|
//! | `0 ≤ lo < hi ≤ 1` | `(0, 1)` | `t/(1 + t)`, `t > 0` |
//! | `0 ≤ lo` | `(0, ∞)` | `t > 0` |
//! | `hi ≤ 0` | `(−∞, 0)` | `−t`, `t > 0` |
//! | otherwise | any nonzero value | `μ ≠ 0` |
//!
//! So the parametrized set contains the sampled domain (its `where` conditions only
//! narrow the domain further), and a sign proved on it holds on the sampled domain.
//! A variable drawn otherwise (`sign()`, `K(…)`, a normal deviate) is not parametrized,
//! and a sign that involves it is not proved this way.

use crate::algebra::positivity::{ParamRat, Parametrization};
use crate::claims::ast::{BinOp, Expr, ExprKind, UnOp};
use crate::claims::catalogue::PExpr;
use std::collections::{BTreeMap, HashMap};
use std::sync::{Arc, Mutex, OnceLock};

/// A parametrized value: a scalar or the components of a vector.
#[derive(Clone)]
enum PVal {
    Scalar(ParamRat),
    Vector(Vec<ParamRat>),
}

/// The parametrizations made so far, by the definitions of the sampled variables
/// (claims on one domain share theirs, with what its sign tests remember).  At most
/// [`MAX_CACHED`] entries.
type Cache = Mutex<HashMap<String, Option<Arc<Parametrization>>>>;

/// The most parametrizations [`parametrization`] keeps.
const MAX_CACHED: usize = 256;

/// The parametrization of the claim's sampled variables, or `None` when none of them
/// can be parametrized; made once per list of definitions.
pub(super) fn parametrization(vars: &[(String, &PExpr)]) -> Option<Arc<Parametrization>> {
    static CACHE: OnceLock<Cache> = OnceLock::new();
    let key: String = (vars.iter())
        .map(|(n, d)| format!("{n} = {}\n", d.text))
        .collect();
    let cache = CACHE.get_or_init(Cache::default);
    if let Some(known) = cache.lock().ok()?.get(&key) {
        return known.clone();
    }
    let par = made(vars);
    let mut cache = cache.lock().ok()?;
    if cache.len() < MAX_CACHED {
        cache.insert(key, par.clone());
    }
    par
}

/// [`parametrization`] made.
fn made(vars: &[(String, &PExpr)]) -> Option<Arc<Parametrization>> {
    let mut par = parametrized(vars, false)?;
    if let Some(exact) = parametrized(vars, true) {
        par.set_alternative(exact);
    }
    Some(Arc::new(par))
}

/// The parametrization with each `uniform(lo, hi)` relaxed as the module says, or, with
/// `exact`, as the interval itself: `(lo + hi·t)/(1 + t)`, `t > 0` (the box the domain
/// lies in, which proves signs such as `1 − |v|² > 0` that the relaxed ranges lose).
fn parametrized(vars: &[(String, &PExpr)], exact: bool) -> Option<Parametrization> {
    let mut par = Parametrization::new();
    let mut env: BTreeMap<String, PVal> = BTreeMap::new();
    for (name, def) in vars {
        if !parametrizable(&def.expr, &env) {
            continue;
        }
        let mut ranges = Vec::new();
        let Some(v) = value(&mut par, &env, &def.expr, (name, &mut ranges, exact)) else {
            continue;
        };
        let text = format!("{name} = {}", relaxed_text(&def.text, &ranges));
        match &v {
            PVal::Scalar(x) => par.bind(name, x.clone(), text),
            PVal::Vector(xs) => {
                for (j, x) in xs.iter().enumerate() {
                    let text = if j == 0 { text.clone() } else { String::new() };
                    par.bind(&format!("{name}{}", j + 1), x.clone(), text);
                }
            }
        }
        env.insert(name.clone(), v);
    }
    (!par.is_empty()).then_some(par)
}

/// Is the definition built only from numbers, parametrized variables, arithmetic,
/// `vec` and `uniform`?
fn parametrizable(e: &Expr, env: &BTreeMap<String, PVal>) -> bool {
    let mut ok = true;
    e.walk(&mut |x| match &x.kind {
        ExprKind::Name(n) => ok &= env.contains_key(n),
        ExprKind::Call(f, _) => ok &= f == "uniform" || f == "vec",
        ExprKind::Num(_) | ExprKind::Unary(UnOp::Neg, _) | ExprKind::Binary(..) => {}
        _ => ok = false,
    });
    ok
}

/// The definition's text with each `uniform(…)`, in order, replaced by its parameter.
fn relaxed_text(text: &str, ranges: &[String]) -> String {
    let mut out = String::new();
    let mut rest = text;
    for r in ranges {
        let Some(i) = rest.find("uniform(") else {
            break;
        };
        let mut depth = 0;
        let end = rest[i..].char_indices().find_map(|(j, c)| {
            match c {
                '(' => depth += 1,
                ')' => depth -= 1,
                _ => {}
            }
            (c == ')' && depth == 0).then_some(i + j + 1)
        });
        let Some(end) = end else { break };
        out.push_str(&rest[..i]);
        out.push_str(r);
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

/// The value of a definition; `ranges` collects how its draws are relaxed.
fn value(
    par: &mut Parametrization,
    env: &BTreeMap<String, PVal>,
    e: &Expr,
    (var, ranges, exact): (&str, &mut Vec<String>, bool),
) -> Option<PVal> {
    let scalar = |v: PVal| match v {
        PVal::Scalar(x) => Some(x),
        PVal::Vector(_) => None,
    };
    Some(match &e.kind {
        ExprKind::Num(s) => {
            let q = crate::numbers::parse_rational(s).ok()?;
            let q = rug::Rational::from((
                rug::Integer::from_str_radix(&q.numer().to_string(), 10).ok()?,
                rug::Integer::from_str_radix(&q.denom().to_string(), 10).ok()?,
            ));
            PVal::Scalar(par.constant(&q))
        }
        ExprKind::Name(n) => env.get(n)?.clone(),
        ExprKind::Unary(UnOp::Neg, a) => {
            PVal::Scalar(scalar(value(par, env, a, (var, ranges, exact))?)?.neg())
        }
        ExprKind::Binary(op, a, b) => {
            let x = scalar(value(par, env, a, (var, ranges, exact))?)?;
            let y = scalar(value(par, env, b, (var, ranges, exact))?)?;
            PVal::Scalar(match op {
                BinOp::Add => x.add(&y),
                BinOp::Sub => x.sub(&y),
                BinOp::Mul => x.mul(&y),
                BinOp::Div => x.div(&y)?,
                BinOp::Pow => {
                    let n = y.as_constant()?;
                    if *n.denom() != 1 {
                        return None;
                    }
                    x.powi(n.numer().to_i64()?)?
                }
                _ => return None,
            })
        }
        ExprKind::Call(f, args) if f == "vec" && args.len() == 3 => {
            let mut xs = Vec::new();
            for a in args {
                xs.push(scalar(value(par, env, a, (var, ranges, exact))?)?);
            }
            PVal::Vector(xs)
        }
        ExprKind::Call(f, args) if f == "uniform" && args.len() == 2 => {
            let lo = scalar(value(par, env, &args[0], (var, ranges, exact))?)?.as_constant()?;
            let hi = scalar(value(par, env, &args[1], (var, ranges, exact))?)?.as_constant()?;
            let name = format!("t{}_{var}", ranges.len() + 1);
            PVal::Scalar(if exact {
                interval(par, &name, (&lo, &hi), ranges)?
            } else {
                relaxed(par, &name, (&lo, &hi), ranges)?
            })
        }
        _ => return None,
    })
}

/// `uniform(lo, hi)` as `(lo + hi·t)/(1 + t)`, `t > 0`: the interval itself.
fn interval(
    par: &mut Parametrization,
    name: &str,
    (lo, hi): (&rug::Rational, &rug::Rational),
    ranges: &mut Vec<String>,
) -> Option<ParamRat> {
    let one = par.constant(&rug::Rational::from(1));
    let t = par.positive(name)?;
    let v = par
        .constant(lo)
        .add(&par.constant(hi).mul(&t))
        .div(&one.add(&t))?;
    ranges.push(format!("({lo} + {hi}*{name})/(1 + {name})"));
    Some(v)
}

/// A parameter for `uniform(lo, hi)`, on a range that contains `(lo, hi)`.
fn relaxed(
    par: &mut Parametrization,
    name: &str,
    (lo, hi): (&rug::Rational, &rug::Rational),
    ranges: &mut Vec<String>,
) -> Option<ParamRat> {
    let one = par.constant(&rug::Rational::from(1));
    let (v, range) = if *lo >= 0 && *hi < 1 {
        let t = par.positive(name)?;
        (t.div(&one.add(&t))?, format!("{name}/(1 + {name})"))
    } else if *lo >= 0 {
        (par.positive(name)?, name.to_string())
    } else if *hi <= 0 {
        (par.positive(name)?.neg(), format!("(-{name})"))
    } else {
        (par.nonzero(name)?, name.to_string())
    };
    ranges.push(range);
    Some(v)
}
