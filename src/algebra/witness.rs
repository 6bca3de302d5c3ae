//! Certified refutations: a point at which a value of the ring is provably not 0.
//!
//! A value `N/D` of the ring is a quotient of polynomials in the field variables and
//! the roots.  At a domain point, every indeterminate and every `sn` of a base argument
//! is given its value there as an exact (binary) rational: for an indeterminate this is
//! the sampled value itself; for `sn v` it is a value `s` with `|s − sn v| ≤ 2^-p` at the
//! ring's precision `p`, the `sn` of a base argument `v'` next to `v` (any `s ∈ (−1, 1)`
//! is `sn v'` of a real `v'` for `0 ≤ k < 1`).  Each root is then the algebraic number
//! its relation gives, taken with the sign of its value at the point, enclosed in an
//! Arb ball (FLINT's ball arithmetic: every enclosure is rigorous).  When the balls of
//! `N` and `D` both exclude 0, the value is certified nonzero at that point: the claim
//! `lhs = rhs` whose `lhs − rhs` it is fails there.  Values with other symbols (named
//! quantities kept free, quarter periods, opaque symbols) get no witness, as their
//! exact values at the point are not known.
//!
//! ```
//! use eulertop::algebra::{Ring, RingOptions};
//! let ring = Ring::new(RingOptions { points: 1, ..Default::default() });
//! let x = ring.indeterminate_f64("x", &[0.75]).unwrap();
//! let r = (x.clone() * x.clone() + ring.integer(1)).sqrt().unwrap();
//! // √(x² + 1) − x is 0.5 at x = 3/4: certified nonzero there
//! let w = ring.witness(&(r - x), 0).unwrap();
//! assert!(w.contains("0.5"), "{w}");
//! ```

use super::flint::Poly;
use super::ring::{Ring, VarKind};
use super::sym::Sym;
use flint_sys::acb::{
    acb_add, acb_clear, acb_contains_zero, acb_init, acb_mul, acb_neg, acb_pow_ui, acb_sqrt,
};
use flint_sys::acb_types::acb_struct;
use flint_sys::arb::arb_get_str;
use flint_sys::arf::{arf_get_mpfr, arf_set_mpfr};
use flint_sys::deps::__mpfr_struct;
use flint_sys::deps::mpfr_rnd_t_MPFR_RNDN;
use rug::{Complex, Float, Integer};
use std::mem::MaybeUninit;

/// A complex ball (an Arb `acb_t`), cleared when dropped.
struct Ball(acb_struct);

impl Ball {
    fn zero() -> Ball {
        let mut b = MaybeUninit::<acb_struct>::uninit();
        // SAFETY: acb_init initialises the struct it is given (exact zero).
        unsafe {
            acb_init(b.as_mut_ptr());
            Ball(b.assume_init())
        }
    }

    /// The exact value of a complex number of MPFR parts (radius 0).
    fn exact(z: &Complex) -> Ball {
        let mut b = Ball::zero();
        // SAFETY: rug and flint-sys link one and the same MPFR (gmp-mpfr-sys), so a
        // `rug::Float` is a valid `__mpfr_struct`; the ball is initialised.
        unsafe {
            arf_set_mpfr(&mut b.0.real.mid, z.real().as_raw().cast::<__mpfr_struct>());
            arf_set_mpfr(&mut b.0.imag.mid, z.imag().as_raw().cast::<__mpfr_struct>());
        }
        b
    }

    /// An integer, exactly.
    fn integer(c: &Integer) -> Ball {
        let bits = c.significant_bits().max(64);
        Ball::exact(&Complex::with_val(bits, (Float::with_val(bits, c), 0)))
    }

    fn op(
        &self,
        o: &Ball,
        prec: i64,
        f: unsafe extern "C" fn(*mut acb_struct, *const acb_struct, *const acb_struct, i64),
    ) -> Ball {
        let mut r = Ball::zero();
        // SAFETY: every ball is initialised; Arb allows any aliasing of the arguments.
        unsafe { f(&mut r.0, &self.0, &o.0, prec) };
        r
    }

    /// The midpoint, rounded to `prec` bits.
    fn midpoint(&self, prec: u32) -> Complex {
        let mut z = Complex::new(prec);
        // SAFETY: as in [`Ball::exact`]; the ball is initialised.
        unsafe {
            let (re, im) = z.as_mut_real_imag();
            arf_get_mpfr(
                re.as_raw_mut().cast::<__mpfr_struct>(),
                &self.0.real.mid,
                mpfr_rnd_t_MPFR_RNDN,
            );
            arf_get_mpfr(
                im.as_raw_mut().cast::<__mpfr_struct>(),
                &self.0.imag.mid,
                mpfr_rnd_t_MPFR_RNDN,
            );
        }
        z
    }

    fn contains_zero(&self) -> bool {
        // SAFETY: the ball is initialised.
        unsafe { acb_contains_zero(&self.0) != 0 }
    }

    /// The real part as Arb prints it (midpoint ± radius).
    fn show(&self) -> String {
        // SAFETY: the ball is initialised; arb_get_str returns a NUL-terminated string
        // allocated by FLINT, freed here once.
        unsafe {
            let p = arb_get_str(&self.0.real, 20, 0);
            let s = std::ffi::CStr::from_ptr(p).to_string_lossy().into_owned();
            flint_sys::flint::flint_free(p.cast());
            s
        }
    }
}

impl Drop for Ball {
    fn drop(&mut self) {
        // SAFETY: the ball was initialised by acb_init and is cleared once.
        unsafe { acb_clear(&mut self.0) }
    }
}

