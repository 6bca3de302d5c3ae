//! Evaluation of the built-in functions on values of any backend.

use super::names::Builtin;
use crate::claims::backend::{Num, RealFn, RealFn2};
use crate::claims::cmath;
use crate::claims::value::Value;
use crate::linalg::{Mat2, Mat3, Vec3};
use crate::special::{JacobiFn, ToolkitFn};

fn arity<T>(a: &[Value<T>], n: usize) -> Result<(), String> {
    if a.len() != n {
        return Err(format!("takes {n} argument(s), got {}", a.len()));
    }
    Ok(())
}

fn not_defined<T, X>(v: &Value<T>) -> Result<X, String> {
    Err(format!("not defined for a {}", v.type_name()))
}

/// Calls the built-in `f` on `a`; `like` carries the working precision.  The error is a
/// one-line message without the function's name (the evaluator adds it).
pub fn apply<T: Num>(f: Builtin, like: &T, a: &[Value<T>]) -> Result<Value<T>, String> {
    if let Some(rf) = real_fn(f) {
        arity(a, 1)?;
        return elementary(f, rf, &a[0]);
    }
    use Builtin as B;
    match f {
        B::Sign | B::Atan2 | B::Min | B::Max => real_misc(f, a),
        B::Re | B::Im | B::Conj | B::Arg | B::Cplx => complex(f, a),
        B::Sn | B::Cn | B::Dn => jacobi(f, a),
        B::Cd | B::Dc | B::Ns | B::Nc | B::Nd | B::Sc | B::Sd | B::Cs | B::Ds => jacobi(f, a),
        B::Am | B::K | B::Kp | B::F | B::JacobiInverse => elliptic(f, a),
        B::Ellipe | B::Ellipeinc | B::Ellippi | B::Jacobizeta => toolkit(f, a),
        B::Heumanlambda | B::Nome | B::Jtheta => toolkit(f, a),
        B::Vec | B::Dot | B::Cross | B::Norm2 | B::Norm | B::VnormInf => vector(f, a),
        B::Sum | B::Prod | B::D | B::Grad => {
            Err(format!("'{}' is a special form, not a function", f.name()))
        }
        _ => matrix(f, like, a),
    }
}

/// The built-ins that are one [`RealFn`] on reals.
fn real_fn(f: Builtin) -> Option<RealFn> {
    use Builtin as B;
    Some(match f {
        B::Sqrt => RealFn::Sqrt,
        B::Abs => RealFn::Abs,
        B::Exp => RealFn::Exp,
        B::Ln => RealFn::Ln,
        B::Sin => RealFn::Sin,
        B::Cos => RealFn::Cos,
        B::Tan => RealFn::Tan,
        B::Atan => RealFn::Atan,
        B::Asin => RealFn::Asin,
        B::Sinh => RealFn::Sinh,
        B::Cosh => RealFn::Cosh,
        B::Tanh => RealFn::Tanh,
        B::Asinh => RealFn::Asinh,
        B::Atanh => RealFn::Atanh,
        B::Floor => RealFn::Floor,
        _ => return None,
    })
}

fn elementary<T: Num>(f: Builtin, rf: RealFn, x: &Value<T>) -> Result<Value<T>, String> {
    match (x, f) {
        (Value::Real(x), Builtin::Abs) => x.stated_abs().map(Value::Real),
        (Value::Real(x), _) => x.real_fn(rf).map(Value::Real),
        (Value::Complex(z), Builtin::Sqrt) => cmath::sqrt(z).map(Value::Complex),
        (Value::Complex(z), Builtin::Exp) => cmath::exp(z).map(Value::Complex),
        (Value::Complex(z), Builtin::Ln) => cmath::ln(z).map(Value::Complex),
        (Value::Complex(z), Builtin::Abs) => cmath::abs(z).map(Value::Real),
        (v, _) => not_defined(v),
    }
}

