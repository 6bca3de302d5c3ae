//! Properties of the special discretizations (impl spec) and the Veselov–Moser
//! matrix algorithm (VM): integrals (int), agreement of (VM) with (gammaMV), ω ∈ SO(3)
//! on the branch (omega as), the root set S and its split.

use eulertop::linalg::{Mat3, Vec3};
use eulertop::model::discretization::{residual, residual_cleared, step_report};
use eulertop::model::veselov_moser::{
    j_diag, lambda_poly, lambda_roots, omega_matrix, split_roots, vm_step,
};
use eulertop::model::{Gamma, Inertia, NewtonOptions};
use eulertop::numbers::{ComplexScalar, Cplx, Real};
use proptest::prelude::*;
use rug::Float;

const GAMMAS: [Gamma; 4] = [Gamma::G0, Gamma::G1, Gamma::G2, Gamma::Vm];

fn inertia_strategy() -> impl Strategy<Value = (f64, f64, f64)> {
    (0.5f64..3.0, 0.1f64..2.0, 0.1f64..2.0).prop_map(|(c, db, da)| (c + db + da, c + db, c))
}

fn point_strategy() -> impl Strategy<Value = (f64, f64, f64)> {
    (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0).prop_filter("away from axes", |(x, y, z)| {
        let n = [x.abs(), y.abs(), z.abs()];
        n.iter().filter(|v| **v > 0.05).count() >= 2
    })
}

fn setup<R: Real>(like: &R, abc: (f64, f64, f64), m: (f64, f64, f64)) -> (Inertia<R>, Vec3<R>) {
    let i = Inertia::new(
        like.from_f64(abc.0),
        like.from_f64(abc.1),
        like.from_f64(abc.2),
    )
    .expect("strategy gives A>B>C>0");
    let v = Vec3::new(like.from_f64(m.0), like.from_f64(m.1), like.from_f64(m.2));
    (i, v)
}

fn rel_diff<R: Real>(x: &R, y: &R) -> f64 {
    let s = x.abs().max_of(&y.abs()).max_of(&x.one());
    ((x.clone() - y.clone()).abs() / s).to_f64()
}

fn check_integrals<R: Real>(like: &R, abc: (f64, f64, f64), m0: (f64, f64, f64), h: f64) {
    let (i, m) = setup(like, abc, m0);
    let h = like.from_f64(h);
    let tol = like.epsilon().to_f64() * 64.0;
    for g in GAMMAS {
        let r = step_report(&i, g, &m, &h, NewtonOptions::default()).expect("Newton converges");
        let mh = r.m;
        assert!(rel_diff(&i.m2(&mh), &i.m2(&m)) <= tol, "M2 {g:?}");
        assert!(rel_diff(&i.energy(&mh), &i.energy(&m)) <= tol, "E {g:?}");
        let res = residual(&i, g, &m, &mh, &h).unwrap();
        assert!(res.max_magnitude() <= tol * (1.0 + m.max_magnitude()));
        // the step actually moves (M is not a fixed point)
        assert!((mh - m.clone()).max_magnitude() > tol * 1e3);
    }
}

