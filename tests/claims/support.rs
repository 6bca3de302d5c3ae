//! What the proof tests share: catalogues with control claims, and one proof attempt.

use eulertop::bindings::euler_top::registry;
use eulertop::claims::catalogue::{Body, Catalogue, load_sources, read_sources};
use eulertop::claims::verdict::ProofInfo;
use eulertop::claims::verdict::context::Ctx;
use eulertop::claims::verdict::symbolic::prove;

/// The catalogue of `identities/` with the control claims `text` added.
pub fn with_catalogue(text: String) -> Catalogue {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/identities"));
    let mut sources = read_sources(dir).expect("catalogue files");
    sources.push(("zz-controls.toml".into(), text));
    load_sources(&sources, registry().expect("registry")).expect("catalogue")
}

/// A catalogue of the control claims `text` alone.
pub fn controls_only(text: String) -> Catalogue {
    load_sources(
        &[("controls.toml".into(), text)],
        registry().expect("registry"),
    )
    .expect("catalogue")
}

/// The symbolic proof attempt of identity `id`.
pub fn attempt(cat: &Catalogue, id: &str) -> ProofInfo {
    let claim = cat.claims.iter().find(|c| c.id == id).expect("claim");
    let Body::Identity { lhs, rhs } = &claim.body else {
        panic!("{id} is not an identity")
    };
    prove(Ctx { cat, claim }, lhs, rhs, false)
}

/// Asserts that the claim is not proved and that the reason contains every one of
/// `words`; returns the reason.
pub fn assert_refused(cat: &Catalogue, id: &str, words: &[&str]) -> String {
    let p = attempt(cat, id);
    assert!(!p.is_proved(), "{id} was proved");
    let why = p.reason.unwrap_or_default();
    for w in words {
        assert!(why.contains(w), "{id}: '{w}' is not in the reason: {why}");
    }
    why
}

/// A control identity claim `lhs = rhs` (expected to hold) over the variables `vars`
/// (TOML pairs such as `["x", "uniform(1, 2)"]`), as catalogue text.
pub fn identity_claim(id: &str, location: &str, vars: &str, lhs: &str, rhs: &str) -> String {
    identity_claim_with(id, location, &format!("vars = [{vars}]"), lhs, rhs)
}

/// A control identity claim `lhs = rhs` (expected to hold) with the catalogue fields
/// `fields` (TOML lines: `domain`, `vars`, `let`, …), as catalogue text.
pub fn identity_claim_with(id: &str, location: &str, fields: &str, lhs: &str, rhs: &str) -> String {
    format!(
        r#"
[[claim]]
id = "{id}"
environment = "Section 2"
role = "statement"
labels = []
location = "{location}"
printed = 'x'
kind = "identity"
expect = "holds"
{fields}
lhs = "{lhs}"
rhs = "{rhs}"
"#
    )
}
