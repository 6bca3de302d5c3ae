//! The paper's identities written directly against the algebra API, shared by the
//! tests (`tests/algebra/algebra_paper.rs`) and the benchmark (`benches/algebra.rs`).
//!
//! Domain points are exact rationals with A > B > C > 0 and E/M² inside the regime.
#![allow(dead_code)]

use eulertop::algebra::{AlgResult, Origin, Ring, Sym};

/// The two regimes of (sol): upper `1/B < E/M² < 1/C`, lower `1/A < E/M² < 1/B`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Regime {
    /// `1/B < E/M² < 1/C`.
    Upper,
    /// `1/A < E/M² < 1/B`.
    Lower,
}

/// The deliberate errors of the controls.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Variant {
    /// As printed (and true).
    True,
    /// A sign flipped.
    SignFlipped,
    /// `k` written for `k²`.
    KForK2,
    /// A square missing (`ν` for `ν²`).
    MissingSquare,
    /// The right side scaled by `1 + 10⁻³⁰`.
    Scaled,
}

/// The top's parameters as symbols of a ring.
pub struct Top {
    pub a_: Sym,
    pub b_: Sym,
    pub c_: Sym,
    pub m2: Sym,
    pub e: Sym,
}

/// A, B, C, M², E at three domain points of the regime.
pub fn top(r: &Ring, regime: Regime) -> AlgResult<Top> {
    let e = match regime {
        Regime::Upper => ["3/4", "9/10", "6/5"],
        Regime::Lower => ["2/5", "14/25", "3/4"],
    };
    Ok(Top {
        a_: r.indeterminate_rational("A", &["3", "5", "5/2"])?,
        b_: r.indeterminate_rational("B", &["2", "3", "17/10"])?,
        c_: r.indeterminate_rational("C", &["1", "2", "9/10"])?,
        m2: r.indeterminate_rational("M2", &["1", "2", "3/2"])?,
        e: r.indeterminate_rational("E", &e)?,
    })
}

/// k², a², b², c², ν² of (k), (abc), (nu).
pub struct Squares {
    pub k2: Sym,
    pub a2: Sym,
    pub b2: Sym,
    pub c2: Sym,
    pub nu2: Sym,
}

pub fn squares(t: &Top, regime: Regime) -> Squares {
    let (a, b, c, m2, e) = (&t.a_, &t.b_, &t.c_, &t.m2, &t.e);
    let p = m2 - &(c * e); // M² − CE
    let q = &(a * e) - m2; // AE − M²
    let ab = a - b;
    let bc = b - c;
    let ac = a - c;
    let abc = &(a * b) * c;
    let a2 = &(a * &p) / &ac;
    let c2 = &(c * &q) / &ac;
    match regime {
        Regime::Upper => Squares {
            k2: &(&ab * &p) / &(&bc * &q),
            a2,
            b2: &(b * &p) / &bc,
            c2,
            nu2: &(&bc * &q) / &abc,
        },
        Regime::Lower => Squares {
            k2: &(&bc * &q) / &(&ab * &p),
            a2,
            b2: &(b * &q) / &ab,
            c2,
            nu2: &(&ab * &p) / &abc,
        },
    }
}

/// k, a, b, c, ν (positive roots) from their definitions.
pub struct Params {
    pub k: Sym,
    pub a: Sym,
    pub b: Sym,
    pub c: Sym,
    pub nu: Sym,
}

pub fn params(r: &Ring, s: &Squares) -> AlgResult<Params> {
    let def = |name: &str, x: &Sym| r.with_origin(Origin::Definition(name.into()), || x.sqrt());
    Ok(Params {
        k: def("k", &s.k2)?,
        a: def("a", &s.a2)?,
        b: def("b", &s.b2)?,
        c: def("c", &s.c2)?,
        nu: def("nu", &s.nu2)?,
    })
}

fn scaled(r: &Ring, x: Sym) -> Sym {
    let eps: rug::Rational = "1000000000000000000000000000001/1000000000000000000000000000000"
        .parse()
        .unwrap();
    &x * &r.rational(&eps)
}

