//! The scalar backends of the evaluator: one trait, [`Num`], implemented for `f64`,
//! [`rug::Float`] (any precision), [`Dual<f64>`], [`Dual<rug::Float>`] (derivatives) and
//! [`Rational`] (exact).  Transcendental operations on rationals are errors (the claim is
//! then not rational and cannot be proved exactly); nothing is approximated silently.

use super::ast::Expr;
use super::eval::{derive_with, EvalError, Evaluator};
use super::registry::ExtFunction;
use super::value::{Cx, Value};
use crate::numbers::{Cplx, Dual, Rational, Real, Scalar};
use crate::special;
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
        // integers (the common case) exactly, without a string conversion
        if s.len() <= 15 && s.bytes().all(|b| b.is_ascii_digit()) {
            if let Ok(n) = s.parse::<i64>() {
                return Ok(self.from_i64(n));
            }
        }
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
    /// Complementary complete integral K'(k) = K(√(1−k²)).
    fn ellipkp(k: &Self) -> Result<Self, String>;
    /// The real u in (−2K, 2K] with the given sn, cn, dn.
    fn jacobi_inverse(s: &Self, c: &Self, d: &Self, k: &Self) -> Result<Self, String>;
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
                special::sncndn(u, k)
                    .map(|(s, c, d)| [s, c, d])
                    .map_err(|e| e.to_string())
            }
            fn sncndn_c(u: &Cx<Self>, k: &Self) -> Result<[Cx<Self>; 3], String> {
                let z = Cplx::new(u.re.clone(), u.im.clone());
                let (s, c, d) = special::sncndn_complex(&z, k).map_err(|e| e.to_string())?;
                let back = |w: Cplx<Self>| Cx { re: w.re, im: w.im };
                Ok([back(s), back(c), back(d)])
            }
            fn am(u: &Self, k: &Self) -> Result<Self, String> {
                special::am(u, k).map_err(|e| e.to_string())
            }
            fn ellipk(k: &Self) -> Result<Self, String> {
                special::ellipk(k).map_err(|e| e.to_string())
            }
            fn ellipkp(k: &Self) -> Result<Self, String> {
                special::ellipkp(k).map_err(|e| e.to_string())
            }
            fn ellipf(phi: &Self, k: &Self) -> Result<Self, String> {
                special::ellipf(phi, k).map_err(|e| e.to_string())
            }
            fn jacobi_inverse(s: &Self, c: &Self, d: &Self, k: &Self) -> Result<Self, String> {
                special::jacobi_inverse(s, c, d, k).map_err(|e| e.to_string())
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
    fn ellipkp(_k: &Self) -> Result<Self, String> {
        not_exact("Kp")
    }
    fn jacobi_inverse(_s: &Self, _c: &Self, _d: &Self, _k: &Self) -> Result<Self, String> {
        not_exact("jacobi_inverse")
    }
    fn ext_call(f: &dyn ExtFunction, args: &[Value<Self>]) -> Result<Value<Self>, String> {
        f.call_exact(args)
    }
}
