//! The claim's symbols on a ring: independent indeterminates, opaque symbols and
//! named quantities, each a field variable with its values at the domain points; and
//! the remembered values of implicitly defined functions.

use super::error::{AlgResult, AlgebraError};
use super::ring::{Ring, VarKind};
use super::sym::Sym;
use rug::{Complex, Float, Rational};

/// Is `name` acceptable for a user symbol (letters and digits, starting with a letter)?
fn valid_name(name: &str) -> bool {
    let mut it = name.chars();
    matches!(it.next(), Some(c) if c.is_ascii_alphabetic()) && it.all(|c| c.is_ascii_alphanumeric())
}

impl Ring {
    /// An independent indeterminate with its values at the domain points.
    pub fn indeterminate(&self, name: &str, values: &[Complex]) -> AlgResult<Sym> {
        self.new_var(name, values, VarKind::Indeterminate)
    }
    /// A new field variable of the given kind, after the checks of its name and values.
    fn new_var(&self, name: &str, values: &[Complex], kind: VarKind) -> AlgResult<Sym> {
        self.check_new_name(name)?;
        self.check_values(name, values)?;
        let prec = self.precision();
        let v = values.iter().map(|z| Complex::with_val(prec, z)).collect();
        let j = self.inner.add_var(name.to_string(), kind, v)?;
        Ok(self.var_sym(j))
    }
    /// An indeterminate with real values given as `f64`.
    pub fn indeterminate_f64(&self, name: &str, values: &[f64]) -> AlgResult<Sym> {
        let prec = self.precision();
        let v: Vec<Complex> = values
            .iter()
            .map(|&x| Complex::with_val(prec, (x, 0)))
            .collect();
        self.indeterminate(name, &v)
    }
    /// An indeterminate with exact rational values (written `3/2`, `-7`, …).
    pub fn indeterminate_rational(&self, name: &str, values: &[&str]) -> AlgResult<Sym> {
        let prec = self.precision();
        let mut v = Vec::with_capacity(values.len());
        for s in values {
            let q: Rational = s.parse().map_err(|_| {
                AlgebraError::Domain(format!("malformed rational '{s}' for {name}"))
            })?;
            v.push(Complex::with_val(prec, (Float::with_val(prec, &q), 0)));
        }
        self.indeterminate(name, &v)
    }
    /// A sign symbol `σ` with the relation `σ² = 1` and its values (each ±1) at the
    /// domain points.  The ring is then the product of its two specialisations σ = 1
    /// and σ = −1: a value is invertible only where both specialisations are (the
    /// norm `p₀² − p₁²` of `p₀ + p₁σ` is their product, and a zero norm is reported as
    /// a zero divisor), so a normal form 0 proves an identity for both signs at once.
    ///
    /// ```
    /// use eulertop::algebra::{Ring, RingOptions};
    /// let ring = Ring::new(RingOptions { points: 2, ..Default::default() });
    /// let s = ring.sign_symbol_f64("s", &[1.0, -1.0]).unwrap();
    /// let x = ring.indeterminate_f64("x", &[0.5, 2.0]).unwrap();
    /// // (s·x)² = x² for either sign
    /// let lhs = (s.clone() * x.clone()) * (s.clone() * x.clone());
    /// assert!(ring.prove(&lhs, &(x.clone() * x.clone())).is_proved());
    /// // but s·x = x only for s = 1
    /// assert!(!ring.prove(&(s.clone() * x.clone()), &x).is_proved());
    /// // and 1 + s has no inverse
    /// assert!(ring.integer(1).try_div(&(ring.integer(1) + s)).is_err());
    /// ```
    pub fn sign_symbol(&self, name: &str, values: &[Complex]) -> AlgResult<Sym> {
        self.check_new_name(name)?;
        self.check_values(name, values)?;
        let prec = self.precision();
        let mut v = Vec::with_capacity(values.len());
        for z in values {
            let unit = z.imag().is_zero() && (*z.real() == 1 || *z.real() == -1);
            if !unit {
                return Err(AlgebraError::Domain(format!(
                    "{name}: a sign symbol takes the values 1 and -1 only"
                )));
            }
            v.push(Complex::with_val(prec, z));
        }
        let one = super::flint::Poly::from_i64(&self.inner.ctx, 1);
        let note = format!("a sign ({name}² = 1: both {name} = 1 and {name} = -1)");
        let i = self.inner.add_root(name.to_string(), one, v, note)?;
        self.state().roots[i].principal = false;
        Ok(self.root_sym(i))
    }
    /// The sign symbols of the ring (roots of the radicand 1), in order of creation.
    pub(crate) fn sign_symbols(&self) -> Vec<Sym> {
        let idx: Vec<usize> = {
            let st = self.state();
            (0..st.roots.len())
                .filter(|&i| st.roots[i].radicand.is_one())
                .collect()
        };
        idx.into_iter().map(|i| self.root_sym(i)).collect()
    }

