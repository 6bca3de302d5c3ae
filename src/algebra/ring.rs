//! The ring: a FLINT context, the symbol table (indeterminates, transcendental symbols,
//! square-root symbols with their relations), the domain points of the shadows, and
//! the record of assumptions a proof rests on.
//!
//! Variables of the FLINT context are laid out so that the relations form a Gröbner
//! basis in the lexicographic order: root symbol `i` (the `i`-th square root adjoined)
//! is variable `R − 1 − i`, so every root is more significant than the roots and
//! field variables its radicand uses, and field variable `j` (indeterminates and
//! transcendental symbols such as `sn` of a base argument) is variable `R + j`.  The
//! leading monomial of `rᵢ² − aᵢ` is then `rᵢ²`, and these are pairwise coprime.

use super::den_factors::DenFactors;
use super::error::{AlgResult, AlgebraError};
use super::flint::{Ctx, Poly};
use super::node::Node;
use super::shadow::Shadow;
use super::sign_state::SignState;
use super::square_classes::FactorBasis;
use super::val::Val;
use rug::{Assign, Complex, Float, Rational};
use std::sync::{Arc, Mutex, MutexGuard};

/// Options of a [`Ring`].
#[derive(Clone, Debug)]
pub struct RingOptions {
    /// Number of domain points at which every value carries its numeric shadow.
    pub points: usize,
    /// MPFR precision of the shadows, in bits.
    pub precision: u32,
    /// Capacity for square-root symbols (fewer variables make FLINT faster;
    /// [`crate::algebra::prove_identity`] doubles the capacities when they run out).
    pub max_roots: usize,
    /// Capacity for field variables (indeterminates and transcendental symbols).
    pub max_vars: usize,
    /// Record the derivation of every value, for certificates.
    pub certificate: bool,
    /// Replace named quantities by their definitions instead of free symbols.
    pub expand_named: bool,
    /// The size bound of intermediate values, in terms (by default `MAX_TERMS`).
    pub max_terms: usize,
    /// Base arguments of the elliptic functions to start from (see
    /// [`crate::algebra::prove_identity`], which fills this in on a restart).
    pub base_hints: Vec<super::base_table::BaseHint>,
    /// A parametrization of the domain with which signs are proved (module
    /// [`super::positivity`]): the signs that `abs` and `sign` in a claim's formulas take.
    pub positivity: Option<Arc<super::parametrization::Parametrization>>,
    /// The signs that define the part of the domain the proof is on (module
    /// [`super::split`]): a value equal to one of them, or to its negative, has that sign.
    pub hypotheses: Vec<(super::sign_state::SignSplit, i32)>,
    /// Values of the claim's indeterminates whose sign differs between domain points and
    /// that the proof carries as sign symbols instead of splitting the domain by them
    /// (see [`Sym::folded_sign`](super::Sym)).
    pub sign_folds: Vec<super::sign_state::SignSplit>,
    /// The time and memory the attempt may take (see [`super::Budget`]).
    pub budget: super::budget::Budget,
    /// Jacobi functions as jet symbols (module `jets`, for the ODE method of
    /// [`super::ode`]) instead of expansions by the addition theorems.
    pub jets: bool,
}

/// The largest numerator plus denominator, in terms, that the prover works with at
/// first ([`RingOptions::max_terms`]); beyond it a proof stops with
/// [`AlgebraError::TooLarge`], or restarts on other bases or, once, with twice the bound
/// when the overflow is less than twice the bound (such values come from iterations
/// written out in a claim, such as Newton steps, not from the paper's identities).
pub const MAX_TERMS: usize = 8_000;

impl Default for RingOptions {
    fn default() -> Self {
        RingOptions {
            points: 3,
            precision: 256,
            max_roots: 16,
            max_vars: 16,
            certificate: false,
            expand_named: false,
            max_terms: MAX_TERMS,
            base_hints: Vec::new(),
            jets: false,
            positivity: None,
            hypotheses: Vec::new(),
            sign_folds: Vec::new(),
            budget: super::budget::Budget::default(),
        }
    }
}

/// Where a decision came from: a definition the claim uses, or the claim's own text.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Origin {
    /// The claim's own formulas.
    Claim,
    /// A named definition (e.g. `nu`), whose branch the definition fixes.
    Definition(String),
}

