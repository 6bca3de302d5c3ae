//! Safe wrappers over the few FLINT 3 types the algebra layer needs.
//!
//! This is the only module of the algebra layer with `unsafe` code.  Every FLINT object
//! is owned by a Rust value that initialises it on construction and clears it in `Drop`
//! (RAII), and every function below checks the preconditions under which FLINT would
//! abort (division by zero, mismatched contexts, impossible powers) before calling it.
//!
//! * [`Ctx`]: a context of multivariate polynomials over ℤ with a fixed number of
//!   variables, ordered lexicographically (`x₀ > x₁ > …`);
//! * [`Poly`]: an element of ℤ[x₀, …, xₙ₋₁] (`fmpz_mpoly`), with ring operations, exact
//!   division, gcd, content, derivative, multivariate division by a list of divisors
//!   (`divrem_ideal`) and factorisation into irreducibles (`fmpz_mpoly_factor`);
//! * [`factor_integer`] (`fmpz_factor`) and [`hnf_rows`] (`fmpz_mat_hnf`).
//!
//! Integers cross the boundary as [`rug::Integer`] (both sides use the same GMP).
//!
//! ```
//! use eulertop::algebra::flint::{Ctx, Poly};
//! let ctx = Ctx::new(2);
//! let (x, y) = (Poly::var(&ctx, 0), Poly::var(&ctx, 1));
//! let f = x.mul(&x).sub(&y.mul(&y)); // x² − y²
//! let fac = f.factor().unwrap();
//! assert_eq!(fac.factors.len(), 2); // (x − y)(x + y)
//! ```

use flint_sys::deps::__mpz_struct;
use flint_sys::flint::fmpz;
use flint_sys::fmpz as fz;
use flint_sys::fmpz_factor as ff;
use flint_sys::fmpz_mat as fmat;
use flint_sys::fmpz_mpoly as fm;
use flint_sys::fmpz_mpoly_factor as fmf;
use flint_sys::fmpz_types::{
    fmpz_factor_struct, fmpz_mat_struct, fmpz_mpoly_factor_struct, fmpz_mpoly_struct,
};
use flint_sys::mpoly_types::{fmpz_mpoly_ctx_struct, ordering_t_ORD_LEX};
use rug::Integer;
use std::mem::MaybeUninit;
use std::sync::Arc;

/// Errors reported by the FLINT wrappers (FLINT itself would abort instead).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FlintError {
    /// Exact division by zero.
    #[error("division by zero")]
    DivisionByZero,
    /// A division that was required to be exact is not.
    #[error("inexact division")]
    Inexact,
    /// FLINT declined the operation (a power or a factorisation too large).
    #[error("FLINT could not complete {0}")]
    Failed(&'static str),
}

/// A context for multivariate polynomials over ℤ in a fixed number of variables, with
/// the lexicographic order in which variable 0 is the most significant.
pub struct Ctx {
    raw: Box<fmpz_mpoly_ctx_struct>,
    nvars: usize,
}

// SAFETY: after initialisation the context is only read by FLINT (every function takes
// it as `const`), so sharing and sending it between threads is sound.
unsafe impl Send for Ctx {}
unsafe impl Sync for Ctx {}

impl std::fmt::Debug for Ctx {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Ctx({} variables)", self.nvars)
    }
}

impl Ctx {
    /// A context with `nvars ≥ 1` variables (shared by the polynomials made in it).
    pub fn new(nvars: usize) -> Arc<Ctx> {
        let nvars = nvars.max(1);
        let mut raw = Box::new(MaybeUninit::<fmpz_mpoly_ctx_struct>::uninit());
        // SAFETY: fmpz_mpoly_ctx_init fully initialises the struct.
        let raw = unsafe {
            fm::fmpz_mpoly_ctx_init(raw.as_mut_ptr(), nvars as i64, ordering_t_ORD_LEX);
            Box::from_raw(Box::into_raw(raw) as *mut fmpz_mpoly_ctx_struct)
        };
        Arc::new(Ctx { raw, nvars })
    }

    /// Number of variables.
    pub fn nvars(&self) -> usize {
        self.nvars
    }

    fn ptr(&self) -> *const fmpz_mpoly_ctx_struct {
        &*self.raw
    }
}

impl Drop for Ctx {
    fn drop(&mut self) {
        // SAFETY: initialised in `new`, cleared exactly once.
        unsafe { fm::fmpz_mpoly_ctx_clear(&mut *self.raw) }
    }
}

/// An owned FLINT integer, for temporaries.
struct Fmpz(fmpz);

impl Fmpz {
    fn new() -> Fmpz {
        let mut f: fmpz = 0;
        // SAFETY: fmpz_init only writes the (small) value 0.
        unsafe { fz::fmpz_init(&mut f) };
        Fmpz(f)
    }
    fn from_integer(z: &Integer) -> Fmpz {
        let mut f = Fmpz::new();
        // SAFETY: `z` is a valid mpz; the two crates declare the same mpz layout.
        unsafe { fz::fmpz_set_mpz(&mut f.0, z.as_raw() as *const __mpz_struct) };
        f
    }
    fn to_integer(&self) -> Integer {
        fmpz_to_integer(&self.0)
    }
}

