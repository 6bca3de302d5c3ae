//! Operators and the numeric traits, so generic model code runs on [`Sym`].
//!
//! Operators cannot return errors: a failure (division by a zero divisor, an
//! undecidable comparison, a transcendental function) is recorded in the ring
//! ([`super::Ring::error`]) and the operation returns a meaningless value (exact 0 with
//! NaN shadows); a proof on such a ring is never reported as proved.

use super::error::{AlgResult, AlgebraError};
use super::sym::Sym;
use crate::numbers::{NumError, Real, Scalar};
use rug::{Complex, Float, Rational};
use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

macro_rules! binop {
    ($tr:ident, $m:ident, $try:ident) => {
        impl $tr for Sym {
            type Output = Sym;
            fn $m(self, o: Sym) -> Sym {
                if self.ring.is_poisoned() {
                    return self.ring.nan();
                }
                let r = self.$try(&o);
                Sym::or_poison(&self.ring, r)
            }
        }
        impl $tr<&Sym> for &Sym {
            type Output = Sym;
            fn $m(self, o: &Sym) -> Sym {
                if self.ring.is_poisoned() {
                    return self.ring.nan();
                }
                let r = self.$try(o);
                Sym::or_poison(&self.ring, r)
            }
        }
    };
}

binop!(Add, add, try_add);
binop!(Sub, sub, try_sub);
binop!(Mul, mul, try_mul);
binop!(Div, div, try_div);

impl Neg for Sym {
    type Output = Sym;
    fn neg(self) -> Sym {
        self.negate()
    }
}

impl Neg for &Sym {
    type Output = Sym;
    fn neg(self) -> Sym {
        self.negate()
    }
}

/// Equality of exact normal forms (values of different rings are never equal).  Equal
/// normal forms mean equal values; different ones prove nothing.
impl PartialEq for Sym {
    fn eq(&self, o: &Sym) -> bool {
        self.ring.same(&o.ring) && self.val.num == o.val.num && self.val.den == o.val.den
    }
}

/// Comparison decided on the domain (see [`Sym::compare`]); `None` (and an error in the
/// ring) when the domain points disagree.
impl PartialOrd for Sym {
    fn partial_cmp(&self, o: &Sym) -> Option<Ordering> {
        match self.compare(o) {
            Ok(c) => Some(c),
            Err(e) => {
                self.ring.poison(e);
                None
            }
        }
    }
}

impl Sym {
    fn not_algebraic(&self, what: &str) -> Sym {
        self.ring
            .poison(AlgebraError::NotAlgebraic(what.to_string()));
        self.ring.nan()
    }

    fn first_shadow_f64(&self) -> f64 {
        self.val
            .sh
            .v
            .first()
            .map_or(f64::NAN, |z| z.real().to_f64())
    }
}

