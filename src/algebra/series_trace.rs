//! The operations that made a proof's power series, recorded for its certificate.
//!
//! When a ring records certificates, every [`Series`] that an operation makes gets an
//! id and a record of the operation and its operands.  The certificate then lists, one
//! `sseries` line each, the whole computation, and the checker redoes it with its own
//! series arithmetic from the leaves alone: the series variable, constants (values of
//! the ring, whose derivations the certificate gives as nodes), the square roots of
//! constant terms (nodes with their branch evidence) and the values of `sn`, `cn`, `dn`
//! at constant terms (elliptic nodes).  No coefficient is taken from the prover:
//!
//! ```text
//! series h step 1 order 2 precision 4   # h = t^step; the claim's order; O(t^precision)
//! sseries s1 = var                      # t
//! sseries s2 = const t7                 # the value of node t7
//! sseries s3 = mul s1 s2                # also add, sub, div, deriv (d/dt), bound (O(t^v))
//! sseries s4 = sqrt s3 root t9          # the constant term's root is node t9
//! sseries s5 = sn s3 s2 base t11 t12 t13   # sn(u, k), k constant, from sn, cn, dn(u(0))
//! sseries s6 = cut s5 3                 # known to O(t^3) only
//! sseries s8 = moving s5 s7             # s5 = sn(u, k₀), k₀ s7's constant term: sn(u, s7)
//! schart delta1(s2; s3; s2; s2; s3; s1) value=s9   # an implicit map's series there
//! sclaim s6 component 1 below 2         # the coefficients of t^e, e < 2, are 0
//! srefute s6 component 1 coefficient 1  # a refutation: the coefficient of t^1 is not 0
//! ssolution x = s12; y = s14            # an existence claim's solution, as series
//! ```

use super::series::Series;
use super::sym::Sym;

/// An operation on power series, with the values of the ring it starts from.
#[derive(Clone, Debug)]
pub(crate) enum SOp {
    /// The series variable.
    Var,
    /// A value that does not depend on the series variable.
    Const(Sym),
    /// Sum, difference, product, quotient of the two operands.
    Add,
    Sub,
    Mul,
    Div,
    /// The square root; the value is the root of the operand's constant term.
    Sqrt(Sym),
    /// `sn`, `cn` or `dn` (0, 1, 2) of `(u, k)` from `(sn, cn, dn)(u(0), k)`.
    Jacobi(u8, [Sym; 3]),
    /// The derivative in the series variable.
    Deriv,
    /// The same value known to `O(tʰ)` only.
    Cut(i32),
    /// `O(tᵛ)` for the operand's valuation `v`.
    Bound,
    /// `sn`, `cn` or `dn` at a modulus `k(t) = k₀ + O(tᵛ)` (the second operand): the
    /// first operand, their value at `k₀`, known to `O(tᵛ)`.
    Moving,
}

/// One operation: its kind and the ids of its operands.
#[derive(Clone, Debug)]
pub(crate) struct SRecord {
    pub op: SOp,
    pub args: Vec<u32>,
}

/// The series operations of a ring, and the coefficients a proof claims 0.
#[derive(Clone, Debug, Default)]
pub(crate) struct SeriesTrace {
    pub records: Vec<SRecord>,
    /// `(series id, component, exponent bound)`: the coefficients below the bound are 0.
    pub claims: Vec<(u32, usize, i32)>,
    /// The working precision of the series.
    pub precision: i32,
    /// The charts of implicit maps: the map's name, its arguments' components and its
    /// value's components, as series ids.
    pub charts: Vec<(String, Vec<Vec<u32>>, Vec<u32>)>,
    /// The power-series solution of an existence claim: its unknowns' names and ids.
    pub solution: Vec<(String, u32)>,
    /// `(series id, component, exponent)` of each coefficient a proof tests, in the
    /// order of its components: a refutation names the one that is not 0.
    pub coefficients: Vec<(u32, usize, i32)>,
}

impl Series {
    /// This value as the result of `op` on `args`: recorded, with a fresh id, when the
    /// ring records certificates.  An operand without an id (made by a step that is not
    /// recorded) makes the proof uncertified.
    pub(crate) fn traced(mut self, op: SOp, args: &[&Series]) -> Series {
        let ring = self.ring().clone();
        if !ring.certifying() {
            return self;
        }
        let ids: Option<Vec<u32>> = args.iter().map(|a| a.trace_id()).collect();
        let Some(ids) = ids else {
            ring.mark_uncertified("a power series made by a step the certificate does not record");
            return self;
        };
        let mut st = ring.state();
        st.series.records.push(SRecord { op, args: ids });
        st.series.precision = st.series.precision.max(self.precision());
        let id = st.series.records.len() as u32;
        drop(st);
        self.set_trace_id(id);
        self
    }

