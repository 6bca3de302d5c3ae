//! Criterion benchmarks of sn+cn+dn (one call returns all three; also the slice call
//! `sncndn_many`): f64, 1024- and 4096-bit MPFR, real argument, with one modulus for the
//! batch (k = 0.8, and in f64 also k = 0.95, the imaginary-argument series) or a new
//! modulus on every call ("fresh k"), plus complex f64.
//! `cargo bench --bench jacobi`.

use criterion::{Criterion, Throughput, black_box, criterion_group};
use eulertop::numbers::C64;
use eulertop::special::{sncndn, sncndn_complex, sncndn_many};
use rug::Float;

/// The batch used everywhere (also by examples/bench_batch.rs and scripts/bench_peers.py):
/// u_i = −10 + 20·(i + 0.5)/n, modulus k = 0.8.
fn batch(n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| -10.0 + 20.0 * (i as f64 + 0.5) / n as f64)
        .collect()
}

/// The fresh-modulus sequence of examples/bench_batch.rs: k_i = 0.05 + 0.94·frac(i·φ).
fn fresh_ks(n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| 0.05 + 0.94 * (i as f64 * 0.618_033_988_749_894_9).fract())
        .collect()
}

fn bench(c: &mut Criterion) {
    let us = batch(1000);
    let ks = fresh_ks(1000);
    let mut g = c.benchmark_group("jacobi");
    g.throughput(Throughput::Elements(us.len() as u64));
    g.bench_function("f64 sncndn x1000", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for u in &us {
                let (s, c, d) = sncndn(black_box(u), black_box(&0.8)).unwrap();
                acc += s + c + d;
            }
            acc
        })
    });
    g.bench_function("f64 sncndn k=0.95 x1000", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for u in &us {
                let (s, c, d) = sncndn(black_box(u), black_box(&0.95)).unwrap();
                acc += s + c + d;
            }
            acc
        })
    });
    g.bench_function("f64 sncndn fresh k x1000", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for (u, k) in us.iter().zip(&ks) {
                let (s, c, d) = sncndn(black_box(u), black_box(k)).unwrap();
                acc += s + c + d;
            }
            acc
        })
    });
    g.bench_function("f64 sncndn_many x1000", |b| {
        b.iter(|| sncndn_many(black_box(&us), black_box(&0.8)).unwrap())
    });
    g.bench_function("f64 complex sncndn x1000", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for u in &us {
                let z = C64::new(*u, 0.37 * u);
                let (s, _, _) = sncndn_complex(black_box(&z), black_box(&0.8)).unwrap();
                acc += s.re;
            }
            acc
        })
    });
    let us1024: Vec<Float> = batch(50)
        .iter()
        .map(|u| Float::with_val(1024, *u))
        .collect();
    let k = Float::with_val(1024, 0.8);
    g.throughput(Throughput::Elements(us1024.len() as u64));
    g.sample_size(10);
    g.bench_function("1024-bit sncndn x50", |b| {
        b.iter(|| {
            for u in &us1024 {
                black_box(sncndn(black_box(u), &k).unwrap());
            }
        })
    });
    for bits in [1024u32, 4096] {
        let n = if bits == 1024 { 50 } else { 10 };
        let us_mp: Vec<Float> = batch(n).iter().map(|u| Float::with_val(bits, *u)).collect();
        let ks_mp: Vec<Float> = fresh_ks(n)
            .iter()
            .map(|k| Float::with_val(bits, *k))
            .collect();
        g.throughput(Throughput::Elements(n as u64));
        g.bench_function(format!("{bits}-bit sncndn fresh k x{n}"), |b| {
            b.iter(|| {
                for (u, k) in us_mp.iter().zip(&ks_mp) {
                    black_box(sncndn(black_box(u), black_box(k)).unwrap());
                }
            })
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
/// As `criterion_main!`, with GMP's kernels for this processor selected first (as the
/// `eulertop` binary does), so that the MPFR figures are the product's.
fn main() {
    eulertop::numbers::gmp_kernels::select();
    benches();
    Criterion::default().configure_from_args().final_summary();
}
