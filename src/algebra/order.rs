//! Signs and comparisons of real values, as the proof decides them (module
//! [`super::decide`]): exact, proved on the domain, by a hypothesis or by a definition,
//! and otherwise not at all.  An undecided sign is an [`AlgebraError::CannotDecide`]
//! (and the ring remembers it, so that the domain may be split by it); the values at
//! the domain points never decide a sign.

use super::error::{AlgResult, AlgebraError};
use super::sym::Sym;
use std::cmp::Ordering;

impl Sym {
    /// The sign (−1, 0, +1) of a real value on the domain.
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// use eulertop::algebra::positivity::Parametrization;
    /// use std::sync::Arc;
    /// // the domain: a and c nonzero, of either sign
    /// let mut par = Parametrization::new();
    /// for v in ["a", "c"] {
    ///     let t = par.nonzero(&format!("t_{v}")).unwrap();
    ///     par.bind(v, t, String::new());
    /// }
    /// let ring = Ring::new(RingOptions { points: 2, positivity: Some(Arc::new(par)), ..Default::default() });
    /// let a = ring.indeterminate_f64("a", &[2.0, 3.0]).unwrap();
    /// let c = ring.indeterminate_f64("c", &[1.0, 0.5]).unwrap();
    /// assert_eq!((a.clone() * a.clone() + ring.integer(1)).sign().unwrap(), 1); // proved
    /// assert!((a - c).sign().is_err()); // positive at both points, but not proved
    /// ```
    pub fn sign(&self) -> AlgResult<i32> {
        match self.decided_sign() {
            Some(s) => Ok(s),
            None => {
                self.ring.note_undecided(self);
                Err(self.unproved_sign())
            }
        }
    }

    /// The sign of a real value as a value: the constant −1 or 1 where one sign holds on
    /// the whole domain, and otherwise `±σ`, a product of the ring's sign symbols, where
    /// the value's sign at every point is that product's there.  The sign of `x·σ`
    /// (constant on the domain, since `σ² = 1`) is then decided as [`Sym::sign`] decides
    /// one (proved, never taken at the points); the value is `sign(x·σ)·σ`.
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// use eulertop::algebra::positivity::Parametrization;
    /// use std::sync::Arc;
    /// // the domain: x > 0
    /// let mut par = Parametrization::new();
    /// for v in ["x"] {
    ///     let t = par.positive(&format!("t_{v}")).unwrap();
    ///     par.bind(v, t, String::new());
    /// }
    /// let ring = Ring::new(RingOptions { points: 2, positivity: Some(Arc::new(par)), ..Default::default() });
    /// let s = ring.sign_symbol_f64("s", &[1.0, -1.0]).unwrap();
    /// let x = ring.indeterminate_f64("x", &[0.5, 2.0]).unwrap();
    /// let v = (s.clone() * x.clone()).sign_value().unwrap();
    /// assert!(ring.prove(&v, &s).is_proved());
    /// assert!(ring.prove(&x.sign_value().unwrap(), &ring.integer(1)).is_proved());
    /// ```
    pub fn sign_value(&self) -> AlgResult<Sym> {
        let ring = &self.ring;
        if let Some(sigma) = self.folded_sign()? {
            return Ok(sigma);
        }
        let varying = !self.is_exact_zero() && self.as_rational().is_none();
        // products of sign symbols, fewest factors first
        let products = ring.sign_products()?;
        let own = (varying && !products.is_empty())
            .then(|| self.point_signs())
            .flatten()
            .filter(|own| own.windows(2).any(|w| w[0] != w[1]));
        if let Some(own) = own {
            for prod in products {
                let Some(pp) = prod.point_signs() else {
                    continue;
                };
                let ratio: Vec<i32> = own.iter().zip(&pp).map(|(a, b)| a * b).collect();
                if ratio.windows(2).all(|w| w[0] == w[1]) {
                    let s = self.try_mul(&prod)?.sign()?;
                    return prod.try_mul(&ring.integer(i64::from(s)));
                }
            }
        }
        Ok(ring.integer(i64::from(self.sign()?)))
    }

