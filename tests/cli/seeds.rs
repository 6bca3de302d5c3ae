//! Proofs do not depend on the seed: `verify --seed N` changes every claim's samples,
//! and the proved claims, the claims that hold by construction and the hypotheses of
//! each proof stay the same.  Run on Section 5 (signs through square roots: the ρ of
//! the corrected Lax pair) and Section 7 (the maps' charts, their branch hypotheses,
//! dn > 0 and sn² ≤ 1 of real arguments, lemmas).

use std::collections::BTreeMap;
use std::process::Command;

/// Claim id → (verdict, the sources of its proof's hypotheses), for the proved ones.
fn proved(only: &str, seed: u64) -> BTreeMap<String, (String, Vec<String>)> {
    let o = Command::new(env!("CARGO_BIN_EXE_eulertop"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["verify", "--only", only, "--format", "json"])
        .args(["--seed", &seed.to_string()])
        .output()
        .expect("binary runs");
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    let claims = v["claims"].as_array().expect("claims");
    claims
        .iter()
        .filter(|c| matches!(c["verdict"].as_str(), Some("proved" | "construction")))
        .map(|c| {
            let mut hyps: Vec<String> = (c["proof"]["hypotheses"].as_array().into_iter())
                .flatten()
                .map(|h| format!("{}: {}", h["kind"], h["source"]))
                .collect();
            hyps.sort();
            let id = c["id"].as_str().unwrap_or_default().to_string();
            (id, (c["verdict"].to_string(), hyps))
        })
        .collect()
}

#[test]
fn the_proved_claims_and_their_hypotheses_do_not_depend_on_the_seed() {
    for only in ["sec5.", "sec7."] {
        let base = proved(only, 0);
        assert!(!base.is_empty(), "{only}: nothing proved");
        for seed in 1..4 {
            assert_eq!(proved(only, seed), base, "{only} with seed {seed}");
        }
    }
}
