//! The algebra layer's building blocks through its public API: relation reduction,
//! square roots (perfect squares, shared factors, i, denesting), division,
//! comparisons, the addition-theorem expansion with quarter and half periods, base
//! refinement, derivatives.  Every expected value is a mathematical identity.

use eulertop::algebra::{AlgebraError, Origin, Ring, RingOptions, Sym, prove_identity};
use eulertop::numbers::{Real, Scalar};
use rug::{Complex, Float};

/// A ring whose domain has `A > B > C > 0`, positive `a`, `b`, `x`, `y`, `phi` and
/// `0 < k < 1`, so that signs in them are proved (a sign the points contradict is not).
fn ring() -> Ring {
    use eulertop::algebra::positivity::Parametrization;
    let mut par = Parametrization::new();
    let one = par.constant(&rug::Rational::from(1));
    let c = par.positive("t_C").unwrap();
    let b = c.add(&par.positive("t_B").unwrap());
    let a = b.add(&par.positive("t_A").unwrap());
    for (n, v) in [("A", a), ("B", b), ("C", c)] {
        par.bind(n, v, String::new());
    }
    for n in ["a", "b", "x", "y", "phi"] {
        let t = par.positive(&format!("t_{n}")).unwrap();
        par.bind(n, t, String::new());
    }
    let t = par.positive("t_k").unwrap();
    par.bind("k", t.div(&one.add(&t)).unwrap(), String::new());
    Ring::new(RingOptions {
        positivity: Some(std::sync::Arc::new(par)),
        ..RingOptions::default()
    })
}

fn var(r: &Ring, name: &str, v: [f64; 3]) -> Sym {
    r.indeterminate_f64(name, &v).unwrap()
}

fn q(r: &Ring, n: i64, d: i64) -> Sym {
    r.rational(&rug::Rational::from((n, d)))
}

#[test]
fn root_relations_reduce_powers() {
    let r = ring();
    let a = var(&r, "a", [2.0, 3.0, 0.5]);
    let x = a.sqrt().unwrap();
    assert_eq!(&x * &x, a);
    assert_eq!(&(&x * &x) * &x, &a * &x);
    let one = r.integer(1);
    // (x + 1)² = a + 2x + 1
    let lhs = &(&x + &one) * &(&x + &one);
    let rhs = &(&a + &(&r.integer(2) * &x)) + &one;
    assert_eq!(lhs, rhs);
    assert_eq!(x.try_powi(4).unwrap(), &a * &a);
    assert_eq!(x.try_powi(-2).unwrap(), &one / &a);
    // √a is a new symbol: no assumption for its own definition
    assert!(r.assumptions().is_empty(), "{:?}", r.assumptions());
}

/// A ring whose domain is `A > C > 0` (`C = t_C`, `A = C + t_A`), so that signs in A
/// and C are proved.
fn ring_a_gt_c() -> Ring {
    use eulertop::algebra::positivity::Parametrization;
    let mut par = Parametrization::new();
    let c = par.positive("t_C").unwrap();
    let a = c.add(&par.positive("t_A").unwrap());
    par.bind("C", c, "C = t_C".into());
    par.bind("A", a, "A = C + t_A".into());
    Ring::new(RingOptions {
        positivity: Some(std::sync::Arc::new(par)),
        ..RingOptions::default()
    })
}

#[test]
fn perfect_squares_take_the_sign_the_domain_proves() {
    let r = ring_a_gt_c();
    let a = var(&r, "A", [3.0, 2.5, 4.0]);
    let c = var(&r, "C", [1.0, 0.5, 2.0]);
    let d = &a - &c;
    let root = (&d * &d).sqrt().unwrap();
    assert_eq!(root, d);
    let neg = (&(&c - &a) * &(&c - &a)).sqrt().unwrap();
    assert_eq!(neg, d, "sqrt((C − A)²) = A − C on a domain where A > C");
    assert!(r.assumptions().is_empty(), "{:?}", r.assumptions());
    // 4A²/9 → 2A/3
    let sq = (&(&(&a * &a) * &r.integer(4)) / &r.integer(9))
        .sqrt()
        .unwrap();
    assert_eq!(sq, &(&a * &r.integer(2)) / &r.integer(3));
    // no root symbol was needed
    assert!(r.relations().is_empty(), "{:?}", r.relations());
}