/// DLMF 22.8.1–3 (`f` = 0, 1, 2 for sn, cn, dn) with a control variant.
pub fn addition(r: &Ring, f: usize, variant: Variant) -> AlgResult<Vec<(Sym, Sym)>> {
    let u = r.indeterminate_f64("u", &[0.3, -0.8, 1.2])?;
    let v = r.indeterminate_f64("v", &[0.5, 0.4, -1.7])?;
    let k = r.indeterminate_f64("k", &[0.5, 0.9, 0.1])?;
    let (su, cu, du) = u.sncndn(&k)?;
    let (sv, cv, dv) = v.sncndn(&k)?;
    let (s, c, d) = (&u + &v).sncndn(&k)?;
    let kk = if variant == Variant::KForK2 {
        k.clone()
    } else {
        &k * &k
    };
    let one = r.integer(1);
    let q = &(&su * &su) * &(&sv * &sv);
    let den = if variant == Variant::SignFlipped {
        &one + &(&kk * &q)
    } else {
        &one - &(&kk * &q)
    };
    let (lhs, num) = match f {
        0 => (s, &(&su * &cv) * &dv + &(&sv * &cu) * &du),
        1 => (c, &(&cu * &cv) - &(&(&su * &du) * &(&sv * &dv))),
        _ => (d, &(&du * &dv) - &(&kk * &(&(&su * &cu) * &(&sv * &cv)))),
    };
    let rhs = &num / &den;
    Ok(vec![(
        lhs,
        if variant == Variant::Scaled {
            scaled(r, rhs)
        } else {
            rhs
        },
    )])
}

/// Section 8, (G0G1): `G₁ − k² sn²(Δφ) G₀ = k² ν² cn² dn²`, with a, b, c, k, ν from
/// (abc), (k), (nu); `named` keeps k and ν as named symbols.
pub fn g0g1(r: &Ring, regime: Regime, variant: Variant, named: bool) -> AlgResult<Vec<(Sym, Sym)>> {
    let t = top(r, regime)?;
    let sq = squares(&t, regime);
    let p = params(r, &sq)?;
    let (k, nu) = if named {
        (r.named("k", &p.k)?, r.named("nu", &p.nu)?)
    } else {
        (p.k.clone(), p.nu.clone())
    };
    let dphi = r.indeterminate_f64("dphi", &[0.3, -0.7, 1.1])?;
    let (s, c, d) = dphi.sncndn(&k)?;
    let k2 = &k * &k;
    let (a2, b2, c2) = (&p.a * &p.a, &p.b * &p.b, &p.c * &p.c);
    let fa = &a2 / &(&t.a_ * &t.a_);
    let fb = &b2 / &(&t.b_ * &t.b_);
    let fc = &c2 / &(&t.c_ * &t.c_);
    let (cc, dd) = (&c * &c, &d * &d);
    let (g0, g1) = match regime {
        Regime::Upper => (
            &(&fa * &cc) + &(&fc * &dd),
            &(&(&fa * &cc) + &(&(&fc * &k2) * &dd)) - &(&(&fb * &cc) * &dd),
        ),
        Regime::Lower => (
            &(&fa * &dd) + &(&fc * &cc),
            &(&(&(&fa * &k2) * &dd) + &(&fc * &cc)) - &(&(&fb * &cc) * &dd),
        ),
    };
    let lhs = &g1 - &(&(&k2 * &(&s * &s)) * &g0);
    let kk = if variant == Variant::KForK2 {
        k.clone()
    } else {
        k2.clone()
    };
    let nn = if variant == Variant::MissingSquare {
        nu.clone()
    } else {
        &nu * &nu
    };
    let rhs = &(&(&kk * &nn) * &cc) * &dd;
    let rhs = match variant {
        Variant::SignFlipped => -rhs,
        Variant::Scaled => scaled(r, rhs),
        _ => rhs,
    };
    Ok(vec![(lhs, rhs)])
}