/// What a proof rests on besides algebra: never a decision taken at domain points.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AssumptionKind {
    /// The solution branch of an implicit map (its name), which a hypothesis of the
    /// claim must state.
    Branch(String),
    /// The value of a step proved by another claim (its id), a lemma of the proof.
    Lemma(String),
    /// A hypothesis the claim states (its label), by which a sign was decided.
    Hypothesis(String),
}

/// A fact a proof rests on (see [`AssumptionKind`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Assumption {
    /// The statement, e.g. the branch the solver selects.
    pub statement: String,
    /// What kind of fact it is.
    pub kind: AssumptionKind,
    /// Where the decided expression came from.
    pub origin: Origin,
}

/// What a field variable stands for.
#[derive(Clone, Debug)]
pub(crate) enum VarKind {
    /// An independent indeterminate of the claim.
    Indeterminate,
    /// A named quantity kept as a free symbol; its definition serves for derivatives.
    Named(Box<Val>),
    /// `sn` of base argument `base` of elliptic table `table`.
    Sn { table: usize, base: usize },
    /// `E(am u, k) − k'² u` of a base argument (for derivatives in the modulus).
    Zeta { table: usize, base: usize },
    /// The quarter period `K(k)` of a table.
    QuarterK { table: usize },
    /// The complementary quarter period `K'(k)` of a table.
    QuarterKp { table: usize },
    /// `sn(K/3)` of a table: algebraic over the modulus, a root of its triplication
    /// polynomial (module `thirds`).
    ThirdK { table: usize },
    /// A symbol the prover cannot expand (constant: derivative 0, else unknown).
    Opaque { constant: bool },
    /// Jet symbol `f` (0: sn, 1: cn, 2: dn) of an argument at a modulus (module `jets`):
    /// the trio's sn is field variable `s`, its cn `s + 1`, its dn `s + 2`.
    Jet {
        f: u8,
        s: usize,
        arg: Box<Val>,
        k: Box<Val>,
    },
}

/// The functions of a jet trio, in the order of [`VarKind::Jet`]'s `f`.
pub(crate) const JET_NAMES: [&str; 3] = ["sn", "cn", "dn"];

/// What a field variable of kind `k` is, for the reader.
pub(crate) fn describe_kind(k: &VarKind) -> String {
    match k {
        VarKind::Indeterminate => "indeterminate".into(),
        VarKind::Named(_) => "named quantity (free symbol)".into(),
        VarKind::Sn { .. } => "sn of a base argument".into(),
        VarKind::Zeta { .. } => "E(am u, k) - k'^2 u of a base argument".into(),
        VarKind::QuarterK { .. } => "quarter period K(k)".into(),
        VarKind::QuarterKp { .. } => "complementary quarter period K'(k)".into(),
        VarKind::ThirdK { .. } => "sn(K/3), a root of its triplication polynomial".into(),
        VarKind::Opaque { .. } => "opaque symbol".into(),
        VarKind::Jet { f, .. } => format!("{} of an argument (jet symbol)", JET_NAMES[*f as usize]),
    }
}

#[derive(Clone, Debug)]
pub(crate) struct VarInfo {
    pub name: String,
    pub kind: VarKind,
    pub values: Vec<Complex>,
}

#[derive(Clone, Debug)]
pub(crate) struct RootInfo {
    pub name: String,
    /// The radicand, a polynomial in field variables and earlier roots.
    pub radicand: Poly,
    /// `r² − radicand`.
    pub relation: Arc<Poly>,
    pub values: Vec<Complex>,
    /// This root and every root its radicand depends on (transitively).
    pub closure: Vec<usize>,
    /// What the root is, for the reader (e.g. `cn(phi)`).
    pub note: String,
    /// Whether the root is real by construction (`cn`, `dn` of a real base argument).
    pub real: bool,
    /// Whether the root is the principal square root of its radicand wherever that is
    /// positive (false for a sign symbol and for a root with prescribed values, such as
    /// `cn u` for `√(1 − sn²u)`): only then is it the positive root where its radicand
    /// is proved positive.
    pub principal: bool,
}