#[test]
fn a_branch_the_domain_does_not_prove_is_never_taken_from_the_points() {
    // A > C at every point, but nothing says so: the branch of sqrt((A − C)²) is open
    let r = Ring::new(RingOptions::default());
    let a = var(&r, "A", [3.0, 2.5, 4.0]);
    let c = var(&r, "C", [1.0, 0.5, 2.0]);
    let d = &a - &c;
    assert!(matches!(
        (&d * &d).sqrt(),
        Err(AlgebraError::CannotDecide(_))
    ));
    assert!(matches!(d.sign(), Err(AlgebraError::CannotDecide(_))));
}

#[test]
fn a_branch_that_changes_sign_on_the_domain_is_not_decided() {
    let r = ring();
    let a = var(&r, "A", [3.0, 0.5, 4.0]);
    let c = var(&r, "C", [1.0, 2.5, 2.0]);
    let d = &a - &c;
    match (&d * &d).sqrt() {
        Err(AlgebraError::CannotDecide(_)) => {}
        other => panic!("expected an undecided branch, got {other:?}"),
    }
    assert!(matches!(d.sign(), Err(AlgebraError::CannotDecide(_))));
}

#[test]
fn square_roots_of_products_share_their_factors() {
    let r = ring();
    let a = var(&r, "A", [3.0, 2.5, 4.0]);
    let b = var(&r, "B", [2.0, 1.5, 3.0]);
    let c = var(&r, "C", [1.0, 0.5, 2.0]);
    let ab = (&a * &b).sqrt().unwrap();
    let bc = (&b * &c).sqrt().unwrap();
    let ac = (&a * &c).sqrt().unwrap();
    // √(AB)·√(BC)·√(AC) = ABC exactly: needs one root per factor, not per call
    assert_eq!(&(&ab * &bc) * &ac, &(&a * &b) * &c);
    assert_eq!(&a.sqrt().unwrap() * &b.sqrt().unwrap(), ab);
    // √(AB)/√A = √B
    assert_eq!(&ab / &a.sqrt().unwrap(), b.sqrt().unwrap());
    assert_eq!(r.relations().len(), 3, "{:?}", r.relations());
}

#[test]
fn negative_radicands_bring_i_and_positive_products_stay_real() {
    let r = ring();
    let a = var(&r, "A", [3.0, 2.5, 4.0]);
    let b = var(&r, "B", [2.0, 1.5, 3.0]);
    let c = var(&r, "C", [1.0, 0.5, 2.0]);
    // (C − A)(C − B) > 0: FLINT's factors A − C, B − C are positive, no i
    let p = (&(&c - &a) * &(&c - &b)).sqrt().unwrap();
    assert!(
        r.symbols().iter().all(|(n, _)| n != "i_"),
        "{:?}",
        r.symbols()
    );
    assert_eq!(&p * &p, &(&c - &a) * &(&c - &b));
    // C − A < 0: √(C − A) = i √(A − C)
    let m = (&c - &a).sqrt().unwrap();
    let i = r.i().unwrap();
    assert_eq!(&i * &i, r.integer(-1));
    assert_eq!(m, &i * &(&a - &c).sqrt().unwrap());
    assert!(m.shadow(0).real().is_zero() && *m.shadow(0).imag() > 0);
}

