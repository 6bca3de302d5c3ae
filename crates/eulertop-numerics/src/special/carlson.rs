//! Carlson's symmetric elliptic integrals `R_F`, `R_D`, `R_J`, `R_C` (DLMF §19.16) by
//! the duplication algorithm (DLMF §19.36(i); Carlson, Numer. Algorithms 10 (1995)).
//!
//! Each step replaces the arguments `x_j` by `(x_j + λ)/4` with
//! `λ = √x√y + √y√z + √z√x` (DLMF 19.26.18–19), which leaves the integral unchanged
//! (up to a known sum for `R_D` and `R_J`) and shrinks the spread of the arguments
//! about their mean `A` fourfold.  Once the relative spread `|X| = |A − x_j|/A` is below
//! `ε^(1/8)` (`R_F`, seventh-order series DLMF 19.36.1) or `ε^(1/6)` (`R_D`, `R_J`, the
//! fifth-order series of Carlson 1995), the truncated Taylor series in the elementary
//! symmetric functions `E₂ … E₅` of the `X_j` finishes the job.  The differences
//! `A − x_j` are taken from the initial ones scaled by `4⁻ⁿ` (exact), not by
//! subtraction.  Any precision: the number of steps grows like `prec/12`.

use super::SpecialError;
use super::dd::{Dd, two_prod, two_sum, with_value};
use crate::numbers::Real;

/// Upper bound on duplication steps (each shrinks the spread fourfold: 2 bits).
const MAX_STEPS: usize = 1 << 20;

/// The spread below which the series of order `order` is accurate to the working
/// epsilon: `2^⌊(−prec − 3)/(order + 1)⌋` (a power of two, exact at every precision).
fn tolerance<R: Real>(x: &R, order: i32) -> R {
    let p = x.prec() as i32;
    x.one().mul_2si((-p - 3).div_euclid(order + 1))
}

/// `√x`, with an exact zero taken as it is: its derivative parts (automatic
/// differentiation through [`crate::numbers::Dual`]) stay finite where `x` is a
/// constant 0, such as the first argument of `R_D(0, k'², 1)`.
pub(crate) fn sqrt0<R: Real>(x: &R) -> R {
    if x.is_zero() { x.clone() } else { x.sqrt() }
}

/// `λ = √x√y + √y√z + √z√x` and the three square roots.
fn lambda<R: Real>(x: &R, y: &R, z: &R) -> (R, [R; 3]) {
    let (sx, sy, sz) = (sqrt0(x), sqrt0(y), sqrt0(z));
    let l = sx.clone() * sy.clone() + sy.clone() * sz.clone() + sz.clone() * sx.clone();
    (l, [sx, sy, sz])
}

/// `(x + λ)/4`.
fn dup<R: Real>(x: &R, l: &R) -> R {
    (x.clone() + l.clone()).mul_2si(-2)
}

fn no_convergence(what: &str) -> SpecialError {
    SpecialError::NoConvergence(format!("{what}: duplication did not converge"))
}

