//! The scalar backends of the evaluator: one trait, [`Num`], implemented for `f64`,
//! [`rug::Float`] (any precision), [`Dual<f64>`], [`Dual<rug::Float>`] (derivatives) and
//! [`Rational`] (exact).  Transcendental operations on rationals are errors (the claim is
//! then not rational and cannot be proved exactly); nothing is approximated silently.

use super::ast::Expr;
use super::eval::{derive_with, EvalError, Evaluator};
use super::registry::ExtFunction;
use super::value::{Cx, Value};
use crate::numbers::{Dual, Rational, Real, Scalar};
use num_traits::{Signed, ToPrimitive};
use rug::Float;

/// Elementary real functions of the language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RealFn {
    /// √x (error for x < 0)
    Sqrt,
    /// |x|
    Abs,
    /// eˣ
    Exp,
    /// ln x (error for x ≤ 0)
    Ln,
    /// sin
    Sin,
    /// cos
    Cos,
    /// tan
    Tan,
    /// arctan
    Atan,
    /// arcsin (error outside [-1, 1])
    Asin,
    /// sinh
    Sinh,
    /// cosh
    Cosh,
    /// tanh
    Tanh,
    /// arsinh
    Asinh,
    /// artanh (error outside (-1, 1))
    Atanh,
    /// ⌊x⌋
    Floor,
}

/// A scalar type the evaluator can compute with.
pub trait Num: Scalar + PartialOrd {
    /// Is this the exact (rational) backend?
    const EXACT: bool;
    /// Converts a literal as written (`0.1` is exactly 1/10 for rationals, correctly
    /// rounded at the working precision otherwise).
    fn lit(&self, s: &str) -> Result<Self, String> {
        self.parse_like(s).map_err(|e| e.to_string())
    }
    /// An elementary function.
    fn real_fn(&self, f: RealFn) -> Result<Self, String>;
    /// `atan2(self, x)`.
    fn atan2_(&self, x: &Self) -> Result<Self, String>;
    /// π at this precision.
    fn pi_(&self) -> Result<Self, String>;
    /// `self^y` for real y, self > 0.
    fn powf_(&self, y: &Self) -> Result<Self, String>;
    /// The value rounded to f64.
    fn to_f64_(&self) -> f64;
    /// Not NaN or infinite.
    fn finite(&self) -> bool;
    /// log2 |self| without underflow (−∞ for zero).
    fn log2_abs(&self) -> f64;
    /// `(sn, cn, dn)` of real `u`, modulus `k`.
    fn sncndn(u: &Self, k: &Self) -> Result<[Self; 3], String>;
    /// `(sn, cn, dn)` of complex `u`, real modulus `k`.
    fn sncndn_c(u: &Cx<Self>, k: &Self) -> Result<[Cx<Self>; 3], String>;
    /// Amplitude am(u, k).
    fn am(u: &Self, k: &Self) -> Result<Self, String>;
    /// Complete elliptic integral K(k).
    fn ellipk(k: &Self) -> Result<Self, String>;
    /// Incomplete elliptic integral F(φ, k).
    fn ellipf(phi: &Self, k: &Self) -> Result<Self, String>;
    /// Calls a registered function on this backend.
    fn ext_call(f: &dyn ExtFunction, args: &[Value<Self>]) -> Result<Value<Self>, String>;
    /// Evaluates `d(body, var[, comp])` (forward-mode AD in the matching dual backend).
    /// Duals (nested derivatives) and rationals cannot differentiate: an error.
    fn derive_in(
        _ev: &Evaluator<'_, Self>,
        _body: &Expr,
        var: &str,
        _comp: Option<i64>,
    ) -> Result<Value<Self>, EvalError> {
        Err(EvalError {
            message: format!(
                "d(..., {var}): nested derivatives and exact derivatives are not supported"
            ),
            span: None,
        })
    }
}