#[test]
fn integer_radicands_and_denesting() {
    let r = ring();
    let s2 = r.integer(2).sqrt().unwrap();
    assert_eq!(r.integer(8).sqrt().unwrap(), &r.integer(2) * &s2);
    assert_eq!(
        &s2 * &r.integer(3).sqrt().unwrap(),
        r.integer(6).sqrt().unwrap()
    );
    // 1/(1 + √2) = √2 − 1 (rationalised denominator)
    let one = r.integer(1);
    assert_eq!(&one / &(&one + &s2), &s2 - &one);
    // √(3 + 2√2) = 1 + √2, found by denesting without a new root
    let n = r.relations().len();
    let x = (&r.integer(3) + &(&r.integer(2) * &s2)).sqrt().unwrap();
    assert_eq!(x, &one + &s2);
    assert_eq!(r.relations().len(), n);
    // √(1 + √2) is not in ℚ(√2): a new root over the tower
    let y = (&one + &s2).sqrt().unwrap();
    assert_eq!(&y * &y, &one + &s2);
    assert_eq!(r.relations().len(), n + 1);
}

#[test]
fn division_by_zero_is_an_error_and_poisons_operators() {
    let r = ring();
    let a = var(&r, "a", [1.0, 2.0, 3.0]);
    let z = &a - &a;
    assert_eq!(a.try_div(&z).unwrap_err(), AlgebraError::DivisionByZero);
    assert!(r.error().is_none());
    let _ = &a / &z;
    assert_eq!(r.error(), Some(AlgebraError::DivisionByZero));
    assert!(
        !r.prove(&a, &a).is_proved(),
        "a poisoned ring proves nothing"
    );
}

#[test]
fn comparisons_are_decided_by_proof() {
    let r = ring_a_gt_c();
    let a = var(&r, "A", [3.0, 2.5, 4.0]);
    let c = var(&r, "C", [1.0, 0.5, 2.0]);
    r.with_origin(Origin::Definition("regime".into()), || {
        assert!(a > c);
    });
    assert!(c < a);
    assert!(r.integer(2) < r.integer(3));
    assert!(r.assumptions().is_empty(), "{:?}", r.assumptions());
    assert_eq!(Real::abs(&(&c - &a)), &a - &c);
    assert!(r.error().is_none());
}

