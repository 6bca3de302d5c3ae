// scratch: max f64 error per modulus over the reference table and a dense MPFR sweep
use eulertop::special::sncndn;
use rug::Float;
fn main() {
    let text = std::fs::read_to_string("tests/data/jacobi_ref_real.csv").unwrap();
    let mut worst: std::collections::BTreeMap<String, (f64, String)> = Default::default();
    for l in text.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let r: Vec<&str> = l.split(',').collect();
        let k: f64 = r[0].parse().unwrap();
        let u: f64 = r[1].parse().unwrap();
        let (s, c, d) = sncndn(&u, &k).unwrap();
        for (i, (g, w)) in [(s, r[3]), (c, r[4]), (d, r[5])].iter().enumerate() {
            let w = Float::with_val(200, Float::parse(w).unwrap());
            let e = (Float::with_val(200, *g - &w).abs().to_f64()) / f64::EPSILON;
            let ent = worst
                .entry(r[0].to_string())
                .or_insert((0.0, String::new()));
            if e > ent.0 {
                *ent = (e, format!("u={u} f{i}"));
            }
        }
    }
    for (k, (e, w)) in &worst {
        println!("table k={k}: {e:.3} eps at {w}");
    }
    // dense sweep against 256-bit evaluation, |u| <= 64 K
    for &k in &[
        0.0001,
        0.1,
        0.5,
        0.8,
        0.9,
        0.95,
        0.99,
        0.999,
        0.999999,
        1.0 - 1e-12,
    ] {
        let kk = eulertop::special::ellipk(&k).unwrap();
        let kf = Float::with_val(256, k);
        let mut mx = [0f64; 3];
        let mut at = [0.0; 3];
        let n = 20000;
        for i in 0..n {
            let u = -8.0 * kk + 16.0 * kk * (i as f64 + 0.37) / n as f64;
            let (s, c, d) = sncndn(&u, &k).unwrap();
            let (s2, c2, d2) = sncndn(&Float::with_val(256, u), &kf).unwrap();
            for (i, (g, w)) in [(s, s2), (c, c2), (d, d2)].into_iter().enumerate() {
                let e = Float::with_val(256, g - &w).abs().to_f64() / f64::EPSILON;
                if e > mx[i] {
                    mx[i] = e;
                    at[i] = u / kk;
                }
            }
        }
        println!(
            "sweep k={k}: sn {:.3} ({:.3}) cn {:.3} ({:.3}) dn {:.3} ({:.3})",
            mx[0], at[0], mx[1], at[1], mx[2], at[2]
        );
    }
}
