//! Truncated power series in one variable `h` with exact coefficients in the prover's
//! tower: the arithmetic of asymptotic claims (`f = O(hᵖ)` as `h → 0⁺`).
//!
//! A [`Series`] is `Σ cₑ hᵉ + O(h^hi)` for `lo ≤ e < hi`, every coefficient a [`Sym`]
//! (an exact element of the ring's field, so a coefficient is 0 exactly when its normal
//! form is).  The leading stored coefficient is nonzero, so `lo` is the valuation; a
//! value whose known coefficients all vanish is stored with `lo = hi`.  Laurent series
//! (negative `lo`) arise from division by a series of positive valuation.
//!
//! * **Precision.**  Every operation tracks the absolute precision `hi` as p-adic
//!   numbers do (`(a·b).hi = min(a.lo + b.hi, b.lo + a.hi)`; a quotient keeps the
//!   smaller relative precision), and every result is cut at the working precision of
//!   [`with_precision`].  So a coefficient below `hi` is exact, never a guess.
//! * **Functions.**  Square roots by the recurrence of `s² = a` (the constant term's
//!   branch decided by [`Sym::sqrt`], i.e. proved on the domain); `sn`, `cn`, `dn` of a
//!   series argument `u = u₀ + w(h)` by integrating DLMF 22.13.1–3
//!   (`s′ = c·d·u′`, `c′ = −s·d·u′`, `d′ = −k²·s·c·u′`) from `(sn, cn, dn)(u₀)`;
//!   circular and hyperbolic functions at moduli 0 and 1 (DLMF 22.5.ii); a modulus
//!   that moves with `h` gives the values at its limit, known to the order at which it
//!   moves (module `series_modulus`).  Functions of
//!   values that do not depend on `h` are the ring's own.  Everything else poisons the
//!   ring (the proof then fails with the reason).
//! * **Comparisons** of values that depend on `h` are decided by the sign of the leading
//!   coefficient (proved on the domain by [`Sym::sign`]): they hold for all small
//!   enough `h > 0`, which is what an asymptotic statement needs.
//!
//! ```
//! use eulertop::algebra::series::{Series, with_precision};
//! use eulertop::algebra::{Ring, RingOptions};
//! let ring = Ring::new(RingOptions { points: 1, ..Default::default() });
//! let k = ring.rational(&rug::Rational::from((1, 2)));
//! with_precision(6, || {
//!     let h = Series::var(&ring);
//!     // sn(h, k) = h − (1 + k²) h³/6 + O(h⁵) (DLMF 22.10.1)
//!     let (s, _, _) = h.sncndn(&Series::constant(&k)).unwrap();
//!     assert_eq!(s.coefficient(1).unwrap().as_rational(), Some(1.into()));
//!     assert_eq!(s.coefficient(2).unwrap().as_rational(), Some(0.into()));
//!     assert_eq!(s.coefficient(3).unwrap().as_rational(), Some(rug::Rational::from((-5, 24))));
//! });
//! ```

use super::error::{AlgResult, AlgebraError};
use super::ring::Ring;
use super::series_trace::SOp;
use super::sym::Sym;
use std::cell::Cell;

thread_local! {
    static PRECISION: Cell<i32> = const { Cell::new(4) };
}

/// Runs `f` with every series cut at `O(h^n)` (restored afterwards).
///
/// ```
/// use eulertop::algebra::series::{Series, with_precision};
/// use eulertop::algebra::{Ring, RingOptions};
/// let ring = Ring::new(RingOptions { points: 1, ..Default::default() });
/// let hi = with_precision(3, || Series::var(&ring).precision());
/// assert_eq!(hi, 3);
/// ```
pub fn with_precision<T>(n: i32, f: impl FnOnce() -> T) -> T {
    let old = PRECISION.with(|c| c.replace(n));
    let out = f();
    PRECISION.with(|c| c.set(old));
    out
}

fn cap() -> i32 {
    PRECISION.with(Cell::get)
}

/// A truncated power series `Σ cₑ hᵉ + O(h^hi)` with exact coefficients.
#[derive(Clone, Debug)]
pub struct Series {
    ring: Ring,
    lo: i32,
    c: Vec<Sym>,
    hi: i32,
    /// The id of the operation that made it, when the ring records certificates
    /// (module [`super::series_trace`]).
    id: Option<u32>,
}

impl Series {
    /// The series variable `h` itself.
    pub fn var(ring: &Ring) -> Series {
        Series::from_coefficients(ring, 1, vec![ring.integer(1)], cap()).traced(SOp::Var, &[])
    }