/// A field variable `v` with `sn v`, `cn v`, `dn v` known at modulus `k`.
#[derive(Clone, Debug)]
pub(crate) struct Prescription {
    pub var: usize,
    pub k: Val,
    pub s: Val,
    pub c: Val,
    pub d: Val,
    /// The symbol, for notes.
    pub what: String,
    /// Why the values hold.
    pub why: String,
    /// An argument with the same sn, cn, dn (so equal to the symbol modulo 4K), which
    /// replaces the symbol inside sn, cn, dn.
    pub equiv: Option<Val>,
    /// A product `σ` of sign symbols when the values are `σ` times sn and cn of `equiv`
    /// (and its dn): the symbol is `equiv + (1 − σ)K` modulo 4K, and an integer multiple
    /// `q` of it inside sn, cn, dn is replaced by `q·equiv`, with sn and cn multiplied by
    /// `σ^q` (DLMF 22.4.3: sn, cn change sign under a shift by 2K, dn does not).
    pub equiv_sign: Option<Val>,
    /// The derivations of `s`, `c`, `d`, when the ring records them (for certificates).
    pub nodes: Option<[Arc<Node>; 3]>,
}

/// A value as the ring stores it: without the ring handle (see [`Val`]), with its
/// derivation when the ring records certificates.
pub(crate) type Stored = (Val, Option<Arc<Node>>);

/// A remembered value of an implicit function: its shape and components.
pub(crate) type ImplicitValue = (String, Vec<Stored>);

/// A change of variables (module [`super::coordinates`]): the claim's variables as
/// values in new indeterminates, the parameters, and the inverse Jacobian `D⁻¹` once
/// computed.
#[derive(Clone, Default)]
pub(crate) struct Coordinates {
    pub coords: Vec<Stored>,
    /// The claim's name of each coordinate (`x`, or `M[2]` for a component), where known.
    pub names: Vec<String>,
    pub params: Vec<Stored>,
    pub inverse: Option<Vec<Vec<Stored>>>,
}

/// The mutable part of a ring.
pub(crate) struct State {
    pub vars: Vec<VarInfo>,
    pub roots: Vec<RootInfo>,
    pub basis: FactorBasis,
    pub tables: Vec<super::base_table::Table>,
    pub assumptions: Vec<Assumption>,
    /// Steps the certificate format does not record (a proof with one has no certificate).
    pub uncertified: Vec<String>,
    pub notes: Vec<String>,
    pub error: Option<AlgebraError>,
    pub origin: Origin,
    pub i_root: Option<usize>,
    pub tower_roots: bool,
    pub rebase_wanted: bool,
    pub dcache: std::collections::HashMap<(usize, usize), Val>,
    pub derivation_lines: Vec<String>,
    /// Opaque function values already made: `f(args)` (rendered) → the symbol.
    pub opaque_calls: std::collections::BTreeMap<String, Stored>,
    /// Values of implicitly defined functions at given arguments (see [`Ring::remember`]).
    pub implicit_values: std::collections::BTreeMap<String, ImplicitValue>,
    /// A symbol or root could not be added for lack of room (the build may have
    /// recovered, or reported it as a message).
    pub capacity_hit: bool,
    /// Symbols whose sn, cn, dn at a modulus are known (see [`Ring::prescribe_sncndn`]).
    pub prescribed: Vec<Prescription>,
    /// The arguments of opaque calls, by the field variable of the call's symbol.
    pub opaque_args: std::collections::BTreeMap<usize, (String, Vec<Stored>)>,
    /// The symbol `Z = E(am v, k) − k'² v` of an opaque symbol `v` with prescribed sn, cn,
    /// dn, by the field variable of `v` (for its derivative when the modulus varies).
    pub opaque_zeta: std::collections::BTreeMap<usize, usize>,
    /// The change of variables of a parametrization, for derivatives.
    pub coordinates: Option<Coordinates>,
    /// [`Inner::var_values`] as last built; emptied when a variable or root is added or
    /// a root's values change.
    pub values_table: Option<Arc<Vec<Vec<Complex>>>>,
    /// The sign-only state: proved signs, stated hypotheses, facts, sign symbols.
    pub signs: SignState,
    /// The operations that made the power series of a proof (module `series_trace`).
    pub series: super::series_trace::SeriesTrace,
    /// Field variables algebraic over the others: `(FLINT variable, defining
    /// polynomial)` (module `algebraic`).
    pub algebraic: Vec<(usize, Arc<Poly>)>,
}

