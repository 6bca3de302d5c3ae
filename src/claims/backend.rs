//! The scalar backends of the evaluator: one trait, [`Num`], for every number system the
//! language computes in.
//!
//! [`Num`] is purely scalar: the field operations and the order come from
//! [`Scalar`] + `PartialOrd`, and the trait adds the language's functions of scalars
//! (elementary, elliptic) as fallible operations.  Every real type ([`Real`]: `f64`,
//! [`rug::Float`] at any precision, [`Dual`](crate::numbers::Dual) over either) is a
//! backend through one blanket implementation; exact rationals ([`Rational`]) implement
//! only what is exact and leave the rest to the defaults, which fail with a message
//! naming the function ("ln is not available in exact rational arithmetic").  Nothing is
//! approximated silently.
//!
//! A backend without transcendental functions (a symbolic one, say) does the same as
//! [`Rational`]: implement [`Num`] with [`Num::real_fn`] for what it can do and keep the
//! defaults for the rest.  How a backend calls registered functions and differentiates
//! are separate traits ([`crate::claims::registry::HostCall`],
//! [`crate::claims::eval::Differentiate`]).

use crate::numbers::{Cplx, Rational, Real, Scalar};
use crate::special;
use num_traits::Signed;

/// Elementary real functions of one argument.
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

/// Real functions of two arguments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RealFn2 {
    /// `atan2(y, x)`, the four-quadrant arc tangent.
    Atan2,
    /// `x^y` for a real, not necessarily integer, `y` (x > 0).
    Pow,
}

impl RealFn2 {
    /// How the function is named in "not available" messages.
    fn what(self) -> &'static str {
        match self {
            RealFn2::Atan2 => "atan2",
            RealFn2::Pow => "a non-integer power",
        }
    }
}

/// Named constants.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Constant {
    /// π.
    Pi,
}