    /// A value that does not depend on `h`.
    pub fn constant(x: &Sym) -> Series {
        Series::from_coefficients(x.ring(), 0, vec![x.clone()], cap())
            .traced(SOp::Const(x.clone()), &[])
    }

    /// The id of the operation that made this value (module [`super::series_trace`]).
    pub(crate) fn trace_id(&self) -> Option<u32> {
        self.id
    }

    pub(crate) fn set_trace_id(&mut self, id: u32) {
        self.id = Some(id);
    }

    /// `Σ c[i] h^(lo+i) + O(h^hi)`, normalised (leading zeros dropped, cut at the
    /// working precision).
    fn from_coefficients(ring: &Ring, lo: i32, c: Vec<Sym>, hi: i32) -> Series {
        let hi = hi.min(cap());
        let mut s = Series {
            ring: ring.clone(),
            lo,
            c,
            hi,
            id: None,
        };
        let keep = usize::try_from((hi - lo).max(0)).unwrap_or(0);
        s.c.truncate(keep);
        let zeros = s.c.iter().take_while(|x| x.is_exact_zero()).count();
        s.c.drain(..zeros);
        // trailing zeros are implicit
        while s.c.last().is_some_and(|x| x.is_exact_zero()) {
            s.c.pop();
        }
        s.lo = if s.c.is_empty() {
            hi
        } else {
            lo + zeros as i32
        };
        s
    }

    /// The ring of the coefficients.
    pub fn ring(&self) -> &Ring {
        &self.ring
    }

    /// The valuation: the exponent of the first nonzero coefficient (`precision()` when
    /// every known coefficient is 0).
    pub fn valuation(&self) -> i32 {
        self.lo
    }

    /// The absolute precision: the value is known up to `O(h^precision)`.
    pub fn precision(&self) -> i32 {
        self.hi
    }

    /// The coefficient of `hᵉ`, if it is known (`e < precision()`).
    pub fn coefficient(&self, e: i32) -> Option<Sym> {
        if e >= self.hi {
            return None;
        }
        Some(self.coef(e))
    }

    fn coef(&self, e: i32) -> Sym {
        if e < self.lo || e >= self.hi {
            return self.ring.integer(0);
        }
        (self.c.get((e - self.lo) as usize).cloned()).unwrap_or_else(|| self.ring.integer(0))
    }

    /// One past the exponent of the last stored (possibly nonzero) coefficient.
    fn stored_end(&self) -> i32 {
        self.lo + self.c.len() as i32
    }

    /// Is the value independent of `h` (a constant known to the working precision)?
    pub fn is_constant(&self) -> bool {
        self.hi >= cap() && (self.c.is_empty() || (self.lo == 0 && self.c.len() == 1))
    }

    /// The constant term, when the value does not depend on `h`.
    pub fn as_constant(&self) -> Option<Sym> {
        self.is_constant().then(|| self.coef(0))
    }

    /// The same value known only to `O(h^hi)` (the smaller of `hi` and its precision).
    pub(crate) fn cut(&self, hi: i32) -> Series {
        Series::from_coefficients(&self.ring, self.lo, self.c.clone(), hi.min(self.hi))
            .traced(SOp::Cut(hi), &[self])
    }

    /// The value `self` of `sn`, `cn` or `dn` at the constant term `k₀` of a modulus
    /// `k(h) = k₀ + O(hᵛ)`, as the value at `k`: known to `O(hᵛ)` (module
    /// `series_modulus`).
    pub(crate) fn at_moving_modulus(&self, k: &Series, v: i32) -> Series {
        Series::from_coefficients(&self.ring, self.lo, self.c.clone(), v.min(self.hi))
            .traced(SOp::Moving, &[self, k])
    }

    /// `self − o`.
    pub fn try_add_neg(&self, o: &Series) -> AlgResult<Series> {
        self.try_add(o, true)
    }

    /// Is the value exactly 0 (no stored coefficient, known to the working precision)?
    pub fn known_zero(&self) -> bool {
        self.c.is_empty() && self.hi >= cap()
    }

    /// A series whose every operation fails: the ring records `e`.
    pub(crate) fn poisoned(&self, e: AlgebraError) -> Series {
        self.ring.poison(e);
        Series {
            ring: self.ring.clone(),
            lo: 0,
            c: vec![self.ring.nan()],
            hi: cap(),
            id: None,
        }
    }

    /// `O(h^v)` for this value's valuation `v`: what is known of `|self|` when the sign
    /// of its leading coefficient is not decided.
    pub(crate) fn bound(&self) -> Series {
        let v = self.lo;
        Series::from_coefficients(&self.ring, v, Vec::new(), v).traced(SOp::Bound, &[self])
    }

