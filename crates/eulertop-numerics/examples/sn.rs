//! sn, cn, dn of the doubles u = 0.7, k = 0.8 in double precision and at 256 bits.
use eulertop_numerics::rug::Float;
use eulertop_numerics::special::sncndn;

fn main() {
    let (sn, cn, dn) = sncndn(&0.7_f64, &0.8).expect("0 <= k");
    println!("f64:      sn = {sn:.17}, cn = {cn:.17}, dn = {dn:.17}");
    let (u, k) = (Float::with_val(256, 0.7), Float::with_val(256, 0.8));
    let (sn, cn, dn) = sncndn(&u, &k).expect("0 <= k");
    println!("256 bits: sn = {sn:.40}\n          cn = {cn:.40}\n          dn = {dn:.40}");
}
