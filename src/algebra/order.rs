//! Signs and comparisons decided from the shadows.
//!
//! A sign is *exact* when the value is an exact rational (or exactly zero), and *proved*
//! when the ring's parametrization of the domain proves it (module
//! [`super::positivity`]); otherwise it is decided from the shadows when every domain point gives the same sign, and the
//! decision is recorded as an assumption of the proof (with its origin: a definition
//! or the claim's own text).  Points that disagree, a value that vanishes at a point,
//! or a value that is not real give [`AlgebraError::CannotDecide`].

use super::error::{AlgResult, AlgebraError};
use super::sym::Sym;
use std::cmp::Ordering;

impl Sym {
    /// The sign (−1, 0, +1) of a real value on the domain.
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// let ring = Ring::new(RingOptions { points: 2, ..Default::default() });
    /// let a = ring.indeterminate_f64("a", &[2.0, 3.0]).unwrap();
    /// let c = ring.indeterminate_f64("c", &[1.0, 0.5]).unwrap();
    /// assert_eq!((a - c).sign().unwrap(), 1);
    /// assert_eq!(ring.assumptions().len(), 1); // "a - c > 0" rests on the domain
    /// ```
    pub fn sign(&self) -> AlgResult<i32> {
        if self.is_exact_zero() {
            return Ok(0);
        }
        if let Some(q) = self.as_rational() {
            return Ok(if q < 0 { -1 } else { 1 });
        }
        let ring = &self.ring;
        if ring.options().strict_signs {
            return self.proved_sign().ok_or_else(|| self.unproved_sign());
        }
        if let Some(s) = (self.proved_sign())
            .or_else(|| self.hypothesis_sign())
            .or_else(|| self.defined_sign())
        {
            return Ok(s);
        }
        let prec = ring.precision();
        let what = self.render_short(160);
        // the carried error scales may be too pessimistic to decide: then the value is
        // evaluated afresh from its normal form, with the error scale of its terms
        let undecided = (0..ring.points()).any(|p| self.val.sh.real_sign(p, prec).is_none());
        let sh = if undecided {
            ring.reevaluated(&self.val)
        } else {
            self.val.sh.clone()
        };
        let mut sign = 0;
        for p in 0..ring.points() {
            let s = sh.real_sign(p, prec).ok_or_else(|| {
                AlgebraError::CannotDecide(format!(
                    "the sign of {what}: zero or not real at a domain point"
                ))
            })?;
            if sign != 0 && s != sign {
                ring.note_undecided(self);
                return Err(AlgebraError::CannotDecide(format!(
                    "the sign of {what}: it differs between domain points"
                )));
            }
            sign = s;
        }
        let rel = if sign > 0 { ">" } else { "<" };
        ring.record_assumption(format!("{what} {rel} 0"), sign);
        Ok(sign)
    }

    /// The sign of a real value as a value: the constant −1 or 1 where one sign holds on
    /// the whole domain, and otherwise `±σ`, a product of the ring's sign symbols, where
    /// the value's sign at every point is that product's there.  The sign of `x·σ`
    /// (constant on the domain, since `σ² = 1`) is then decided as [`Sym::sign`] decides
    /// one, proved or recorded as an assumption; the value is `sign(x·σ)·σ`.
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// let ring = Ring::new(RingOptions { points: 2, ..Default::default() });
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

    /// Decides that a value whose normal form is not 0 is nonzero on the domain: it must
    /// be clearly nonzero at every domain point, and the decision is recorded as an
    /// assumption (`x - 1 ≠ 0`).  A normal form that is not 0 alone proves nothing: an
    /// indeterminate drawn from the integers 1..3 is 1 at some points.
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// let ring = Ring::new(RingOptions { points: 2, ..Default::default() });
    /// let a = ring.indeterminate_f64("a", &[2.0, 3.0]).unwrap();
    /// assert!(a.nonzero_on_domain().is_ok());
    /// assert!((a - ring.integer(3)).nonzero_on_domain().is_err()); // a = 3 at a point
    /// ```
    pub fn nonzero_on_domain(&self) -> AlgResult<()> {
        if let Some(q) = self.as_rational() {
            return if q == 0 {
                Err(AlgebraError::CannotDecide("a value is exactly 0".into()))
            } else {
                Ok(())
            };
        }
        let ring = &self.ring;
        if ring.options().strict_signs {
            return self
                .proved_sign()
                .map(|_| ())
                .ok_or_else(|| self.unproved_sign());
        }
        if self.proved_sign().is_some() {
            return Ok(());
        }
        let prec = ring.precision();
        let sh = ring.reevaluated(&self.val);
        if let Some(p) = (0..ring.points()).find(|&p| sh.is_small(p, prec)) {
            return Err(AlgebraError::CannotDecide(format!(
                "whether {} is 0: it vanishes at domain point {}",
                self.render_short(160),
                p + 1
            )));
        }
        ring.record_assumption(format!("{} ≠ 0", self.render_short(160)), 0);
        Ok(())
    }

    /// Why a sign is not decided where signs must be proved.
    fn unproved_sign(&self) -> AlgebraError {
        AlgebraError::CannotDecide(format!(
            "the sign of {} is not proved on the domain (the claim states a condition, so its signs are proved, never taken at domain points)",
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