    /// `self ± o`.
    pub fn try_add(&self, o: &Series, sub: bool) -> AlgResult<Series> {
        let lo = self.lo.min(o.lo);
        let hi = self.hi.min(o.hi);
        let mut c = Vec::new();
        for e in lo..hi {
            let (a, b) = (self.coef(e), o.coef(e));
            c.push(if sub { a.try_sub(&b)? } else { a.try_add(&b)? });
        }
        let op = if sub { SOp::Sub } else { SOp::Add };
        Ok(Series::from_coefficients(&self.ring, lo, c, hi).traced(op, &[self, o]))
    }

    /// `self · o`.
    pub fn try_mul(&self, o: &Series) -> AlgResult<Series> {
        let lo = self.lo + o.lo;
        let hi = (self.lo + o.hi).min(o.lo + self.hi).min(cap());
        let mut c = Vec::new();
        for e in lo..hi {
            let (a_end, b_end) = (self.stored_end(), o.stored_end());
            let pairs: Vec<(Sym, Sym)> = (self.lo..a_end)
                .filter(|i| (o.lo..b_end).contains(&(e - i)))
                .map(|i| (self.coef(i), o.coef(e - i)))
                .collect();
            c.push(sum_of_products(&self.ring, &pairs)?);
        }
        Ok(Series::from_coefficients(&self.ring, lo, c, hi).traced(SOp::Mul, &[self, o]))
    }

    /// `self / o`; `o` must have a known nonzero coefficient.
    pub fn try_div(&self, o: &Series) -> AlgResult<Series> {
        let Some(b0) = o.c.first() else {
            return Err(AlgebraError::Domain(format!(
                "division by a series whose known coefficients vanish (O(h^{}))",
                o.hi
            )));
        };
        let lo = self.lo - o.lo;
        let rel = (self.hi - self.lo).min(o.hi - o.lo);
        let n = (lo + rel).min(cap()) - lo;
        let inv = self.ring.integer(1).try_div(b0)?;
        let mut q: Vec<Sym> = Vec::new();
        for i in 0..n.max(0) {
            let pairs: Vec<(Sym, Sym)> = (0..i)
                .map(|j| (q[j as usize].clone(), o.coef(o.lo + i - j)))
                .collect();
            let rest = sum_of_products(&self.ring, &pairs)?;
            q.push(self.coef(self.lo + i).try_sub(&rest)?.try_mul(&inv)?);
        }
        Ok(Series::from_coefficients(&self.ring, lo, q, lo + n).traced(SOp::Div, &[self, o]))
    }

    /// `√self`, the constant term's branch decided by [`Sym::sqrt`] (proved on the
    /// domain); the valuation must be even.
    pub fn try_sqrt(&self) -> AlgResult<Series> {
        let Some(a0) = self.c.first() else {
            // √(O(h^hi)) = O(h^⌊hi/2⌋): the square root of the bound
            let hi = self.hi.div_euclid(2);
            let out = Series::from_coefficients(&self.ring, hi, Vec::new(), hi);
            let zero = self.ring.integer(0);
            return Ok(out.traced(SOp::Sqrt(zero), &[self]));
        };
        if self.lo % 2 != 0 {
            return Err(AlgebraError::Domain(format!(
                "the square root of a series of odd valuation {} (not a power series in h)",
                self.lo
            )));
        }
        let s0 = a0.sqrt()?;
        let root = s0.clone();
        let inv = self.ring.integer(2).try_mul(&s0)?.try_powi(-1)?;
        let n = self.hi - self.lo;
        let mut s = vec![s0];
        for i in 1..n {
            let pairs: Vec<(Sym, Sym)> = (1..i)
                .map(|j| (s[j as usize].clone(), s[(i - j) as usize].clone()))
                .collect();
            let rest = sum_of_products(&self.ring, &pairs)?;
            s.push(self.coef(self.lo + i).try_sub(&rest)?.try_mul(&inv)?);
        }
        let lo = self.lo / 2;
        Ok(Series::from_coefficients(&self.ring, lo, s, lo + n).traced(SOp::Sqrt(root), &[self]))
    }

    /// The sign for small `h > 0`: that of the leading coefficient, proved on the
    /// domain.
    pub fn sign(&self) -> AlgResult<i32> {
        match self.c.first() {
            Some(c0) => c0.sign(),
            None => Err(AlgebraError::CannotDecide(format!(
                "the sign of a series whose known coefficients vanish (O(h^{}))",
                self.hi
            ))),
        }
    }