/// A scalar type the evaluator can compute with.
///
/// Every method but [`Num::real_fn`] has a default that fails with
/// "`what` is not available in [`Num::ARITHMETIC`]", so a backend states only what it can
/// compute.
pub trait Num: Scalar + PartialOrd {
    /// Is this an exact backend (no rounding: a zero is a proof)?
    const EXACT: bool;
    /// The arithmetic, for messages: "exact rational arithmetic".
    const ARITHMETIC: &'static str;
    /// Converts a literal as written (`0.1` is exactly 1/10 for rationals, correctly
    /// rounded at the working precision otherwise).
    fn lit(&self, s: &str) -> Result<Self, String> {
        // integers (the common case) exactly, without a string conversion
        if s.len() <= 15
            && s.bytes().all(|b| b.is_ascii_digit())
            && let Ok(n) = s.parse::<i64>()
        {
            return Ok(self.from_i64(n));
        }
        let v = self.parse_like(s);
        // a literal is never silently 0: one that underflows is an error, as in jacobi
        if let Ok(x) = &v
            && x.is_zero()
            && crate::numbers::is_decimal(s)
            && crate::numbers::nonzero_mantissa(s)
        {
            let bits = self
                .precision()
                .map_or("exact".to_string(), |b| format!("{b} bits"));
            return Err(format!("the number {s} underflows to 0 at {bits}"));
        }
        v.map_err(|e| {
            // a well-formed decimal fails only by its size
            if crate::numbers::is_decimal(s) {
                let bits = self
                    .precision()
                    .map_or("exact".to_string(), |b| format!("{b} bits"));
                format!("the number {s} is out of range (it overflows at {bits})")
            } else {
                e.to_string()
            }
        })
    }
    /// An elementary function of one argument.
    fn real_fn(&self, f: RealFn) -> Result<Self, String>;
    /// Is every value an enclosure ([`Real::ENCLOSES`])?
    const ENCLOSES: bool = false;
    /// The value as a ball ([`Real::as_ball`]).
    fn as_ball(&self) -> Option<&crate::numbers::Ball> {
        None
    }
    /// A ball as a value of this type ([`Real::from_ball`]).
    fn from_ball(_x: crate::numbers::Ball) -> Option<Self> {
        None
    }
    /// Why a value is meaningless, when the number system records failures inside
    /// operators (see [`Real::failure`]).
    fn failure(&self) -> Option<String> {
        None
    }
    /// A real function of two arguments: `f(self, y)`.
    fn real_fn2(&self, f: RealFn2, _y: &Self) -> Result<Self, String> {
        unavailable::<Self, _>(f.what())
    }
    /// A named constant at the precision of `self`.
    fn constant(&self, c: Constant) -> Result<Self, String> {
        match c {
            Constant::Pi => unavailable::<Self, _>("pi"),
        }
    }
    /// `[sn, cn, dn]` of real `u`, modulus `k`.
    fn sncndn(_u: &Self, _k: &Self) -> Result<[Self; 3], String> {
        unavailable::<Self, _>("sn/cn/dn")
    }
    /// `[sn, cn, dn]` of complex `u`, real modulus `k`.
    fn sncndn_complex(_u: &Cplx<Self>, _k: &Self) -> Result<[Cplx<Self>; 3], String> {
        unavailable::<Self, _>("sn/cn/dn")
    }
    /// `[sn, cn, dn]` of complex `u` and a complex modulus `k`.
    fn sncndn_complex_modulus(_u: &Cplx<Self>, _k: &Cplx<Self>) -> Result<[Cplx<Self>; 3], String> {
        unavailable::<Self, _>("sn/cn/dn of a complex modulus")
    }
    /// Amplitude am(u, k).
    fn am(_u: &Self, _k: &Self) -> Result<Self, String> {
        unavailable::<Self, _>("am")
    }
    /// Complete elliptic integral K(k).
    fn ellipk(_k: &Self) -> Result<Self, String> {
        unavailable::<Self, _>("K")
    }
    /// Incomplete elliptic integral F(φ, k).
    fn ellipf(_phi: &Self, _k: &Self) -> Result<Self, String> {
        unavailable::<Self, _>("F")
    }
    /// Complementary complete integral K'(k) = K(√(1−k²)).
    fn ellipkp(_k: &Self) -> Result<Self, String> {
        unavailable::<Self, _>("Kp")
    }
    /// The real u in (−2K, 2K] with the given sn, cn, dn.
    fn jacobi_inverse(_s: &Self, _c: &Self, _d: &Self, _k: &Self) -> Result<Self, String> {
        unavailable::<Self, _>("jacobi_inverse")
    }
    /// A function of the elliptic toolkit (E, Π, Z, Λ₀, the nome, θ_j) at `args`.
    fn toolkit(f: special::ToolkitFn, _args: &[Self]) -> Result<Self, String> {
        unavailable::<Self, _>(f.name())
    }
}

/// The error of a function the backend `T` cannot compute.
pub fn unavailable<T: Num, X>(what: &str) -> Result<X, String> {
    Err(format!("{what} is not available in {}", T::ARITHMETIC))
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
            if !R::DEFERS_DOMAIN_CHECKS && *x <= z {
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
    } else if let Some(why) = Real::failure(&r) {
        Err(format!("{f:?}: {why}"))
    } else if r.to_f64().is_finite() {
        // a dual number: the value is finite, its derivative is not (√x at 0)
        let name = format!("{f:?}").to_lowercase();
        Err(format!(
            "the derivative of {name} at {:.6e} is not finite",
            x.to_f64()
        ))
    } else {
        Err(format!("{f:?} of {:.6e} is not finite", x.to_f64()))
    }
}

/// The real types of the evaluator, which compute every function of the language
/// through [`Real`]: `f64`, MPFR, balls, dual numbers over them, the prover's symbols
/// and power series.  (A marker rather than every [`Real`], so that [`Rational`], which
/// is not one, may have an implementation of [`Num`] of its own: the real types are
/// defined in `eulertop-numerics`, and only this crate's own trait tells the compiler
/// that the two implementations do not overlap.)
pub trait RealNum: Real {}

