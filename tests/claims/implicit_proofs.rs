//! The prover's changes of variables and special rules on controls: implicit maps
//! (parametrized steps, stated values, phase steps), derivatives by the chain rule, the
//! amplitude of F(asin x, k), hyperbolic functions as modulus 1.  The true controls are
//! proved; deliberately wrong variants (of the maps, of δ, of a derivative, of a sign)
//! never are.

use eulertop::bindings::euler_top::registry;
use eulertop::claims::catalogue::{Body, Catalogue, load_sources, read_sources};
use eulertop::claims::verdict::context::Ctx;
use eulertop::claims::verdict::symbolic::prove;

const CONTROLS: &str = r#"
[[claim]]
id = "t.impl-spec-1.g1"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: (impl spec 1) with gamma1, as printed"
printed = 'x'
kind = "identity"
expect = "proved"
hypotheses = ["branch-gamma1"]
domain = "top"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
Mh = step_gamma1(M, h, A, B, C)
P = M + Mh
gam = 4 * MsqP(M) / MsqP(P)
'''
lhs = "Mh[1] - M[1]"
rhs = "0.25 * h * gam * (1/B - 1/C) * P[2] * P[3]"

[[claim]]
id = "t.impl-spec-1.g1.no-four"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: gamma1 with the factor 4 dropped"
printed = 'x'
kind = "identity"
expect = "refuted"
hypotheses = ["branch-gamma1"]
domain = "top"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
Mh = step_gamma1(M, h, A, B, C)
P = M + Mh
gam = MsqP(M) / MsqP(P)
'''
lhs = "Mh[1] - M[1]"
rhs = "0.25 * h * gam * (1/B - 1/C) * P[2] * P[3]"

[[claim]]
id = "t.impl-spec-1.g2.sign"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: (impl spec 1) with a sign flipped"
printed = 'x'
kind = "identity"
expect = "refuted"
hypotheses = ["branch-gamma2"]
domain = "top"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
Mh = step_gamma2(M, h, A, B, C)
P = M + Mh
gam = 4 * EnP(M, A, B, C) / dot(P, OmP(P, A, B, C))
'''
lhs = "Mh[1] - M[1]"
rhs = "-0.25 * h * gam * (1/B - 1/C) * P[2] * P[3]"

[[claim]]
id = "t.prop4.vm.wrong-integral"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: a quantity the VM step does not keep"
printed = 'x'
kind = "identity"
expect = "refuted"
hypotheses = ["branch-vm"]
domain = "top"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
Mh = step_vm(M, h, A, B, C)
'''
lhs = "Mh[1]^2 + Mh[2]^2"
rhs = "M[1]^2 + M[2]^2"

[[claim]]
id = "t.master12.delta-off"
environment = "Proposition 6"
role = "control"
labels = []
location = "control: delta1 off by a factor 1 + 1e-30"
printed = 'x'
kind = "identity"
expect = "refuted"
hypotheses = ["branch-delta1"]
domain = "ell_up"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
k = kE(A, B, C, Msq, E)
x = delta1(A, B, C, Msq, E, h) * (1 + 1e-30)
'''
lhs = "sn(x, k) / (cn(x, k) * dn(x, k))"
rhs = "h * nuE(A, B, C, Msq, E) / 2 / (1 - alpha1(A, B, C, Msq, E) * sn(x, k)^2)"

[[claim]]
id = "t.master12.alpha2-for-gamma1"
environment = "Proposition 6"
role = "control"
labels = []
location = "control: delta1 with the alpha of gamma2"
printed = 'x'
kind = "identity"
expect = "refuted"
hypotheses = ["branch-delta1"]
domain = "ell_up"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
k = kE(A, B, C, Msq, E)
x = delta1(A, B, C, Msq, E, h)
'''
lhs = "sn(x, k) / (cn(x, k) * dn(x, k))"
rhs = "h * nuE(A, B, C, Msq, E) / 2 / (1 - alpha2(A, B, C, Msq, E) * sn(x, k)^2)"
[[claim]]
id = "t.chain.msq-M1"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: the derivative of the kept M^2 through the step, by the chain rule"
printed = 'x'
kind = "identity"
expect = "proved"
hypotheses = ["branch-gamma2"]
domain = "top"
vars = [["h", "uniform(0.01, 0.1)"]]
let = "Mh = step_gamma2(M, h, A, B, C)"
lhs = "d(MsqP(Mh), M, 1)"
rhs = "2 * M[1]"