    /// The derivative in `h`.
    pub fn derivative(&self) -> AlgResult<Series> {
        let mut c = Vec::new();
        for e in self.lo..self.hi {
            c.push(self.coef(e).try_mul(&self.ring.integer(i64::from(e)))?);
        }
        Ok(
            Series::from_coefficients(&self.ring, self.lo - 1, c, self.hi - 1)
                .traced(SOp::Deriv, &[self]),
        )
    }

    /// Maps a function of the ring over a value independent of `h`; `what` names it
    /// in the error otherwise.
    pub(crate) fn on_constant(
        &self,
        what: &str,
        f: impl FnOnce(&Sym) -> AlgResult<Sym>,
    ) -> AlgResult<Series> {
        match self.as_constant() {
            Some(x) => Ok(Series::constant(&f(&x)?)),
            None => Err(AlgebraError::NotAlgebraic(format!(
                "{what} of a value that depends on h"
            ))),
        }
    }

    /// A rendering for messages: the known coefficients.
    pub fn render_short(&self, max: usize) -> String {
        let mut parts: Vec<String> = (self.lo..self.hi)
            .map(|e| format!("({})·h^{e}", self.coef(e).render_short(max)))
            .collect();
        parts.push(format!("O(h^{})", self.hi));
        parts.join(" + ")
    }
}

/// `Σ aᵢ·bᵢ` over one denominator (0 for no terms).
fn sum_of_products(ring: &Ring, pairs: &[(Sym, Sym)]) -> AlgResult<Sym> {
    if pairs.is_empty() {
        return Ok(ring.integer(0));
    }
    let terms: Vec<(&Sym, &Sym, bool)> = pairs.iter().map(|(a, b)| (a, b, false)).collect();
    Sym::try_sum_of_products(&terms)
}

impl Series {
    /// `(sn, cn, dn)(self, k)` for a modulus `k` independent of `h`: the constant
    /// term's values from the ring ([`Sym::sncndn`]), the higher coefficients by
    /// integrating DLMF 22.13.1–3 along `u(h)`.
    pub fn sncndn(&self, k: &Series) -> AlgResult<(Series, Series, Series)> {
        if k.as_constant().is_none() {
            return self.sncndn_moving(k);
        }
        let k0 = k.coef(0);
        if self.lo < 0 || self.hi <= 0 {
            return Err(AlgebraError::Pole(
                "sn, cn, dn of a series with a pole at h = 0 or no known constant term".into(),
            ));
        }
        let u0 = self.coef(0);
        let (one, zero) = (self.ring.integer(1), self.ring.integer(0));
        let (s0, c0, d0) = if u0.is_exact_zero() {
            (zero, one.clone(), one)
        } else {
            u0.sncndn(&k0)?
        };
        let base = [s0.clone(), c0.clone(), d0.clone()];
        let du = self.derivative()?;
        let k2 = k0.try_mul(&k0)?;
        let n = self.hi as usize;
        let (mut s, mut c, mut d) = (vec![s0], vec![c0], vec![d0]);
        let (mut cd, mut sd, mut sc) = (Vec::new(), Vec::new(), Vec::new());
        for m in 0..n.saturating_sub(1) {
            cd.push(convolve(&self.ring, &c, &d, m)?);
            sd.push(convolve(&self.ring, &s, &d, m)?);
            sc.push(convolve(&self.ring, &s, &c, m)?);
            let dus: Vec<Sym> = (0..=m).map(|j| du.coef(j as i32)).collect();
            let step = |prod: &[Sym], f: &Sym| -> AlgResult<Sym> {
                let t = convolve(&self.ring, prod, &dus, m)?;
                t.try_mul(f)?.try_div(&self.ring.integer(m as i64 + 1))
            };
            s.push(step(&cd, &self.ring.integer(1))?);
            c.push(step(&sd, &self.ring.integer(-1))?);
            d.push(step(&sc, &k2.negate())?);
        }
        let hi = self.hi;
        let mk = |v: Vec<Sym>, f: u8| {
            Series::from_coefficients(&self.ring, 0, v, hi)
                .traced(SOp::Jacobi(f, base.clone()), &[self, k])
        };
        Ok((mk(s, 0), mk(c, 1), mk(d, 2)))
    }
}

/// The coefficient `m` of the product of two series given by their coefficients from
/// exponent 0 (both known up to `m`).
fn convolve(ring: &Ring, a: &[Sym], b: &[Sym], m: usize) -> AlgResult<Sym> {
    let pairs: Vec<(Sym, Sym)> = (0..=m).map(|i| (a[i].clone(), b[m - i].clone())).collect();
    sum_of_products(ring, &pairs)
}