impl Drop for Fmpz {
    fn drop(&mut self) {
        // SAFETY: initialised in `new`.
        unsafe { fz::fmpz_clear(&mut self.0) }
    }
}

fn fmpz_to_integer(f: *const fmpz) -> Integer {
    let mut z = Integer::new();
    // SAFETY: `f` points to an initialised fmpz; `z` is a valid mpz.
    unsafe { fz::fmpz_get_mpz(z.as_raw_mut() as *mut __mpz_struct, f) };
    z
}

/// A multivariate polynomial over ℤ in the variables of its [`Ctx`].
pub struct Poly {
    raw: fmpz_mpoly_struct,
    ctx: Arc<Ctx>,
}

// SAFETY: a Poly owns its coefficient and exponent arrays; FLINT reads `const` inputs
// without modifying them, and FLINT frees big coefficients from any thread.
unsafe impl Send for Poly {}
unsafe impl Sync for Poly {}

impl std::fmt::Debug for Poly {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let names: Vec<String> = (0..self.ctx.nvars).map(|i| format!("x{i}")).collect();
        write!(f, "{}", self.render(&names))
    }
}

impl Clone for Poly {
    fn clone(&self) -> Poly {
        let mut p = Poly::zero(&self.ctx);
        // SAFETY: both initialised in the same context.
        unsafe { fm::fmpz_mpoly_set(&mut p.raw, &self.raw, self.ctx.ptr()) };
        p
    }
}

impl Drop for Poly {
    fn drop(&mut self) {
        // SAFETY: initialised on construction, cleared once.
        unsafe { fm::fmpz_mpoly_clear(&mut self.raw, self.ctx.ptr()) }
    }
}

impl PartialEq for Poly {
    fn eq(&self, other: &Poly) -> bool {
        self.same_ctx(other);
        // SAFETY: both initialised in the same context.
        unsafe { fm::fmpz_mpoly_equal(&self.raw, &other.raw, self.ctx.ptr()) != 0 }
    }
}
impl Eq for Poly {}

/// The prime modulo which [`Poly`]'s hash takes coefficients (2⁶⁴ − 59).
const HASH_PRIME: u64 = 0xFFFF_FFFF_FFFF_FFC5;

/// Hashes the length and at most 16 evenly spaced terms: equal polynomials hash
/// alike, and hashing a polynomial of thousands of terms stays cheap (equality
/// then compares them all).
impl std::hash::Hash for Poly {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        let len = self.len();
        len.hash(state);
        let step = len.div_ceil(16).max(1);
        let mut exps = vec![0u64; self.ctx.nvars];
        for i in (0..len).step_by(step) {
            // the coefficient modulo a prime and the exponents folded into one word:
            // equal polynomials hash alike, with two words per sampled term
            // SAFETY: i < len, so `coeffs + i` is an initialised fmpz.
            let c = unsafe { fz::fmpz_fdiv_ui(self.raw.coeffs.add(i), HASH_PRIME) };
            self.term_exponents(i, &mut exps);
            let folded = exps.iter().fold(0u64, |h, &e| {
                h.wrapping_mul(0x100_0000_01b3).wrapping_add(e)
            });
            (c, folded).hash(state);
        }
    }
}

/// A factorisation `constant · Π factorᵢ^expᵢ` with primitive irreducible factors of
/// positive leading coefficient.
#[derive(Debug, Clone)]
pub struct Factored {
    /// The integer constant (content and sign).
    pub constant: Integer,
    /// The irreducible factors with their multiplicities.
    pub factors: Vec<(Poly, u64)>,
}

impl Poly {
    fn blank(ctx: &Arc<Ctx>) -> Poly {
        let mut raw = MaybeUninit::<fmpz_mpoly_struct>::uninit();
        // SAFETY: fmpz_mpoly_init fully initialises the struct (to zero).
        let raw = unsafe {
            fm::fmpz_mpoly_init(raw.as_mut_ptr(), ctx.ptr());
            raw.assume_init()
        };
        Poly {
            raw,
            ctx: ctx.clone(),
        }
    }

    /// The zero polynomial.
    pub fn zero(ctx: &Arc<Ctx>) -> Poly {
        Poly::blank(ctx)
    }

    /// The constant `n`.
    pub fn from_i64(ctx: &Arc<Ctx>, n: i64) -> Poly {
        let mut p = Poly::blank(ctx);
        // SAFETY: initialised polynomial in its context.
        unsafe { fm::fmpz_mpoly_set_si(&mut p.raw, n, ctx.ptr()) };
        p
    }

    /// The constant `z`.
    pub fn from_integer(ctx: &Arc<Ctx>, z: &Integer) -> Poly {
        let mut p = Poly::blank(ctx);
        let f = Fmpz::from_integer(z);
        // SAFETY: initialised polynomial and integer.
        unsafe { fm::fmpz_mpoly_set_fmpz(&mut p.raw, &f.0, ctx.ptr()) };
        p
    }

    /// The variable `xᵢ` (panics if `i` is not below the number of variables: that is a
    /// programming error of the caller, never a consequence of input).
    pub fn var(ctx: &Arc<Ctx>, i: usize) -> Poly {
        assert!(i < ctx.nvars, "variable index out of range");
        let mut p = Poly::blank(ctx);
        // SAFETY: index checked above.
        unsafe { fm::fmpz_mpoly_gen(&mut p.raw, i as i64, ctx.ptr()) };
        p
    }