fn check_vm_matrix<R: Real>(like: &R, abc: (f64, f64, f64), m0: (f64, f64, f64), h: f64) {
    let (i, m) = setup(like, abc, m0);
    let h = like.from_f64(h);
    let eps = like.epsilon().to_f64();
    let s = vm_step(&i, &m, &h).expect("VM Newton converges");
    let w = s.omega.clone();
    let id = Mat3::identity(like);
    // orthogonal with det 1
    assert!((w.transpose() * w.clone() - id.clone()).max_magnitude() <= 64.0 * eps);
    assert!((w.det() - like.one()).abs().to_f64() <= 64.0 * eps);
    // (omega as): ω − I − hΩ = O(h²)
    let dev = (w.clone() - id - omega_matrix(&i, &m).scale(&h)).max_magnitude();
    let hm = h.to_f64() * (1.0 + m.max_magnitude());
    assert!(dev <= 10.0 * hm * hm * (1.0 + omega_matrix(&i, &m).max_magnitude()).powi(2));
    // matrix VM agrees with implicit gamma_VM map
    let r = step_report(&i, Gamma::Vm, &m, &h, NewtonOptions::default()).unwrap();
    let d = (r.m - s.m_hat.clone()).max_magnitude();
    assert!(
        d <= 256.0 * eps * (1.0 + m.max_magnitude()),
        "VM mismatch {d:e}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn integrals_f64(abc in inertia_strategy(), m in point_strategy(), h in 0.001f64..0.1) {
        check_integrals(&1.0f64, abc, m, h);
    }

    #[test]
    fn vm_matrix_f64(abc in inertia_strategy(), m in point_strategy(), h in 0.001f64..0.1) {
        check_vm_matrix(&1.0f64, abc, m, h);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

    #[test]
    fn integrals_256(abc in inertia_strategy(), m in point_strategy(), h in 0.001f64..0.1) {
        check_integrals(&Float::with_val(256, 1), abc, m, h);
    }

    #[test]
    fn vm_matrix_256(abc in inertia_strategy(), m in point_strategy(), h in 0.001f64..0.1) {
        check_vm_matrix(&Float::with_val(256, 1), abc, m, h);
    }
}

#[test]
fn newton_1024_bits() {
    let like = Float::with_val(1024, 1);
    check_integrals(&like, (3.0, 2.0, 1.0), (0.3, -0.7, 1.1), 0.05);
    check_vm_matrix(&like, (3.0, 2.0, 1.0), (0.3, -0.7, 1.1), 0.05);
}

fn check_roots<R: Real>(like: &R) {
    let (i, m) = setup(like, (3.0, 2.0, 1.5), (0.3, -0.7, 1.1));
    let h = like.from_f64(0.05);
    let tol = like.epsilon().to_f64().sqrt() * 1e-2; // roots of a polynomial: ~√ε near clusters
    let s = lambda_roots(&i, &m, &h).unwrap();
    assert_eq!(s.len(), 6);
    // each root annihilates det(I − hλM − λ²J²) (Horner in complex arithmetic)
    let p = lambda_poly(&i, &m, &h);
    for z in &s {
        let mut acc = Cplx::new(like.zero(), like.zero());
        for c in p.iter().rev() {
            acc = acc * z.clone() + Cplx::new(c.clone(), like.zero());
        }
        assert!(acc.abs().to_f64() < like.epsilon().to_f64() * 1e4);
    }
    let st = vm_step(&i, &m, &h).unwrap();
    let (sp, sm) = split_roots(&i, &st.omega).unwrap();
    // S₊ ∪ S₋ = S and S₊ = −S₋
    for z in sp.iter().chain(sm.iter()) {
        assert!(
            s.iter()
                .any(|y| (y.clone() - z.clone()).abs().to_f64() < tol)
        );
    }
    for z in &sp {
        assert!(
            sm.iter()
                .any(|y| (y.clone() + z.clone()).abs().to_f64() < tol)
        );
    }
    // S₋ is real positive and O(h)-close to 1/J
    let j = j_diag(&i);
    for z in &sm {
        assert!(z.im.abs().to_f64() < tol && z.re > like.zero());
        assert!(
            j.0.iter()
                .any(|jj| (z.re.to_f64() - 1.0 / jj.to_f64()).abs() < 10.0 * h.to_f64())
        );
    }
}

#[test]
fn root_set_and_split() {
    check_roots(&1.0f64);
    check_roots(&Float::with_val(256, 1));
}

#[test]
fn large_h_fails_cleanly() {
    let (i, m) = setup(&1.0f64, (3.0, 2.0, 1.0), (0.3, -0.7, 1.1));
    for g in GAMMAS {
        let r = step_report(&i, g, &m, &50.0, NewtonOptions::default());
        // either a clean error or a genuine solution of the implicit equation
        if let Ok(rep) = r {
            let res = residual(&i, g, &m, &rep.m, &50.0).unwrap();
            assert!(res.max_magnitude() < 1e-10);
        }
    }
    assert!(step_report(&i, Gamma::Vm, &m, &50.0, NewtonOptions::default()).is_err());
}

/// The cleared residual is the residual times the denominator of γ, and γ is its
/// fraction, for every map, at points that solve nothing (an identity of the formulas).
#[test]
fn the_cleared_residual_is_the_residual_times_the_denominator_of_gamma() {
    let i = Inertia::new(3.0_f64, 2.0, 1.0).unwrap();
    let m = Vec3::new(0.3, -1.1, 0.7);
    let mhat = Vec3::new(0.35, -1.0, 0.72);
    let h = 0.05;
    for g in [Gamma::G0, Gamma::G1, Gamma::G2, Gamma::Vm] {
        let (n, d) = g.fraction(&i, &m, &mhat, &h).unwrap();
        assert!((g.eval(&i, &m, &mhat, &h).unwrap() - n / d).abs() < 1e-15);
        let r = residual(&i, g, &m, &mhat, &h).unwrap();
        let (rc, d2) = residual_cleared(&i, g, &m, &mhat, &h).unwrap();
        assert_eq!(d, d2);
        for j in 0..3 {
            assert!((rc.0[j] - d * r.0[j]).abs() < 1e-14, "{g:?} component {j}");
        }
    }
}