/// (MV alphabeta): `G₁ = k²ν²(1 + α sn²Δφ − β sn⁴Δφ)`.
pub fn g1_alphabeta(r: &Ring, regime: Regime) -> AlgResult<Vec<(Sym, Sym)>> {
    let t = top(r, regime)?;
    let sq = squares(&t, regime);
    let p = params(r, &sq)?;
    let dphi = r.indeterminate_f64("dphi", &[0.3, -0.7, 1.1])?;
    let (s, c, d) = dphi.sncndn(&p.k)?;
    let k2 = &p.k * &p.k;
    let (a, b, cc_, m2, e) = (&t.a_, &t.b_, &t.c_, &t.m2, &t.e);
    let fa = &sq.a2 / &(a * a);
    let fb = &sq.b2 / &(b * b);
    let fc = &sq.c2 / &(cc_ * cc_);
    let (c2, d2) = (&c * &c, &d * &d);
    let g1 = match regime {
        Regime::Upper => &(&(&fa * &c2) + &(&(&fc * &k2) * &d2)) - &(&(&fb * &c2) * &d2),
        Regime::Lower => &(&(&(&fa * &k2) * &d2) + &(&fc * &c2)) - &(&(&fb * &c2) * &d2),
    };
    let two = r.integer(2);
    let top_ = &(&(&two * a) * &(cc_ * e)) - &(&(&(a + cc_) - b) * m2);
    let p_ = m2 - &(cc_ * e);
    let q_ = &(a * e) - m2;
    let (alpha, beta) = match regime {
        Regime::Upper => (
            &top_ / &(&(b - cc_) * &q_),
            &(&(a * cc_) / &(&(b - cc_) * &(b - cc_))) * &(&p_ / &q_),
        ),
        Regime::Lower => (
            &top_ / &(&(a - b) * &p_),
            &(&(a * cc_) / &(&(a - b) * &(a - b))) * &(&q_ / &p_),
        ),
    };
    let s2 = &s * &s;
    let inner = &(&r.integer(1) + &(&alpha * &s2)) - &(&beta * &(&s2 * &s2));
    Ok(vec![(g1, &(&k2 * &(&p.nu * &p.nu)) * &inner)])
}

/// (M-M 1–3): the six sum and difference formulae.
pub fn mm(r: &Ring, regime: Regime, from_phi: bool) -> AlgResult<Vec<(Sym, Sym)>> {
    let t = top(r, regime)?;
    let p = params(r, &squares(&t, regime))?;
    let (phi, phih) = if from_phi {
        let phi = r.indeterminate_f64("phi", &[0.2, -0.9, 1.4])?;
        let phih = r.indeterminate_f64("phih", &[0.7, -0.3, 2.1])?;
        (phi, phih)
    } else {
        let pb = r.indeterminate_f64("phibar", &[0.45, -0.6, 1.75])?;
        let dp = r.indeterminate_f64("dphi", &[0.25, 0.3, 0.35])?;
        (&pb - &dp, &pb + &dp)
    };
    let k = &p.k;
    let (s0, c0, d0) = phi.sncndn(k)?;
    let (s1, c1, d1) = phih.sncndn(k)?;
    let half = r.rational(&rug::Rational::from((1, 2)));
    let (sb, cb, db) = (&(&phi + &phih) * &half).sncndn(k)?;
    let (sd, cd, dd) = (&(&phih - &phi) * &half).sncndn(k)?;
    let k2 = k * k;
    let den = &r.integer(1) - &(&k2 * &(&(&sb * &sb) * &(&sd * &sd)));
    let two = r.integer(2);
    let (m1, m1h, m3, m3h) = match regime {
        Regime::Upper => (&p.a * &c0, &p.a * &c1, &p.c * &d0, &p.c * &d1),
        Regime::Lower => (&p.a * &d0, &p.a * &d1, &p.c * &c0, &p.c * &c1),
    };
    let (m2, m2h) = (&p.b * &s0, &p.b * &s1);
    let sdsd = &(&(&sb * &db) * &sd) * &dd; // sn φ̄ dn φ̄ sn Δ dn Δ
    let scsc = &(&(&k2 * &(&sb * &cb)) * &sd) * &cd; // k² sn φ̄ cn φ̄ sn Δ cn Δ
    let f = |x: &Sym, coef: &Sym| &(&(&two * coef) / &den) * x;
    let (d1_, s1_, d3_, s3_) = match regime {
        Regime::Upper => (
            -f(&sdsd, &p.a),
            f(&(&cb * &cd), &p.a),
            -f(&scsc, &p.c),
            f(&(&db * &dd), &p.c),
        ),
        Regime::Lower => (
            -f(&scsc, &p.a),
            f(&(&db * &dd), &p.a),
            -f(&sdsd, &p.c),
            f(&(&cb * &cd), &p.c),
        ),
    };
    let d2_ = f(&(&(&cb * &db) * &sd), &p.b);
    let s2_ = f(&(&(&sb * &cd) * &dd), &p.b);
    let lhs = [
        &m1h - &m1,
        &m1h + &m1,
        &m2h - &m2,
        &m2h + &m2,
        &m3h - &m3,
        &m3h + &m3,
    ];
    let rhs = [d1_, s1_, d2_, s2_, d3_, s3_];
    combine(r, &lhs, &rhs)
}