[[claim]]
id = "t.chain.msq-A"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: M^2 of the step does not depend on A at fixed M"
printed = 'x'
kind = "identity"
expect = "proved"
hypotheses = ["branch-gamma1"]
domain = "top"
vars = [["h", "uniform(0.01, 0.1)"]]
let = "Mh = step_gamma1(M, h, A, B, C)"
lhs = "d(MsqP(Mh), A)"
rhs = "0"

[[claim]]
id = "t.chain.msq-M1.wrong"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: a wrong derivative through the step"
printed = 'x'
kind = "identity"
expect = "refuted"
hypotheses = ["branch-gamma2"]
domain = "top"
vars = [["h", "uniform(0.01, 0.1)"]]
let = "Mh = step_gamma2(M, h, A, B, C)"
lhs = "d(MsqP(Mh), M, 1)"
rhs = "2 * Mh[1]"
[[claim]]
id = "t.chain.half-args.wrong-sign"
environment = "Theorem 1"
role = "control"
labels = []
location = "control: the chain rule through half sums with a sign flipped"
printed = 'x'
kind = "identity"
expect = "refuted"
domain = "ell_up"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
k = kE(A, B, C, Msq, E)
x = (phi + phi2) / 2
y = (phi2 - phi) / 2
Q = sn(x, k) * cn(y, k) + sn(y, k)^2
'''
lhs = "d(Q, phi)"
rhs = "0.5 * (d(Q, x) + d(Q, y))"

[[claim]]
id = "t.chain.half-args"
environment = "Theorem 1"
role = "control"
labels = []
location = "control: the chain rule through half sums"
printed = 'x'
kind = "identity"
expect = "proved"
domain = "ell_up"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
k = kE(A, B, C, Msq, E)
x = (phi + phi2) / 2
y = (phi2 - phi) / 2
Q = sn(x, k) * cn(y, k) + sn(y, k)^2
'''
lhs = "d(Q, phi)"
rhs = "0.5 * (d(Q, x) - d(Q, y))"

[[claim]]
id = "t.chain.direct-use"
environment = "Theorem 1"
role = "control"
labels = []
location = "control: a derivative in a let while the variable is also used directly"
printed = 'x'
kind = "identity"
expect = "holds"
domain = "ell_up"
vars = [["h", "uniform(0.01, 0.1)"]]
let = '''
k = kE(A, B, C, Msq, E)
x = (phi + phi2) / 2
Q = sn(x, k) + phi
'''
lhs = "d(Q, x)"
rhs = "cn(x, k) * dn(x, k)"
[[claim]]
id = "t.amplitude.sn"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: sn, cn, dn of F(asin x, k)"
printed = 'x'
kind = "identity"
expect = "proved"
vars = [["x", "uniform(0.1, 0.9)"], ["k", "uniform(0.1, 0.9)"]]
let = "v = F(asin(x), k)"
lhs = "vec(sn(v, k), cn(v, k), dn(v, k))"
rhs = "vec(x, sqrt(1 - x^2), sqrt(1 - k^2 * x^2))"

[[claim]]
id = "t.amplitude.cn-sign"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: the wrong sign of cn of F(asin x, k)"
printed = 'x'
kind = "identity"
expect = "refuted"
vars = [["x", "uniform(0.1, 0.9)"], ["k", "uniform(0.1, 0.9)"]]
let = "v = F(asin(x), k)"
lhs = "cn(v, k)"
rhs = "-sqrt(1 - x^2)"

[[claim]]
id = "t.amplitude.other-modulus"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: the amplitude at another modulus is not prescribed"
printed = 'x'
kind = "identity"
expect = "refuted"
vars = [["x", "uniform(0.1, 0.9)"], ["k", "uniform(0.1, 0.5)"]]
let = "v = F(asin(x), k)"
lhs = "sn(v, 2 * k)"
rhs = "x"
[[claim]]
id = "t.hyperbolic.addition"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: the addition theorem of tanh and cosh^2 - sinh^2 = 1"
printed = 'x'
kind = "identity"
expect = "proved"
vars = [["u", "uniform(-2, 2)"], ["v", "uniform(-2, 2)"]]
lhs = "vec(tanh(u + v), cosh(u)^2 - sinh(u)^2, d(tanh(u), u))"
rhs = "vec((tanh(u) + tanh(v)) / (1 + tanh(u) * tanh(v)), 1, 1 / cosh(u)^2)"