pub(crate) struct Inner {
    pub ctx: Arc<Ctx>,
    pub opts: RingOptions,
    pub state: Mutex<State>,
    /// Remembered factorisations of the ring's denominators.
    pub dens: DenFactors,
    /// Set with the first error: the ring's values are then meaningless, and the
    /// operators stop computing.
    pub poisoned: std::sync::atomic::AtomicBool,
}

/// A tower of fields ℚ(x₁…xₙ)(r₁)…(rₘ), rᵢ² = aᵢ, with numeric shadows at domain
/// points; the factory of [`Sym`](super::Sym) values.  Cloning gives another handle to the same
/// ring.
///
/// ```
/// use eulertop::algebra::{Ring, RingOptions};
/// let ring = Ring::new(RingOptions { points: 2, ..Default::default() });
/// let x = ring.indeterminate_f64("x", &[0.5, 2.0]).unwrap();
/// let one = ring.integer(1);
/// let lhs = (x.clone() + one.clone()) * (x.clone() - one.clone());
/// let rhs = x.clone() * x - one;
/// assert!(ring.prove(&lhs, &rhs).is_proved());
/// ```
#[derive(Clone)]
pub struct Ring {
    pub(crate) inner: Arc<Inner>,
}

impl std::fmt::Debug for Ring {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Ring({} points)", self.inner.opts.points)
    }
}

impl Ring {
    /// A new ring with no symbols.
    pub fn new(opts: RingOptions) -> Ring {
        let ctx = Ctx::new(opts.max_roots + opts.max_vars);
        let state = State {
            vars: Vec::new(),
            roots: Vec::new(),
            basis: FactorBasis::default(),
            tables: Vec::new(),
            assumptions: Vec::new(),
            uncertified: Vec::new(),
            notes: Vec::new(),
            error: None,
            origin: Origin::Claim,
            i_root: None,
            tower_roots: false,
            rebase_wanted: false,
            dcache: std::collections::HashMap::new(),
            derivation_lines: Vec::new(),
            opaque_calls: std::collections::BTreeMap::new(),
            implicit_values: std::collections::BTreeMap::new(),
            coordinates: None,
            prescribed: Vec::new(),
            capacity_hit: false,
            opaque_args: std::collections::BTreeMap::new(),
            opaque_zeta: std::collections::BTreeMap::new(),
            values_table: None,
            series: Default::default(),
            signs: SignState::default(),
            algebraic: Vec::new(),
        };
        Ring {
            inner: Arc::new(Inner {
                ctx,
                opts,
                state: Mutex::new(state),
                dens: DenFactors::default(),
                poisoned: std::sync::atomic::AtomicBool::new(false),
            }),
        }
    }

    /// The options the ring was made with.
    pub fn options(&self) -> &RingOptions {
        &self.inner.opts
    }