    /// The sign of the value at each domain point, from its shadow (evaluated afresh
    /// from its normal form where the shadow's error bound cannot tell); `None` where a
    /// point cannot tell.
    pub(crate) fn point_signs(&self) -> Option<Vec<i32>> {
        let ring = &self.ring;
        let prec = ring.precision();
        let at = |sh: &super::shadow::Shadow| {
            (0..ring.points())
                .map(|p| sh.real_sign(p, prec))
                .collect::<Option<Vec<i32>>>()
        };
        at(&self.val.sh).or_else(|| at(&ring.reevaluated(&self.val)))
    }

    /// Decides that a value is nonzero on the domain: its sign must be decided (see
    /// [`Sym::sign`]).  A normal form that is not 0 alone proves nothing: an
    /// indeterminate drawn from the integers 1..3 is 1 at some points.
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// use eulertop::algebra::positivity::Parametrization;
    /// use std::sync::Arc;
    /// // the domain: a nonzero, of either sign
    /// let mut par = Parametrization::new();
    /// for v in ["a"] {
    ///     let t = par.nonzero(&format!("t_{v}")).unwrap();
    ///     par.bind(v, t, String::new());
    /// }
    /// let ring = Ring::new(RingOptions { points: 2, positivity: Some(Arc::new(par)), ..Default::default() });
    /// let a = ring.indeterminate_f64("a", &[2.0, 3.0]).unwrap();
    /// assert!((a.clone() * a.clone() + ring.integer(1)).nonzero_on_domain().is_ok());
    /// assert!((a - ring.integer(3)).nonzero_on_domain().is_err()); // not proved
    /// ```
    pub fn nonzero_on_domain(&self) -> AlgResult<()> {
        match self.decided_sign() {
            Some(0) => Err(AlgebraError::CannotDecide("a value is exactly 0".into())),
            Some(_) => Ok(()),
            // no split: the parts x > 0 and x < 0 would leave out x = 0, the very set
            // an equality test is about
            None => Err(AlgebraError::CannotDecide(format!(
                "whether {} is 0 on the domain: its sign is not proved",
                self.render_short(160)
            ))),
        }
    }

    /// Why a sign is not decided: it is neither proved nor given by a hypothesis.
    fn unproved_sign(&self) -> AlgebraError {
        AlgebraError::CannotDecide(format!(
            "the sign of {} is not proved on the domain, and no hypothesis gives it",
            self.render_short(160)
        ))
    }

    /// Compares two real values on the domain (see [`Sym::sign`]).
    pub fn compare(&self, o: &Sym) -> AlgResult<Ordering> {
        let d = self.try_sub(o)?;
        Ok(match d.sign()? {
            s if s < 0 => Ordering::Less,
            0 => Ordering::Equal,
            _ => Ordering::Greater,
        })
    }

    /// `|self|` for a real value whose sign is decided on the domain.
    pub fn abs(&self) -> AlgResult<Sym> {
        Ok(if self.sign()? < 0 {
            self.negate()
        } else {
            self.clone()
        })
    }

    /// A function of one argument by name, for evaluators of expression languages:
    /// `sqrt`, `abs` and `sign` (as ±1) are algebraic; every other name (exp, ln, asin,
    /// am, F, …) is [`AlgebraError::NotAlgebraic`].  `sn`, `cn`, `dn` take a modulus
    /// and have their own methods.
    ///
    /// ```
    /// use eulertop::algebra::{AlgebraError, Ring, RingOptions};
    /// let ring = Ring::new(RingOptions { points: 1, ..Default::default() });
    /// let x = ring.indeterminate_f64("x", &[0.25]).unwrap();
    /// assert_eq!(x.function("sqrt").unwrap().shadow(0).real().to_f64(), 0.5);
    /// assert_eq!(x.function("asin").unwrap_err(), AlgebraError::NotAlgebraic("asin".into()));
    /// ```
    pub fn function(&self, name: &str) -> AlgResult<Sym> {
        match name {
            "sqrt" => self.sqrt(),
            "abs" => self.abs(),
            "sign" => Ok(self.ring.integer(i64::from(self.sign()?))),
            _ => Err(AlgebraError::NotAlgebraic(name.to_string())),
        }
    }
}