    /// The context of this polynomial.
    pub fn ctx(&self) -> &Arc<Ctx> {
        &self.ctx
    }

    fn same_ctx(&self, other: &Poly) {
        assert!(
            Arc::ptr_eq(&self.ctx, &other.ctx),
            "polynomials of different contexts"
        );
    }

    /// Is this the zero polynomial?
    pub fn is_zero(&self) -> bool {
        // SAFETY: initialised polynomial.
        unsafe { fm::fmpz_mpoly_is_zero(&self.raw, self.ctx.ptr()) != 0 }
    }

    /// Is this the constant 1?
    pub fn is_one(&self) -> bool {
        // SAFETY: initialised polynomial.
        unsafe { fm::fmpz_mpoly_is_one(&self.raw, self.ctx.ptr()) != 0 }
    }

    /// The value if the polynomial is a constant.
    pub fn as_constant(&self) -> Option<Integer> {
        // SAFETY: initialised polynomial; the fmpz is initialised by Fmpz::new.
        unsafe {
            if fm::fmpz_mpoly_is_fmpz(&self.raw, self.ctx.ptr()) == 0 {
                return None;
            }
            let mut f = Fmpz::new();
            fm::fmpz_mpoly_get_fmpz(&mut f.0, &self.raw, self.ctx.ptr());
            Some(f.to_integer())
        }
    }

    /// Number of terms.
    pub fn len(&self) -> usize {
        // SAFETY: initialised polynomial.
        unsafe { fm::fmpz_mpoly_length(&self.raw, self.ctx.ptr()) as usize }
    }

    /// Is this the zero polynomial (no terms)?
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    fn binop(
        &self,
        other: &Poly,
        f: unsafe extern "C" fn(
            *mut fmpz_mpoly_struct,
            *const fmpz_mpoly_struct,
            *const fmpz_mpoly_struct,
            *const fmpz_mpoly_ctx_struct,
        ),
    ) -> Poly {
        self.same_ctx(other);
        let mut p = Poly::blank(&self.ctx);
        // SAFETY: all three initialised in the same context; FLINT allows aliasing-free
        // output here.
        unsafe { f(&mut p.raw, &self.raw, &other.raw, self.ctx.ptr()) };
        p
    }

    /// `self + other`.
    pub fn add(&self, other: &Poly) -> Poly {
        self.binop(other, fm::fmpz_mpoly_add)
    }

    /// `self − other`.
    pub fn sub(&self, other: &Poly) -> Poly {
        self.binop(other, fm::fmpz_mpoly_sub)
    }

    /// `self · other`.
    pub fn mul(&self, other: &Poly) -> Poly {
        self.binop(other, fm::fmpz_mpoly_mul)
    }

    /// `−self`.
    pub fn neg(&self) -> Poly {
        let mut p = Poly::blank(&self.ctx);
        // SAFETY: initialised in the same context.
        unsafe { fm::fmpz_mpoly_neg(&mut p.raw, &self.raw, self.ctx.ptr()) };
        p
    }

    /// `self^e`.
    pub fn pow(&self, e: u64) -> Result<Poly, FlintError> {
        let mut p = Poly::blank(&self.ctx);
        // SAFETY: initialised in the same context; failure is reported by the return.
        let ok = unsafe { fm::fmpz_mpoly_pow_ui(&mut p.raw, &self.raw, e, self.ctx.ptr()) };
        if ok == 0 {
            return Err(FlintError::Failed("a power"));
        }
        Ok(p)
    }

    /// `z · self`.
    pub fn scale(&self, z: &Integer) -> Poly {
        let f = Fmpz::from_integer(z);
        let mut p = Poly::blank(&self.ctx);
        // SAFETY: initialised operands.
        unsafe { fm::fmpz_mpoly_scalar_mul_fmpz(&mut p.raw, &self.raw, &f.0, self.ctx.ptr()) };
        p
    }

    /// `self / z` for an integer `z` dividing every coefficient.
    pub fn div_integer(&self, z: &Integer) -> Result<Poly, FlintError> {
        if *z == 0 {
            return Err(FlintError::DivisionByZero);
        }
        let ok = self.coefficients().iter().all(|c| c.is_divisible(z));
        if !ok {
            return Err(FlintError::Inexact);
        }
        let f = Fmpz::from_integer(z);
        let mut p = Poly::blank(&self.ctx);
        // SAFETY: z ≠ 0 and divides every coefficient (checked).
        unsafe { fm::fmpz_mpoly_scalar_divexact_fmpz(&mut p.raw, &self.raw, &f.0, self.ctx.ptr()) };
        Ok(p)
    }

    /// The exact quotient `self / other`, or `None` if `other` does not divide `self`.
    pub fn divides(&self, other: &Poly) -> Result<Option<Poly>, FlintError> {
        self.same_ctx(other);
        if other.is_zero() {
            return Err(FlintError::DivisionByZero);
        }
        let mut q = Poly::blank(&self.ctx);
        // SAFETY: divisor non-zero, operands initialised in the same context.
        let ok =
            unsafe { fm::fmpz_mpoly_divides(&mut q.raw, &self.raw, &other.raw, self.ctx.ptr()) };
        Ok(if ok != 0 { Some(q) } else { None })
    }