/// `R_F(x, y, z)` for `x, y, z ≥ 0`, at most one of them 0, at the precision of `x`
/// (DLMF 19.16.1, duplication DLMF 19.36.1).  The caller checks the arguments.
pub(crate) fn rf<R: Real>(x: &R, y: &R, z: &R) -> Result<R, SpecialError> {
    let three = x.from_i64(3);
    let a0 = (x.clone() + y.clone() + z.clone()) / three;
    let (dx, dy) = (a0.clone() - x.clone(), a0.clone() - y.clone());
    let spread = dx
        .abs()
        .max_of(&dy.abs())
        .max_of(&(a0.clone() - z.clone()).abs());
    let tol = tolerance(x, 7);
    let (mut x, mut y, mut z, mut a) = (x.clone(), y.clone(), z.clone(), a0);
    let mut n = 0i32;
    while spread.mul_2si(-2 * n) > tol.clone() * a.abs() {
        if n as usize >= MAX_STEPS {
            return Err(no_convergence("R_F"));
        }
        let (l, _) = lambda(&x, &y, &z);
        (x, y, z, a) = (dup(&x, &l), dup(&y, &l), dup(&z, &l), dup(&a, &l));
        n += 1;
    }
    let xx = dx.mul_2si(-2 * n) / a.clone();
    let yy = dy.mul_2si(-2 * n) / a.clone();
    let zz = -(xx.clone() + yy.clone());
    let e2 = xx.clone() * yy.clone() - zz.sqr();
    let e3 = xx * yy * zz;
    let r = |p: i64, q: i64| a.from_ratio(p, q);
    // DLMF 19.36.1 less its leading 1
    let small = -(e2.clone() * r(1, 10)) + e3.clone() * r(1, 14) + e2.sqr() * r(1, 24)
        - e2.clone() * e3.clone() * r(3, 44)
        - e2.sqr() * e2.clone() * r(5, 208)
        + e3.sqr() * r(3, 104)
        + e2.sqr() * e3 * r(1, 16);
    Ok(one_plus_over_sqrt(&small, &a))
}

/// `(1 + s)/√a` for a small `s` (the series of `R_F` less its 1) and `a > 0`.  For the
/// fixed-precision types (no guard bits) rounded about once: with `y = fl(√a)`,
/// `r = fl(1/y)` and the exact residuals `a − y² = 2aδ` and `1 − y·r = e` (two-products),
/// `(1 + s)/√a = r(1 + e + s − δ)` to second order in the small quantities; plainly
/// `1 + s` rounded, a square root and a division cost up to 2.6 ε of `R_F` on their own.
/// Multi-precision types divide plainly.
fn one_plus_over_sqrt<R: Real>(s: &R, a: &R) -> R {
    let y = a.sqrt();
    let plain = (a.one() + s.clone()) / y.clone();
    if !R::FIXED {
        return plain;
    }
    let (av, yv) = (a.to_f64(), y.to_f64());
    let (p, pe) = two_prod(yv, yv);
    let delta = ((av - p) - pe) / (2.0 * av);
    let rv = 1.0 / yv;
    let (q, qe) = two_prod(yv, rv);
    let e = (1.0 - q) - qe;
    with_value(&plain, rv + rv * ((e + s.to_f64()) - delta))
}

/// The running sum of the duplication terms of `R_D` and `R_J`.  For the
/// fixed-precision types (`Real::FIXED`, no guard bits) it also collects the rounding
/// error of every addition (Knuth's two-sum) in an `f64`, and [`Terms::finish`] adds
/// `3·2^j·sum` to the series part error-free, so that the sum is as good as if it were
/// formed in twice the precision and the result is rounded about once; without this the
/// roundings of the sum were the larger part of the `R_D`, `R_J` error (up to 2.5 ε).
/// Multi-precision types, which carry guard bits, add plainly.
struct Terms<R> {
    hi: R,
    lo: f64,
}

impl<R: Real> Terms<R> {
    fn new(zero: R) -> Self {
        Terms { hi: zero, lo: 0.0 }
    }

    /// `sum += x`.
    fn add(&mut self, x: R) {
        if R::FIXED {
            let (s, e) = two_sum(self.hi.to_f64(), x.to_f64());
            self.hi = with_value(&(self.hi.clone() + x), s);
            self.lo += e;
        } else {
            self.hi = self.hi.clone() + x;
        }
    }

    /// `head + 3·2^j·sum` (`j` 0 or 1; `3·sum = sum + 2·sum` by a two-sum, exact with
    /// its error; `2^j` exact), rounded once but for the collected errors.
    fn finish(self, head: R, j: i32) -> R {
        let three = (self.hi.clone() + self.hi.mul_2si(1)).mul_2si(j);
        if !R::FIXED {
            return head + three;
        }
        let v = self.hi.to_f64();
        let (t, te) = two_sum(v, v * 2.0);
        let sc = f64::from(1u32 << j);
        let (h, he) = two_sum(head.to_f64(), t * sc);
        let exact = head + three;
        let lo = exact.from_f64(he + (te + 3.0 * self.lo) * sc);
        with_value(&exact, h) + lo
    }
}