    /// The products of the ring's sign symbols (at most four symbols), each with
    /// either sign (`+` first), fewest factors first.
    pub(crate) fn sign_products(&self) -> AlgResult<Vec<Sym>> {
        let signs = self.sign_symbols();
        let n = signs.len().min(4);
        let mut masks: Vec<u32> = (1..1u32 << n).collect();
        masks.sort_by_key(|m| m.count_ones());
        let mut out = Vec::with_capacity(2 * masks.len());
        for mask in masks {
            let mut prod = self.integer(1);
            for (j, s) in signs.iter().enumerate().take(n) {
                if mask & (1 << j) != 0 {
                    prod = prod.try_mul(s)?;
                }
            }
            let neg = prod.negate();
            out.push(prod);
            out.push(neg);
        }
        Ok(out)
    }

    /// A sign symbol with values given as `f64` (see [`Ring::sign_symbol`]).
    pub fn sign_symbol_f64(&self, name: &str, values: &[f64]) -> AlgResult<Sym> {
        let prec = self.precision();
        let v: Vec<Complex> = values
            .iter()
            .map(|&x| Complex::with_val(prec, (x, 0)))
            .collect();
        self.sign_symbol(name, &v)
    }
    /// A symbol the prover cannot expand (such as `u0` given by an inverse function),
    /// with its values; `constant` says whether its derivative with respect to every
    /// indeterminate is 0 (otherwise a derivative through it is an error).
    pub fn opaque(&self, name: &str, values: &[Complex], constant: bool) -> AlgResult<Sym> {
        self.new_var(name, values, VarKind::Opaque { constant })
    }
    /// A named quantity (`k`, `nu`, …): a free symbol standing for `definition` (with the
    /// definition's values, and its derivative for the chain rule), or the definition
    /// itself when the ring expands named quantities.  Proving with free symbols first
    /// keeps expressions small; an identity proved so holds for every value of the
    /// symbol, in particular for the definition.
    pub fn named(&self, name: &str, definition: &Sym) -> AlgResult<Sym> {
        if self.inner.opts.expand_named {
            return Ok(definition.clone());
        }
        self.check_new_name(name)?;
        if !definition.ring.same(self) {
            return Err(AlgebraError::RingMismatch);
        }
        let values = definition.val.sh.v.clone();
        let kind = VarKind::Named(Box::new((*definition.val).clone()));
        let j = self.inner.add_var(name.to_string(), kind, values)?;
        Ok(self.var_sym(j))
    }
    fn check_new_name(&self, name: &str) -> AlgResult<()> {
        if !valid_name(name) {
            return Err(AlgebraError::Domain(format!(
                "symbol name '{name}' must be letters and digits, starting with a letter"
            )));
        }
        let st = self.state();
        if st.vars.iter().any(|v| v.name == name) || st.roots.iter().any(|r| r.name == name) {
            return Err(AlgebraError::Domain(format!(
                "symbol '{name}' defined twice"
            )));
        }
        Ok(())
    }
    fn check_values(&self, name: &str, values: &[Complex]) -> AlgResult<()> {
        if values.len() != self.points() {
            return Err(AlgebraError::Domain(format!(
                "{name}: {} values for {} domain points",
                values.len(),
                self.points()
            )));
        }
        if values
            .iter()
            .any(|z| !z.real().is_finite() || !z.imag().is_finite())
        {
            return Err(AlgebraError::Domain(format!("{name}: non-finite value")));
        }
        Ok(())
    }
    /// Remembers `values` (of the caller's `shape`) as the value of an implicitly
    /// defined function at the arguments described by `key` (the function's name and
    /// the normal forms of its arguments), so that evaluating the call returns them.
    pub fn remember(&self, key: &str, shape: &str, values: &[Sym]) {
        let vals = values.iter().map(Sym::stored).collect();
        self.state()
            .implicit_values
            .insert(key.to_string(), (shape.to_string(), vals));
    }
    /// The shape and values remembered for `key`, if any.
    pub fn recall(&self, key: &str) -> Option<(String, Vec<Sym>)> {
        let (shape, vals) = self.state().implicit_values.get(key).cloned()?;
        let syms = vals.into_iter().map(|s| Sym::restored(self, s)).collect();
        Some((shape, syms))
    }
}