    /// The greatest common divisor, with positive leading coefficient (0 if both are 0).
    ///
    /// Algorithm: FLINT's Zippel variant `fmpz_mpoly_gcd_zippel2` (sparse
    /// interpolation with Kaltofen–Monagan scaling, exact over ℤ), and FLINT's general
    /// `fmpz_mpoly_gcd` (which picks among Brown, Zippel and Hensel) where it gives up.
    /// On the 7-variable denominators of the phase-step proofs the Zippel variant takes
    /// 64 % of the time of the general choice, whose dense Brown route is up to 20×
    /// slower.  (The normal forms need few gcds: see `den_factors`.)
    ///
    /// ```
    /// use eulertop::algebra::flint::{Ctx, Poly};
    /// let ctx = Ctx::new(2);
    /// let (x, y) = (Poly::var(&ctx, 0), Poly::var(&ctx, 1));
    /// let a = x.mul(&y).sub(&y);                         // (x − 1)·y
    /// let b = x.mul(&x).sub(&Poly::from_i64(&ctx, 1));   // (x − 1)(x + 1)
    /// assert_eq!(a.gcd(&b).unwrap(), x.sub(&Poly::from_i64(&ctx, 1)));
    /// ```
    pub fn gcd(&self, other: &Poly) -> Result<Poly, FlintError> {
        self.same_ctx(other);
        let mut g = Poly::blank(&self.ctx);
        // SAFETY: operands initialised in the same context; failure reported by return.
        let mut ok = unsafe {
            fm::fmpz_mpoly_gcd_zippel2(&mut g.raw, &self.raw, &other.raw, self.ctx.ptr())
        };
        if ok == 0 {
            // SAFETY: as above.
            ok = unsafe { fm::fmpz_mpoly_gcd(&mut g.raw, &self.raw, &other.raw, self.ctx.ptr()) };
        }
        if ok == 0 {
            return Err(FlintError::Failed("a gcd"));
        }
        Ok(g)
    }

    /// The square root with positive leading coefficient, if the polynomial is a
    /// perfect square.
    pub fn sqrt(&self) -> Option<Poly> {
        let mut q = Poly::blank(&self.ctx);
        // SAFETY: operands initialised in the same context.
        let ok = unsafe { fm::fmpz_mpoly_sqrt(&mut q.raw, &self.raw, self.ctx.ptr()) };
        if ok == 0 {
            return None;
        }
        Some(if q.leading_coefficient() < 0 {
            q.neg()
        } else {
            q
        })
    }

    /// The coefficients in term order.
    pub fn coefficients(&self) -> Vec<Integer> {
        let mut out = Vec::with_capacity(self.len());
        self.for_each_term(|c, _| out.push(c.clone()));
        out
    }

    /// The gcd of the integer coefficients, with the sign of the leading coefficient
    /// (0 for the zero polynomial), so that `self / content` has a positive leading
    /// coefficient.
    pub fn integer_content(&self) -> Integer {
        let cs = self.coefficients();
        let mut g = Integer::new();
        for c in &cs {
            g.gcd_mut(c);
            if g == 1 {
                break;
            }
        }
        if cs.first().is_some_and(|c| *c < 0) {
            g = -g;
        }
        g
    }

    /// The leading coefficient (0 for the zero polynomial).
    pub fn leading_coefficient(&self) -> Integer {
        if self.is_zero() {
            return Integer::new();
        }
        self.term_coefficient(0)
    }

    /// The exponents of term `i` into `exps` (one entry per variable).
    fn term_exponents(&self, i: usize, exps: &mut [u64]) {
        assert!(i < self.len() && exps.len() == self.ctx.nvars);
        // SAFETY: i < len; the buffer has nvars entries (checked); exponents of
        // polynomials built here fit in 64 bits.
        unsafe {
            fm::fmpz_mpoly_get_term_exp_ui(exps.as_mut_ptr(), &self.raw, i as i64, self.ctx.ptr())
        };
    }

    fn term_coefficient(&self, i: usize) -> Integer {
        let mut f = Fmpz::new();
        // SAFETY: i < len (callers), f initialised.
        unsafe {
            fm::fmpz_mpoly_get_term_coeff_fmpz(&mut f.0, &self.raw, i as i64, self.ctx.ptr())
        };
        f.to_integer()
    }

    /// Calls `f(coefficient, exponents)` for every term, in the (lexicographic) term order.
    pub fn for_each_term(&self, mut f: impl FnMut(&Integer, &[u64])) {
        let n = self.ctx.nvars;
        let mut exps = vec![0u64; n];
        // one Integer for every coefficient in turn (an allocation only when one grows)
        let mut c = Integer::new();
        for i in 0..self.len() {
            self.term_coefficient_into(i, &mut c);
            self.term_exponents(i, &mut exps);
            f(&c, &exps);
        }
    }

    /// The coefficient of term `i` into `c`.
    fn term_coefficient_into(&self, i: usize, c: &mut Integer) {
        assert!(i < self.len());
        // SAFETY: i < len, so `coeffs + i` is an initialised fmpz of the polynomial;
        // `c` is a valid mpz.
        unsafe { fz::fmpz_get_mpz(c.as_raw_mut() as *mut __mpz_struct, self.raw.coeffs.add(i)) };
    }