    /// Records that `value` is the power series of the implicit map `name` at `args`
    /// (each argument's components): the certificate's `schart` line, which the recheck
    /// substitutes into the map's equations as the catalogue states them.
    pub(crate) fn record_chart(name: &str, args: &[Vec<Series>], value: &[Series]) {
        let Some(ring) = value.first().map(|v| v.ring().clone()) else {
            return;
        };
        if !ring.certifying() {
            return;
        }
        let ids = |xs: &[Series]| {
            xs.iter()
                .map(Series::trace_id)
                .collect::<Option<Vec<u32>>>()
        };
        let argv: Option<Vec<Vec<u32>>> = args.iter().map(|a| ids(a)).collect();
        match (argv, ids(value)) {
            (Some(a), Some(v)) => ring.state().series.charts.push((name.to_string(), a, v)),
            _ => ring.mark_uncertified("a power series whose computation is not recorded"),
        }
    }

    /// Records `x` as the power-series solution of an existence claim in the `unknowns`:
    /// the certificate's `ssolution` line, its claim.
    pub(crate) fn record_solution(unknowns: &[String], x: &[Series]) {
        let Some(ring) = x.first().map(|v| v.ring().clone()) else {
            return;
        };
        if !ring.certifying() {
            return;
        }
        match x.iter().map(Series::trace_id).collect::<Option<Vec<u32>>>() {
            Some(ids) => {
                ring.state().series.solution = unknowns.iter().cloned().zip(ids).collect();
            }
            None => ring.mark_uncertified("a power series whose computation is not recorded"),
        }
    }

    /// Records that the proof tests this value's coefficient of `t^exponent`
    /// (component `component`, from 1): a refutation's certificate names it
    /// (`srefute`).
    pub(crate) fn note_coefficient(&self, component: usize, exponent: i32) {
        let ring = self.ring().clone();
        if !ring.certifying() {
            return;
        }
        if let Some(id) = self.trace_id() {
            let st = &mut ring.state().series;
            st.coefficients.push((id, component, exponent));
        }
    }

    /// Records that the coefficients of this value below `t^below` are 0 (component
    /// `component` of the examined value, from 1); the certificate then claims that.
    pub(crate) fn claim_vanishing(&self, component: usize, below: i32) {
        let ring = self.ring().clone();
        if !ring.certifying() {
            return;
        }
        match self.trace_id() {
            Some(id) => ring.state().series.claims.push((id, component, below)),
            None => ring.mark_uncertified("a power series whose computation is not recorded"),
        }
    }
}

/// The `sseries` line of record `i` (from 1), with `node` giving the certificate's id of
/// a value (`None` when a value has no derivation: no certificate then).
pub(crate) fn record_line(
    i: usize,
    r: &SRecord,
    node: &mut dyn FnMut(&Sym) -> Option<usize>,
) -> Option<String> {
    let a = |j: usize| format!("s{}", r.args[j]);
    let body = match &r.op {
        SOp::Var => "var".to_string(),
        SOp::Const(x) => format!("const t{}", node(x)?),
        SOp::Add => format!("add {} {}", a(0), a(1)),
        SOp::Sub => format!("sub {} {}", a(0), a(1)),
        SOp::Mul => format!("mul {} {}", a(0), a(1)),
        SOp::Div => format!("div {} {}", a(0), a(1)),
        SOp::Sqrt(x) => format!("sqrt {} root t{}", a(0), node(x)?),
        SOp::Jacobi(f, [s, c, d]) => format!(
            "{} {} {} base t{} t{} t{}",
            ["sn", "cn", "dn"][usize::from(*f)],
            a(0),
            a(1),
            node(s)?,
            node(c)?,
            node(d)?
        ),
        SOp::Deriv => format!("deriv {}", a(0)),
        SOp::Cut(h) => format!("cut {} {h}", a(0)),
        SOp::Bound => format!("bound {}", a(0)),
        SOp::Moving => format!("moving {} {}", a(0), a(1)),
    };
    Some(format!("sseries s{i} = {body}\n"))
}