fn real_fn_generic<R: Real>(x: &R, f: RealFn) -> Result<R, String> {
    let z = x.zero();
    let one = x.one();
    let r = match f {
        RealFn::Sqrt => {
            if *x < z {
                return Err(format!("sqrt of negative value {:.6e}", x.to_f64()));
            }
            x.sqrt()
        }
        RealFn::Abs => x.abs(),
        RealFn::Exp => x.exp(),
        RealFn::Ln => {
            if *x <= z {
                return Err(format!("ln of non-positive value {:.6e}", x.to_f64()));
            }
            x.ln()
        }
        RealFn::Sin => x.sin(),
        RealFn::Cos => x.cos(),
        RealFn::Tan => x.tan(),
        RealFn::Atan => x.atan(),
        RealFn::Asin => {
            if x.abs() > one {
                return Err(format!("asin of {:.6e} outside [-1, 1]", x.to_f64()));
            }
            x.asin()
        }
        RealFn::Sinh => x.sinh(),
        RealFn::Cosh => x.cosh(),
        RealFn::Tanh => x.tanh(),
        RealFn::Asinh => x.asinh(),
        RealFn::Atanh => {
            if x.abs() >= one {
                return Err(format!("atanh of {:.6e} outside (-1, 1)", x.to_f64()));
            }
            x.atanh()
        }
        RealFn::Floor => x.floor(),
    };
    if r.is_finite() {
        Ok(r)
    } else {
        Err(format!("{f:?} of {:.6e} is not finite", x.to_f64()))
    }
}

fn check_k<R: Real>(k: &R) -> Result<(), String> {
    if k.abs() >= k.one() || !k.is_finite() {
        return Err(format!("modulus k = {:.6e} outside |k| < 1", k.to_f64()));
    }
    Ok(())
}

/// Jacobi sn, cn, dn and am of real argument by the AGM / descending Landen scheme
/// (DLMF 22.20(ii)); generic so that duals differentiate through it.
pub fn sncndn_am_real<R: Real>(u: &R, k: &R) -> Result<([R; 3], R), String> {
    check_k(k)?;
    let one = u.one();
    if k.is_zero() {
        let (s, c) = u.sin_cos();
        return Ok(([s, c, one.clone()], u.clone()));
    }
    let eps = u.epsilon();
    let kp = (one.clone() - k.sqr()).sqrt();
    let mut a = vec![one.clone()];
    let mut c = vec![k.clone()];
    let mut b = kp;
    let mut extra = 0;
    for _ in 0..200 {
        let n = a.len() - 1;
        if c[n].abs() <= eps.clone() * a[n].abs() {
            extra += 1;
            if extra > 1 {
                break;
            }
        }
        let an = a[n].clone();
        let a1 = (an.clone() + b.clone()).mul_2si(-1);
        let c1 = (an.clone() - b.clone()).mul_2si(-1);
        b = (an * b).sqrt();
        a.push(a1);
        c.push(c1);
    }
    let n = a.len() - 1;
    let mut phi = a[n].clone() * u.clone();
    phi = phi.mul_2si(n as i32);
    let mut phi_next = phi.clone();
    for j in (1..=n).rev() {
        let t = c[j].clone() / a[j].clone() * phi.sin();
        let t = if t.abs() > one {
            one.clone() * t.from_i64(t.signum_i() as i64)
        } else {
            t
        };
        phi_next = phi.clone();
        phi = (phi.clone() + t.asin()).mul_2si(-1);
    }
    let (s, cc) = phi.sin_cos();
    let d = if n == 0 {
        (one - k.sqr() * s.sqr()).sqrt()
    } else {
        cc.clone() / (phi_next - phi.clone()).cos()
    };
    if !(s.is_finite() && cc.is_finite() && d.is_finite()) {
        return Err(format!("sn/cn/dn not finite at u = {:.6e}", u.to_f64()));
    }
    Ok(([s, cc, d], phi))
}

fn ellipk_generic<R: Real>(k: &R) -> Result<R, String> {
    check_k(k)?;
    let one = k.one();
    let mut a = one.clone();
    let mut b = (one - k.sqr()).sqrt();
    let eps = k.epsilon();
    for _ in 0..200 {
        if (a.clone() - b.clone()).abs() <= eps.clone() * a.clone() {
            let a1 = (a.clone() + b.clone()).mul_2si(-1);
            return Ok(k.pi() / a1.mul_2si(1));
        }
        let a1 = (a.clone() + b.clone()).mul_2si(-1);
        b = (a * b).sqrt();
        a = a1;
    }
    Err("AGM for K(k) did not converge".into())
}

