//! Times sn+cn+dn over the benchmark batch in-process (for scripts/bench_peers.py):
//! `cargo run --release --example bench_batch -- BITS N REPEATS [all] [many] [fresh] [k=K]
//! [kmin=A] [kmax=B]`
//! prints the median and the minimum over REPEATS of the time per evaluation in
//! nanoseconds (with `all`: every batch's time per evaluation).  By default every
//! argument is one `sncndn(u, k)` call with the fixed modulus k = 0.8 (or `k=K`); with `many` the
//! batch is one `sncndn_many(&us, k)` call (f64 only); with `fresh` every call has its
//! own modulus `k_i = 0.05 + 0.94·frac(i·φ)` (φ the golden ratio, so no two calls share
//! a modulus and the moduli fill [0.05, 0.99] evenly; `kmin=A`, `kmax=B` fill [A, B]
//! instead).  Time is wall-clock time of the
//! batch (`std::time::Instant`; the per-thread CPU clocks of the build machine advance
//! in scheduler ticks of 4 ms, too coarse for a batch of a few milliseconds), and both
//! the median and the minimum are reported.
//! Batch: u_i = −10 + 20·(i + 0.5)/N.
//!
//! With `fn=NAME` the batch times a function of the elliptic toolkit instead, on the
//! same u_i and k_i (as scripts/bench_gsl.c does for GSL): `ellipe` E(k_i),
//! `ellipeinc` E(u_i/4, k_i), `ellippi` Π(0.3, u_i/8, k_i), `jtheta` θ₃(u_i, q_i) with
//! q_i = k_i/2.

use eulertop::numbers::Real;
use eulertop::special::{ToolkitFn, sncndn, sncndn_many};
use rug::Float;
use std::hint::black_box;
use std::time::Instant;

/// The modulus of call `i` in the fresh-modulus mode, in `[lo, hi]`.
fn fresh_k(i: usize, (lo, hi): (f64, f64)) -> f64 {
    let phi = 0.618_033_988_749_894_9_f64;
    lo + (hi - lo) * (i as f64 * phi).fract()
}

fn main() {
    // GMP's kernels for this processor, before any other thread runs
    eulertop::numbers::gmp_kernels::select();
    let a: Vec<String> = std::env::args().collect();
    let arg = |i: usize, d: usize| a.get(i).and_then(|s| s.parse().ok()).unwrap_or(d);
    let (bits, n, reps) = (arg(1, 53) as u32, arg(2, 1000), arg(3, 5).max(1));
    let flag = |f: &str| a.iter().skip(4).any(|x| x == f);
    let fresh = flag("fresh");
    let value = |key: &str, default: f64| -> f64 {
        a.iter()
            .skip(4)
            .find_map(|x| x.strip_prefix(key).and_then(|v| v.parse().ok()))
            .unwrap_or(default)
    };
    let fixed_k = value("k=", 0.8);
    let range = (value("kmin=", 0.05), value("kmax=", 0.99));
    let us: Vec<f64> = (0..n)
        .map(|i| -10.0 + 20.0 * (i as f64 + 0.5) / n as f64)
        .collect();
    let ks: Vec<f64> = (0..n)
        .map(|i| if fresh { fresh_k(i, range) } else { fixed_k })
        .collect();
    let p = bits.max(2);
    let us_mp: Vec<Float> = us.iter().map(|u| Float::with_val(p, *u)).collect();
    let ks_mp: Vec<Float> = ks.iter().map(|k| Float::with_val(p, *k)).collect();
    let toolkit = a.iter().skip(4).find_map(|x| x.strip_prefix("fn="));
    if let Some(name) = toolkit {
        let f = ToolkitFn::from_name(name).expect("a toolkit function");
        let times = if bits == 53 {
            toolkit_batch(f, &us, &ks, reps)
        } else {
            toolkit_batch(f, &us_mp, &ks_mp, reps)
        };
        report(times, flag("all"));
        return;
    }
    let mut times = Vec::new();
    for _ in 0..reps {
        let t0 = Instant::now();
        if bits == 53 && flag("many") {
            let out = sncndn_many(black_box(&us), black_box(&fixed_k)).expect("in domain");
            black_box(out);
        } else if bits == 53 {
            let mut acc = 0.0;
            for (u, k) in us.iter().zip(&ks) {
                let (s, c, d) = sncndn(black_box(u), black_box(k)).expect("in domain");
                acc += s + c + d;
            }
            black_box(acc);
        } else {
            for (u, k) in us_mp.iter().zip(&ks_mp) {
                black_box(sncndn(u, k).expect("in domain"));
            }
        }
        times.push(t0.elapsed().as_nanos() as f64 / n as f64);
    }
    report(times, flag("all"));
}

/// Prints every batch's time (`all`) or the median and the minimum.
fn report(mut times: Vec<f64>, all: bool) {
    if all {
        let all: Vec<String> = times.iter().map(|t| t.to_string()).collect();
        println!("{}", all.join(" "));
        return;
    }
    times.sort_by(|a, b| a.total_cmp(b));
    println!("{} {}", times[times.len() / 2], times[0]);
}

/// Times per evaluation (ns) of `reps` batches of the toolkit function `f` at the
/// arguments of the module documentation.
fn toolkit_batch<R: Real>(f: ToolkitFn, us: &[R], ks: &[R], reps: usize) -> Vec<f64> {
    let args: Vec<Vec<R>> = us
        .iter()
        .zip(ks)
        .map(|(u, k)| match f {
            ToolkitFn::Ellipe => vec![k.clone()],
            ToolkitFn::Ellipeinc => vec![u.mul_2si(-2), k.clone()],
            ToolkitFn::Ellippi => vec![u.from_ratio(3, 10), u.mul_2si(-3), k.clone()],
            _ => vec![u.from_i64(3), u.clone(), k.mul_2si(-1)],
        })
        .collect();
    (0..reps)
        .map(|_| {
            let t0 = Instant::now();
            for a in &args {
                black_box(f.eval(black_box(a)).expect("in domain"));
            }
            t0.elapsed().as_nanos() as f64 / args.len() as f64
        })
        .collect()
}