    pub(crate) fn state(&self) -> MutexGuard<'_, State> {
        self.inner.state()
    }

    /// Number of domain points.
    pub fn points(&self) -> usize {
        self.inner.opts.points
    }

    /// Shadow precision in bits.
    pub fn precision(&self) -> u32 {
        self.inner.opts.precision
    }

    /// Is this the same ring as `other`?
    pub fn same(&self, other: &Ring) -> bool {
        Arc::ptr_eq(&self.inner, &other.inner)
    }

    /// Sets where the following decisions come from (a definition or the claim).
    pub fn set_origin(&self, origin: Origin) {
        self.state().origin = origin;
    }

    /// Runs `f` with decisions attributed to `origin`, then restores the previous one.
    pub fn with_origin<T>(&self, origin: Origin, f: impl FnOnce() -> T) -> T {
        let prev = std::mem::replace(&mut self.state().origin, origin);
        let out = f();
        self.state().origin = prev;
        out
    }

    /// The assumptions recorded so far.
    pub fn assumptions(&self) -> Vec<Assumption> {
        self.state().assumptions.clone()
    }

    /// The signs proved with the parametrization of the domain (`x > 0`), in order.
    pub fn proved_signs(&self) -> Vec<String> {
        let st = self.state();
        st.signs
            .proved_signs
            .iter()
            .map(|(_, _, s)| s.clone())
            .collect()
    }

    /// The parametrization of the domain, for the reader, when a sign was proved with it.
    pub fn parametrization(&self) -> Option<String> {
        let used = !self.state().signs.proved_signs.is_empty();
        (self.inner.opts.positivity.as_ref())
            .filter(|_| used)
            .map(|p| p.describe())
    }

    /// The first error met inside an operator (`+`, `*`, comparisons, …), which cannot
    /// return a `Result`; the value it produced is meaningless.
    pub fn error(&self) -> Option<AlgebraError> {
        self.state().error.clone()
    }

    /// Whether the ring records derivations for certificates.
    pub(crate) fn certifying(&self) -> bool {
        self.inner.opts.certificate
    }

    pub(crate) fn poison(&self, e: AlgebraError) {
        let mut st = self.state();
        if st.error.is_none() {
            st.error = Some(e);
        }
        self.inner
            .poisoned
            .store(true, std::sync::atomic::Ordering::Relaxed);
    }

    /// Whether an error has been recorded ([`Ring::error`]): no proof on the ring can
    /// succeed any more, so the operators return at once.
    pub(crate) fn is_poisoned(&self) -> bool {
        self.inner
            .poisoned
            .load(std::sync::atomic::Ordering::Relaxed)
    }

    /// The symbols: `(name, what it is)` for field variables and roots.
    pub fn symbols(&self) -> Vec<(String, String)> {
        let st = self.state();
        let mut out: Vec<(String, String)> = st
            .vars
            .iter()
            .map(|v| (v.name.clone(), describe_kind(&v.kind)))
            .collect();
        out.extend(st.roots.iter().map(|r| (r.name.clone(), r.note.clone())));
        out
    }

    /// The relations `r² = a` of the root symbols, rendered.
    pub fn relations(&self) -> Vec<String> {
        let names = self.inner.names();
        let st = self.state();
        st.roots
            .iter()
            .map(|r| format!("{}**2 = {}", r.name, r.radicand.render(&names)))
            .collect()
    }

    /// Notes on the derivation (addition-theorem instances, period shifts used).
    pub fn notes(&self) -> Vec<String> {
        self.state().notes.clone()
    }

    /// Adds a note on the derivation (shown with the proof; repeated notes are kept once).
    pub fn note(&self, s: String) {
        let mut st = self.state();
        if !st.notes.contains(&s) {
            st.notes.push(s);
        }
    }

    /// Records a fact the proof rests on besides algebra (see [`AssumptionKind`]): the
    /// solution branch of an implicit map, a lemma, a stated hypothesis.
    pub fn assume(&self, kind: AssumptionKind, statement: String) {
        let mut st = self.state();
        if st.assumptions.iter().all(|a| a.statement != statement) {
            let origin = st.origin.clone();
            st.assumptions.push(Assumption {
                statement,
                kind,
                origin,
            });
        }
    }

    /// Records a step that the certificate format does not record: the proof then has no
    /// certificate (rather than one a recheck would reject).
    pub fn mark_uncertified(&self, why: &str) {
        let mut st = self.state();
        if !st.uncertified.iter().any(|w| w == why) {
            st.uncertified.push(why.to_string());
        }
    }

    /// A symbol name not yet used in this ring: `base`, else `base` followed by a letter
    /// and a number.
    pub fn fresh_name(&self, base: &str) -> String {
        let st = self.state();
        let taken =
            |n: &str| st.vars.iter().any(|v| v.name == n) || st.roots.iter().any(|r| r.name == n);
        if !taken(base) {
            return base.to_string();
        }
        (2..)
            .map(|j| format!("{base}x{j}"))
            .find(|n| !taken(n))
            .unwrap_or_default()
    }
}

impl Inner {
    pub(crate) fn state(&self) -> MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// FLINT variable of root `i`.
    pub(crate) fn root_var(&self, i: usize) -> usize {
        self.opts.max_roots - 1 - i
    }

