//! Existence certified at the samples: the Krawczyk test in ball arithmetic gives each
//! sampled solution of an existence claim a box with exactly one solution, and gives no
//! certificate for a box without one.

use super::support::{controls_only, with_catalogue};
use eulertop::claims::catalogue::{Body, Catalogue};
use eulertop::claims::sampler::Stream;
use eulertop::claims::verdict::context::Ctx;
use eulertop::claims::verdict::existence::{Spec, certify};
use eulertop::claims::verdict::{Options, ProofMethod, Verdict, run_claim};

/// An existence claim `x² = a` for `a` in [1, 4], with the stated set `in`.
fn square_root(id: &str, in_set: &str) -> String {
    format!(
        "[[claim]]\nid = \"{id}\"\nlocation = \"test\"\nprinted = 'x'\nkind = \"existence\"\nexpect = \"holds\"\nvars = [[\"a\", \"uniform(1, 4)\"]]\nunknowns = [\"x\"]\nequations = [\"x^2 - a\"]\nstart = [\"uniform(0.5, 3)\"]\nin = \"{in_set}\"\nenvironment = \"Section 2\"\nrole = \"statement\"\n"
    )
}

/// The certificate of the box `center ± radius` at the first sample point of `id`.
fn certify_at(
    cat: &Catalogue,
    id: &str,
    center: impl Fn(f64) -> f64,
    radius: f64,
) -> Result<String, String> {
    let claim = cat.claims.iter().find(|c| c.id == id).expect("claim");
    let Body::Existence {
        unknowns,
        equations,
        start,
        in_set,
        tries,
    } = &claim.body
    else {
        panic!("{id} is not an existence claim")
    };
    let spec = Spec {
        unknowns,
        equations,
        start,
        in_set: in_set.as_ref(),
        tries: *tries,
    };
    let ctx = Ctx { cat, claim };
    let point = ctx
        .sampler(Stream::Samples)
        .expect("sampler")
        .draw()
        .expect("point");
    let a = point
        .vars
        .iter()
        .find(|(n, _)| n == "a")
        .expect("a")
        .1
        .as_real()
        .expect("real");
    certify(ctx, spec, &point, &[center(a)], &[radius]).map(|c| c.describe(unknowns))
}

#[test]
fn a_box_with_the_root_is_certified_and_boxes_without_it_are_not() {
    let cat = controls_only(square_root("sq", "x > 0"));
    let ok = certify_at(&cat, "sq", f64::sqrt, 1e-9).expect("certified");
    assert!(ok.starts_with("x ∈ ["), "{ok}");
    // one thousandth off: the box holds no root
    let off = certify_at(&cat, "sq", |a| a.sqrt() + 1e-3, 1e-9);
    assert!(off.unwrap_err().contains("not inside the box"));
    // around −√a: a root, but outside the stated set x > 0
    let neg = certify_at(&cat, "sq", |a| -a.sqrt(), 1e-9);
    assert!(neg.unwrap_err().contains("stated set"));
}

#[test]
fn a_sampled_existence_claim_carries_its_boxes_and_still_only_holds() {
    let cat = controls_only(square_root("sq", "x > 0"));
    let r = run_claim(&cat, &cat.claims[0], &Options::default());
    assert_eq!(r.verdict, Verdict::Holds, "{}", r.reason);
    assert_eq!(r.proof.method, ProofMethod::Interval);
    assert_eq!(r.proof.notes.len(), r.samples);
    assert!(
        r.proof
            .reason
            .as_deref()
            .unwrap_or_default()
            .contains("not the whole domain")
    );
}

#[test]
fn the_papers_existence_claims_are_proved_for_small_h() {
    let cat = with_catalogue(String::new());
    for id in [
        "sec3.impl-map.existence",
        "sec8.S.roots",
        "sec8.roots.positive.tri",
        "sec8.roots.negative.wide",
        "sec8.S-minus.model.tri",
    ] {
        let claim = cat.claims.iter().find(|c| c.id == id).expect("claim");
        let r = run_claim(&cat, claim, &Options::default());
        let why = r.proof.reason.clone().unwrap_or_default();
        // each is proved for every small enough h by the implicit function theorem
        // (tests/claims/series_orders.rs), which supersedes the samples' certificates;
        // a claim that only holds keeps them (the test above)
        assert_eq!(r.verdict, Verdict::Proved, "{id}: {}", r.reason);
        assert_eq!(r.proof.method, ProofMethod::Series, "{id}: {why}");
    }
}