#[test]
fn transcendental_functions_are_refused_with_a_reason() {
    let r = ring();
    let a = var(&r, "a", [0.5, 1.5, 2.5]);
    let _ = a.exp();
    match r.error() {
        Some(AlgebraError::NotAlgebraic(w)) => assert_eq!(w, "exp"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn scalar_constants_are_exact() {
    let r = ring();
    let a = var(&r, "a", [0.5, 1.5, 2.5]);
    assert_eq!(a.from_f64(0.375), q(&r, 3, 8));
    assert_eq!(a.parse_like("1.25").unwrap(), q(&r, 5, 4));
    assert_eq!(a.parse_like("-3e-4").unwrap(), q(&r, -3, 10000));
    assert_eq!(a.mul_2si(-3), &a / &r.integer(8));
    assert_eq!(q(&r, 7, 2).floor(), r.integer(3));
}

fn period_ring() -> (Ring, Sym, Sym) {
    let r = ring();
    let u = var(&r, "u", [0.3, -0.8, 1.2]);
    let k = var(&r, "k", [0.5, 0.9, 0.2]);
    (r, u, k)
}

#[test]
fn quarter_period_shifts_follow_dlmf_22_4_3() {
    let (r, u, k) = period_ring();
    let kk = r.quarter_period(&k).unwrap();
    let (s, c, d) = u.sncndn(&k).unwrap();
    let kp = (&r.integer(1) - &(&k * &k)).sqrt().unwrap();
    let (s1, c1, d1) = (&u + &kk).sncndn(&k).unwrap();
    assert_eq!(s1, &c / &d);
    assert_eq!(c1, -(&(&kp * &s) / &d));
    assert_eq!(d1, &kp / &d);
    let (s2, c2, d2) = (&u + &(&r.integer(2) * &kk)).sncndn(&k).unwrap();
    assert_eq!((s2, c2, d2), (-&s, -&c, d.clone()));
    let (s4, c4, d4) = (&u - &(&r.integer(4) * &kk)).sncndn(&k).unwrap();
    assert_eq!((s4, c4, d4), (s.clone(), c.clone(), d.clone()));
    let (sk, ck, dk) = kk.sncndn(&k).unwrap();
    assert_eq!(sk, r.integer(1));
    assert!(ck.is_exact_zero());
    assert_eq!(dk, kp);
}

#[test]
fn imaginary_period_shifts_and_poles() {
    let (r, u, k) = period_ring();
    let kp = r.quarter_period_prime(&k).unwrap();
    let i = r.i().unwrap();
    let ikp = &i * &kp;
    let (s, c, d) = u.sncndn(&k).unwrap();
    let (s1, c1, d1) = (&u + &ikp).sncndn(&k).unwrap();
    assert_eq!(s1, &r.integer(1) / &(&k * &s));
    assert_eq!(c1, -(&(&i * &d) / &(&k * &s)));
    assert_eq!(d1, -(&(&i * &c) / &s));
    assert!(matches!(ikp.sncndn(&k), Err(AlgebraError::Pole(_))));
    // sn has period 2iK'
    let (s2, _, _) = (&u + &(&r.integer(2) * &ikp)).sncndn(&k).unwrap();
    assert_eq!(s2, s);
}

#[test]
fn half_periods_are_consistent_with_the_addition_theorem() {
    let (r, u, k) = period_ring();
    let kk = r.quarter_period(&k).unwrap();
    let half = &kk / &r.integer(2);
    let (sh, ch, dh) = half.sncndn(&k).unwrap();
    let one = r.integer(1);
    let kp = (&one - &(&k * &k)).sqrt().unwrap();
    assert_eq!(&sh * &sh, &one / &(&one + &kp));
    assert_eq!(&dh * &dh, kp);
    // sn(K/2 + K/2) by DLMF 22.8.1 with the table values is sn K = 1
    let k2 = &k * &k;
    let s4 = sh.try_powi(4).unwrap();
    let doubled = &(&(&r.integer(2) * &sh) * &(&ch * &dh)) / &(&one - &(&k2 * &s4));
    assert_eq!(doubled, one);
    // sn(u + K/2) from the table, pushed once more by K/2, is sn(u + K)
    let (s, c, d) = (&u + &half).sncndn(&k).unwrap();
    let den = &one - &(&k2 * &(&(&s * &s) * &(&sh * &sh)));
    let pushed = &(&(&(&s * &ch) * &dh) + &(&(&sh * &c) * &d)) / &den;
    assert_eq!(pushed, (&u + &kk).sn(&k).unwrap());
    // sn(iK'/2)² = −1/k
    let ikp2 = &(&r.i().unwrap() * &r.quarter_period_prime(&k).unwrap()) / &r.integer(2);
    let si = ikp2.sn(&k).unwrap();
    assert_eq!(&si * &si, -(&one / &k));
}

#[test]
fn half_arguments_refine_the_base_arguments_by_a_restart() {
    // sn φ̂ = sn(φ̄ + Δ) with φ̄ = (φ + φ̂)/2, Δ = (φ̂ − φ)/2 after sn φ, sn φ̂ are seen
    let proof = prove_identity(RingOptions::default(), "half arguments", |r| {
        let phi = r.indeterminate_f64("phi", [0.2, -0.9, 1.4].as_slice())?;
        let phih = r.indeterminate_f64("phih", [0.7, -0.3, 2.1].as_slice())?;
        let k = r.indeterminate_f64("k", [0.5, 0.9, 0.2].as_slice())?;
        let _ = phi.sn(&k)?;
        let lhs = phih.sn(&k)?;
        let half = q(r, 1, 2);
        let (sb, cb, db) = (&(&phi + &phih) * &half).sncndn(&k)?;
        let (sd, cd, dd) = (&(&phih - &phi) * &half).sncndn(&k)?;
        let den = &r.integer(1) - &(&(&k * &k) * &(&(&sb * &sb) * &(&sd * &sd)));
        Ok((lhs, &(&(&(&sb * &cd) * &dd) + &(&(&sd * &cb) * &db)) / &den))
    });
    assert!(proof.is_proved(), "{:?}", proof.outcome);
    assert!(
        proof.attempts >= 2,
        "the first evaluation must ask for refined bases"
    );
}

#[test]
fn derivatives_of_the_jacobi_functions() {
    let (r, u, k) = period_ring();
    let (s, c, d) = u.sncndn(&k).unwrap();
    assert_eq!(s.derivative(&u).unwrap(), &c * &d);
    assert_eq!(c.derivative(&u).unwrap(), -(&s * &d));
    assert_eq!(d.derivative(&u).unwrap(), -(&(&k * &k) * &(&s * &c)));
    // chain rule through a root: d/du sn(√a·u) = √a cn dn
    let a = var(&r, "a", [2.0, 0.5, 1.5]);
    let ra = a.sqrt().unwrap();
    let (s2, c2, d2) = (&ra * &u).sncndn(&k).unwrap();
    assert_eq!(s2.derivative(&u).unwrap(), &(&ra * &c2) * &d2);
    // d/da √a = 1/(2√a)
    assert_eq!(
        ra.derivative(&a).unwrap(),
        &r.integer(1) / &(&r.integer(2) * &ra)
    );
    assert!(matches!(
        s.derivative(&(&u + &a)),
        Err(AlgebraError::Derivative(_))
    ));
}

/// Central difference of sn in k at 256 bits (independent of the prover).
fn sn_dk_numeric(u: f64, k: f64) -> f64 {
    let h = Float::with_val(256, 1e-30);
    let uf = Float::with_val(256, u);
    let kf = Float::with_val(256, k);
    let (sp, _, _) = eulertop::special::sncndn(&uf, &Float::with_val(256, &kf + &h)).unwrap();
    let (sm, _, _) = eulertop::special::sncndn(&uf, &Float::with_val(256, &kf - &h)).unwrap();
    Float::with_val(256, (sp - sm) / (Float::with_val(256, 2) * h)).to_f64()
}

#[test]
fn derivatives_in_the_modulus() {
    let (_r, u, k) = period_ring();
    let (s, c, d) = u.sncndn(&k).unwrap();
    let dk_s = s.derivative(&k).unwrap();
    // the Pythagorean relations are constant in k
    assert!(
        (&(&s * &s) + &(&c * &c))
            .derivative(&k)
            .unwrap()
            .is_exact_zero()
    );
    let dn_rel = &(&d * &d) + &(&(&k * &k) * &(&s * &s));
    assert!(dn_rel.derivative(&k).unwrap().is_exact_zero());
    for (p, (uu, kk)) in [(0.3, 0.5), (-0.8, 0.9), (1.2, 0.2)].iter().enumerate() {
        let expect = sn_dk_numeric(*uu, *kk);
        let got = dk_s.shadow(p).real().to_f64();
        assert!(
            (got - expect).abs() < 1e-12 * expect.abs().max(1.0),
            "point {p}: {got} vs {expect}"
        );
        let nf = dk_s.eval_normal_form()[p].real().to_f64();
        assert!(
            (nf - expect).abs() < 1e-12 * expect.abs().max(1.0),
            "point {p}: {nf} vs {expect}"
        );
    }
}

#[test]
fn normal_forms_evaluate_to_their_shadows() {
    let (r, u, k) = period_ring();
    let a = var(&r, "a", [2.0, 0.5, 1.5]);
    let (s, c, d) = (&u + &a).sncndn(&k).unwrap();
    let x = &(&(&s * &c) + &(&d / &(&a + &r.integer(3)))) / &(&a.sqrt().unwrap() + &r.integer(1));
    let nf = x.eval_normal_form();
    for (p, z) in nf.iter().enumerate() {
        let diff = Complex::with_val(256, z - x.shadow(p));
        assert!(Float::with_val(64, diff.abs_ref()) < 1e-60, "point {p}");
    }
}

#[test]
fn opaque_arguments_are_base_arguments_of_their_own() {
    // u0 = i·v0 with v0 unknown to the prover: sn(u0 + u) still follows DLMF 22.8.1
    let (r, u, k) = period_ring();
    let vals: Vec<Complex> = [0.4, 0.7, 0.2]
        .iter()
        .map(|&y| Complex::with_val(256, (0, y)))
        .collect();
    let u0 = r.opaque("uzero", &vals, true).unwrap();
    let (s0, c0, d0) = u0.sncndn(&k).unwrap();
    let (su, cu, du) = u.sncndn(&k).unwrap();
    let one = r.integer(1);
    let den = &one - &(&(&k * &k) * &(&(&s0 * &s0) * &(&su * &su)));
    let rhs = &(&(&(&s0 * &cu) * &du) + &(&(&su * &c0) * &d0)) / &den;
    assert_eq!((&u0 + &u).sn(&k).unwrap(), rhs);
    // constant: no derivative; a non-constant opaque symbol has none to offer
    assert!(s0.derivative(&u).unwrap().is_exact_zero());
    let w = r.opaque("w", &vals, false).unwrap();
    assert!(matches!(
        w.sn(&k).unwrap().derivative(&u),
        Err(AlgebraError::Derivative(_))
    ));
}

#[test]
fn a_ring_that_runs_out_of_symbols_is_rebuilt_larger() {
    // 9 indeterminates and 9 roots in a ring made for 4 of each
    let small = RingOptions {
        max_roots: 4,
        max_vars: 4,
        ..Default::default()
    };
    let proof = prove_identity(small.clone(), "capacity", |r| {
        let mut lhs = r.integer(0);
        let mut rhs = r.integer(0);
        for i in 0..9 {
            let x = r.indeterminate_f64(&format!("x{i}"), &[1.5 + i as f64, 2.0, 3.5])?;
            let s = x.sqrt()?;
            lhs = &lhs + &(&s * &s);
            rhs = &rhs + &x;
        }
        Ok((lhs, rhs))
    });
    assert!(proof.is_proved(), "{:?}", proof.outcome);
    assert!(proof.attempts >= 2);
    let r = Ring::new(small);
    let xs: Vec<_> = (0..5)
        .map(|i| r.indeterminate_f64(&format!("x{i}"), &[1.0, 2.0, 3.0]))
        .collect();
    assert!(matches!(xs[4], Err(AlgebraError::Capacity(_))));
}

/// Recording, rendering and dropping a derivation walk it without recursion.  The
/// chain is 50 000 additions deep and runs on a thread with a 256 KiB stack: a
/// recursive walk would need at least 16 bytes per level (a return address and one
/// saved register), 800 KB in all, and would overflow it three times over.
#[test]
fn long_derivations_are_recorded_and_dropped_without_recursion() {
    const DEPTH: i64 = 50_000;
    let body = || {
        let r = Ring::new(RingOptions {
            certificate: true,
            ..Default::default()
        });
        let x = var(&r, "x", [0.5, 1.5, 2.5]);
        let mut acc = r.integer(0);
        for _ in 0..DEPTH {
            acc = &acc + &x;
        }
        let expect = &x * &r.integer(DEPTH);
        let cert = r
            .certificate(&[(acc.clone(), expect.clone())], "long", None)
            .expect("recorded");
        assert!(cert.lines().count() > DEPTH as usize);
        drop(acc);
    };
    std::thread::Builder::new()
        .stack_size(256 << 10)
        .spawn(body)
        .expect("a thread")
        .join()
        .expect("no overflow and no failed assertion");
}

/// `(x + 2²²⁰) − 2²²⁰` is `x` exactly, but its shadow has lost about 220 of its 256
/// bits: the carried error scale cannot decide the sign, the value evaluated afresh
/// from its normal form can.  A value that really vanishes at a point stays undecided.
#[test]
fn signs_are_decided_from_the_normal_form_when_the_carried_scale_is_too_coarse() {
    let r = ring();
    let x = var(&r, "x", [1.5, 2.5, 0.75]);
    let big = r.rational(&(rug::Rational::from(1) << 220u32));
    let v = &(&x + &big) - &big;
    assert_eq!(v, x);
    assert_eq!(v.sign().unwrap(), 1);
    assert_eq!(v.negate().sign().unwrap(), -1);
    let y = var(&r, "y", [1.5, 2.0, 0.75]);
    let w = &(&(&x - &y) + &big) - &big;
    assert!(w.sign().is_err(), "x − y vanishes at two points");
    // a square root whose branch is decided the same way
    let sq = (&(&(&v * &v) + &big) - &big).sqrt().unwrap();
    assert_eq!(sq, x);
}

/// A radicand that is the square of a polynomial gets its root without a new symbol.
#[test]
fn perfect_square_radicands_need_no_root_symbol() {
    let r = ring();
    let a = var(&r, "a", [2.0, 3.0, 0.5]);
    let b = var(&r, "b", [1.0, 0.25, 4.0]);
    let p = &(&a * &a) + &(&b * &r.integer(3));
    let root = (&p * &p).sqrt().unwrap();
    assert_eq!(root, p);
    assert!(r.relations().is_empty(), "{:?}", r.relations());
}

#[test]
fn after_the_first_error_the_operators_stop_and_the_error_stays() {
    let r = ring();
    let x = var(&r, "x", [0.5, -1.0, 2.0]);
    let y = var(&r, "y", [1.5, 2.0, 3.0]);
    // the sign of x is not proved (it differs between the points): the comparison
    // poisons the ring
    let _ = x > r.integer(0);
    let first = r.error().expect("an undecidable sign is recorded");
    assert!(
        first.to_string().contains("not proved on the domain"),
        "{first}"
    );
    // later operations do not compute (nor record anything else), and nothing is proved
    let big = (x.clone() + y.clone()).powi(12) * (x.clone() - y.clone()).powi(12);
    assert!(big.is_exact_zero());
    let _ = big.clone() / (x.clone() - x.clone());
    assert_eq!(r.error().map(|e| e.to_string()), Some(first.to_string()));
    assert!(!r.prove(&(x.clone() * y.clone()), &(y * x)).is_proved());
}

#[test]
fn the_inverse_of_sn_in_a_varying_modulus_differentiates_as_the_inverse_function() {
    // v = F(asin x, k), the inverse of sn: sn(v, k) = x, cn v = √(1 − x²),
    // dn v = √(1 − k²x²).  Its derivatives in x and in k (through the symbol
    // Z = E(am v, k) − k'²v) must agree with central differences of F at the points.
    use eulertop::special::ellipf;
    let (xs, ks) = ([0.3, 0.6], [0.5, 0.8]);
    // x, k ∈ (0, 1), so that the roots √(1 − x²), √(1 − k²x²) are proved positive
    let mut par = eulertop::algebra::positivity::Parametrization::new();
    let one = par.constant(&rug::Rational::from(1));
    for n in ["x", "k"] {
        let t = par.positive(&format!("t_{n}")).unwrap();
        par.bind(n, t.div(&one.add(&t)).unwrap(), String::new());
    }
    let ring = Ring::new(RingOptions {
        points: 2,
        positivity: Some(std::sync::Arc::new(par)),
        ..Default::default()
    });
    let x = ring.indeterminate_f64("x", &xs).unwrap();
    let k = ring.indeterminate_f64("k", &ks).unwrap();
    let f = |x: f64, k: f64| ellipf(&x.asin(), &k).unwrap();
    let values: Vec<Complex> = (0..2)
        .map(|i| Complex::with_val(256, (f(xs[i], ks[i]), 0)))
        .collect();
    let v = ring.opaque("v", &values, false).unwrap();
    let one = ring.integer(1);
    let c = (one.clone() - x.clone() * x.clone()).sqrt().unwrap();
    let d = (one - k.clone() * k.clone() * x.clone() * x.clone())
        .sqrt()
        .unwrap();
    ring.prescribe_sncndn(&v, &k, &x, &c, &d, "v = F(asin x, k)")
        .unwrap();
    let (dvdx, dvdk) = (v.derivative(&x).unwrap(), v.derivative(&k).unwrap());
    let h = 1e-6;
    for i in 0..2 {
        let fx = (f(xs[i] + h, ks[i]) - f(xs[i] - h, ks[i])) / (2.0 * h);
        let fk = (f(xs[i], ks[i] + h) - f(xs[i], ks[i] - h)) / (2.0 * h);
        let got = |s: &Sym| s.shadow(i).real().to_f64();
        assert!(
            (got(&dvdx) - fx).abs() < 1e-7,
            "dv/dx {} vs {fx}",
            got(&dvdx)
        );
        assert!(
            (got(&dvdk) - fk).abs() < 1e-7,
            "dv/dk {} vs {fk}",
            got(&dvdk)
        );
    }
}

/// A first attempt that meets an argument needing a multiple of a base (`φ + 2δ` over
/// the bases `φ`, `δ` as they came) restarts at once on a cheaper basis of the
/// arguments seen (`δ`, `φ + δ`), over which every argument is one addition away.
#[test]
fn an_argument_that_needs_a_multiple_of_a_base_restarts_on_a_cheaper_basis() {
    let opts = RingOptions {
        points: 3,
        ..Default::default()
    };
    let proof = prove_identity(opts, "midpoint", |r| {
        let k = r.indeterminate_f64("k", &[0.3, 0.5, 0.7])?;
        let phi = r.indeterminate_f64("phi", &[0.2, 0.4, 0.9])?;
        let d = r.indeterminate_f64("d", &[0.1, -0.3, 0.25])?;
        let (s, ..) = phi.sncndn(&k)?;
        let (sd, ..) = d.sncndn(&k)?;
        let far = &phi + &(&d + &d);
        let (s2, ..) = far.sncndn(&k)?;
        // sn(φ + 2δ) − sn φ·sn δ, written two ways
        let lhs = &s2 - &(&s * &sd);
        let rhs = &(&phi + &(&r.integer(2) * &d)).sn(&k)? - &(&sd * &s);
        Ok((lhs, rhs))
    });
    assert!(proof.is_proved(), "{:?}", proof.outcome);
    assert_eq!(proof.attempts, 2);
    let multiples: Vec<&String> = (proof.notes.iter())
        .filter(|n| n.contains("with argument") && n.contains("2*b_"))
        .collect();
    assert!(multiples.is_empty(), "{multiples:?}");
}

/// A named quantity is a free symbol first; when that attempt stops with an error (here
/// the sign of `k = √x`, which the parametrization proves only through the definition),
/// the proof is tried again with the definition, as after a nonzero normal form.
#[test]
fn a_named_attempt_that_stops_with_an_error_retries_with_the_definitions() {
    use eulertop::algebra::positivity::Parametrization;
    let mut par = Parametrization::new();
    let t = par.positive("t1").expect("a parameter");
    par.bind("x", t, "x = t1".into());
    let opts = RingOptions {
        positivity: Some(std::sync::Arc::new(par)),
        ..Default::default()
    };
    let proof = prove_identity(opts, "k·sign(k) = k for k = √x", |r| {
        let x = r.indeterminate_f64("x", &[0.5, 1.5, 2.5])?;
        let k = r.named("k", &x.sqrt()?)?;
        let s = k.stated_sign().map_err(AlgebraError::Domain)?;
        Ok((&k * &r.integer(i64::from(s)), k.clone()))
    });
    assert!(proof.is_proved(), "{:?}", proof.outcome);
    assert!(proof.expanded_named);
}