    /// FLINT variable of field variable `j`.
    pub(crate) fn kvar(&self, j: usize) -> usize {
        self.opts.max_roots + j
    }

    /// The root index of FLINT variable `idx`, if it is a root.
    pub(crate) fn root_of_var(&self, idx: usize) -> Option<usize> {
        (idx < self.opts.max_roots).then(|| self.opts.max_roots - 1 - idx)
    }

    pub(crate) fn const_val(&self, q: &Rational) -> Val {
        let num = Poly::from_integer(&self.ctx, q.numer());
        let den = Poly::from_integer(&self.ctx, q.denom());
        let prec = self.opts.precision;
        let z = Complex::with_val(prec, (Float::with_val(prec, q), 0));
        Val {
            num,
            den,
            sh: Shadow::leaf(vec![z; self.opts.points]),
        }
    }

    pub(crate) fn add_var(
        &self,
        name: String,
        kind: VarKind,
        values: Vec<Complex>,
    ) -> AlgResult<usize> {
        let mut st = self.state();
        if st.vars.len() >= self.opts.max_vars {
            // noted in the ring too, so the prover restarts with more room when the
            // error reaches it only as a message
            st.capacity_hit = true;
            return Err(AlgebraError::Capacity(format!(
                "more than {} field variables (adding {name})",
                self.opts.max_vars
            )));
        }
        st.vars.push(VarInfo { name, kind, values });
        st.values_table = None;
        Ok(st.vars.len() - 1)
    }

    /// Adjoins a root with relation `r² = radicand` and the given values.
    pub(crate) fn add_root(
        &self,
        name: String,
        radicand: Poly,
        values: Vec<Complex>,
        note: String,
    ) -> AlgResult<usize> {
        let mut st = self.state();
        let i = st.roots.len();
        if i >= self.opts.max_roots {
            st.capacity_hit = true;
            return Err(AlgebraError::Capacity(format!(
                "more than {} square roots",
                self.opts.max_roots
            )));
        }
        let r = Poly::var(&self.ctx, self.root_var(i));
        let relation = Arc::new(r.mul(&r).sub(&radicand));
        let mut closure = vec![i];
        for idx in radicand.used_vars() {
            if let Some(j) = self.root_of_var(idx) {
                closure.extend(st.roots[j].closure.iter().copied());
            }
        }
        closure.sort_unstable();
        closure.dedup();
        st.values_table = None;
        st.roots.push(RootInfo {
            name,
            radicand,
            relation,
            values,
            closure,
            note,
            real: false,
            principal: true,
        });
        Ok(i)
    }

    /// Names of all FLINT variables, for rendering.
    pub(crate) fn names(&self) -> Vec<String> {
        let st = self.state();
        let n = self.ctx.nvars();
        let mut names: Vec<String> = (0..n).map(|i| format!("unused_{i}")).collect();
        for (j, v) in st.vars.iter().enumerate() {
            names[self.kvar(j)] = v.name.clone();
        }
        for (i, r) in st.roots.iter().enumerate() {
            names[self.root_var(i)] = r.name.clone();
        }
        names
    }

    /// The values of every FLINT variable at every point (`[var][point]`; unused
    /// variables are 0), built once until a variable or root is added or changed.
    pub(crate) fn var_values(&self) -> Arc<Vec<Vec<Complex>>> {
        let mut st = self.state();
        if let Some(t) = &st.values_table {
            return t.clone();
        }
        let table = Arc::new(self.build_var_values(&st));
        st.values_table = Some(table.clone());
        table
    }

    fn build_var_values(&self, st: &State) -> Vec<Vec<Complex>> {
        let prec = self.opts.precision;
        let zero = Complex::with_val(prec, 0);
        let mut vals = vec![vec![zero; self.opts.points]; self.ctx.nvars()];
        for (j, v) in st.vars.iter().enumerate() {
            vals[self.kvar(j)] = v.values.clone();
        }
        for (i, r) in st.roots.iter().enumerate() {
            vals[self.root_var(i)] = r.values.clone();
        }
        vals
    }

