//! Sign cases proved at once: case variables drawn by `sign()` become sign symbols
//! (σ² = 1), so one normal form covers every case.  An identity that holds for one
//! sign only is never proved, and where the joint route cannot decide (a square root
//! that vanishes in one case), the cases are enumerated.

use super::support::{attempt, identity_claim_with, with_catalogue};
use eulertop::claims::catalogue::Catalogue;
use eulertop::claims::verdict::ProofInfo;

fn control(id: &str, lhs: &str, rhs: &str) -> String {
    let fields = r#"domain = "inertia"
vars = [["s", "sign()"], ["t", "sign()"], ["x", "uniform(1, 2)"]]"#;
    identity_claim_with(id, "control: sign cases", fields, lhs, rhs)
}

const CONTROLS: [(&str, &str, &str); 6] = [
    ("t.sign.square", "s*s*t*t*x", "x"),
    ("t.sign.both-vanish", "(1 + s)*x*s", "(1 + s)*x"),
    ("t.sign.one-sign-only", "s*x", "x"),
    ("t.sign.product-only", "s*t*x", "x"),
    (
        "t.sign.vanishing-root",
        "sqrt((1 + s)^2*x)",
        "(1 + s)*sqrt(x)",
    ),
    ("t.sign.zero-divisor", "x/(1 + s)*(1 + s)", "x"),
];

fn catalogue() -> Catalogue {
    let text: String = CONTROLS
        .iter()
        .map(|(id, l, r)| control(id, l, r))
        .collect();
    with_catalogue(text)
}

fn joint(p: &ProofInfo) -> bool {
    p.notes.iter().any(|n| n.contains("sign symbols"))
}

#[test]
fn identities_true_for_every_sign_are_proved_once_for_all_cases() {
    let cat = catalogue();
    for id in ["t.sign.square", "t.sign.both-vanish"] {
        let p = attempt(&cat, id);
        assert!(p.is_proved(), "{id}: {:?}", p.reason);
        assert!(joint(&p), "{id}: not proved jointly: {:?}", p.notes);
        assert!(p.cases.is_empty(), "{id}: {:?}", p.cases);
        assert!(
            p.relations.iter().any(|r| r == "s**2 = 1"),
            "{:?}",
            p.relations
        );
    }
}

#[test]
fn identities_true_for_some_signs_only_are_not_proved() {
    let cat = catalogue();
    // x/(1 + s)·(1 + s) = x fails at s = −1, where 1 + s is 0: in the joint ring 1 + s
    // is a zero divisor and has no inverse
    for id in [
        "t.sign.one-sign-only",
        "t.sign.product-only",
        "t.sign.zero-divisor",
    ] {
        let p = attempt(&cat, id);
        assert!(!p.is_proved(), "{id} was proved");
        assert!(
            p.reason.as_deref().unwrap_or("").contains("case"),
            "{id}: the failing case is not named: {:?}",
            p.reason
        );
    }
}

#[test]
fn cases_are_enumerated_where_the_joint_route_cannot_decide() {
    let cat = catalogue();
    let p = attempt(&cat, "t.sign.vanishing-root");
    assert!(p.is_proved(), "{:?}", p.reason);
    assert!(!joint(&p));
    assert_eq!(p.cases.len(), 4, "{:?}", p.cases);
}

/// A claim of the Euler-top catalogue on the domain `ell_up` (signs `sa`, `sc` drawn by
/// the domain), as a control.
fn ell_control(id: &str, lhs: &str, rhs: &str) -> String {
    let fields = r#"domain = "ell_up"
let = '''
kk = kE(A, B, C, Msq, E)
q = ell_coords(ellM(A, B, C, Msq, E, phi, sa, sc), A, B, C)
'''"#;
    identity_claim_with(id, "control: sectors as sign symbols", fields, lhs, rhs)
}

#[test]
fn the_sector_of_a_point_is_a_sign_symbol_and_its_phase_an_argument_up_to_that_sign() {
    // ell_coords takes sign a = sign c = sign M₃ in the upper regime (b > 0), so for
    // ellM's signs sa, sc the phase is φ where sa·sc = 1 and φ + 2K where sa·sc = −1:
    // sn of the phase is sa·sc·sn φ, and its dn is dn φ, in every sign case at once
    let text = [
        ell_control("t.sector.sn", "sn(q[3], kk)", "sa*sc*sn(phi, kk)"),
        ell_control("t.sector.dn", "dn(q[3], kk)", "dn(phi, kk)"),
        ell_control("t.sector.sn-unsigned", "sn(q[3], kk)", "sn(phi, kk)"),
    ]
    .concat();
    let cat = with_catalogue(text);
    for id in ["t.sector.sn", "t.sector.dn"] {
        let p = attempt(&cat, id);
        assert!(p.is_proved(), "{id}: {:?}", p.reason);
        assert!(joint(&p), "{id}: not proved jointly: {:?}", p.notes);
        assert!(
            p.notes.iter().any(|n| n.contains("plus (1 - ")),
            "{id}: the phase is not an argument up to a sign: {:?}",
            p.notes
        );
    }
    // without the sign the identity holds in two of the four cases only
    let p = attempt(&cat, "t.sector.sn-unsigned");
    assert!(!p.is_proved(), "sn of the phase = sn φ was proved");
}