impl Scalar for Sym {
    /// The three products summed over one common denominator and brought to lowest
    /// terms once ([`Sym::try_sum_of_products`]; a certificate records it as one `dot`
    /// step).
    fn dot3(a: [&Self; 3], b: [&Self; 3]) -> Self {
        if a[0].ring.is_poisoned() {
            return a[0].ring.nan();
        }
        let r = Sym::try_sum_of_products(&[
            (a[0], b[0], false),
            (a[1], b[1], false),
            (a[2], b[2], false),
        ]);
        Sym::or_poison(&a[0].ring, r)
    }
    /// As [`Scalar::dot3`], for `a·b − c·d`.
    fn det2(a: &Self, b: &Self, c: &Self, d: &Self) -> Self {
        if a.ring.is_poisoned() {
            return a.ring.nan();
        }
        let r = Sym::try_sum_of_products(&[(a, b, false), (c, d, true)]);
        Sym::or_poison(&a.ring, r)
    }
    fn zero(&self) -> Self {
        self.ring.integer(0)
    }
    fn one(&self) -> Self {
        self.ring.integer(1)
    }
    fn from_i64(&self, n: i64) -> Self {
        self.ring.integer(n)
    }
    fn from_f64(&self, x: f64) -> Self {
        match Rational::from_f64(x) {
            Some(q) => self.ring.rational(&q),
            None => self.not_algebraic("a non-finite number"),
        }
    }
    fn from_ratio(&self, n: i64, d: i64) -> Self {
        if d == 0 {
            self.ring.poison(AlgebraError::DivisionByZero);
            return self.ring.nan();
        }
        self.ring.rational(&Rational::from((n, d)))
    }
    fn parse_like(&self, s: &str) -> Result<Self, NumError> {
        let q = crate::numbers::parse_rational(s)?;
        let q: Rational = format!("{}/{}", q.numer(), q.denom())
            .parse()
            .map_err(|_| NumError::Parse(s.to_string()))?;
        Ok(self.ring.rational(&q))
    }
    fn precision(&self) -> Option<u32> {
        None
    }
    fn is_zero(&self) -> bool {
        self.is_exact_zero()
    }
    /// The sign symbol of a value whose sign the ring carries that way
    /// ([`crate::algebra::RingOptions::sign_folds`]).
    fn sign_symbol(&self) -> Result<Option<Self>, String> {
        self.folded_sign().map_err(|e| e.to_string())
    }
    fn stated_sign(&self) -> Result<i32, String> {
        match self.decided_sign() {
            Some(s) => Ok(s),
            None => Err({
                self.ring.note_undecided(self);
                format!(
                    "the sign of {} is neither exact nor proved on the domain: sign and abs in a claim's formulas are decided only by proof or a stated hypothesis (a sign taken at domain points would be the condition the formula states)",
                    self.render_short(80)
                )
            }),
        }
    }
    fn test_zero(&self) -> bool {
        if self.is_exact_zero() {
            return true;
        }
        if let Err(e) = self.nonzero_on_domain() {
            self.ring.poison(e);
        }
        false
    }
    fn magnitude(&self) -> f64 {
        self.val
            .sh
            .v
            .first()
            .map_or(f64::NAN, |z| Float::with_val(53, z.abs_ref()).to_f64())
    }
    fn try_sqrt(&self) -> Result<Self, NumError> {
        self.sqrt().map_err(|e| {
            self.ring.poison(e);
            NumError::NotExact("a symbolic square root (the ring records why)")
        })
    }
    fn to_f64(&self) -> f64 {
        self.first_shadow_f64()
    }
    fn is_finite(&self) -> bool {
        !self.val.sh.has_non_finite()
    }
    fn to_decimal(&self, digits: usize) -> String {
        match self.as_rational() {
            Some(q) => q.to_string(),
            None => format!(
                "{} ≈ {}",
                self.render_short(80),
                Float::with_val(64, self.val.sh.v[0].real())
                    .to_string_radix(10, Some(digits.max(1)))
            ),
        }
    }
}

