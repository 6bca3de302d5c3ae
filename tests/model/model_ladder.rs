//! The precision ladder of the model's Newton solvers (module `model::ladder`): above
//! `LADDER_BITS` bits the implicit maps (impl spec) and the Veselov–Moser step start at
//! their own solution at about half the precision.  At 2048 and 4096 bits the step is
//! the solution that the plain iteration from the predictor finds at `LADDER_BITS`
//! bits (they agree to `2^(16 − LADDER_BITS)` relative), and at most three Newton
//! steps are taken at full precision, where the plain iteration takes more already at
//! `LADDER_BITS` bits.
//! (That each step solves its equations to working precision the solvers check
//! themselves: they return an error otherwise.)

use eulertop::linalg::Vec3;
use eulertop::model::discretization::{NewtonOptions, step_report};
use eulertop::model::ladder::LADDER_BITS;
use eulertop::model::veselov_moser::vm_step;
use eulertop::model::{Gamma, Inertia};
use rug::Float;

/// `max |a_i − b_i| / max |b_i|`, at `LADDER_BITS` bits.
fn rel_diff(a: &Vec3<Float>, b: &Vec3<Float>) -> Float {
    let lo = |x: &Float| Float::with_val(LADDER_BITS, x);
    let mut d = Float::new(LADDER_BITS);
    let mut n = Float::new(LADDER_BITS);
    for i in 0..3 {
        d = d.max(&(lo(&a.0[i]) - lo(&b.0[i])).abs());
        n = n.max(&lo(&b.0[i]).abs());
    }
    d / n
}

fn case(bits: u32) -> (Inertia<Float>, Vec3<Float>, Inertia<Float>, Vec3<Float>) {
    let f = |p: u32, x: f64| Float::with_val(p, x);
    let i = |p| Inertia::new(f(p, 3.0), f(p, 2.0), f(p, 1.0)).unwrap();
    let m = |p| Vec3::new(f(p, 0.3), f(p, -0.7), f(p, 1.1));
    (i(bits), m(bits), i(LADDER_BITS), m(LADDER_BITS))
}

/// The step `got` (with its Newton steps) is the plain solution `plain` at
/// `LADDER_BITS` bits, to `2^(16 − LADDER_BITS)` relative, in at most three steps, where
/// the plain iteration takes more.
fn check(what: &str, got: (&Vec3<Float>, usize), plain: (&Vec3<Float>, usize)) {
    let rel = rel_diff(got.0, plain.0);
    let bound = Float::with_val(LADDER_BITS, Float::u_exp(1, 16 - LADDER_BITS as i32));
    assert!(rel <= bound, "{what}: relative difference {rel:.3e}");
    assert!(
        got.1 <= 3 && plain.1 > 3,
        "{what}: {} steps, plain {} at {LADDER_BITS} bits",
        got.1,
        plain.1
    );
}

#[test]
fn implicit_maps_above_the_ladder_find_the_plain_solution_in_few_steps() {
    for bits in [2048u32, 4096] {
        let (i, m, i_lo, m_lo) = case(bits);
        for g in [Gamma::G0, Gamma::G1, Gamma::G2, Gamma::Vm] {
            for h in [0.1, -0.3] {
                let opts = NewtonOptions::default();
                let r = step_report(&i, g, &m, &Float::with_val(bits, h), opts).unwrap();
                let plain = step_report(&i_lo, g, &m_lo, &Float::with_val(LADDER_BITS, h), opts);
                let plain = plain.unwrap();
                check(
                    &format!("{g:?} h = {h} at {bits} bits"),
                    (&r.m, r.iterations),
                    (&plain.m, plain.iterations),
                );
            }
        }
    }
}

#[test]
fn vm_step_above_the_ladder_finds_the_plain_solution_in_few_steps() {
    for bits in [2048u32, 4096] {
        let (i, m, i_lo, m_lo) = case(bits);
        for h in [0.1, -0.3] {
            let s = vm_step(&i, &m, &Float::with_val(bits, h)).unwrap();
            let plain = vm_step(&i_lo, &m_lo, &Float::with_val(LADDER_BITS, h)).unwrap();
            check(
                &format!("VM step h = {h} at {bits} bits"),
                (&s.m_hat, s.iterations),
                (&plain.m_hat, plain.iterations),
            );
        }
    }
}
