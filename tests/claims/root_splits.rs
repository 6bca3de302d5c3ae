//! Signs of values in a square root: decided from the signs of their root-free parts
//! (`a + b·√R` by the signs of `a`, `b` and `a² − b²R`), which split the domain where
//! they are undecided; never from the values at the points.

use super::support::{attempt, controls_only, identity_claim_with};

fn claim(id: &str, seed: u64, lhs: &str, rhs: &str) -> String {
    identity_claim_with(
        id,
        "control: root splits",
        &format!(
            "vars = [[\"x\", \"uniform(-1, 1)\"], [\"z\", \"uniform(-1, 1)\"]]\nseed = {seed}"
        ),
        lhs,
        rhs,
    )
}

const WEDGE: &str = "if x - sqrt(2) * z > 0 and x + sqrt(2) * z > 0 then 1 else 0";

fn catalogue(seed: u64) -> eulertop::claims::catalogue::Catalogue {
    controls_only(format!(
        "{}{}",
        // the wedge x > √2|z| is x > 0 and x² > 2z²
        claim(
            "t.root.wedge",
            seed,
            WEDGE,
            "if x^2 - 2 * z^2 > 0 and x > 0 then 1 else 0"
        ),
        // false on a thin band 0 < x² − 2z² ≤ 1/50 (a few percent of the square)
        claim(
            "t.root.wedge-band",
            seed,
            WEDGE,
            "if x^2 - 2 * z^2 > 1/50 and x > 0 then 1 else 0"
        ),
    ))
}

#[test]
fn a_wedge_in_a_square_root_is_proved_by_parts_free_of_the_root() {
    for seed in 1..4 {
        let p = attempt(&catalogue(seed), "t.root.wedge");
        assert!(p.is_proved(), "seed {seed}: {:?}", p.reason);
    }
    let p = attempt(&catalogue(0), "t.root.wedge");
    assert!(p.is_proved(), "{:?}", p.reason);
    // the parts: the signs of a = x, of b (z) and of q = x² − 2z²
    assert!(
        p.cases
            .iter()
            .any(|c| c.contains("x**2") || c.contains("z**2")),
        "{:?}",
        p.cases
    );
}

#[test]
fn a_wedge_claim_false_on_a_thin_band_is_not_proved_with_any_seed() {
    for seed in 0..8 {
        let p = attempt(&catalogue(seed), "t.root.wedge-band");
        assert!(!p.is_proved(), "proved with seed {seed}: {:?}", p.cases);
    }
}