/// The component identities `lhsᵢ = rhsᵢ`.
pub fn combine(_r: &Ring, lhs: &[Sym], rhs: &[Sym]) -> AlgResult<Vec<(Sym, Sym)>> {
    Ok(lhs.iter().cloned().zip(rhs.iter().cloned()).collect())
}

/// (sol) solves (ET): `Ṁ₁ = (1/B − 1/C) M₂M₃` and cyclically, `M(t)` from (sol).
pub fn sol_et(r: &Ring, regime: Regime) -> AlgResult<Vec<(Sym, Sym)>> {
    let t = top(r, regime)?;
    let p = params(r, &squares(&t, regime))?;
    let time = r.indeterminate_f64("t", &[0.4, -1.3, 2.2])?;
    let t0 = r.indeterminate_f64("t0", &[0.1, 0.5, -0.35])?;
    let (s, c, d) = (&p.nu * &(&time - &t0)).sncndn(&p.k)?;
    let m = match regime {
        Regime::Upper => [&p.a * &c, &p.b * &s, &p.c * &d],
        Regime::Lower => [&p.a * &d, &p.b * &s, &p.c * &c],
    };
    let one = r.integer(1);
    let inv = |x: &Sym| &one / x;
    let rhs = [
        &(&inv(&t.b_) - &inv(&t.c_)) * &(&m[1] * &m[2]),
        &(&inv(&t.c_) - &inv(&t.a_)) * &(&m[2] * &m[0]),
        &(&inv(&t.a_) - &inv(&t.b_)) * &(&m[0] * &m[1]),
    ];
    let lhs = [
        m[0].derivative(&time)?,
        m[1].derivative(&time)?,
        m[2].derivative(&time)?,
    ];
    combine(r, &lhs, &rhs)
}

/// A 3×3 matrix of symbols.
pub type Mat = [[Sym; 3]; 3];

fn mat(r: &Ring, f: impl Fn(usize, usize) -> Sym) -> Mat {
    let _ = r;
    [
        [f(0, 0), f(0, 1), f(0, 2)],
        [f(1, 0), f(1, 1), f(1, 2)],
        [f(2, 0), f(2, 1), f(2, 2)],
    ]
}

fn mat_mul(r: &Ring, a: &Mat, b: &Mat) -> Mat {
    mat(r, |i, j| {
        let mut s = &a[i][0] * &b[0][j];
        for l in 1..3 {
            s = &s + &(&a[i][l] * &b[l][j]);
        }
        s
    })
}

fn eye(r: &Ring) -> Mat {
    mat(r, |i, j| r.integer(i64::from(i == j)))
}

/// The inverse by the adjugate.
fn mat_inv(r: &Ring, a: &Mat) -> Mat {
    let c = |i: usize, j: usize| {
        let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
        let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
        &(&a[i1][j1] * &a[i2][j2]) - &(&a[i1][j2] * &a[i2][j1])
    };
    let det = &(&(&a[0][0] * &c(0, 0)) + &(&a[0][1] * &c(0, 1))) + &(&a[0][2] * &c(0, 2));
    mat(r, |i, j| &c(j, i) / &det)
}

/// Lemma 2 through the appendix: with `V = PM(v)`, `ω = (I + V)(I − V)⁻¹`,
/// `W = 2V/(1 + |V|²)`, `γ = 2/(1 + √(1 − |W|²))`: `ω = I + W + (γ/2) W²`, the nine
/// entries (domain |v| < 1).
/// [`cayley`] with the hypothesis `1 − |v|² > 0` stated (label `small-v`).
pub fn cayley_small_v(r: &Ring) -> AlgResult<Vec<(Sym, Sym)>> {
    cayley_with(r, true)
}