    /// Builds a polynomial from terms (repeated monomials are added up).  Each exponent
    /// slice must have one entry per variable.
    pub fn from_terms<'a>(
        ctx: &Arc<Ctx>,
        terms: impl IntoIterator<Item = (&'a Integer, &'a [u64])>,
    ) -> Poly {
        let mut p = Poly::blank(ctx);
        for (c, e) in terms {
            assert_eq!(e.len(), ctx.nvars, "exponent vector of the wrong length");
            let f = Fmpz::from_integer(c);
            // SAFETY: exponent vector has nvars entries (checked).
            unsafe { fm::fmpz_mpoly_push_term_fmpz_ui(&mut p.raw, &f.0, e.as_ptr(), ctx.ptr()) };
        }
        // SAFETY: initialised polynomial; sorting and combining make it canonical.
        unsafe {
            fm::fmpz_mpoly_sort_terms(&mut p.raw, ctx.ptr());
            fm::fmpz_mpoly_combine_like_terms(&mut p.raw, ctx.ptr());
        }
        p
    }

    /// The degree in each variable (−1 for every variable of the zero polynomial).
    pub fn degrees(&self) -> Vec<i64> {
        let mut d = vec![0i64; self.ctx.nvars];
        // SAFETY: buffer has nvars entries.
        unsafe { fm::fmpz_mpoly_degrees_si(d.as_mut_ptr(), &self.raw, self.ctx.ptr()) };
        d
    }

    /// The degree in variable `i` (−1 for the zero polynomial).
    pub fn degree(&self, i: usize) -> i64 {
        assert!(i < self.ctx.nvars, "variable index out of range");
        // SAFETY: index checked.
        unsafe { fm::fmpz_mpoly_degree_si(&self.raw, i as i64, self.ctx.ptr()) }
    }

    /// The indices of the variables that occur.
    pub fn used_vars(&self) -> Vec<usize> {
        let mut used = vec![0 as libc::c_int; self.ctx.nvars];
        // SAFETY: buffer has nvars entries.
        unsafe { fm::fmpz_mpoly_used_vars(used.as_mut_ptr(), &self.raw, self.ctx.ptr()) };
        (0..self.ctx.nvars).filter(|&i| used[i] != 0).collect()
    }

    /// The partial derivative with respect to variable `i`.
    pub fn derivative(&self, i: usize) -> Poly {
        assert!(i < self.ctx.nvars, "variable index out of range");
        let mut p = Poly::blank(&self.ctx);
        // SAFETY: index checked, operands initialised.
        unsafe { fm::fmpz_mpoly_derivative(&mut p.raw, &self.raw, i as i64, self.ctx.ptr()) };
        p
    }

    /// The coefficient of `xᵢ^e` when the polynomial is viewed as a polynomial in `xᵢ`.
    pub fn coefficient_in(&self, i: usize, e: u64) -> Poly {
        assert!(i < self.ctx.nvars, "variable index out of range");
        let mut p = Poly::blank(&self.ctx);
        let vars = [i as i64];
        let exps = [e];
        // SAFETY: one variable index (checked) with one exponent.
        unsafe {
            fm::fmpz_mpoly_get_coeff_vars_ui(
                &mut p.raw,
                &self.raw,
                vars.as_ptr(),
                exps.as_ptr(),
                1,
                self.ctx.ptr(),
            )
        };
        p
    }

    /// The coefficients when the polynomial is viewed as a polynomial in the variables
    /// `vars` (each a polynomial in the other variables), in no particular order.
    ///
    /// ```
    /// use eulertop::algebra::flint::{Ctx, Poly};
    /// let ctx = Ctx::new(2);
    /// let (x, y) = (Poly::var(&ctx, 0), Poly::var(&ctx, 1));
    /// let p = x.mul(&y).add(&x).add(&y.mul(&y));         // (x)·y + (1)·y² + x
    /// let mut lens: Vec<usize> = p.coefficients_in(&[1]).iter().map(|c| c.len()).collect();
    /// lens.sort();
    /// assert_eq!(lens, vec![1, 1, 1]);
    /// ```
    pub fn coefficients_in(&self, vars: &[usize]) -> Vec<Poly> {
        assert!(
            vars.iter().all(|&i| i < self.ctx.nvars),
            "variable index out of range"
        );
        let mut groups: std::collections::HashMap<Vec<u64>, Poly> =
            std::collections::HashMap::new();
        let mut exps = vec![0u64; self.ctx.nvars];
        let mut f = Fmpz::new();
        for i in 0..self.len() {
            self.term_exponents(i, &mut exps);
            // SAFETY: i < len; f is initialised.
            unsafe {
                fm::fmpz_mpoly_get_term_coeff_fmpz(&mut f.0, &self.raw, i as i64, self.ctx.ptr())
            };
            let key: Vec<u64> = vars.iter().map(|&v| exps[v]).collect();
            for &v in vars {
                exps[v] = 0;
            }
            let p = groups.entry(key).or_insert_with(|| Poly::blank(&self.ctx));
            // SAFETY: the exponent buffer has nvars entries; p and f are initialised.
            unsafe {
                fm::fmpz_mpoly_push_term_fmpz_ui(&mut p.raw, &f.0, exps.as_ptr(), self.ctx.ptr())
            };
        }
        let mut out: Vec<Poly> = groups.into_values().collect();
        for p in &mut out {
            // SAFETY: initialised polynomial; sorting and combining make it canonical.
            unsafe {
                fm::fmpz_mpoly_sort_terms(&mut p.raw, self.ctx.ptr());
                fm::fmpz_mpoly_combine_like_terms(&mut p.raw, self.ctx.ptr());
            }
        }
        out
    }

    /// The gcd of the coefficients when the polynomial is viewed as a polynomial in the
    /// variables `vars` (with coefficients in the other variables).
    pub fn content_in(&self, vars: &[usize]) -> Result<Poly, FlintError> {
        let mut v: Vec<i64> = vars.iter().map(|&i| i as i64).collect();
        assert!(
            vars.iter().all(|&i| i < self.ctx.nvars),
            "variable index out of range"
        );
        let mut g = Poly::blank(&self.ctx);
        // SAFETY: indices checked; FLINT reads the index array only.
        let ok = unsafe {
            fm::fmpz_mpoly_content_vars(
                &mut g.raw,
                &self.raw,
                v.as_mut_ptr(),
                v.len() as i64,
                self.ctx.ptr(),
            )
        };
        if ok == 0 {
            return Err(FlintError::Failed("a content"));
        }
        Ok(g)
    }

    /// The remainder of `self` on division by `divisors` (multivariate division in the
    /// lexicographic order).  When the divisors are a Gröbner basis with leading
    /// coefficients ±1, the remainder is the unique normal form.
    pub fn rem_ideal(&self, divisors: &[&Poly]) -> Poly {
        if divisors.is_empty() {
            return self.clone();
        }
        for d in divisors {
            self.same_ctx(d);
            assert!(!d.is_zero(), "zero divisor polynomial");
        }
        let mut qs: Vec<Poly> = divisors.iter().map(|_| Poly::blank(&self.ctx)).collect();
        let mut qp: Vec<*mut fmpz_mpoly_struct> =
            qs.iter_mut().map(|q| &mut q.raw as *mut _).collect();
        let bp: Vec<*mut fmpz_mpoly_struct> = divisors
            .iter()
            .map(|d| &d.raw as *const _ as *mut fmpz_mpoly_struct)
            .collect();
        let mut r = Poly::blank(&self.ctx);
        // SAFETY: all polynomials initialised in the same context, none zero; FLINT only
        // reads the divisors (the `*mut` in the binding is a C `const` array of pointers).
        unsafe {
            fm::fmpz_mpoly_divrem_ideal(
                qp.as_mut_ptr(),
                &mut r.raw,
                &self.raw,
                bp.as_ptr(),
                bp.len() as i64,
                self.ctx.ptr(),
            )
        };
        r
    }

    /// The factorisation into irreducible factors over ℤ.
    pub fn factor(&self) -> Result<Factored, FlintError> {
        if self.is_zero() {
            return Err(FlintError::DivisionByZero);
        }
        let mut raw = MaybeUninit::<fmpz_mpoly_factor_struct>::uninit();
        // SAFETY: init fully initialises the factor struct; it is cleared below.
        let mut f = unsafe {
            fmf::fmpz_mpoly_factor_init(raw.as_mut_ptr(), self.ctx.ptr());
            raw.assume_init()
        };
        // SAFETY: initialised operands in the same context.
        let ok = unsafe { fmf::fmpz_mpoly_factor(&mut f, &self.raw, self.ctx.ptr()) };
        let result = if ok == 0 {
            Err(FlintError::Failed("a factorisation"))
        } else {
            Ok(self.read_factors(&mut f))
        };
        // SAFETY: initialised above, cleared once.
        unsafe { fmf::fmpz_mpoly_factor_clear(&mut f, self.ctx.ptr()) };
        result
    }

    fn read_factors(&self, f: &mut fmpz_mpoly_factor_struct) -> Factored {
        let mut c = Fmpz::new();
        // SAFETY: `f` holds a successful factorisation; indices below its length.
        unsafe {
            fmf::fmpz_mpoly_factor_get_constant_fmpz(&mut c.0, f, self.ctx.ptr());
            let n = fmf::fmpz_mpoly_factor_length(f, self.ctx.ptr());
            let mut factors = Vec::with_capacity(n as usize);
            for i in 0..n {
                let mut b = Poly::blank(&self.ctx);
                fmf::fmpz_mpoly_factor_get_base(&mut b.raw, f, i, self.ctx.ptr());
                let e = fmf::fmpz_mpoly_factor_get_exp_si(f, i, self.ctx.ptr());
                factors.push((b, e as u64));
            }
            Factored {
                constant: c.to_integer(),
                factors,
            }
        }
    }

    /// Renders the polynomial with the given variable names, in SymPy/Python syntax
    /// (`3*x^2` is written `3*x**2`).
    pub fn render(&self, names: &[String]) -> String {
        if self.is_zero() {
            return "0".to_string();
        }
        let mut out = String::new();
        self.for_each_term(|c, e| {
            let mono: Vec<String> = e
                .iter()
                .enumerate()
                .filter(|&(_, &k)| k > 0)
                .map(|(i, &k)| {
                    let name = names.get(i).cloned().unwrap_or_else(|| format!("x{i}"));
                    if k == 1 { name } else { format!("{name}**{k}") }
                })
                .collect();
            let neg = *c < 0;
            let abs = c.clone().abs();
            if out.is_empty() {
                out.push_str(if neg { "-" } else { "" });
            } else {
                out.push_str(if neg { " - " } else { " + " });
            }
            if mono.is_empty() {
                out.push_str(&abs.to_string());
            } else if abs == 1 {
                out.push_str(&mono.join("*"));
            } else {
                out.push_str(&format!("{abs}*{}", mono.join("*")));
            }
        });
        out
    }
}