fn real_misc<T: Num>(f: Builtin, a: &[Value<T>]) -> Result<Value<T>, String> {
    match f {
        Builtin::Sign => {
            arity(a, 1)?;
            let x = a[0].as_real()?;
            Ok(Value::Real(x.stated_sign_value()?))
        }
        Builtin::Atan2 => {
            arity(a, 2)?;
            let (y, x) = (a[0].as_real()?, a[1].as_real()?);
            y.real_fn2(RealFn2::Atan2, &x).map(Value::Real)
        }
        _ => {
            if a.is_empty() {
                return Err("needs at least one argument".into());
            }
            let mut best = a[0].as_real()?;
            for v in &a[1..] {
                let x = v.as_real()?;
                let min = f == Builtin::Min;
                if (min && x < best) || (!min && x > best) {
                    best = x;
                }
            }
            Ok(Value::Real(best))
        }
    }
}

fn complex<T: Num>(f: Builtin, a: &[Value<T>]) -> Result<Value<T>, String> {
    if f == Builtin::Cplx {
        arity(a, 2)?;
        let z = crate::numbers::Cplx::new(a[0].as_real()?, a[1].as_real()?);
        return Ok(Value::Complex(z));
    }
    arity(a, 1)?;
    if let (Value::CMat2(m), Builtin::Conj) = (&a[0], f) {
        return Ok(Value::CMat2(Mat2::from_fn(|i, j| cmath::conj(&m.0[i][j]))));
    }
    let w = a[0].as_complex()?;
    match f {
        Builtin::Re => Ok(Value::Real(w.re)),
        Builtin::Im => Ok(Value::Real(w.im)),
        Builtin::Conj => Ok(Value::Complex(cmath::conj(&w))),
        _ => cmath::arg(&w).map(Value::Real),
    }
}

/// The twelve Jacobi functions `pq = p/q` (Glaisher's notation) from sn, cn, dn of a
/// real or complex `u`: one division at the working precision; a zero denominator is a
/// pole, reported as an error.
fn jacobi<T: Num>(f: Builtin, a: &[Value<T>]) -> Result<Value<T>, String> {
    let triple = jacobi_triple(a)?;
    jacobi_pick(f, a, &triple)
}

/// `[sn, cn, dn](u, k)` for the arguments `[u, k]` of a Jacobi built-in (real or complex
/// `u`; a real or a complex modulus `k`, the latter with a complex result also for a real
/// `u`): all twelve functions are quotients of these three.
pub fn jacobi_triple<T: Num>(a: &[Value<T>]) -> Result<[Value<T>; 3], String> {
    arity(a, 2)?;
    if let Value::Complex(k) = &a[1] {
        let u = match &a[0] {
            Value::Real(u) => crate::numbers::Cplx::new(u.clone(), u.zero()),
            Value::Complex(u) => u.clone(),
            v => return Err(not_a_number_u(v)),
        };
        return Ok(T::sncndn_complex_modulus(&u, k)?.map(Value::Complex));
    }
    let k = a[1].as_real()?;
    Ok(match &a[0] {
        Value::Real(u) => T::sncndn(u, &k)?.map(Value::Real),
        Value::Complex(u) => T::sncndn_complex(u, &k)?.map(Value::Complex),
        v => return Err(not_a_number_u(v)),
    })
}

/// The error for an argument `u` of a Jacobi built-in that is not a number.
fn not_a_number_u<T: Num>(v: &Value<T>) -> String {
    format!(
        "argument u must be real or complex, got a {}",
        v.type_name()
    )
}