impl RealNum for f64 {}
impl RealNum for rug::Float {}
impl RealNum for crate::numbers::Ball {}
impl<R: Real> RealNum for crate::numbers::Dual<R> {}
impl RealNum for crate::algebra::Sym {}
impl RealNum for crate::algebra::series::Series {}

/// Every real type computes every function of the language.
impl<R: RealNum> Num for R {
    const EXACT: bool = false;
    const ARITHMETIC: &'static str = "floating-point arithmetic";
    const ENCLOSES: bool = <R as Real>::ENCLOSES;
    fn as_ball(&self) -> Option<&crate::numbers::Ball> {
        Real::as_ball(self)
    }
    fn from_ball(x: crate::numbers::Ball) -> Option<Self> {
        <R as Real>::from_ball(x)
    }
    fn failure(&self) -> Option<String> {
        Real::failure(self)
    }
    fn real_fn(&self, f: RealFn) -> Result<Self, String> {
        real_fn_generic(self, f)
    }
    fn real_fn2(&self, f: RealFn2, y: &Self) -> Result<Self, String> {
        match f {
            RealFn2::Atan2 => Ok(Real::atan2(self, y)),
            RealFn2::Pow => {
                if *self <= self.zero() {
                    return Err(format!(
                        "real power of non-positive base {:.6e}",
                        self.to_f64()
                    ));
                }
                Ok(Real::powf(self, y))
            }
        }
    }
    fn constant(&self, c: Constant) -> Result<Self, String> {
        match c {
            Constant::Pi => Ok(Real::pi(self)),
        }
    }
    fn sncndn(u: &Self, k: &Self) -> Result<[Self; 3], String> {
        special::sncndn(u, k)
            .map(|(s, c, d)| [s, c, d])
            .map_err(|e| e.to_string())
    }
    fn sncndn_complex(u: &Cplx<Self>, k: &Self) -> Result<[Cplx<Self>; 3], String> {
        special::sncndn_complex(u, k)
            .map(|(s, c, d)| [s, c, d])
            .map_err(|e| e.to_string())
    }
    fn sncndn_complex_modulus(u: &Cplx<Self>, k: &Cplx<Self>) -> Result<[Cplx<Self>; 3], String> {
        special::sncndn_complex_modulus(u, k)
            .map(|(s, c, d)| [s, c, d])
            .map_err(|e| e.to_string())
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
    fn toolkit(f: special::ToolkitFn, args: &[Self]) -> Result<Self, String> {
        f.eval(args).map_err(|e| e.to_string())
    }
}

/// Exact rationals: `sqrt` of perfect squares, `abs` and `floor`; everything else is
/// "not available in exact rational arithmetic".
impl Num for Rational {
    const EXACT: bool = true;
    const ARITHMETIC: &'static str = "exact rational arithmetic";
    fn real_fn(&self, f: RealFn) -> Result<Self, String> {
        match f {
            RealFn::Sqrt => self.try_sqrt().map_err(|e| e.to_string()),
            RealFn::Abs => Ok(Signed::abs(self)),
            RealFn::Floor => Ok(self.floor()),
            _ => unavailable::<Self, _>(&format!("{f:?}")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rationals_refuse_what_is_not_exact() {
        let q = Rational::from_integer(4.into());
        assert_eq!(
            q.real_fn(RealFn::Sqrt),
            Ok(Rational::from_integer(2.into()))
        );
        assert_eq!(
            q.real_fn(RealFn::Exp).unwrap_err(),
            "Exp is not available in exact rational arithmetic"
        );
        assert!(q.constant(Constant::Pi).is_err());
        assert!(
            Rational::ellipk(&q)
                .unwrap_err()
                .starts_with("K is not available")
        );
    }

    #[test]
    fn reals_compute_and_check_domains() {
        assert_eq!(4.0f64.real_fn(RealFn::Sqrt), Ok(2.0));
        assert!((-1.0f64).real_fn(RealFn::Ln).is_err());
        assert!((-1.0f64).real_fn2(RealFn2::Pow, &0.5).is_err());
        assert_eq!(1.0f64.constant(Constant::Pi), Ok(std::f64::consts::PI));
    }
}
