//! Times sn+cn+dn over the benchmark batch in-process (for scripts/bench_peers.py):
//! `cargo run --release --example bench_batch -- BITS N REPEATS [all] [many]`
//! prints the median and the minimum over REPEATS of the time per evaluation in
//! nanoseconds (with `all`: every batch's time per evaluation).  By default every
//! argument is one `sncndn(u, k)` call; with `many` the batch is one
//! `sncndn_many(&us, k)` call (f64 only).  Time is wall-clock time of the batch (`std::time::Instant`): on this
//! machine the per-thread CPU clocks (`/proc/thread-self/schedstat`,
//! `CLOCK_THREAD_CPUTIME_ID`) advance in scheduler ticks of 4 ms, too coarse for a
//! batch of a few milliseconds, so wall time over many repeats is used and both the
//! median and the minimum are reported.
//! Batch: u_i = −10 + 20·(i + 0.5)/N, modulus k = 0.8 (parameter m = 0.64).

use eulertop::special::{sncndn, sncndn_many};
use rug::Float;
use std::hint::black_box;
use std::time::Instant;

fn main() {
    let a: Vec<String> = std::env::args().collect();
    let arg = |i: usize, d: usize| a.get(i).and_then(|s| s.parse().ok()).unwrap_or(d);
    let (bits, n, reps) = (arg(1, 53) as u32, arg(2, 1000), arg(3, 5).max(1));
    let flag = |f: &str| a.iter().skip(4).any(|x| x == f);
    let us: Vec<f64> = (0..n)
        .map(|i| -10.0 + 20.0 * (i as f64 + 0.5) / n as f64)
        .collect();
    let k = Float::with_val(bits.max(2), 0.8);
    let us_mp: Vec<Float> = if bits == 53 {
        Vec::new()
    } else {
        us.iter().map(|u| Float::with_val(bits, *u)).collect()
    };
    let mut times = Vec::new();
    for _ in 0..reps {
        let t0 = Instant::now();
        if bits == 53 && flag("many") {
            let out = sncndn_many(black_box(&us), black_box(&0.8)).expect("in domain");
            black_box(out);
        } else if bits == 53 {
            let mut acc = 0.0;
            for u in &us {
                let (s, c, d) = sncndn(black_box(u), black_box(&0.8)).expect("in domain");
                acc += s + c + d;
            }
            black_box(acc);
        } else {
            for u in &us_mp {
                black_box(sncndn(u, &k).expect("in domain"));
            }
        }
        times.push(t0.elapsed().as_nanos() as f64 / n as f64);
    }
    if flag("all") {
        let all: Vec<String> = times.iter().map(|t| t.to_string()).collect();
        println!("{}", all.join(" "));
        return;
    }
    times.sort_by(|a, b| a.total_cmp(b));
    println!("{} {}", times[times.len() / 2], times[0]);
}
