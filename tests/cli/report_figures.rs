//! The model figures of the report: files written, well-formed SVG, deterministic,
//! measured orders near 2 (the maps are midpoint-like: γ = 1 + O(h²)), and the
//! φ̄-independence of Δφ for the Poisson maps γ₁, γ₂, γ_VM against its failure for γ₀.

use eulertop::model::Gamma;
use eulertop::model::experiments::{
    CASES, GAMMAS, ORBIT_SAMPLES, PHASE_GRID, PHASE_H, fitted_orders, orbit_comparison,
    phase_curves,
};
use eulertop::report::figures::model::write_all;
use eulertop::stats::{loglog_slope, ls_slope};
use std::path::PathBuf;

const FILES: [&str; 4] = [
    "dphi-vs-phibar.svg",
    "dphi-vs-phibar-lower.svg",
    "orbits.svg",
    "error-vs-h.svg",
];

fn out_dir(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&d);
    d
}

#[test]
fn writes_valid_svg_files_deterministically() {
    let (d1, d2) = (out_dir("figs-a"), out_dir("figs-b"));
    write_all(&d1).expect("figures written");
    write_all(&d2).expect("figures written again");
    for f in FILES {
        let a = std::fs::read(d1.join(f)).expect("file exists");
        let b = std::fs::read(d2.join(f)).expect("file exists");
        assert_eq!(a, b, "{f} differs between two runs");
        let s = String::from_utf8(a).expect("utf-8");
        let t = s.trim();
        assert!(t.starts_with("<svg"), "{f} does not start with <svg");
        assert!(t.ends_with("</svg>"), "{f} does not end with </svg>");
        assert_eq!(t.matches("<svg").count(), 1, "{f}");
        assert!(
            !s.contains("NaN") && !s.contains("inf"),
            "{f} has non-finite values"
        );
        // data was drawn: many path/line/circle elements and the labels present
        let shapes = s.matches("<polyline").count() + s.matches("<circle").count();
        assert!(shapes > 20, "{f} has only {shapes} shapes");
        assert!(s.contains("A,B,C = 3, 2, 1"), "{f} title lacks the inertia");
    }
    let dphi = std::fs::read_to_string(d1.join("dphi-vs-phibar.svg")).unwrap();
    for g in ["γ0", "γ1", "γ2", "γVM"] {
        assert!(dphi.contains(g), "Δφ figure lacks panel {g}");
    }
    let err = std::fs::read_to_string(d1.join("error-vs-h.svg")).unwrap();
    assert_eq!(err.matches(": order ").count(), 2 * GAMMAS.len());
}

#[test]
fn loglog_slope_recovers_power_laws() {
    for p in [1.0, 2.0, 3.5] {
        let pts: Vec<(f64, f64)> = (0..6)
            .map(|j| {
                let h = 0.5f64.powi(j);
                (h, 7.0 * h.powf(p))
            })
            .collect();
        assert!((loglog_slope(&pts).unwrap() - p).abs() < 1e-12);
    }
    // degenerate data gives no slope instead of a NaN
    assert_eq!(loglog_slope(&[(0.5, 1.0)]), None);
    assert_eq!(loglog_slope(&[(0.5, 1.0), (0.25, 0.0)]), None);
    assert_eq!(ls_slope(&[2.0, 2.0, 2.0], &[1.0, 2.0, 3.0]), None);
    assert_eq!(ls_slope(&[1.0, 2.0], &[1.0]), None);
}

#[test]
fn orbit_comparison_iterates_follow_discrete_solution() {
    let c = orbit_comparison().expect("orbits computed");
    assert_eq!(c.continuous.len(), ORBIT_SAMPLES + 1);
    assert_eq!(c.t_end, c.steps as f64 * c.h);
    let m0 = CASES[0].start();
    for run in &c.runs {
        assert_eq!(run.iterates.len(), c.steps + 1);
        assert_eq!(run.discrete.len(), c.steps + 1);
        // M₀ is the start point, and (sol), (discr sol) pass through it
        assert_eq!(run.iterates[0], m0);
        assert!((run.discrete[0].clone() - m0.clone()).max_magnitude() < 1e-14);
        // the Poisson maps follow (discr sol) along the whole orbit
        for (a, b) in run.iterates.iter().zip(&run.discrete) {
            assert!(
                (a.clone() - b.clone()).max_magnitude() < 1e-11,
                "{:?}",
                run.gamma
            );
        }
    }
    assert!((c.continuous[0].1.clone() - m0).max_magnitude() < 1e-14);
}

#[test]
fn fitted_orders_are_two() {
    let fits = fitted_orders().expect("orbits computed");
    assert_eq!(fits.len(), CASES.len() * GAMMAS.len());
    for f in &fits {
        assert!(
            (f.order - 2.0).abs() <= 0.2,
            "{} {:?}: order {}",
            f.case,
            f.gamma,
            f.order
        );
        // errors decrease monotonically and stay well above rounding level
        for w in f.points.windows(2) {
            assert!(w[1].1 < w[0].1, "{} {:?}: {:?}", f.case, f.gamma, f.points);
        }
        assert!(f.points.iter().all(|p| p.1 > 1e-12 && p.1.is_finite()));
    }
}

#[test]
fn poisson_maps_have_phibar_independent_phase_step() {
    for case in &CASES {
        let curves = phase_curves(case).expect("phases computed");
        assert_eq!(curves.len(), GAMMAS.len() * PHASE_H.len());
        for h in PHASE_H {
            let get = |g: Gamma| {
                curves
                    .iter()
                    .find(|c| c.gamma == g && c.h == h)
                    .expect("curve present")
            };
            let g0 = get(Gamma::G0);
            assert_eq!(g0.points.len(), PHASE_GRID);
            // working precision: a few hundred ulps of Δφ ≈ hν/2 (φ itself is up to 2K)
            let tol = 256.0 * f64::EPSILON;
            let mut worst: f64 = 0.0;
            for g in [Gamma::G1, Gamma::G2, Gamma::Vm] {
                let c = get(g);
                assert!(
                    c.spread() <= tol,
                    "{} {g:?} h={h}: spread {}",
                    case.name,
                    c.spread()
                );
                // and every Δφ equals the predicted δ of (master12) / (MV master)
                let d = c.predicted.expect("δ predicted");
                for p in &c.points {
                    assert!((p.1 - d).abs() <= tol, "{} {g:?} h={h}", case.name);
                }
                worst = worst.max(c.spread());
            }
            // γ0 is not φ̄-independent: its spread is many orders of magnitude larger
            assert!(
                g0.spread() > 1e-6 * g0.half_h_nu && g0.spread() > 1e6 * worst.max(f64::EPSILON),
                "{} h={h}: gamma0 spread {}",
                case.name,
                g0.spread()
            );
            assert!(g0.predicted.is_none());
        }
    }
}
