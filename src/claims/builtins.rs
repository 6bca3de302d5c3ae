//! Built-in functions: elementary, elliptic (modulus k) and linear algebra.  The list is
//! documented in `identities/README.md`.

use super::backend::{Num, RealFn};
use super::eval::Evaluator;
use super::value::{Cx, Value};

/// Names of all built-in functions (registered functions may not reuse them).
pub const BUILTINS: &[&str] = &[
    "sqrt",
    "abs",
    "exp",
    "ln",
    "sin",
    "cos",
    "tan",
    "atan",
    "asin",
    "sinh",
    "cosh",
    "tanh",
    "asinh",
    "atanh",
    "floor",
    "sign",
    "atan2",
    "min",
    "max",
    "re",
    "im",
    "conj",
    "arg",
    "cplx",
    "sn",
    "cn",
    "dn",
    "am",
    "K",
    "Kp",
    "F",
    "vec",
    "dot",
    "cross",
    "norm2",
    "norm",
    "transpose",
    "det",
    "inv",
    "tr",
    "comm",
    "I3",
    "I2",
    "diag",
    "pauli",
    "skew",
    "unskew",
    "vnorm_inf",
    "sum",
    "prod",
    "d",
    "grad",
];

/// Is `name` a built-in function?
pub fn is_builtin(name: &str) -> bool {
    BUILTINS.contains(&name)
}

fn arity<T>(a: &[Value<T>], n: usize) -> Result<(), String> {
    if a.len() != n {
        return Err(format!("takes {n} argument(s), got {}", a.len()));
    }
    Ok(())
}

fn real_fn_of(name: &str) -> Option<RealFn> {
    Some(match name {
        "sqrt" => RealFn::Sqrt,
        "abs" => RealFn::Abs,
        "exp" => RealFn::Exp,
        "ln" => RealFn::Ln,
        "sin" => RealFn::Sin,
        "cos" => RealFn::Cos,
        "tan" => RealFn::Tan,
        "atan" => RealFn::Atan,
        "asin" => RealFn::Asin,
        "sinh" => RealFn::Sinh,
        "cosh" => RealFn::Cosh,
        "tanh" => RealFn::Tanh,
        "asinh" => RealFn::Asinh,
        "atanh" => RealFn::Atanh,
        "floor" => RealFn::Floor,
        _ => return None,
    })
}

fn mat3_fn<T: Num>(f: impl Fn(usize, usize) -> T) -> Value<T> {
    Value::Mat3(std::array::from_fn(|i| std::array::from_fn(|j| f(i, j))))
}

fn det3<T: Num>(m: &[[T; 3]; 3]) -> T {
    let c = |i: usize, j: usize| m[i][j].clone();
    c(0, 0) * (c(1, 1) * c(2, 2) - c(1, 2) * c(2, 1))
        - c(0, 1) * (c(1, 0) * c(2, 2) - c(1, 2) * c(2, 0))
        + c(0, 2) * (c(1, 0) * c(2, 1) - c(1, 1) * c(2, 0))
}

/// Calls the built-in `name`; `None` if there is no such built-in.
pub fn call<T: Num>(
    ev: &Evaluator<'_, T>,
    name: &str,
    a: &[Value<T>],
) -> Option<Result<Value<T>, String>> {
    if !is_builtin(name) {
        return None;
    }
    Some(call_inner(ev.like(), name, a))
}