fn ellipf_generic<R: Real>(phi: &R, k: &R) -> Result<R, String> {
    check_k(k)?;
    // Newton on am(u) = phi; d am/du = dn >= sqrt(1-k^2) > 0.
    let mut u = phi.clone();
    let eps = phi.epsilon();
    for _ in 0..200 {
        let ([_, _, d], am) = sncndn_am_real(&u, k)?;
        let du = (am - phi.clone()) / d;
        u = u - du.clone();
        if du.abs() <= eps.clone() * (u.abs() + u.one()) {
            // one more step for the derivative part of duals
            let ([_, _, d], am) = sncndn_am_real(&u, k)?;
            return Ok(u.clone() - (am - phi.clone()) / d);
        }
    }
    Err(format!(
        "F(phi, k): Newton did not converge at phi = {:.6e}",
        phi.to_f64()
    ))
}

/// Complex sn, cn, dn by the Jacobi imaginary transformation and the addition theorem
/// (Abramowitz–Stegun 16.21.1–3).
fn sncndn_complex_generic<R: Real>(u: &Cx<R>, k: &R) -> Result<[Cx<R>; 3], String> {
    check_k(k)?;
    let ([s, c, d], _) = sncndn_am_real(&u.re, k)?;
    let kp = (k.one() - k.sqr()).sqrt();
    let ([s1, c1, d1], _) = sncndn_am_real(&u.im, &kp)?;
    let k2 = k.sqr();
    let den = c1.sqr() + k2.clone() * s.sqr() * s1.sqr();
    if den.is_zero() {
        return Err("pole of sn/cn/dn".into());
    }
    let sn = Cx {
        re: s.clone() * d1.clone() / den.clone(),
        im: c.clone() * d.clone() * s1.clone() * c1.clone() / den.clone(),
    };
    let cn = Cx {
        re: c.clone() * c1.clone() / den.clone(),
        im: -(s.clone() * d.clone() * s1.clone() * d1.clone()) / den.clone(),
    };
    let dn = Cx {
        re: d * c1 * d1 / den.clone(),
        im: -(k2 * s * c * s1) / den,
    };
    Ok([sn, cn, dn])
}

trait Log2Abs {
    fn log2_abs_impl(&self) -> f64;
}
impl Log2Abs for f64 {
    fn log2_abs_impl(&self) -> f64 {
        f64::abs(*self).log2()
    }
}
impl Log2Abs for Float {
    fn log2_abs_impl(&self) -> f64 {
        if Float::is_zero(self) {
            return f64::NEG_INFINITY;
        }
        let (m, e) = self.to_f64_exp();
        m.abs().log2() + f64::from(e)
    }
}
impl<S: Log2Abs> Log2Abs for Dual<S> {
    fn log2_abs_impl(&self) -> f64 {
        self.v.log2_abs_impl()
    }
}
fn log2_abs_of<S: Log2Abs>(x: &S) -> f64 {
    x.log2_abs_impl()
}

macro_rules! real_backend {
    ($t:ty, $call:ident, $deriv:ident) => {
        impl Num for $t {
            const EXACT: bool = false;
            fn real_fn(&self, f: RealFn) -> Result<Self, String> {
                real_fn_generic(self, f)
            }
            fn atan2_(&self, x: &Self) -> Result<Self, String> {
                Ok(Real::atan2(self, x))
            }
            fn pi_(&self) -> Result<Self, String> {
                Ok(Real::pi(self))
            }
            fn powf_(&self, y: &Self) -> Result<Self, String> {
                if *self <= self.zero() {
                    return Err(format!(
                        "real power of non-positive base {:.6e}",
                        Real::to_f64(self)
                    ));
                }
                Ok(Real::powf(self, y))
            }
            fn to_f64_(&self) -> f64 {
                Real::to_f64(self)
            }
            fn finite(&self) -> bool {
                Real::is_finite(self)
            }
            fn log2_abs(&self) -> f64 {
                log2_abs_of(self)
            }
            fn sncndn(u: &Self, k: &Self) -> Result<[Self; 3], String> {
                sncndn_am_real(u, k).map(|r| r.0)
            }
            fn sncndn_c(u: &Cx<Self>, k: &Self) -> Result<[Cx<Self>; 3], String> {
                sncndn_complex_generic(u, k)
            }
            fn am(u: &Self, k: &Self) -> Result<Self, String> {
                sncndn_am_real(u, k).map(|r| r.1)
            }
            fn ellipk(k: &Self) -> Result<Self, String> {
                ellipk_generic(k)
            }
            fn ellipf(phi: &Self, k: &Self) -> Result<Self, String> {
                ellipf_generic(phi, k)
            }
            fn ext_call(f: &dyn ExtFunction, args: &[Value<Self>]) -> Result<Value<Self>, String> {
                f.$call(args)
            }
            real_backend!(@derive $deriv);
        }
    };
    (@derive yes) => {
        fn derive_in(
            ev: &Evaluator<'_, Self>,
            body: &Expr,
            var: &str,
            comp: Option<i64>,
        ) -> Result<Value<Self>, EvalError> {
            derive_with(ev, body, var, comp)
        }
    };
    (@derive no) => {};
}

