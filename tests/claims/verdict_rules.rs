//! The verdict rules on the real catalogue: the sign condition abcν > 0 is tested as a
//! sign (it fails when the sign is wrong), and the count of Lemma 1 is vacuous on a domain
//! where no component of M + M̂ vanishes, but exercised on the catalogue's own domain.

use eulertop::bindings::euler_top::registry;
use eulertop::claims::catalogue::{Catalogue, load_sources};
use eulertop::claims::verdict::{Options, Verdict, run_claim};
use std::path::Path;

/// The catalogue's sources, with `edit` applied to the text of the file named `file`,
/// and `extra` as one more file.
fn catalogue_with(file: &str, edit: impl Fn(&str) -> String, extra: &str) -> Catalogue {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("identities");
    let mut paths: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    paths.sort();
    let mut sources: Vec<(String, String)> = paths
        .iter()
        .map(|p| {
            let text = std::fs::read_to_string(p).unwrap();
            let text = if p.file_name().is_some_and(|n| n == file) {
                edit(&text)
            } else {
                text
            };
            (p.display().to_string(), text)
        })
        .collect();
    if !extra.is_empty() {
        sources.push(("zz-extra.toml".into(), extra.into()));
    }
    load_sources(&sources, registry().unwrap()).unwrap()
}

fn verdict(cat: &Catalogue, id: &str) -> (Verdict, String) {
    let claim = cat.claims.iter().find(|c| c.id == id).unwrap();
    let opts = Options {
        bits: vec![53, 128],
        exact: false,
    };
    let r = run_claim(cat, claim, &opts);
    (r.verdict, r.reason)
}

const SIGN: [&str; 2] = ["sec2.sol.sign-abcnu.up", "sec2.sol.sign-abcnu.lo"];

#[test]
fn the_sign_of_abc_nu_is_tested_as_a_sign() {
    let cat = catalogue_with("02-euler-top.toml", str::to_string, "");
    for id in SIGN {
        let (v, why) = verdict(&cat, id);
        assert_eq!(v, Verdict::Holds, "{id}: {why}");
    }
    // b nu of the opposite sign, as if abc nu < 0: the claims must fail
    let bnu = "bnu = ETrhs(vec(a, 0, c), A, B, C)[2]";
    let flipped = catalogue_with(
        "02-euler-top.toml",
        |t| {
            assert_eq!(t.matches(bnu).count(), 2);
            t.replace(bnu, "bnu = -ETrhs(vec(a, 0, c), A, B, C)[2]")
        },
        "",
    );
    for id in SIGN {
        let (v, why) = verdict(&flipped, id);
        assert_eq!(v, Verdict::Refuted, "{id}: {why}");
    }
}

/// Lemma 1's count on the generic domain `top` (every |M_i| > 0.1).
const GENERIC: &str = r#"
[[claim]]
id = "lemma1.two-nonzero.generic"
environment = "Lemma 1"
role = "statement"
location = "Lemma 1 on generic points"
printed = "at least two of M_k + M^_k do not vanish"
kind = "identity"
expect = "holds"
domain = "top"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
P = M + step_gamma1(M, h, A, B, C)
'''
lhs = "if (if abs(P[1]) > 2^-40 * norm(P) then 1 else 0) + (if abs(P[2]) > 2^-40 * norm(P) then 1 else 0) + (if abs(P[3]) > 2^-40 * norm(P) then 1 else 0) >= 2 then 1 else 0"
rhs = "1"
scale = "1"
"#;

#[test]
fn lemma_1_is_exercised_on_its_domain_and_vacuous_off_it() {
    let cat = catalogue_with("06-poisson.toml", str::to_string, GENERIC);
    let (v, why) = verdict(&cat, "sec6.lemma1.two-nonzero");
    assert_eq!(v, Verdict::Holds, "{why}");
    let (v, why) = verdict(&cat, "lemma1.two-nonzero.generic");
    assert_eq!(v, Verdict::Inconclusive, "{why}");
    assert!(
        why.starts_with("vacuous on domain 'top': the condition 'abs(P[1]) > 2^-40 * norm(P)' is true at all 8 samples"),
        "{why}"
    );
}