impl Real for Sym {
    const FIXED: bool = false;
    const BY_RULE: bool = true;
    const DEFERS_DOMAIN_CHECKS: bool = true;
    fn failure(&self) -> Option<String> {
        self.ring.error().map(|e| e.to_string())
    }
    fn sncndn_by_rule(u: &Self, k: &Self) -> Result<(Self, Self, Self), String> {
        if u.ring.options().jets {
            return u.ring.jet_sncndn(u, k).map_err(|e| e.to_string());
        }
        u.sncndn(k).map_err(|e| e.to_string())
    }
    fn quarter_period_by_rule(k: &Self, complementary: bool) -> Result<Self, String> {
        let r = if complementary {
            k.ring.quarter_period_prime(k)
        } else {
            k.ring.quarter_period(k)
        };
        r.map_err(|e| e.to_string())
    }
    fn prec(&self) -> u32 {
        self.ring.precision()
    }
    fn with_prec(&self, _bits: u32) -> Self {
        self.clone()
    }
    fn pi(&self) -> Self {
        self.not_algebraic("pi")
    }
    fn mul_2si(&self, n: i32) -> Self {
        let mut q = Rational::from(1);
        if n >= 0 {
            q <<= n.unsigned_abs();
        } else {
            q >>= n.unsigned_abs();
        }
        self * &self.ring.rational(&q)
    }
    fn abs(&self) -> Self {
        let r = Sym::abs(self);
        Sym::or_poison(&self.ring, r)
    }
    fn sqrt(&self) -> Self {
        let r = Sym::sqrt(self);
        Sym::or_poison(&self.ring, r)
    }
    fn exp(&self) -> Self {
        self.not_algebraic("exp")
    }
    fn ln(&self) -> Self {
        // an opaque symbol, undefined (an error) where the argument is not positive;
        // its derivative is x'/x (module `derive`)
        let r = Sym::opaque_call("ln", &[self], |z| {
            let positive =
                z[0].imag().is_zero() && z[0].real().is_sign_positive() && !z[0].real().is_zero();
            positive.then(|| z[0].clone().ln())
        });
        Sym::or_poison(&self.ring, r)
    }
    fn sin(&self) -> Self {
        // sin u = sn(u, 0) (DLMF 22.5.ii: at k = 0, sn = sin, cn = cos, dn = 1)
        self.circular(|s, _| Ok(s.clone()))
    }
    fn cos(&self) -> Self {
        self.circular(|_, c| Ok(c.clone()))
    }
    fn atan(&self) -> Self {
        self.not_algebraic("atan")
    }
    fn atan2(&self, _x: &Self) -> Self {
        self.not_algebraic("atan2")
    }
    fn asin(&self) -> Self {
        let r = Sym::opaque_call("asin", &[self], |z| Some(z[0].clone().asin()));
        Sym::or_poison(&self.ring, r)
    }
    fn am_by_rule(u: &Self, k: &Self) -> Result<Self, String> {
        Sym::am_rule(u, k).map_err(|e| e.to_string())
    }
    fn ellipf_by_rule(phi: &Self, k: &Self) -> Result<Self, String> {
        Sym::ellipf_rule(phi, k).map_err(|e| e.to_string())
    }
    fn jacobi_inverse_by_rule(sn: &Self, cn: &Self, dn: &Self, k: &Self) -> Result<Self, String> {
        Sym::jacobi_inverse_rule(sn, cn, dn, k).map_err(|e| e.to_string())
    }
    fn opaque_by_rule(
        f: &str,
        args: &[&Self],
        values: &dyn Fn(&[rug::Float]) -> Option<rug::Float>,
    ) -> Result<Self, String> {
        Sym::opaque_call(f, args, |z| {
            let re: Vec<rug::Float> = z.iter().map(|c| c.real().clone()).collect();
            let prec = re.first().map_or(128, |x| x.prec());
            values(&re).map(|x| Complex::with_val(prec, (x, 0)))
        })
        .map_err(|e| e.to_string())
    }
    fn sinh(&self) -> Self {
        // sinh u = sn(u, 1)/cn(u, 1) (DLMF 22.5.ii: sn = tanh, cn = dn = sech at k = 1)
        self.hyperbolic(|s, c| s.try_div(c))
    }
    fn cosh(&self) -> Self {
        self.hyperbolic(|_, c| c.try_powi(-1))
    }
    fn tanh(&self) -> Self {
        self.hyperbolic(|s, _| Ok(s.clone()))
    }
    fn asinh(&self) -> Self {
        self.not_algebraic("asinh")
    }
    fn atanh(&self) -> Self {
        self.not_algebraic("atanh")
    }
    fn signum_value(&self) -> Self {
        Sym::or_poison(&self.ring, self.sign_value())
    }
    fn floor(&self) -> Self {
        match self.as_rational() {
            Some(q) => self.ring.rational(&Rational::from(q.floor_ref())),
            None => self.not_algebraic("floor"),
        }
    }
    fn round(&self) -> Self {
        match self.as_rational() {
            Some(q) => self.ring.rational(&Rational::from(q.round_ref())),
            None => self.not_algebraic("round"),
        }
    }
}

impl Sym {
    /// A hyperbolic function of a real argument through the elliptic functions of
    /// modulus 1 (DLMF 22.5.ii), so the addition theorems and exact derivatives apply.
    fn hyperbolic(&self, f: impl Fn(&Sym, &Sym) -> AlgResult<Sym>) -> Sym {
        let one = self.ring.integer(1);
        let r = self.sncndn(&one).and_then(|(s, c, _)| f(&s, &c));
        Sym::or_poison(&self.ring, r)
    }

    /// A circular function of a real argument from sn and cn at modulus 0.
    fn circular(&self, f: impl Fn(&Sym, &Sym) -> AlgResult<Sym>) -> Sym {
        let zero = self.ring.integer(0);
        let r = self.sncndn(&zero).and_then(|(s, c, _)| f(&s, &c));
        Sym::or_poison(&self.ring, r)
    }

    /// The value as a complex shadow at every point (for callers that print values).
    pub fn values(&self) -> Vec<Complex> {
        self.val.sh.v.clone()
    }
}