/// The Jacobi built-in `f` at the arguments `a`, from `[sn, cn, dn]` there
/// ([`jacobi_triple`]); a pole is an error.
pub fn jacobi_pick<T: Num>(
    f: Builtin,
    a: &[Value<T>],
    triple: &[Value<T>; 3],
) -> Result<Value<T>, String> {
    // the modulus: real, or complex (then no special case k = 1 below)
    let (one, k_is_one) = match &a[1] {
        Value::Complex(k) => (k.re.one(), false),
        v => {
            let k = v.as_real()?;
            (k.one(), (k.clone() - k.one()).is_zero())
        }
    };
    let g = JacobiFn::from_name(f.name()).ok_or("not a Jacobi function")?;
    let [s, c, d] = triple;
    let pick = |i: Option<usize>| i.map(|i| [s, c, d][i].clone());
    let (p, q) = g.parts();
    let num = pick(p).unwrap_or_else(|| Value::Real(one.clone()));
    let Some(den) = pick(q) else {
        return Ok(num);
    };
    let zero = match &den {
        Value::Real(x) => x.is_zero(),
        Value::Complex(z) => z.re.is_zero() && z.im.is_zero(),
        _ => false,
    };
    // sn vanishes only at its zeros 2jK (+ 2liK'), of which only 0 is representable; a
    // zero cn or dn is an underflow (e.g. sech u at k = 1), so the quotient overflows
    if zero && q == Some(0) {
        return Err(format!("pole: sn(u, k) = 0 at u = {}", at(&a[0])));
    }
    let overflow = || format!("overflows at u = {}", at(&a[0]));
    // at k = 1, cn = dn = sech u: cd = dc = 1 exactly, also where sech u underflows
    let unit = k_is_one && matches!((p, q), (Some(1), Some(2)) | (Some(2), Some(1)));
    if unit && matches!(a[0], Value::Real(_)) {
        return Ok(Value::Real(one));
    }
    if zero {
        return Err(overflow());
    }
    let v = num.div(&den)?;
    let finite = match &v {
        Value::Real(x) => x.is_finite(),
        Value::Complex(z) => z.re.is_finite() && z.im.is_finite(),
        _ => true,
    };
    if finite { Ok(v) } else { Err(overflow()) }
}

/// `u` for a message: a real or a complex number in `f64`.
fn at<T: Num>(u: &Value<T>) -> String {
    match u {
        Value::Complex(z) => format!("{:e} + {:e}i", z.re.to_f64(), z.im.to_f64()),
        Value::Real(x) => format!("{:e}", x.to_f64()),
        v => v.type_name().to_string(),
    }
}

fn elliptic<T: Num>(f: Builtin, a: &[Value<T>]) -> Result<Value<T>, String> {
    let r = |j: usize| a[j].as_real();
    match f {
        Builtin::Am => {
            arity(a, 2)?;
            T::am(&r(0)?, &r(1)?).map(Value::Real)
        }
        Builtin::K => {
            arity(a, 1)?;
            T::ellipk(&r(0)?).map(Value::Real)
        }
        Builtin::Kp => {
            arity(a, 1)?;
            T::ellipkp(&r(0)?).map(Value::Real)
        }
        Builtin::F => {
            arity(a, 2)?;
            T::ellipf(&r(0)?, &r(1)?).map(Value::Real)
        }
        _ => {
            arity(a, 4)?;
            T::jacobi_inverse(&r(0)?, &r(1)?, &r(2)?, &r(3)?).map(Value::Real)
        }
    }
}

/// The functions of the elliptic toolkit ([`ToolkitFn`], same names): real arguments,
/// `jtheta`'s index an integer.
fn toolkit<T: Num>(f: Builtin, a: &[Value<T>]) -> Result<Value<T>, String> {
    let g = ToolkitFn::from_name(f.name()).ok_or("not a toolkit function")?;
    arity(a, g.arity())?;
    let args = a
        .iter()
        .map(Value::as_real)
        .collect::<Result<Vec<T>, _>>()?;
    T::toolkit(g, &args).map(Value::Real)
}

fn vector<T: Num>(f: Builtin, a: &[Value<T>]) -> Result<Value<T>, String> {
    if f == Builtin::Vec {
        arity(a, 3)?;
        let v = Vec3::new(a[0].as_real()?, a[1].as_real()?, a[2].as_real()?);
        return Ok(Value::Vec3(v));
    }
    if matches!(f, Builtin::Dot | Builtin::Cross) {
        arity(a, 2)?;
        let (x, y) = (a[0].as_vec3()?, a[1].as_vec3()?);
        return Ok(if f == Builtin::Dot {
            Value::Real(x.dot(&y))
        } else {
            Value::Vec3(x.cross(&y))
        });
    }
    arity(a, 1)?;
    let x = a[0].as_vec3()?;
    match f {
        Builtin::VnormInf => {
            let mut m = x.0[0].real_fn(RealFn::Abs)?;
            for c in &x.0[1..] {
                let t = c.real_fn(RealFn::Abs)?;
                if t > m {
                    m = t;
                }
            }
            Ok(Value::Real(m))
        }
        Builtin::Norm => x.norm2().real_fn(RealFn::Sqrt).map(Value::Real),
        _ => Ok(Value::Real(x.norm2())),
    }
}