pub fn cayley(r: &Ring) -> AlgResult<Vec<(Sym, Sym)>> {
    cayley_with(r, false)
}

fn cayley_with(r: &Ring, small_v: bool) -> AlgResult<Vec<(Sym, Sym)>> {
    let v1 = r.indeterminate_rational("v1", &["1/5", "-1/3", "2/7"])?;
    let v2 = r.indeterminate_rational("v2", &["1/4", "1/6", "-3/5"])?;
    let v3 = r.indeterminate_rational("v3", &["-1/3", "1/2", "1/9"])?;
    if small_v {
        let small = &r.integer(1) - &(&(&(&v1 * &v1) + &(&v2 * &v2)) + &(&v3 * &v3));
        r.state_hypothesis(&small, 1, "small-v".into());
    }
    let z = r.integer(0);
    // PM(x) = [[0, x3, −x2], [−x3, 0, x1], [x2, −x1, 0]]
    let pm = |x1: &Sym, x2: &Sym, x3: &Sym| -> Mat {
        [
            [z.clone(), x3.clone(), -x2],
            [-x3, z.clone(), x1.clone()],
            [x2.clone(), -x1, z.clone()],
        ]
    };
    let vm = pm(&v1, &v2, &v3);
    let id = eye(r);
    let plus = mat(r, |i, j| &id[i][j] + &vm[i][j]);
    let minus = mat(r, |i, j| &id[i][j] - &vm[i][j]);
    let omega = mat_mul(r, &plus, &mat_inv(r, &minus));
    let vsq = &(&(&v1 * &v1) + &(&v2 * &v2)) + &(&v3 * &v3);
    let f = &r.integer(2) / &(&r.integer(1) + &vsq);
    let w = mat(r, |i, j| &f * &vm[i][j]);
    let wsq = &(&(&w[1][2] * &w[1][2]) + &(&w[2][0] * &w[2][0])) + &(&w[0][1] * &w[0][1]);
    let root = r.with_origin(Origin::Claim, || (&r.integer(1) - &wsq).sqrt())?;
    let gamma = &r.integer(2) / &(&r.integer(1) + &root);
    let w2 = mat_mul(r, &w, &w);
    let half_g = &gamma / &r.integer(2);
    let rhs = mat(r, |i, j| &(&id[i][j] + &w[i][j]) + &(&half_g * &w2[i][j]));
    let flat = |m: &Mat| -> Vec<Sym> { m.iter().flat_map(|row| row.iter().cloned()).collect() };
    combine(r, &flat(&omega), &flat(&rhs))
}

/// The domain of [`top`] as a parametrization by positive parameters, with which the
/// prover proves signs: `C = t_C`, `B = C + t_B`, `A = B + t_A`, `M² = t_M`, and E/M²
/// inside the regime, `1/B + s/(1 + s)·(1/C − 1/B)` (upper) or
/// `1/A + s/(1 + s)·(1/B − 1/A)` (lower); the Cayley parameters `v1`, `v2`, `v3`
/// nonzero of either sign.
pub fn domain(regime: Regime) -> std::sync::Arc<eulertop::algebra::positivity::Parametrization> {
    use eulertop::algebra::positivity::Parametrization;
    let mut par = Parametrization::new();
    let one = par.constant(&rug::Rational::from(1));
    let c = par.positive("t_C").unwrap();
    let b = c.add(&par.positive("t_B").unwrap());
    let a = b.add(&par.positive("t_A").unwrap());
    let m2 = par.positive("t_M").unwrap();
    let s = par.positive("s").unwrap();
    let frac = s.div(&one.add(&s)).unwrap();
    let inv = |x: &eulertop::algebra::positivity::ParamRat| one.div(x).unwrap();
    let (lo, hi) = match regime {
        Regime::Upper => (inv(&b), inv(&c)),
        Regime::Lower => (inv(&a), inv(&b)),
    };
    let e = m2.mul(&lo.add(&frac.mul(&hi.sub(&lo))));
    for (name, v) in [("A", a), ("B", b), ("C", c), ("M2", m2), ("E", e)] {
        par.bind(name, v, String::new());
    }
    for name in ["v1", "v2", "v3"] {
        let v = par.nonzero(&format!("mu_{name}")).unwrap();
        par.bind(name, v, String::new());
    }
    std::sync::Arc::new(par)
}