    /// Evaluates a polynomial at every point from the variables' values.
    pub(crate) fn eval_poly(&self, p: &Poly, vals: &[Vec<Complex>]) -> Vec<Complex> {
        let prec = self.opts.precision;
        let npts = self.opts.points;
        let mut out = vec![Complex::with_val(prec, 0); npts];
        let powers = Powers::new(p, vals, prec);
        let mut t = Complex::new(prec);
        p.for_each_term(|c, e| {
            for (pt, acc) in out.iter_mut().enumerate() {
                t.mut_real().assign(c);
                t.mut_imag().assign(0);
                for (idx, &k) in e.iter().enumerate() {
                    if k > 0 {
                        t *= powers.get(idx, k, pt);
                    }
                }
                *acc += &t;
            }
        });
        out
    }

    /// Evaluates a polynomial at every point with its own error scale: the sum of the
    /// terms' moduli times the number of roundings a term and the sum take (each leaf
    /// value is taken as correct to the working precision).  Direct evaluation bounds
    /// the error by the terms, where the error scales carried through a long
    /// derivation may have grown far beyond them.
    pub(crate) fn eval_poly_scaled(&self, p: &Poly, vals: &[Vec<Complex>]) -> Shadow {
        let prec = self.opts.precision;
        let npts = self.opts.points;
        let mut out = vec![Complex::with_val(prec, 0); npts];
        let mut size = vec![Float::with_val(64, 0); npts];
        let mut roundings = 1u64;
        let powers = Powers::new(p, vals, prec);
        let mut t = Complex::new(prec);
        let mut modulus = Float::new(64);
        p.for_each_term(|c, e| {
            roundings += 2 + e.iter().sum::<u64>();
            for (pt, acc) in out.iter_mut().enumerate() {
                t.mut_real().assign(c);
                t.mut_imag().assign(0);
                for (idx, &k) in e.iter().enumerate() {
                    if k > 0 {
                        t *= powers.get(idx, k, pt);
                    }
                }
                modulus.assign(t.abs_ref());
                size[pt] += &modulus;
                *acc += &t;
            }
        });
        let extra = (roundings as f64).log2();
        let lscale = size
            .iter()
            .map(|s| {
                let (m, e) = s.to_f64_exp();
                if m == 0.0 {
                    0.0
                } else {
                    (m.abs().log2() + e as f64 + extra).max(0.0)
                }
            })
            .collect();
        Shadow::with_scale(out, lscale)
    }

    /// Relations of the roots that occur in `p` and of the roots those depend on.
    pub(crate) fn relations_for(&self, p: &Poly) -> Vec<Arc<Poly>> {
        let st = self.state();
        let mut need: Vec<usize> = Vec::new();
        for idx in p.used_vars() {
            if let Some(i) = self.root_of_var(idx) {
                need.extend(st.roots[i].closure.iter().copied());
            }
        }
        need.sort_unstable();
        need.dedup();
        need.iter().map(|&i| st.roots[i].relation.clone()).collect()
    }
}

/// The powers `vᵏ` of the variables' values at the points, each computed once as
/// `((v·v)·v)…`, the order in which a term's evaluation would compute it.
struct Powers {
    /// `table[idx][k − 1][pt]`.
    table: Vec<Vec<Vec<Complex>>>,
}

impl Powers {
    fn new(p: &Poly, vals: &[Vec<Complex>], prec: u32) -> Powers {
        let degs = p.degrees();
        let table = vals
            .iter()
            .enumerate()
            .map(|(idx, v)| {
                let d = degs.get(idx).copied().unwrap_or(0).max(0) as usize;
                let mut rows: Vec<Vec<Complex>> = Vec::with_capacity(d);
                while rows.len() < d {
                    let row = match rows.last() {
                        None => v.iter().map(|x| Complex::with_val(prec, x)).collect(),
                        Some(prev) => prev
                            .iter()
                            .zip(v)
                            .map(|(a, b)| Complex::with_val(prec, a * b))
                            .collect(),
                    };
                    rows.push(row);
                }
                rows
            })
            .collect();
        Powers { table }
    }

    fn get(&self, idx: usize, k: u64, pt: usize) -> &Complex {
        &self.table[idx][k as usize - 1][pt]
    }
}
