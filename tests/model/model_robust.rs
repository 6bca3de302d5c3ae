//! No panics and no silent garbage: for random (also large) h, every step either
//! returns a solution of (impl spec) / (M thru omega) or a clean error; Φ⁻¹ on points
//! with zero components returns a value or a clean error; `model::orbit` is the step map
//! iterated and stops at the first failing step.

use eulertop::linalg::Vec3;
use eulertop::model::discretization::{residual, step};
use eulertop::model::elliptic_coords::{m_to_phi, phi_to_m};
use eulertop::model::veselov_moser::vm_step;
use eulertop::model::{Gamma, Inertia};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]
    #[test]
    fn steps_never_panic(c in 0.2f64..2.0, db in 0.01f64..2.0, da in 0.01f64..2.0,
                         m in (-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0), h in -20.0f64..20.0) {
        let i = Inertia::new(c + db + da, c + db, c).unwrap();
        let m = Vec3::new(m.0, m.1, m.2);
        for g in [Gamma::G0, Gamma::G1, Gamma::G2, Gamma::Vm] {
            if let Ok(x) = step(&i, g, &m, &h) {
                let r = residual(&i, g, &m, &x, &h).unwrap();
                prop_assert!(r.max_magnitude() <= 1e-13 * (1.0 + m.max_magnitude() + x.max_magnitude()));
            }
        }
        if let Ok(s) = vm_step(&i, &m, &h) {
            let w = s.omega;
            let e = (w.transpose() * w.clone() - eulertop::linalg::Mat3::identity(&1.0)).max_magnitude();
            prop_assert!(e < 1e-12);
        }
    }

    #[test]
    fn phi_inverse_never_panics(z in prop::sample::select(vec![0usize, 1, 2, 3, 4, 5, 6, 7]),
                                m in (-2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0)) {
        let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
        let v = Vec3::new(
            if z & 1 == 1 { 0.0 } else { m.0 },
            if z & 2 == 2 { 0.0 } else { m.1 },
            if z & 4 == 4 { 0.0 } else { m.2 },
        );
        if let Ok(c) = m_to_phi(&i, &v) {
            let back = phi_to_m(&c.params, c.sector, &c.phi).unwrap();
            prop_assert!((back - v).max_magnitude() < 1e-9);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 100, ..ProptestConfig::default() })]
    /// `model::orbit` is the step map iterated: the same points as repeated `step` /
    /// `vm_step` calls, and it ends after the first failing step.
    #[test]
    fn orbit_is_the_iterated_step(m in (-3.0f64..3.0, -3.0f64..3.0, 0.1f64..3.0),
                                  h in -3.0f64..3.0, g in 0usize..5) {
        use eulertop::model::{orbit, Stepper};
        let i = Inertia::new(3.0, 2.0, 1.0).unwrap();
        let m0 = Vec3::new(m.0, m.1, m.2);
        let stepper = match g {
            0 => Stepper::Implicit(Gamma::G0),
            1 => Stepper::Implicit(Gamma::G1),
            2 => Stepper::Implicit(Gamma::G2),
            3 => Stepper::Implicit(Gamma::Vm),
            _ => Stepper::Matrix,
        };
        let mut it = orbit(&i, stepper, &m0, &h);
        let mut cur = m0.clone();
        for _ in 0..6 {
            let direct = match stepper {
                Stepper::Implicit(g) => step(&i, g, &cur, &h),
                Stepper::Matrix => vm_step(&i, &cur, &h).map(|s| s.m_hat),
            };
            match (it.next(), direct) {
                (Some(Ok(a)), Ok(b)) => {
                    prop_assert_eq!(&a, &b);
                    cur = b;
                }
                (Some(Err(a)), Err(b)) => {
                    // (the messages: a residual NaN makes the errors unequal as values)
                    prop_assert_eq!(a.to_string(), b.to_string());
                    prop_assert!(it.next().is_none(), "orbit goes on after an error");
                    break;
                }
                (a, b) => prop_assert!(false, "orbit {:?} but step {:?}", a, b),
            }
        }
    }
}