[[claim]]
id = "t.hyperbolic.wrong"
environment = "Proposition 4"
role = "control"
labels = []
location = "control: a wrong hyperbolic identity"
printed = 'x'
kind = "identity"
expect = "refuted"
vars = [["u", "uniform(-2, 2)"], ["v", "uniform(-2, 2)"]]
lhs = "tanh(u + v)"
rhs = "(tanh(u) + tanh(v)) / (1 - tanh(u) * tanh(v))"

[[claim]]
id = "t.vm.stated.explicit-euler"
environment = "Theorem 2"
role = "control"
labels = []
location = "control: the explicit Euler step stated as the VM step"
printed = 'x'
kind = "identity"
expect = "refuted"
hypotheses = ["branch-vm"]
domain = "top"
vars = [["h", "uniform(0.01, 0.1)"]]
lhs = "step_vm(M, h, A, B, C)"
rhs = "M + h * ETrhs(M, A, B, C)"

[[claim]]
id = "t.vm.stated.scaled"
environment = "Theorem 3"
role = "control"
labels = []
location = "control: the VM step stated as the phase shift by 2 delta_VM, scaled by 1 + 1e-30"
printed = 'x'
kind = "identity"
expect = "holds"
hypotheses = ["branch-delta-vm", "branch-vm"]
domain = "ell_up"
vars = [["h", "uniform(0.01, 0.1)"]]
lhs = "step_vm(ellM(A, B, C, Msq, E, phi, sa, sc), h, A, B, C)"
rhs = "ellM(A, B, C, Msq, E, phi + 2 * delta_vm(A, B, C, Msq, E, h), sa, sc) * (1 + 1e-30)"
"#;

fn catalogue() -> Catalogue {
    let dir = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/identities"));
    let mut sources = read_sources(dir).expect("catalogue files");
    sources.push(("controls.toml".into(), CONTROLS.into()));
    load_sources(&sources, registry().expect("registry")).expect("catalogue with controls loads")
}

fn proved(cat: &Catalogue, id: &str) -> (bool, String) {
    let claim = cat
        .claims
        .iter()
        .find(|c| c.id == id)
        .expect("claim exists");
    let Body::Identity { lhs, rhs } = &claim.body else {
        panic!("{id} is not an identity")
    };
    let p = prove(Ctx { cat, claim }, lhs, rhs, false);
    (p.is_proved(), p.reason.unwrap_or_default())
}

#[test]
fn the_printed_map_is_proved_and_its_wrong_variants_are_not() {
    let cat = catalogue();
    let (ok, why) = proved(&cat, "t.impl-spec-1.g1");
    assert!(ok, "control not proved: {why}");
    for id in [
        "t.impl-spec-1.g1.no-four",
        "t.impl-spec-1.g2.sign",
        "t.prop4.vm.wrong-integral",
        "t.master12.delta-off",
        "t.master12.alpha2-for-gamma1",
        "t.chain.msq-M1.wrong",
        "t.chain.half-args.wrong-sign",
        "t.chain.direct-use",
        "t.amplitude.cn-sign",
        "t.amplitude.other-modulus",
        "t.hyperbolic.wrong",
        "t.vm.stated.explicit-euler",
        "t.vm.stated.scaled",
    ] {
        let (ok, why) = proved(&cat, id);
        assert!(!ok, "{id} was proved");
        assert!(!why.is_empty(), "{id}: no reason given");
    }
}

#[test]
fn true_controls_are_proved() {
    let cat = catalogue();
    for id in [
        "t.chain.msq-M1",
        "t.chain.msq-A",
        "t.chain.half-args",
        "t.amplitude.sn",
    ] {
        let (ok, why) = proved(&cat, id);
        assert!(ok, "{id}: {why}");
    }
}

#[test]
fn proposition_4_is_proved_for_every_map() {
    let cat = catalogue();
    for g in ["g0", "g1", "g2", "vm"] {
        let (ok, why) = proved(&cat, &format!("sec6.prop4.{g}"));
        assert!(ok, "sec6.prop4.{g}: {why}");
    }
}

/// A stated value substituted into a map's equations solves them; the proof also shows
/// that it is the map's branch (the difference of the two as power series in h is
/// O(h)), so the Corollary's step, whose map argument moves with h, is proved with it.
#[test]
fn a_stated_value_is_shown_to_be_the_branch() {
    let cat = super::support::with_catalogue(String::new());
    for id in ["sec6.corollary.up", "sec7.master12.step.lo"] {
        let p = super::support::attempt(&cat, id);
        assert!(p.is_proved(), "{id}: {:?}", p.reason);
        assert!(
            p.notes
                .iter()
                .any(|n| n.starts_with("the stated value is the map's branch")),
            "{id}: {:?}",
            p.notes
        );
    }
}