/// The factorisation of a non-zero integer: its sign and the primes with multiplicities.
pub fn factor_integer(n: &Integer) -> Result<(i32, Vec<(Integer, u64)>), FlintError> {
    if *n == 0 {
        return Err(FlintError::DivisionByZero);
    }
    let x = Fmpz::from_integer(n);
    let mut raw = MaybeUninit::<fmpz_factor_struct>::uninit();
    // SAFETY: init fully initialises the struct, cleared below; entries read below `num`.
    unsafe {
        ff::fmpz_factor_init(raw.as_mut_ptr());
        let mut f = raw.assume_init();
        ff::fmpz_factor(&mut f, &x.0);
        let mut out = Vec::with_capacity(f.num as usize);
        for i in 0..f.num as usize {
            out.push((fmpz_to_integer(f.p.add(i)), *f.exp.add(i)));
        }
        let sign = f.sign;
        ff::fmpz_factor_clear(&mut f);
        Ok((sign, out))
    }
}

/// The Hermite normal form of the integer matrix with the given rows, without its zero
/// rows: a basis of the lattice the rows generate.
pub fn hnf_rows(rows: &[Vec<Integer>]) -> Vec<Vec<Integer>> {
    let r = rows.len();
    let c = rows.first().map_or(0, |row| row.len());
    if r == 0 || c == 0 {
        return Vec::new();
    }
    assert!(
        rows.iter().all(|row| row.len() == c),
        "rows of different lengths"
    );
    let mut a = MaybeUninit::<fmpz_mat_struct>::uninit();
    let mut h = MaybeUninit::<fmpz_mat_struct>::uninit();
    // SAFETY: both matrices initialised with r×c entries, indices below r and c,
    // cleared once at the end.
    unsafe {
        fmat::fmpz_mat_init(a.as_mut_ptr(), r as i64, c as i64);
        fmat::fmpz_mat_init(h.as_mut_ptr(), r as i64, c as i64);
        let (mut a, mut h) = (a.assume_init(), h.assume_init());
        for (i, row) in rows.iter().enumerate() {
            for (j, v) in row.iter().enumerate() {
                let e = fmat::fmpz_mat_entry(&a, i as i64, j as i64);
                fz::fmpz_set_mpz(e, v.as_raw() as *const __mpz_struct);
            }
        }
        fmat::fmpz_mat_hnf(&mut h, &a);
        let mut out = Vec::new();
        for i in 0..r {
            let row: Vec<Integer> = (0..c)
                .map(|j| fmpz_to_integer(fmat::fmpz_mat_entry(&h, i as i64, j as i64)))
                .collect();
            if row.iter().any(|v| *v != 0) {
                out.push(row);
            }
        }
        fmat::fmpz_mat_clear(&mut a);
        fmat::fmpz_mat_clear(&mut h);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn xyz() -> (Arc<Ctx>, Poly, Poly, Poly) {
        let ctx = Ctx::new(3);
        let (x, y, z) = (Poly::var(&ctx, 0), Poly::var(&ctx, 1), Poly::var(&ctx, 2));
        (ctx, x, y, z)
    }

    #[test]
    fn ring_operations_and_equality() {
        let (ctx, x, y, _) = xyz();
        let lhs = x.add(&y).pow(2).unwrap();
        let two = Poly::from_i64(&ctx, 2);
        let rhs = x.mul(&x).add(&two.mul(&x).mul(&y)).add(&y.mul(&y));
        assert_eq!(lhs, rhs);
        assert!(lhs.sub(&rhs).is_zero());
        assert_ne!(lhs, x);
        assert_eq!(lhs.len(), 3);
        assert_eq!(two.as_constant(), Some(Integer::from(2)));
        assert_eq!(x.as_constant(), None);
    }

    #[test]
    fn exact_division_and_gcd() {
        let (ctx, x, y, _) = xyz();
        let a = x.sub(&y);
        let b = x.add(&y);
        let p = a.mul(&b);
        assert_eq!(p.divides(&a).unwrap(), Some(b.clone()));
        assert_eq!(p.divides(&x).unwrap(), None);
        assert_eq!(
            p.divides(&Poly::zero(&ctx)),
            Err(FlintError::DivisionByZero)
        );
        let g = p.gcd(&a.mul(&x)).unwrap();
        // gcd is x − y up to sign, normalised to a positive leading coefficient
        assert_eq!(g, a);
        let six = p.scale(&Integer::from(6));
        assert_eq!(
            six.div_integer(&Integer::from(3)).unwrap(),
            p.scale(&Integer::from(2))
        );
        assert_eq!(p.div_integer(&Integer::from(2)), Err(FlintError::Inexact));
        assert_eq!(six.integer_content(), Integer::from(6));
        assert_eq!(six.neg().integer_content(), Integer::from(-6));
    }

    #[test]
    fn factorisation_of_a_difference_of_squares_with_content() {
        let (_, x, y, z) = xyz();
        // −12 (x − y)² (x + y) z
        let p = x
            .sub(&y)
            .pow(2)
            .unwrap()
            .mul(&x.add(&y))
            .mul(&z)
            .scale(&Integer::from(-12));
        let f = p.factor().unwrap();
        assert_eq!(f.constant, Integer::from(-12));
        let mut back = Poly::from_integer(p.ctx(), &f.constant);
        for (b, e) in &f.factors {
            assert!(b.leading_coefficient() > 0);
            back = back.mul(&b.pow(*e).unwrap());
        }
        assert_eq!(back, p);
        let exps: Vec<u64> = f.factors.iter().map(|(_, e)| *e).collect();
        assert_eq!(exps.iter().sum::<u64>(), 4);
        assert!(exps.contains(&2));
    }

    #[test]
    fn remainder_modulo_square_relations() {
        // r > s > x in lex; relations r² − x, s² − (1 − x)
        let ctx = Ctx::new(3);
        let (r, s, x) = (Poly::var(&ctx, 0), Poly::var(&ctx, 1), Poly::var(&ctx, 2));
        let one = Poly::from_i64(&ctx, 1);
        let g1 = r.mul(&r).sub(&x);
        let g2 = s.mul(&s).sub(&one.sub(&x));
        // (r + s)² = x + (1 − x) + 2rs = 1 + 2rs
        let p = r.add(&s).pow(2).unwrap();
        let rem = p.rem_ideal(&[&g1, &g2]);
        let expect = one.add(&r.mul(&s).scale(&Integer::from(2)));
        assert_eq!(rem, expect);
        // r⁴ = x²
        assert_eq!(r.pow(4).unwrap().rem_ideal(&[&g1, &g2]), x.mul(&x));
    }

    #[test]
    fn derivative_degrees_coefficients_and_content() {
        let (ctx, x, y, z) = xyz();
        let p = x.pow(3).unwrap().mul(&y).add(&z.mul(&x)); // x³y + xz
        let three = Poly::from_i64(&ctx, 3);
        assert_eq!(p.derivative(0), three.mul(&x.mul(&x)).mul(&y).add(&z));
        assert_eq!(p.degrees(), vec![3, 1, 1]);
        assert_eq!(p.degree(1), 1);
        assert_eq!(p.used_vars(), vec![0, 1, 2]);
        assert_eq!(p.coefficient_in(0, 3), y);
        assert_eq!(p.coefficient_in(0, 1), z);
        assert_eq!(p.coefficient_in(0, 2), Poly::zero(&ctx));
        // content in x of x³y + x z·y is y
        let q = p.mul(&y);
        assert_eq!(
            q.content_in(&[0]).unwrap(),
            y.mul(&y).gcd(&z.mul(&y)).unwrap()
        );
    }

    #[test]
    fn terms_round_trip_and_render() {
        let (ctx, x, y, _) = xyz();
        let p = x
            .mul(&x)
            .scale(&Integer::from(-3))
            .add(&y)
            .sub(&Poly::from_i64(&ctx, 5));
        let mut terms: Vec<(Integer, Vec<u64>)> = Vec::new();
        p.for_each_term(|c, e| terms.push((c.clone(), e.to_vec())));
        let back = Poly::from_terms(&ctx, terms.iter().map(|(c, e)| (c, e.as_slice())));
        assert_eq!(back, p);
        let names: Vec<String> = ["a", "b", "c"].iter().map(|s| s.to_string()).collect();
        assert_eq!(p.render(&names), "-3*a**2 + b - 5");
        let sq = p.mul(&p);
        assert_eq!(sq.sqrt().map(|r| r.mul(&r)), Some(sq.clone()));
        assert_eq!(p.sqrt(), None);
        assert_eq!(Poly::zero(&ctx).render(&names), "0");
    }

    #[test]
    fn integer_factorisation_and_hnf() {
        let (sign, f) = factor_integer(&Integer::from(-360)).unwrap();
        assert_eq!(sign, -1);
        let f: Vec<(i64, u64)> = f.iter().map(|(p, e)| (p.to_i64().unwrap(), *e)).collect();
        assert_eq!(f, vec![(2, 3), (3, 2), (5, 1)]);
        assert!(factor_integer(&Integer::new()).is_err());
        // lattice generated by (2, 0), (1, 1), (0, 2): basis (1, 1), (0, 2)
        let rows: Vec<Vec<Integer>> = [[2, 0], [1, 1], [0, 2]]
            .iter()
            .map(|r| r.iter().map(|&v| Integer::from(v)).collect())
            .collect();
        let h = hnf_rows(&rows);
        let h: Vec<Vec<i64>> = h
            .iter()
            .map(|r| r.iter().map(|v| v.to_i64().unwrap()).collect())
            .collect();
        assert_eq!(h, vec![vec![1, 1], vec![0, 2]]);
    }
}