fn matrix<T: Num>(f: Builtin, like: &T, a: &[Value<T>]) -> Result<Value<T>, String> {
    let z = like.zero();
    match f {
        Builtin::I3 | Builtin::I2 => {
            arity(a, 0)?;
            Ok(if f == Builtin::I3 {
                Value::Mat3(Mat3::identity(&z))
            } else {
                Value::CMat2(Mat2::from_fn(|i, j| {
                    cmath::real(if i == j { z.one() } else { z.zero() })
                }))
            })
        }
        Builtin::Diag => {
            let d = match a.len() {
                1 => a[0].as_vec3()?,
                3 => Vec3::new(a[0].as_real()?, a[1].as_real()?, a[2].as_real()?),
                n => return Err(format!("takes 1 vec3 or 3 reals, got {n} arguments")),
            };
            Ok(Value::Mat3(Mat3::diag(&d)))
        }
        Builtin::Pauli => {
            arity(a, 1)?;
            pauli(&z, a[0].as_int()?)
        }
        Builtin::Skew => {
            arity(a, 1)?;
            let [x, y, w] = a[0].as_vec3()?.0;
            Ok(Value::Mat3(Mat3([
                [z.clone(), -w.clone(), y.clone()],
                [w, z.clone(), -x.clone()],
                [-y, x, z],
            ])))
        }
        Builtin::Unskew => {
            arity(a, 1)?;
            let m = a[0].as_mat3()?.0;
            let v = Vec3::new(m[2][1].clone(), m[0][2].clone(), m[1][0].clone());
            Ok(Value::Vec3(v))
        }
        Builtin::Comm => {
            arity(a, 2)?;
            a[0].mul(&a[1])?.sub(&a[1].mul(&a[0])?)
        }
        _ => {
            arity(a, 1)?;
            square(f, like, &a[0])
        }
    }
}

/// transpose, det, tr, inv of one square matrix (inv also of a scalar).
fn square<T: Num>(f: Builtin, like: &T, x: &Value<T>) -> Result<Value<T>, String> {
    match (f, x) {
        (Builtin::Transpose, Value::Mat3(m)) => Ok(Value::Mat3(m.transpose())),
        (Builtin::Transpose, Value::CMat2(m)) => Ok(Value::CMat2(m.transpose())),
        (Builtin::Det, Value::Mat3(m)) => Ok(Value::Real(m.det())),
        (Builtin::Det, Value::CMat2(m)) => Ok(Value::Complex(m.det())),
        (Builtin::Tr, Value::Mat3(m)) => Ok(Value::Real(m.trace())),
        (Builtin::Tr, Value::CMat2(m)) => Ok(Value::Complex(m.trace())),
        (Builtin::Inv, Value::Mat3(m)) => match m.inverse() {
            Some(i) => Ok(Value::Mat3(i)),
            None => Err("singular matrix".into()),
        },
        (Builtin::Inv, Value::CMat2(m)) => {
            // scaled by 1/det, so an exactly singular matrix is an error
            let di = cmath::div(&cmath::real(like.one()), &m.det())?;
            let adj = Mat2([
                [m.0[1][1].clone(), -m.0[0][1].clone()],
                [-m.0[1][0].clone(), m.0[0][0].clone()],
            ]);
            Ok(Value::CMat2(Mat2::from_fn(|i, j| {
                adj.0[i][j].clone() * di.clone()
            })))
        }
        (Builtin::Inv, Value::Real(_) | Value::Complex(_)) => Value::Real(like.one()).div(x),
        (_, v) => not_defined(v),
    }
}

fn pauli<T: Num>(z: &T, k: i64) -> Result<Value<T>, String> {
    let (o, n, i) = (cmath::real(z.one()), cmath::real(z.zero()), cmath::i(z));
    match k {
        1 => Ok(Value::CMat2(Mat2([[n.clone(), o.clone()], [o, n]]))),
        2 => Ok(Value::CMat2(Mat2([[n.clone(), -i.clone()], [i, n]]))),
        3 => Ok(Value::CMat2(Mat2([[o.clone(), n.clone()], [n, -o]]))),
        _ => Err(format!("pauli({k}): index must be 1, 2 or 3")),
    }
}