/// The fifth-order series of `R_D` and `R_J` (Carlson 1995, (2.29) and (2.39)):
/// `1 − 3E₂/14 + E₃/6 + 9E₂²/88 − 3E₄/22 − 9E₂E₃/52 + 3E₅/26`.
fn series5<R: Real>(e: [R; 4]) -> R {
    let [e2, e3, e4, e5] = e;
    let one = e2.one();
    let r = |p: i64, q: i64| one.from_ratio(p, q);
    one.clone() - e2.clone() * r(3, 14) + e3.clone() * r(1, 6) + e2.sqr() * r(9, 88)
        - e4 * r(3, 22)
        - e2 * e3 * r(9, 52)
        + e5 * r(3, 26)
}

/// `R_D(x, y, z) = R_J(x, y, z, z)` for `x, y ≥ 0` (not both 0), `z > 0`, at the
/// precision of `x` (DLMF 19.16.5, duplication Carlson 1995 §2).
pub(crate) fn rd<R: Real>(x: &R, y: &R, z: &R) -> Result<R, SpecialError> {
    let a0 = (x.clone() + y.clone() + z.clone() * x.from_i64(3)) / x.from_i64(5);
    let (dx, dy) = (a0.clone() - x.clone(), a0.clone() - y.clone());
    let spread = dx
        .abs()
        .max_of(&dy.abs())
        .max_of(&(a0.clone() - z.clone()).abs());
    let tol = tolerance(x, 5);
    let (mut x, mut y, mut z, mut a) = (x.clone(), y.clone(), z.clone(), a0);
    let mut sum = Terms::new(x.zero());
    let mut n = 0i32;
    while spread.mul_2si(-2 * n) > tol.clone() * a.abs() {
        if n as usize >= MAX_STEPS {
            return Err(no_convergence("R_D"));
        }
        let (l, [_, _, sz]) = lambda(&x, &y, &z);
        sum.add((sz * (z.clone() + l.clone())).recip().mul_2si(-2 * n));
        (x, y, z, a) = (dup(&x, &l), dup(&y, &l), dup(&z, &l), dup(&a, &l));
        n += 1;
    }
    let xx = dx.mul_2si(-2 * n) / a.clone();
    let yy = dy.mul_2si(-2 * n) / a.clone();
    let zz = -(xx.clone() + yy.clone()) / a.from_i64(3);
    let xy = xx * yy;
    let z2 = zz.sqr();
    let e2 = xy.clone() - z2.clone() * a.from_i64(6);
    let e3 = (xy.clone() * a.from_i64(3) - z2.clone() * a.from_i64(8)) * zz.clone();
    let e4 = (xy.clone() - z2.clone()) * z2.clone() * a.from_i64(3);
    let e5 = xy * z2 * zz;
    let head = series5([e2, e3, e4, e5]) / (a.clone() * a.sqrt());
    Ok(sum.finish(head.mul_2si(-2 * n), 0))
}

/// `R_C(1, 1 + e) = atan(√e)/√e` (`e > 0`), `atanh(√−e)/√−e` (`−1 < e < 0`), `1` at
/// `e = 0` (DLMF 19.2.17–18); a power series for `|e| ≤ 1/16`, so that no relative
/// accuracy is lost as `e → 0`.
pub(crate) fn rc1<R: Real>(e: &R) -> R {
    let one = e.one();
    if e.abs() <= one.mul_2si(-4) {
        // Σ (−e)^j/(2j + 1)
        let eps = e.epsilon().mul_2si(-2);
        let (mut sum, mut term, mut j) = (one.clone(), one.clone(), 0i64);
        while term.abs() > eps {
            term = -(term * e.clone());
            j += 1;
            sum = sum + term.clone() / e.from_i64(2 * j + 1);
        }
        return sum;
    }
    if *e > e.zero() {
        let t = e.sqrt();
        t.atan() / t
    } else {
        let t = (-e.clone()).sqrt();
        t.atanh() / t
    }
}