real_backend!(f64, call_f64, yes);
real_backend!(Float, call_mpfr, yes);
real_backend!(Dual<f64>, call_dual_f64, no);
real_backend!(Dual<Float>, call_dual_mpfr, no);

fn not_exact<T>(what: &str) -> Result<T, String> {
    Err(format!(
        "{what} is not available in exact rational arithmetic"
    ))
}

impl Num for Rational {
    const EXACT: bool = true;
    fn real_fn(&self, f: RealFn) -> Result<Self, String> {
        match f {
            RealFn::Sqrt => self.try_sqrt().map_err(|e| e.to_string()),
            RealFn::Abs => Ok(Signed::abs(self)),
            RealFn::Floor => Ok(self.floor()),
            _ => not_exact(&format!("{f:?}")),
        }
    }
    fn atan2_(&self, _x: &Self) -> Result<Self, String> {
        not_exact("atan2")
    }
    fn pi_(&self) -> Result<Self, String> {
        not_exact("pi")
    }
    fn powf_(&self, _y: &Self) -> Result<Self, String> {
        not_exact("a non-integer power")
    }
    fn to_f64_(&self) -> f64 {
        self.to_f64().unwrap_or(f64::NAN)
    }
    fn finite(&self) -> bool {
        true
    }
    fn log2_abs(&self) -> f64 {
        if num_traits::Zero::is_zero(self) {
            return f64::NEG_INFINITY;
        }
        let n = self.numer().abs();
        let d = self.denom().abs();
        let shift = |x: &num_bigint::BigInt| -> (f64, i64) {
            let b = x.bits() as i64;
            let s = (b - 60).max(0);
            let top: num_bigint::BigInt = x >> (s as usize);
            (top.to_f64().unwrap_or(1.0), s)
        };
        let (nf, ns) = shift(&n);
        let (df, ds) = shift(&d);
        nf.log2() - df.log2() + (ns - ds) as f64
    }
    fn sncndn(_u: &Self, _k: &Self) -> Result<[Self; 3], String> {
        not_exact("sn/cn/dn")
    }
    fn sncndn_c(_u: &Cx<Self>, _k: &Self) -> Result<[Cx<Self>; 3], String> {
        not_exact("sn/cn/dn")
    }
    fn am(_u: &Self, _k: &Self) -> Result<Self, String> {
        not_exact("am")
    }
    fn ellipk(_k: &Self) -> Result<Self, String> {
        not_exact("K")
    }
    fn ellipf(_p: &Self, _k: &Self) -> Result<Self, String> {
        not_exact("F")
    }
    fn ext_call(f: &dyn ExtFunction, args: &[Value<Self>]) -> Result<Value<Self>, String> {
        f.call_exact(args)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn agm_matches_identities() {
        for &(u, k) in &[(0.3, 0.5), (1.7, 0.9), (-2.5, 0.1), (4.0, 0.99)] {
            let ([s, c, d], _) = sncndn_am_real(&u, &k).unwrap();
            assert!((s * s + c * c - 1.0).abs() < 1e-14);
            assert!((k * k * s * s + d * d - 1.0).abs() < 1e-14);
            // d sn/du = cn dn by duals
            let ([sd, _, _], _) = sncndn_am_real(&Dual::var(u), &Dual::constant(k)).unwrap();
            assert!((sd.d - c * d).abs() < 1e-12, "{u} {k}");
        }
        // K(0) = pi/2
        assert!((ellipk_generic(&0.0f64).unwrap() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        // sn(K) = 1
        let kk = ellipk_generic(&0.7f64).unwrap();
        let ([s, _, _], _) = sncndn_am_real(&kk, &0.7).unwrap();
        assert!((s - 1.0).abs() < 1e-14);
        let f = ellipf_generic(&1.2f64, &0.6).unwrap();
        let (_, am) = sncndn_am_real(&f, &0.6).unwrap();
        assert!((am - 1.2).abs() < 1e-14);
    }
}