fn call_inner<T: Num>(like: &T, name: &str, a: &[Value<T>]) -> Result<Value<T>, String> {
    if let Some(f) = real_fn_of(name) {
        arity(a, 1)?;
        return match (&a[0], name) {
            (Value::Real(x), _) => x.real_fn(f).map(Value::Real),
            (Value::Complex(z), "sqrt") => z.sqrt().map(Value::Complex),
            (Value::Complex(z), "exp") => z.exp().map(Value::Complex),
            (Value::Complex(z), "ln") => z.ln().map(Value::Complex),
            (Value::Complex(z), "abs") => z.abs().map(Value::Real),
            (v, _) => Err(format!("not defined for a {}", v.type_name())),
        };
    }
    let z = like.zero();
    match name {
        "sign" => {
            arity(a, 1)?;
            let x = a[0].as_real()?;
            Ok(Value::Real(if x > z {
                z.one()
            } else if x < z {
                -z.one()
            } else {
                z
            }))
        }
        "atan2" => {
            arity(a, 2)?;
            a[0].as_real()?.atan2_(&a[1].as_real()?).map(Value::Real)
        }
        "min" | "max" => {
            if a.is_empty() {
                return Err("needs at least one argument".into());
            }
            let mut best = a[0].as_real()?;
            for v in &a[1..] {
                let x = v.as_real()?;
                if (name == "min" && x < best) || (name == "max" && x > best) {
                    best = x;
                }
            }
            Ok(Value::Real(best))
        }
        "re" | "im" | "conj" | "arg" => {
            arity(a, 1)?;
            if let (Value::CMat2(m), "conj") = (&a[0], name) {
                return Ok(Value::CMat2(std::array::from_fn(|i| {
                    std::array::from_fn(|j| m[i][j].conj())
                })));
            }
            let w = a[0].as_complex()?;
            match name {
                "re" => Ok(Value::Real(w.re)),
                "im" => Ok(Value::Real(w.im)),
                "conj" => Ok(Value::Complex(w.conj())),
                _ => w.arg().map(Value::Real),
            }
        }
        "cplx" => {
            arity(a, 2)?;
            Ok(Value::Complex(Cx::new(a[0].as_real()?, a[1].as_real()?)))
        }
        "sn" | "cn" | "dn" => {
            arity(a, 2)?;
            let k = a[1].as_real()?;
            let j = ["sn", "cn", "dn"]
                .iter()
                .position(|n| *n == name)
                .unwrap_or(0);
            match &a[0] {
                Value::Real(u) => T::sncndn(u, &k).map(|r| Value::Real(r[j].clone())),
                Value::Complex(u) => T::sncndn_c(u, &k).map(|r| Value::Complex(r[j].clone())),
                v => Err(format!(
                    "argument u must be real or complex, got a {}",
                    v.type_name()
                )),
            }
        }
        "am" => {
            arity(a, 2)?;
            T::am(&a[0].as_real()?, &a[1].as_real()?).map(Value::Real)
        }
        "K" => {
            arity(a, 1)?;
            T::ellipk(&a[0].as_real()?).map(Value::Real)
        }
        "Kp" => {
            arity(a, 1)?;
            T::ellipkp(&a[0].as_real()?).map(Value::Real)
        }
        "F" => {
            arity(a, 2)?;
            T::ellipf(&a[0].as_real()?, &a[1].as_real()?).map(Value::Real)
        }
        "jacobi_inverse" => {
            arity(a, 4)?;
            T::jacobi_inverse(
                &a[0].as_real()?,
                &a[1].as_real()?,
                &a[2].as_real()?,
                &a[3].as_real()?,
            )
            .map(Value::Real)
        }
        "vec" => {
            arity(a, 3)?;
            Ok(Value::Vec3([
                a[0].as_real()?,
                a[1].as_real()?,
                a[2].as_real()?,
            ]))
        }
        "dot" => {
            arity(a, 2)?;
            let (x, y) = (a[0].as_vec3()?, a[1].as_vec3()?);
            Ok(Value::Real(
                x[0].clone() * y[0].clone()
                    + x[1].clone() * y[1].clone()
                    + x[2].clone() * y[2].clone(),
            ))
        }
        "norm2" | "norm" | "vnorm_inf" => {
            arity(a, 1)?;
            let x = a[0].as_vec3()?;
            if name == "vnorm_inf" {
                let mut m = x[0].real_fn(RealFn::Abs)?;
                for c in &x[1..] {
                    let t = c.real_fn(RealFn::Abs)?;
                    if t > m {
                        m = t;
                    }
                }
                return Ok(Value::Real(m));
            }
            let n2 = x[0].clone() * x[0].clone()
                + x[1].clone() * x[1].clone()
                + x[2].clone() * x[2].clone();
            if name == "norm" {
                n2.real_fn(RealFn::Sqrt).map(Value::Real)
            } else {
                Ok(Value::Real(n2))
            }
        }
        "cross" => {
            arity(a, 2)?;
            let (x, y) = (a[0].as_vec3()?, a[1].as_vec3()?);
            let c = |i: usize, j: usize| x[i].clone() * y[j].clone() - x[j].clone() * y[i].clone();
            Ok(Value::Vec3([c(1, 2), c(2, 0), c(0, 1)]))
        }
        "transpose" => {
            arity(a, 1)?;
            match &a[0] {
                Value::Mat3(m) => Ok(mat3_fn(|i, j| m[j][i].clone())),
                Value::CMat2(m) => Ok(Value::CMat2(std::array::from_fn(|i| {
                    std::array::from_fn(|j| m[j][i].clone())
                }))),
                v => Err(format!("not defined for a {}", v.type_name())),
            }
        }
        "det" => {
            arity(a, 1)?;
            match &a[0] {
                Value::Mat3(m) => Ok(Value::Real(det3(m))),
                Value::CMat2(m) => Ok(Value::Complex(
                    m[0][0].mul(&m[1][1]).sub(&m[0][1].mul(&m[1][0])),
                )),
                v => Err(format!("not defined for a {}", v.type_name())),
            }
        }
        "tr" => {
            arity(a, 1)?;
            match &a[0] {
                Value::Mat3(m) => Ok(Value::Real(
                    m[0][0].clone() + m[1][1].clone() + m[2][2].clone(),
                )),
                Value::CMat2(m) => Ok(Value::Complex(m[0][0].add(&m[1][1]))),
                v => Err(format!("not defined for a {}", v.type_name())),
            }
        }
        "inv" => {
            arity(a, 1)?;
            match &a[0] {
                Value::Mat3(m) => {
                    let d = det3(m);
                    if d.is_zero() {
                        return Err("singular matrix".into());
                    }
                    let c = |i: usize, j: usize| m[i % 3][j % 3].clone();
                    Ok(mat3_fn(|j, i| {
                        (c(i + 1, j + 1) * c(i + 2, j + 2) - c(i + 1, j + 2) * c(i + 2, j + 1))
                            / d.clone()
                    }))
                }
                Value::CMat2(m) => {
                    let d = m[0][0].mul(&m[1][1]).sub(&m[0][1].mul(&m[1][0]));
                    let one = Cx::real(z.one());
                    let di = one.div(&d)?;
                    Ok(Value::CMat2([
                        [m[1][1].mul(&di), m[0][1].neg().mul(&di)],
                        [m[1][0].neg().mul(&di), m[0][0].mul(&di)],
                    ]))
                }
                Value::Real(_) | Value::Complex(_) => Value::Real(z.one()).div(&a[0]),
                v => Err(format!("not defined for a {}", v.type_name())),
            }
        }
        "comm" => {
            arity(a, 2)?;
            a[0].mul(&a[1])?.sub(&a[1].mul(&a[0])?)
        }
        "I3" => {
            arity(a, 0)?;
            Ok(mat3_fn(|i, j| if i == j { z.one() } else { z.zero() }))
        }
        "I2" => {
            arity(a, 0)?;
            Ok(Value::CMat2(std::array::from_fn(|i| {
                std::array::from_fn(|j| Cx::real(if i == j { z.one() } else { z.zero() }))
            })))
        }
        "diag" => {
            let d = match a.len() {
                1 => a[0].as_vec3()?,
                3 => [a[0].as_real()?, a[1].as_real()?, a[2].as_real()?],
                n => return Err(format!("takes 1 vec3 or 3 reals, got {n} arguments")),
            };
            Ok(mat3_fn(|i, j| if i == j { d[i].clone() } else { z.zero() }))
        }
        "pauli" => {
            arity(a, 1)?;
            let k = a[0].as_int()?;
            let (o, n, im) = (
                Cx::real(z.one()),
                Cx::real(z.zero()),
                Cx::new(z.zero(), z.one()),
            );
            match k {
                1 => Ok(Value::CMat2([[n.clone(), o.clone()], [o, n]])),
                2 => Ok(Value::CMat2([[n.clone(), im.neg()], [im, n]])),
                3 => Ok(Value::CMat2([[o.clone(), n.clone()], [n, o.neg()]])),
                _ => Err(format!("pauli({k}): index must be 1, 2 or 3")),
            }
        }
        "skew" => {
            arity(a, 1)?;
            let v = a[0].as_vec3()?;
            let (x, y, w) = (v[0].clone(), v[1].clone(), v[2].clone());
            Ok(Value::Mat3([
                [z.clone(), -w.clone(), y.clone()],
                [w, z.clone(), -x.clone()],
                [-y, x, z],
            ]))
        }
        "unskew" => {
            arity(a, 1)?;
            let m = a[0].as_mat3()?;
            Ok(Value::Vec3([
                m[2][1].clone(),
                m[0][2].clone(),
                m[1][0].clone(),
            ]))
        }
        _ => Err(format!("'{name}' is a special form, not a function")),
    }
}