/// `R_J(x, y, z, p)` for `x, y, z ≥ 0` (at most one 0) and `p > 0`, at the precision
/// of `x` (DLMF 19.16.2, duplication Carlson 1995 (2.36)–(2.40)).
pub(crate) fn rj<R: Real>(x: &R, y: &R, z: &R, p: &R) -> Result<R, SpecialError> {
    let five = x.from_i64(5);
    let a0 = (x.clone() + y.clone() + z.clone() + p.clone().mul_2si(1)) / five;
    let d = [x, y, z, p].map(|v| a0.clone() - v.clone());
    let spread = d.iter().fold(x.zero(), |m, v| m.max_of(&v.abs()));
    let delta = (p.clone() - x.clone()) * (p.clone() - y.clone()) * (p.clone() - z.clone());
    let tol = tolerance(x, 5);
    let (mut x, mut y, mut z, mut p, mut a) = (x.clone(), y.clone(), z.clone(), p.clone(), a0);
    let mut sum = Terms::new(x.zero());
    let mut n = 0i32;
    while spread.mul_2si(-2 * n) > tol.clone() * a.abs() {
        if n as usize >= MAX_STEPS {
            return Err(no_convergence("R_J"));
        }
        let (l, [sx, sy, sz]) = lambda(&x, &y, &z);
        let sp = sqrt0(&p);
        let dn = (sp.clone() + sx) * (sp.clone() + sy) * (sp + sz);
        let en = (delta.clone() / dn.sqr()).mul_2si(-6 * n);
        sum.add((rc1(&en) / dn).mul_2si(-2 * n));
        (x, y, z) = (dup(&x, &l), dup(&y, &l), dup(&z, &l));
        (p, a) = (dup(&p, &l), dup(&a, &l));
        n += 1;
    }
    let [xx, yy, zz, _] = d.map(|v| v.mul_2si(-2 * n) / a.clone());
    let pp = -(xx.clone() + yy.clone() + zz.clone()).mul_2si(-1);
    let xyz = xx.clone() * yy.clone() * zz.clone();
    let p2 = pp.sqr();
    let e2 = xx.clone() * yy.clone() + xx * zz.clone() + yy * zz - p2.clone() * a.from_i64(3);
    let e3 = xyz.clone() + e2.clone() * pp.clone().mul_2si(1) + p2.clone() * pp.clone().mul_2si(2);
    let e4 = (xyz.clone().mul_2si(1)
        + e2.clone() * pp.clone()
        + p2.clone() * pp.clone() * a.from_i64(3))
        * pp.clone();
    let e5 = xyz * p2;
    let head = series5([e2, e3, e4, e5]) / (a.clone() * a.sqrt());
    Ok(sum.finish(head.mul_2si(-2 * n), 1))
}

/// `√x` of a double-double, an exact zero taken as it is ([`sqrt0`]).
fn sqrt0_dd<R: Real>(x: &Dd<R>) -> Dd<R> {
    if x.hi.is_zero() { x.clone() } else { x.sqrt() }
}

/// `(1 + t)/d` as a double-double for a small `t` in `f64` (its own rounding counts
/// only `|t|·2⁻⁵³`).
fn one_plus_over<R: Real>(t: f64, d: &Dd<R>) -> Dd<R> {
    let inv = Dd::from(d.hi.one()).div(d);
    inv.add(&inv.mul_r(&d.hi.from_f64(t)))
}

/// `R_C(1, 1 + e) − 1` in `f64` for `|e| ≤ 1/16` (the series of [`rc1`] less its 1),
/// else `None`.
fn rc1_minus_one(e: f64) -> Option<f64> {
    if e.abs() > 1.0 / 16.0 {
        return None;
    }
    // Σ_{j ≥ 1} (−e)^j/(2j + 1)
    let (mut sum, mut term, mut j) = (0.0, 1.0, 0.0);
    while term.abs() > 1e-20 {
        term *= -e;
        j += 1.0;
        sum += term / (2.0 * j + 1.0);
    }
    Some(sum)
}

