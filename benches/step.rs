//! Cost of one step of the special discretization with γ_VM (gammaMV) and of the
//! Veselov–Moser matrix step, in f64 and MPFR at 256 and 1024 bits; prints the Newton
//! iteration counts.  Run: `cargo bench --bench step`.

use criterion::{Criterion, black_box, criterion_group};
use eulertop::linalg::Vec3;
use eulertop::model::discretization::{step, step_report};
use eulertop::model::veselov_moser::vm_step;
use eulertop::model::{Gamma, Inertia, NewtonOptions};
use eulertop::numbers::Real;
use rug::Float;

fn setup<R: Real>(like: &R) -> (Inertia<R>, Vec3<R>, R) {
    let i = Inertia::new(like.from_f64(3.0), like.from_f64(2.0), like.from_f64(1.0)).unwrap();
    let m = Vec3::new(like.from_f64(0.3), like.from_f64(-0.7), like.from_f64(1.1));
    (i, m, like.from_f64(0.01))
}

fn report_iterations<R: Real>(like: &R, label: &str) {
    let (i, m, h) = setup(like);
    for g in [Gamma::G0, Gamma::G1, Gamma::G2, Gamma::Vm] {
        let r = step_report(&i, g, &m, &h, NewtonOptions::default()).unwrap();
        eprintln!(
            "newton {label} {}: {} iterations, residual {:e}",
            g.name(),
            r.iterations,
            r.residual
        );
    }
    let v = vm_step(&i, &m, &h).unwrap();
    eprintln!("newton {label} VM matrix: {} iterations", v.iterations);
}

fn bench(c: &mut Criterion) {
    report_iterations(&1.0f64, "f64");
    for bits in [256u32, 1024, 4096] {
        report_iterations(&Float::with_val(bits, 1), &format!("{bits} bits"));
    }
    let (i, m, h) = setup(&1.0f64);
    c.bench_function("gammaVM step f64", |b| {
        b.iter(|| step(&i, Gamma::Vm, black_box(&m), &h).unwrap())
    });
    c.bench_function("gamma1 step f64", |b| {
        b.iter(|| step(&i, Gamma::G1, black_box(&m), &h).unwrap())
    });
    c.bench_function("VM matrix step f64", |b| {
        b.iter(|| vm_step(&i, black_box(&m), &h).unwrap())
    });
    c.bench_function("1000 gammaVM steps f64", |b| {
        b.iter(|| {
            let mut x = m.clone();
            for _ in 0..1000 {
                x = step(&i, Gamma::Vm, &x, &h).unwrap();
            }
            x
        })
    });
    for bits in [256u32, 1024, 4096] {
        let (i, m, h) = setup(&Float::with_val(bits, 1));
        c.bench_function(&format!("gammaVM step {bits} bits"), |b| {
            b.iter(|| step(&i, Gamma::Vm, black_box(&m), &h).unwrap())
        });
        c.bench_function(&format!("VM matrix step {bits} bits"), |b| {
            b.iter(|| vm_step(&i, black_box(&m), &h).unwrap())
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).measurement_time(std::time::Duration::from_secs(2)).warm_up_time(std::time::Duration::from_millis(500));
    targets = bench
}
/// As `criterion_main!`, with GMP's kernels for this processor selected first (as the
/// `eulertop` binary does), so that the MPFR figures are the product's.
fn main() {
    eulertop::numbers::gmp_kernels::select();
    benches();
    Criterion::default().configure_from_args().final_summary();
}