/// A polynomial of the ring's context evaluated in balls (`None` where a variable it
/// uses has no ball).
fn eval(p: &Poly, balls: &[Option<Ball>], prec: i64) -> Option<Ball> {
    let mut acc = Ball::zero();
    let mut missing = false;
    p.for_each_term(|c, e| {
        if missing {
            return;
        }
        let mut t = Ball::integer(c);
        for (i, &k) in e.iter().enumerate().filter(|(_, k)| **k > 0) {
            let Some(Some(b)) = balls.get(i) else {
                missing = true;
                return;
            };
            let mut pw = Ball::zero();
            // SAFETY: every ball is initialised.
            unsafe { acb_pow_ui(&mut pw.0, &b.0, k, prec) };
            t = t.op(&pw, prec, acb_mul);
        }
        acc = acc.op(&t, prec, acb_add);
    });
    (!missing).then_some(acc)
}

impl Ring {
    /// A certificate that `d` is not 0 at domain point `point` (see the module): the
    /// enclosure of its value there, or `None` where the balls do not exclude 0 or a
    /// symbol of `d` has no exact value at the point.
    pub fn witness(&self, d: &Sym, point: usize) -> Option<String> {
        if point >= self.points() {
            return None;
        }
        // the point's values are exact: a difference far below the ring's precision is
        // certified at a higher one
        let p0 = i64::from(self.precision());
        [p0, 4 * p0, 16 * p0]
            .into_iter()
            .find_map(|prec| self.witness_at(d, point, prec))
    }

    /// [`Ring::witness`] with balls of `prec` bits.
    fn witness_at(&self, d: &Sym, point: usize, prec: i64) -> Option<String> {
        let (vars, roots) = {
            let st = self.state();
            let vars: Vec<(usize, bool, Complex)> = (st.vars.iter().enumerate())
                .map(|(j, v)| {
                    let exact = matches!(v.kind, VarKind::Indeterminate | VarKind::Sn { .. });
                    (self.inner.kvar(j), exact, v.values[point].clone())
                })
                .collect();
            let roots: Vec<(usize, Poly, Complex)> = (st.roots.iter().enumerate())
                .map(|(i, r)| {
                    (
                        self.inner.root_var(i),
                        r.radicand.clone(),
                        r.values[point].clone(),
                    )
                })
                .collect();
            (vars, roots)
        };
        let mut balls: Vec<Option<Ball>> = (0..self.inner.ctx.nvars()).map(|_| None).collect();
        for (idx, exact, z) in vars {
            if exact {
                balls[idx] = Some(Ball::exact(&z));
            }
        }
        // a root's radicand uses earlier roots only: adjoin them in order
        for (idx, radicand, z) in roots {
            let Some(a) = eval(&radicand, &balls, prec) else {
                continue;
            };
            let mut r = Ball::zero();
            // SAFETY: every ball is initialised.
            unsafe { acb_sqrt(&mut r.0, &a.0, prec) };
            // the root's value at the point is r or −r: the one nearer it
            let mid = r.midpoint(self.precision());
            let (d_plus, d_minus) = (
                Complex::with_val(64, &z - &mid).abs().real().clone(),
                Complex::with_val(64, &z + &mid).abs().real().clone(),
            );
            if d_minus < d_plus {
                let mut neg = Ball::zero();
                // SAFETY: every ball is initialised.
                unsafe { acb_neg(&mut neg.0, &r.0) };
                r = neg;
            }
            balls[idx] = Some(r);
        }
        let n = eval(&d.val.num, &balls, prec)?;
        let q = eval(&d.val.den, &balls, prec)?;
        if n.contains_zero() || q.contains_zero() {
            return None;
        }
        Some(format!(
            "numerator {} and denominator {} (Arb balls, real parts) exclude 0",
            n.show(),
            q.show()
        ))
    }
}

/// An exact binary value `m*2^e` (the form the certificate checker reads).
fn exact_text(x: &Float) -> String {
    match x.to_integer_exp() {
        Some((m, e)) if m != 0 => {
            let zeros = m.find_one(0).unwrap_or(0);
            let e = i64::from(e) + i64::from(zeros);
            format!("{}*2^{e}", m >> zeros)
        }
        _ => "0".into(),
    }
}

/// A value to 60 significant digits, for choosing a branch.
fn approx_text(x: &Float) -> String {
    if x.is_zero() {
        return "0".into();
    }
    x.to_string_radix(10, Some(60))
}

impl Ring {
    /// The `at` lines of a refutation's certificate at domain point `point`: the exact
    /// value of every indeterminate and every `sn` of a base argument (as in
    /// [`Ring::witness`]), real and imaginary part, and each root's value there to 60
    /// digits, by which the checker picks the root's branch (the sign of its value at the
    /// point).
    pub(super) fn point_lines(&self, point: usize) -> String {
        let st = self.state();
        let mut out = String::new();
        for v in &st.vars {
            let z = &v.values[point];
            let line = if matches!(v.kind, VarKind::Indeterminate | VarKind::Sn { .. }) {
                format!(
                    "at {} = {} {}\n",
                    v.name,
                    exact_text(z.real()),
                    exact_text(z.imag())
                )
            } else {
                // another symbol: its value at the point, which the checker ties to the
                // bases and periods it enters
                format!(
                    "at {} ~ {} {}\n",
                    v.name,
                    approx_text(z.real()),
                    approx_text(z.imag())
                )
            };
            out.push_str(&line);
        }
        for r in &st.roots {
            let z = &r.values[point];
            out.push_str(&format!(
                "at {} ~ {} {}\n",
                r.name,
                approx_text(z.real()),
                approx_text(z.imag())
            ));
        }
        out
    }
}