/// `R_J(x, y, z, p)` for the fixed-precision types in double-double (DLMF 19.16.2), for
/// the arguments of [`rj`] given as double-doubles: the same duplication and
/// fifth-order series (Carlson 1995 (2.36)–(2.40)) with the arguments, `λ`, the
/// products `dₙ` and the terms `R_C(1, 1 + eₙ)/dₙ` in double-double (`R_C − 1` in
/// `f64` where `|eₙ| ≤ 1/16`), so that the result is good to about `2⁻⁶²` relative
/// before it is rounded, where [`rj`] in `f64` is good to about 1.5 ε.  One more
/// duplication step than [`rj`] (spread `≤ 2⁻¹²`).  For `f64`: `eₙ` and the series
/// are formed from the values alone, so the derivative parts of a `Dual` would not be
/// carried through them.
pub(crate) fn rj_dd<R: Real>(
    x: &Dd<R>,
    y: &Dd<R>,
    z: &Dd<R>,
    p: &Dd<R>,
) -> Result<Dd<R>, SpecialError> {
    let [x, y, z, p] = [x, y, z, p].map(Dd::norm);
    let fifth = Dd::from(x.hi.one()).div(&Dd::from(x.hi.from_i64(5)));
    let a0 = x.add(&y).add(&z).add(&p.mul_2si(1)).mul(&fifth);
    let d = [&x, &y, &z].map(|v| a0.add(&v.neg()).v());
    let spread = d.iter().fold((a0.v() - p.v()).abs(), |m, v| m.max(v.abs()));
    let delta = p.add(&x.neg()).mul(&p.add(&y.neg())).mul(&p.add(&z.neg()));
    let (mut x, mut y, mut z, mut p, mut a) = (x, y, z, p, a0);
    let mut sum = Dd::from(x.hi.zero());
    let mut n = 0i32;
    while spread * 4f64.powi(-n) > a.v().abs() * 2f64.powi(-12) {
        if n as usize >= MAX_STEPS {
            return Err(no_convergence("R_J"));
        }
        let [sx, sy, sz, sp] = [&x, &y, &z, &p].map(sqrt0_dd);
        let l = sx.mul(&sy).add(&sy.mul(&sz)).add(&sz.mul(&sx));
        let dn = sp.add(&sx).mul(&sp.add(&sy)).mul(&sp.add(&sz)).norm();
        // eₙ from the whole double-doubles (R_C(1, 1 + e) is ill-conditioned near e = −1)
        let en = delta.div(&dn.sqr()).to_r().to_f64() * 2f64.powi(-6 * n);
        let term = match rc1_minus_one(en) {
            Some(t) => one_plus_over(t, &dn),
            None => Dd::from(rc1(&x.hi.from_f64(en))).div(&dn),
        };
        sum = sum.add(&term.mul_2si(-2 * n));
        let dup = |v: &Dd<R>| v.add(&l).mul_2si(-2);
        (x, y, z, p, a) = (dup(&x), dup(&y), dup(&z), dup(&p), dup(&a));
        n += 1;
    }
    let av = a.v();
    let [xx, yy, zz] = d.map(|v| v * 4f64.powi(-n) / av);
    let pp = -(xx + yy + zz) / 2.0;
    let (xyz, p2) = (xx * yy * zz, pp * pp);
    let e2 = xx * yy + xx * zz + yy * zz - 3.0 * p2;
    let e3 = xyz + 2.0 * e2 * pp + 4.0 * p2 * pp;
    let e4 = (2.0 * xyz + e2 * pp + 3.0 * p2 * pp) * pp;
    let e5 = xyz * p2;
    let series =
        -3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0 - 3.0 * e4 / 22.0 - 9.0 * e2 * e3 / 52.0
            + 3.0 * e5 / 26.0;
    let head = one_plus_over(series, &a.mul(&a.sqrt()));
    let six = Dd::from(x.hi.from_i64(6));
    Ok(head.mul_2si(-2 * n).add(&sum.mul(&six)))
}
