use eulertop::special::sncndn;
use std::hint::black_box;
use std::time::Instant;
fn run(us: &[f64], k: f64) -> f64 {
    let mut best = f64::MAX;
    for _ in 0..200 {
        let t0 = Instant::now();
        let mut acc = 0.0;
        for u in us {
            let (s, c, d) = sncndn(black_box(u), black_box(&k)).unwrap();
            acc += s + c + d;
        }
        black_box(acc);
        best = best.min(t0.elapsed().as_nanos() as f64 / us.len() as f64);
    }
    best
}
fn main() {
    let n = 20000;
    let mk = |a: f64, b: f64| {
        (0..n)
            .map(|i| a + (b - a) * (i as f64 + 0.5) / n as f64)
            .collect::<Vec<f64>>()
    };
    println!("batch [-10,10] k=0.8: {:.1}", run(&mk(-10.0, 10.0), 0.8));
    println!("j=0 [-0.9,0.9] k=0.8: {:.1}", run(&mk(-0.9, 0.9), 0.8));
    println!("|t|>K/2 [1.1,1.9] k=0.8: {:.1}", run(&mk(1.1, 1.9), 0.8));
    println!("batch k=0.3: {:.1}", run(&mk(-10.0, 10.0), 0.3));
    println!("batch k=0.99: {:.1}", run(&mk(-10.0, 10.0), 0.99));
    println!("batch k=0: {:.1}", run(&mk(-10.0, 10.0), 0.0));
    let mut best = f64::MAX;
    let us = mk(-10.0, 10.0);
    for _ in 0..200 {
        let t0 = Instant::now();
        let mut acc = 0.0;
        for u in &us {
            let (s, c) = black_box(*u * 0.1).sin_cos();
            acc += s + c;
        }
        black_box(acc);
        best = best.min(t0.elapsed().as_nanos() as f64 / n as f64);
    }
    println!("libm sin_cos: {best:.1}");
    let mut best = f64::MAX;
    for _ in 0..200 {
        let t0 = Instant::now();
        let mut acc = 0.0;
        let mut acc2 = 0.0;
        for u in &us {
            let (s, c, d) = sncndn(black_box(u), black_box(&0.8)).unwrap();
            let (s2, c2, d2) = sncndn(black_box(&(u + 0.001)), black_box(&0.8)).unwrap();
            acc += s + c + d;
            acc2 += s2 + c2 + d2;
        }
        black_box(acc + acc2);
        best = best.min(t0.elapsed().as_nanos() as f64 / (2 * n) as f64);
    }
    println!("two per iteration k=0.8: {best:.1}");
}
#[allow(dead_code)]
fn unused() {}
