//! Tiny perturbations of proved claims: the catalogue's proved identities, each with its
//! right side multiplied by 1 + 10⁻³⁰, are refuted with a witness (a domain point at
//! which lhs − rhs is certified nonzero), never left inconclusive.

use eulertop::bindings::euler_top::registry;
use eulertop::claims::catalogue::{Catalogue, load_sources, read_sources};
use eulertop::claims::verdict::{Options, ProofMethod, Verdict, run_claim};

/// Proved claims of the catalogue with a nonzero right side written on one line: the
/// elliptic functions, square-root towers, the Veselov–Moser factorization, the phase
/// shifts of Sections 5 to 8.
const PROVED: [&str; 6] = [
    "bg.dlmf-22.6.1.sn-cn",
    "sec8.factor1",
    "sec5.u0.corrected.rho-real",
    "sec4.period-4K.lo",
    "sec8.MV-aux3",
    "sec7.lhs-master.g1.corrected.lo",
];

/// The catalogue with the right side of each claim of `ids` times `1 + 10^(-30)`.
fn perturbed(ids: &[&str]) -> Catalogue {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/identities"));
    let mut sources = read_sources(dir).expect("catalogue files");
    let mut done = 0;
    for (_, text) in &mut sources {
        let mut current = String::new();
        let lines: Vec<String> = (text.lines())
            .map(|l| {
                if let Some(id) = l.strip_prefix("id = \"") {
                    current = id.trim_end_matches('"').to_string();
                }
                match l.strip_prefix("rhs = \"") {
                    Some(r) if ids.contains(&current.as_str()) && !r.contains("'''") => {
                        done += 1;
                        format!("rhs = \"({}) * (1 + 10^(-30))\"", r.trim_end_matches('"'))
                    }
                    _ => l.to_string(),
                }
            })
            .collect();
        *text = lines.join("\n");
    }
    assert_eq!(done, ids.len(), "every claim's rhs is on one line");
    load_sources(&sources, registry().expect("registry")).expect("catalogue")
}

#[test]
fn proved_claims_times_one_plus_ten_to_the_minus_thirty_are_refuted_with_witnesses() {
    let cat = perturbed(&PROVED);
    for id in PROVED {
        let claim = cat.claims.iter().find(|c| c.id == id).expect("claim");
        let r = run_claim(&cat, claim, &Options::default());
        assert_eq!(r.verdict, Verdict::Refuted, "{id}: {}", r.reason);
        assert_eq!(r.proof.method, ProofMethod::Witness, "{id}: {}", r.reason);
        let w = r.proof.witness.as_deref().unwrap_or_default();
        assert!(w.contains("exclude 0"), "{id}: {w}");
    }
}

#[test]
fn the_unperturbed_claim_is_proved() {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/identities"));
    let sources = read_sources(dir).expect("catalogue files");
    let cat = load_sources(&sources, registry().expect("registry")).expect("catalogue");
    let claim = (cat.claims.iter())
        .find(|c| c.id == PROVED[1])
        .expect("claim");
    let r = run_claim(&cat, claim, &Options::default());
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
}
