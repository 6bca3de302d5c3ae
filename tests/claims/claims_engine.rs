//! Tests of the claim engine: parser errors with positions, no panics on arbitrary
//! input, evaluator properties, and the verdict engine on identities whose truth is
//! known mathematically.

use eulertop::claims::builtins::Builtin;
use eulertop::claims::catalogue::{Catalogue, load_sources};
use eulertop::claims::eval::{Backend, Evaluator};
use eulertop::claims::parser::{parse_bindings, parse_expr};
use eulertop::claims::registry::Registry;
use eulertop::claims::value::Value;
use eulertop::claims::verdict::{Options, Verdict, run_claim};
use eulertop::linalg::Vec3;
use eulertop::numbers::Rational;
use proptest::prelude::*;

fn load(src: &str) -> Result<Catalogue, String> {
    load_sources(&[("t.toml".to_string(), src.to_string())], Registry::new())
        .map_err(|e| e.to_string())
}

fn claim(body: &str) -> String {
    // the structure fields go last (before an inner table), so error lines stay put
    let (own, inner) = body.split_at(body.find("[claim.inner]").unwrap_or(body.len()));
    format!(
        "[[claim]]\nid = \"c\"\nlocation = \"test\"\nprinted = 'x'\n{own}\nenvironment = \"Section 2\"\nrole = \"statement\"\n{inner}\n"
    )
}

fn verdict_of(src: &str, bits: &[u32]) -> eulertop::claims::verdict::ClaimResult {
    let cat = load(src).unwrap_or_else(|e| panic!("load failed: {e}"));
    let opts = Options {
        bits: bits.to_vec(),
        exact: true,
    };
    run_claim(&cat, &cat.claims[0], &opts)
}

const LADDER: [u32; 4] = [53, 128, 256, 512];

// ---------- parser and loader errors ----------

#[test]
fn syntax_error_has_file_line_column_and_underline() {
    let src = claim(
        "kind = \"identity\"\nexpect = \"holds\"\nvars = [[\"x\", \"uniform(0, 1)\"]]\nlhs = \"x + * 2\"\nrhs = \"x\"",
    );
    let err = load(&src).unwrap_err();
    // line 8 is `lhs = "x + * 2"`; the '*' is at column 12
    assert!(err.starts_with("t.toml:8:12: syntax error"), "{err}");
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines[1].trim(), "lhs = \"x + * 2\"");
    let caret = lines[2].find('^').unwrap();
    let star = lines[1].find('*').unwrap();
    assert_eq!(caret, star, "{err}");
}

#[test]
fn multiline_let_error_points_into_the_block() {
    let src = claim(
        "kind = \"identity\"\nexpect = \"holds\"\nlet = '''\na = 1\nb = 2 + * 3\n'''\nlhs = \"a\"\nrhs = \"a\"",
    );
    let err = load(&src).unwrap_err();
    assert!(err.starts_with("t.toml:9:9: syntax error"), "{err}");
}

#[test]
fn unknown_field_function_kind_and_duplicates_are_errors() {
    let e = load(&claim(
        "kind = \"identity\"\nexpect = \"holds\"\nlhs = \"1\"\nrhs = \"1\"\nsampels = 3",
    ))
    .unwrap_err();
    assert!(e.starts_with("t.toml:") && e.contains("sampels"), "{e}");
    let e = load(&claim(
        "kind = \"identity\"\nexpect = \"holds\"\nlhs = \"frob(1)\"\nrhs = \"1\"",
    ))
    .unwrap_err();
    assert!(
        e.contains("unknown function 'frob'") && e.starts_with("t.toml:7:8"),
        "{e}"
    );
    let e = load(&claim("kind = \"identiy\"\nexpect = \"holds\"")).unwrap_err();
    assert!(
        e.contains("unknown variant `identiy`") && e.starts_with("t.toml:5:8:"),
        "{e}"
    );
    let twice = format!(
        "{}{}",
        claim("kind = \"identity\"\nexpect = \"holds\"\nlhs = \"1\"\nrhs = \"1\""),
        claim("kind = \"identity\"\nexpect = \"holds\"\nlhs = \"1\"\nrhs = \"1\"")
    );
    let e = load(&twice).unwrap_err();
    assert!(e.contains("duplicate claim id 'c'"), "{e}");
    let e = load("[[claim]]\nid = \"x\"\nkind = \"identity\"").unwrap_err();
    assert!(e.contains("missing required field"), "{e}");
    let e = load("this is not toml").unwrap_err();
    assert!(e.starts_with("t.toml:1:"), "{e}");
}

#[test]
fn parser_basics() {
    assert!(parse_expr("if a < b then [1, 2, 3] else vec(1, 2, 3)").is_ok());
    assert!(parse_expr("sum(k, 1, 3, k^2)").is_ok());
    assert!(parse_expr("sum(1, 1, 3, k)").is_err());
    assert!(parse_expr("d(x^2)").is_err());
    assert!(parse_expr("1.2.3").is_err());
    assert!(parse_expr("2x").is_err());
    assert!(parse_expr("(((1").is_err());
    assert!(parse_bindings("f(x, y) = x*y\n# comment\ng = f(1,\n 2)\n").map(|b| b.len()) == Ok(2));
}

proptest! {
    #[test]
    fn parser_never_panics(s in "\\PC{0,60}") {
        let _ = parse_expr(&s);
        let _ = parse_bindings(&s);
    }

    #[test]
    fn parser_never_panics_on_language_soup(parts in proptest::collection::vec(
        prop_oneof![Just("("), Just(")"), Just("["), Just("]"), Just(","), Just("+"), Just("-"),
                    Just("*"), Just("^"), Just("x"), Just("1.5"), Just("sin"), Just("if"),
                    Just("then"), Just("else"), Just("sum"), Just("d"), Just("\n"), Just("#"),
                    Just("<="), Just("and"), Just("not"), Just("e"), Just("3e")], 0..40)) {
        let s: String = parts.concat();
        let _ = parse_expr(&s);
        let _ = parse_bindings(&s);
    }

    #[test]
    fn loader_never_panics(s in "\\PC{0,200}") {
        let _ = load(&s);
        let _ = load(&format!("{}{s}", claim("kind = \"identity\"\nexpect = \"holds\"\nlhs = ")));
    }

    #[test]
    fn evaluator_is_consistent_across_backends(x in -10.0f64..10.0, y in -10.0f64..10.0) {
        let reg = Registry::new();
        // exact: a polynomial identity is exactly zero over the rationals
        let q = Rational::from_float(x).unwrap();
        let mut ev = Evaluator::new(&reg, q.clone());
        ev.bind("x", Value::Real(q));
        ev.bind("y", Value::Real(Rational::from_float(y).unwrap()));
        let e = parse_expr("(x + y)^3 - x^3 - 3*x^2*y - 3*x*y^2 - y^3").unwrap();
        prop_assert_eq!(ev.eval(&e).unwrap(), Value::Real(Rational::from_integer(0.into())));
        // f64 and 256-bit MPFR agree on a smooth expression to f64 accuracy
        let f = parse_expr("sin(x) * exp(y / 10) + atan2(y, x)").unwrap();
        let mut e64 = Evaluator::new(&reg, 0.0f64);
        e64.bind("x", Value::Real(x));
        e64.bind("y", Value::Real(y));
        let v64 = e64.eval(&f).unwrap().as_real().unwrap();
        let like = rug::Float::new(256);
        let mut emp = Evaluator::new(&reg, like.clone());
        emp.bind("x", Value::Real(rug::Float::with_val(256, x)));
        emp.bind("y", Value::Real(rug::Float::with_val(256, y)));
        let vmp = emp.eval(&f).unwrap().as_real().unwrap().to_f64();
        prop_assert!((v64 - vmp).abs() <= 1e-14 * (1.0 + vmp.abs()));
        // derivatives by duals: d(x^3 sin x, x) = 3x^2 sin x + x^3 cos x
        let d = parse_expr("d(x^3 * sin(x), x)").unwrap();
        let dv = e64.eval(&d).unwrap().as_real().unwrap();
        let want = 3.0 * x * x * x.sin() + x * x * x * x.cos();
        prop_assert!((dv - want).abs() <= 1e-12 * (1.0 + want.abs()));
    }
}

/// `X * P * transpose(X)` and `transpose(X) * P * X` are evaluated as a congruence when
/// `P` is antisymmetric: exactly the products in another association, and the plain
/// products when `P` is not antisymmetric or `transpose` is a function of the claim.
#[test]
fn a_congruence_is_the_product_as_written() {
    use eulertop::linalg::Mat3;
    let reg = Registry::new();
    let q = |n: i64, d: i64| Rational::new(n.into(), d.into());
    let m = |e: [[i64; 3]; 3], d: i64| Mat3(e.map(|r| r.map(|n| q(n, d))));
    let mut ev = Evaluator::new(&reg, q(0, 1));
    ev.bind("X", Value::Mat3(m([[2, -1, 5], [7, 3, -4], [1, 6, 9]], 5)));
    ev.bind(
        "P",
        Value::Mat3(m([[0, -3, 2], [3, 0, -7], [-2, 7, 0]], 11)),
    );
    ev.bind(
        "S",
        Value::Mat3(m([[1, -3, 2], [3, 0, -7], [-2, 7, 0]], 11)),
    );
    let ok = |s: &str| ev.eval(&parse_expr(s).unwrap()).unwrap();
    for mid in ["P", "S"] {
        assert_eq!(
            ok(&format!("X * {mid} * transpose(X)")),
            ok(&format!("X * ({mid} * transpose(X))"))
        );
        assert_eq!(
            ok(&format!("transpose(X) * {mid} * X")),
            ok(&format!("transpose(X) * ({mid} * X)"))
        );
    }
    // a `transpose` of the claim's own is the one applied
    for b in parse_bindings("transpose(Y) = 2 * Y").unwrap() {
        ev.bind_let(&b).unwrap();
    }
    let ok = |s: &str| ev.eval(&parse_expr(s).unwrap()).unwrap();
    assert_eq!(ok("X * P * transpose(X)"), ok("X * P * (2 * X)"));
}

#[test]
fn evaluator_types_and_errors() {
    let reg = Registry::new();
    let ev = Evaluator::new(&reg, 0.0f64);
    let ok = |s: &str| ev.eval(&parse_expr(s).unwrap()).unwrap();
    let err = |s: &str| ev.eval(&parse_expr(s).unwrap()).unwrap_err().message;
    assert_eq!(
        ok("cross(vec(1,0,0), vec(0,1,0))"),
        Value::Vec3(Vec3::new(0.0, 0.0, 1.0))
    );
    assert_eq!(ok("det([[2,0,0],[0,3,0],[0,0,4]])"), Value::Real(24.0));
    // σ1 σ2 = i σ3
    let z = ok("pauli(1) * pauli(2) - i * pauli(3)");
    assert!(z.magnitude() == 0.0);
    assert_eq!(ok("sum(k, 1, 4, k^2)"), Value::Real(30.0));
    assert_eq!(ok("[1,2,3][2]"), Value::Real(2.0));
    assert!(err("sqrt(-1)").contains("negative"));
    assert!(err("1/0").contains("division by zero"));
    assert!(err("vec(1,2,3) * vec(1,2,3)").contains("dot/cross"));
    assert!(err("[1,2,3][4]").contains("out of range"));
    assert!(err("nosuch").contains("unknown variable"));
    // k > 1: the reciprocal-modulus transformation (DLMF 22.17.2)
    let (a, b) = (ok("sn(1, 1.5)"), ok("sn(1.5, 1/1.5)/1.5"));
    assert!((a.as_real().unwrap() - b.as_real().unwrap()).abs() < 1e-15);
    // DLMF 22.17.1: sn depends on k² only
    assert_eq!(ok("sn(1, -0.5)"), ok("sn(1, 0.5)"));
    // complex sqrt is principal
    assert_eq!(ok("sqrt(cplx(-4, 0))"), ok("2*i"));
}

// ---------- verdicts on identities of known truth ----------

#[test]
fn true_identity_holds_with_small_loss() {
    // sin and cos are sn and cn of modulus 0 in the prover, so this is also proved
    let r = verdict_of(
        &claim(
            "kind = \"identity\"\nexpect = \"proved\"\nvars = [[\"x\", \"uniform(-3, 3)\"]]\nlhs = \"sin(x)^2 + cos(x)^2\"\nrhs = \"1\"",
        ),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert!(r.loss_bits.unwrap() <= 8.0);
    assert_eq!(r.residuals.len(), 4);
    assert_eq!(r.samples, 8);
    assert!(r.as_expected);
}

#[test]
fn false_identity_is_refuted_with_counterexample() {
    // sin² + cos² = 1 + x²/1000 is false for every x ≠ 0 (x ≥ 1/2 here)
    let r = verdict_of(
        &claim(
            "kind = \"identity\"\nexpect = \"refuted\"\nvars = [[\"x\", \"uniform(0.5, 1)\"]]\nlhs = \"sin(x)^2 + cos(x)^2\"\nrhs = \"1 + x^2/1000\"",
        ),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    let c = r.counterexample.expect("counterexample");
    assert_eq!(c.point[0].name, "x");
    let x: f64 = c.point[0].value.parse().unwrap();
    assert!((0.5..=1.0).contains(&x));
    let rhs: f64 = c.rhs.parse().unwrap();
    assert!((rhs - (1.0 + x * x / 1000.0)).abs() < 1e-15);
}

#[test]
fn tiny_discrepancy_is_refuted_by_a_witness_not_held() {
    // a constant 2^-80 discrepancy: invisible at 53 bits, visible from 128 bits on, but
    // below the refutation floor 2^-30, so the ladder alone is inconclusive; the normal
    // form x − (x + 2^-80) is certified nonzero at a domain point
    let r = verdict_of(
        &claim(
            "kind = \"identity\"\nexpect = \"refuted\"\nvars = [[\"x\", \"uniform(0.5, 1)\"]]\nlhs = \"x\"\nrhs = \"x + 2^-80\"",
        ),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    assert_eq!(
        r.proof.method,
        eulertop::claims::verdict::ProofMethod::Witness
    );
    assert!(
        r.reason.contains("numerically: residual neither"),
        "{}",
        r.reason
    );
    assert!(r.loss_bits.unwrap() > 24.0);
}

#[test]
fn exact_points_are_evidence_and_the_normal_form_proves() {
    let r = verdict_of(
        &claim(
            "kind = \"identity\"\nexpect = \"proved\"\nvars = [[\"a\", \"uniform(-2, 2)\"], [\"b\", \"uniform(-2, 2)\"]]\nlhs = \"(a + b)^2\"\nrhs = \"a^2 + 2*a*b + b^2\"\nexact = true\nexact_samples = 3",
        ),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    let ex = r.exact.unwrap();
    assert_eq!(ex.points, 3);
    assert_eq!(ex.set_size, Some((1 << 24) + 1));
    assert!(ex.all_zero && ex.note.contains("not a proof"));
    assert!(
        r.proof.is_proved(),
        "proved by the normal form, not by the points"
    );
}

#[test]
fn exact_false_identity_refuted_exactly() {
    let r = verdict_of(
        &claim(
            "kind = \"identity\"\nexpect = \"refuted\"\nvars = [[\"a\", \"uniform(1, 2)\"], [\"b\", \"uniform(1, 2)\"]]\nlhs = \"(a + b)^2\"\nrhs = \"a^2 + b^2\"\nexact = true",
        ),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Refuted);
    assert_eq!(r.counterexample.unwrap().bits, 0, "exact counterexample");
    // normal() gives no Schwartz–Zippel bound for the rational points, but the symbolic
    // normal form proves the identity whatever the sampling
    let r = verdict_of(
        &claim(
            "kind = \"identity\"\nexpect = \"proved\"\nvars = [[\"a\", \"normal()\"]]\nlhs = \"(a + 1)^2\"\nrhs = \"a^2 + 2*a + 1\"\nexact = true",
        ),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert!(r.proof.is_proved());
    assert_eq!(r.exact.unwrap().set_size, None);
}

#[test]
fn unevaluable_samples_are_reported_not_counted() {
    // sqrt(x) fails for x < 0 (about half the draws): failures are listed and replaced
    let r = verdict_of(
        &claim(
            "kind = \"identity\"\nexpect = \"holds\"\nsamples = 20\nvars = [[\"x\", \"uniform(-1, 3)\"]]\nlhs = \"sqrt(x)^2\"\nrhs = \"x\"",
        ),
        &[53, 128],
    );
    assert_eq!(r.verdict, Verdict::Holds);
    assert_eq!(r.samples, 20);
    assert!(!r.failures.is_empty() && r.failures.len() < 20);
    assert!(
        r.failures
            .iter()
            .all(|f| f.message.contains("sqrt of negative"))
    );
    // when every sample fails the claim is inconclusive
    let r = verdict_of(
        &claim(
            "kind = \"identity\"\nexpect = \"inconclusive\"\nvars = [[\"x\", \"uniform(-3, -1)\"]]\nlhs = \"sqrt(x)\"\nrhs = \"x\"",
        ),
        &[53],
    );
    assert_eq!(r.verdict, Verdict::Inconclusive);
    assert!(r.reason.contains("could not be evaluated"));
}

#[test]
fn thin_domain_is_a_clear_inconclusive() {
    let r = verdict_of(
        &claim(
            "kind = \"identity\"\nexpect = \"inconclusive\"\nvars = [[\"x\", \"uniform(0, 1)\"]]\nwhere = [\"x > 2\"]\nlhs = \"x\"\nrhs = \"x\"",
        ),
        &[53],
    );
    assert_eq!(r.verdict, Verdict::Inconclusive);
    assert!(
        r.reason.contains("domain too thin") && r.reason.contains("x > 2"),
        "{}",
        r.reason
    );
}

#[test]
fn asymptotic_slopes() {
    // sin h − h = −h³/6 + O(h⁵): order 3 holds (and its power series proves it), order 4
    // is refuted
    let base = "kind = \"asymptotic\"\nvars = [[\"x\", \"uniform(1, 2)\"]]\nexpr = \"x * (sin(h) - h)\"\nvar = \"h\"\nh0 = 0.05\nsteps = 5\n";
    let r = verdict_of(
        &claim(&format!("{base}expect = \"proved\"\norder = 3")),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert!(r.as_expected);
    assert!((r.residuals[3].slope().unwrap() - 3.0).abs() < 0.01);
    let r = verdict_of(
        &claim(&format!("{base}expect = \"refuted\"\norder = 4")),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
}

#[test]
fn independence_existence_negation() {
    let dom = "vars = [[\"k\", \"uniform(0.1, 0.9)\"], [\"u\", \"uniform(-2, 2)\"]]\n";
    // sn² + cn² = 1: its derivative in u has the normal form 0, so it is proved
    let r = verdict_of(
        &claim(&format!(
            "kind = \"independence\"\nexpect = \"proved\"\n{dom}expr = \"sn(u, k)^2 + cn(u, k)^2\"\nwrt = \"u\""
        )),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert!(r.as_expected);
    // sn² depends on u: never proved
    let r = verdict_of(
        &claim(&format!(
            "kind = \"independence\"\nexpect = \"refuted\"\n{dom}expr = \"sn(u, k)^2\"\nwrt = \"u\""
        )),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    let r = verdict_of(
        &claim(&format!(
            "kind = \"independence\"\nexpect = \"refuted\"\n{dom}expr = \"dn(u, k)\"\nwrt = \"u\""
        )),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Refuted, "{}", r.reason);
    // x² = a has a positive root for a in [1, 4]
    let r = verdict_of(
        &claim(
            "kind = \"existence\"\nexpect = \"holds\"\nvars = [[\"a\", \"uniform(1, 4)\"]]\nunknowns = [\"x\"]\nequations = [\"x^2 - a\"]\nstart = [\"uniform(0.5, 3)\"]\nin = \"x > 0\"",
        ),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Holds, "{}", r.reason);
    // x² = −a has no real root: Newton fails, inconclusive (never refuted)
    let r = verdict_of(
        &claim(
            "kind = \"existence\"\nexpect = \"inconclusive\"\nvars = [[\"a\", \"uniform(1, 4)\"]]\nunknowns = [\"x\"]\nequations = [\"x^2 + a\"]\nstart = [\"uniform(0.5, 3)\"]",
        ),
        &[53, 128],
    );
    assert_eq!(r.verdict, Verdict::Inconclusive);
    // negation of a false identity: proved by a point where the inner lhs − rhs is
    // certified nonzero, with the inner counterexample as evidence too
    let r = verdict_of(
        &claim(
            "kind = \"negation\"\nexpect = \"proved\"\nvars = [[\"x\", \"uniform(0.5, 1)\"]]\n[claim.inner]\nkind = \"identity\"\nlhs = \"sin(2*x)\"\nrhs = \"2*sin(x)\"",
        ),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert_eq!(
        r.proof.method,
        eulertop::claims::verdict::ProofMethod::Witness
    );
    assert!(r.counterexample.is_some());
    // exp is outside the prover's field, but Arb encloses it: proved by a witness in
    // ball arithmetic
    let r = verdict_of(
        &claim(
            "kind = \"negation\"\nexpect = \"proved\"\nvars = [[\"x\", \"uniform(0.5, 1)\"]]\n[claim.inner]\nkind = \"identity\"\nlhs = \"exp(2*x)\"\nrhs = \"2*exp(x)\"",
        ),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Proved, "{}", r.reason);
    assert!(r.reason.contains("Arb ball arithmetic"), "{}", r.reason);
    // the amplitude am is outside both (the balls run no numerical iteration): the
    // negation holds by sampling only
    let r = verdict_of(
        &claim(
            "kind = \"negation\"\nexpect = \"holds\"\nvars = [[\"x\", \"uniform(0.5, 1)\"]]\n[claim.inner]\nkind = \"identity\"\nlhs = \"am(2*x, 0.5)\"\nrhs = \"2*am(x, 0.5)\"",
        ),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Holds, "{}", r.reason);
}

#[test]
fn definitions_are_global_and_deterministic() {
    let src = format!(
        "{}[[claim]]\nid = \"d\"\nlocation = \"l\"\nprinted = 'p'\nenvironment = \"Section 2\"\nrole = \"definition\"\nkind = \"definition\"\ndefine = '''\nsq(x) = x * x\n'''\n",
        claim(
            "kind = \"identity\"\nexpect = \"holds\"\nvars = [[\"x\", \"uniform(-1, 1)\"]]\nlhs = \"sq(x + 1)\"\nrhs = \"x^2 + 2*x + 1\""
        )
    );
    let mut a = verdict_of(&src, &LADDER);
    let mut b = verdict_of(&src, &LADDER);
    assert_eq!(a.verdict, Verdict::Proved, "{}", a.reason);
    // everything but the wall times is deterministic
    (a.proof.ms, b.proof.ms) = (0.0, 0.0);
    (a.elapsed_ms, b.elapsed_ms) = (0.0, 0.0);
    assert_eq!(
        serde_json::to_string(&a).unwrap(),
        serde_json::to_string(&b).unwrap()
    );
}

#[test]
fn model_functions_register_without_clashes() {
    let reg = eulertop::bindings::euler_top::registry().unwrap();
    let names: Vec<String> = reg.registered().into_iter().map(|(n, _, _)| n).collect();
    for n in [
        "Omega",
        "step_gamma1",
        "step_vm",
        "ell_coords",
        "ell_inverse",
        "delta_vm",
        "w",
    ] {
        assert!(names.iter().any(|m| m == n), "{n} not registered");
    }
    // E(M) from the registry equals the definition
    let ev = Evaluator::new(&reg, 0.0f64);
    let v = ev
        .eval(&parse_expr("energy(vec(1, 2, 3), 3, 2, 1) - (1/3 + 4/2 + 9/1)").unwrap())
        .unwrap();
    assert!(v.magnitude() < 1e-15);
}

struct Boom;
impl eulertop::claims::registry::GenericFunction for Boom {
    fn call<R: eulertop::claims::backend::RealNum>(
        &self,
        _a: &[Value<R>],
    ) -> Result<Value<R>, String> {
        panic!("boom from another layer")
    }
}

#[test]
fn a_panicking_registered_function_gives_inconclusive_not_a_crash() {
    let mut reg = Registry::new();
    reg.register("boom", 1, "panics", Boom).unwrap();
    assert!(reg.register("sin", 1, "clash", Boom).is_err());
    let src = claim(
        "kind = \"identity\"\nexpect = \"holds\"\nvars = [[\"x\", \"uniform(0, 1)\"]]\nlhs = \"boom(x)\"\nrhs = \"x\"",
    );
    let cat = load_sources(&[("t.toml".into(), src)], reg).unwrap();
    let r = run_claim(&cat, &cat.claims[0], &Options::default());
    assert_eq!(r.verdict, Verdict::Inconclusive);
    assert!(
        r.reason.contains("panic") && r.reason.contains("boom from another layer"),
        "{}",
        r.reason
    );
    assert!(!r.as_expected);
}

// ---------- depth limits: errors, never stack overflows ----------

#[test]
fn long_flat_chains_are_syntax_errors_not_crashes() {
    // 8,400 terms: a chain of operators nests one level per operator
    let e = parse_expr(&format!("{}1", "1+".repeat(8400))).unwrap_err();
    assert!(e.message.contains("nested too deeply"), "{}", e.message);
    // 200 terms are fine and sum up
    let reg = Registry::new();
    let ev = Evaluator::new(&reg, 0.0f64);
    let v = ev
        .eval(&parse_expr(&format!("{}1", "1+".repeat(199))).unwrap())
        .unwrap();
    assert_eq!(v, Value::Real(200.0));
    // in a catalogue the error has the file position
    let lhs = format!("{}x", "x+".repeat(2999));
    let err = load(&claim(&format!(
        "kind = \"identity\"\nexpect = \"holds\"\nvars = [[\"x\", \"uniform(1, 2)\"]]\nlhs = \"{lhs}\"\nrhs = \"x\""
    )))
    .unwrap_err();
    assert!(err.starts_with("t.toml:8:") && err.contains("nested too deeply"));
}

#[test]
fn deep_function_nesting_is_an_error_even_on_a_small_stack() {
    // f0(x) = x + x + … (250 levels), f_j(x) = f_{j-1}(x) + x + … (the call 240 levels
    // down a left-deep chain): more than 2,000 nested evaluations in all, on a thread
    // with 256 KiB of stack
    let mut src = format!("f0(x) = {}x\n", "x+".repeat(249));
    for j in 1..10 {
        src.push_str(&format!("f{j}(x) = f{}(x){}\n", j - 1, "+x".repeat(240)));
    }
    let mut reg = Registry::new();
    for b in parse_bindings(&src).unwrap() {
        reg.define(b).unwrap();
    }
    let out = std::thread::Builder::new()
        .stack_size(256 * 1024)
        .spawn(move || {
            let ev = Evaluator::new(&reg, rug::Float::new(128));
            ev.eval(&parse_expr("f9(1)").unwrap()).map(|_| ())
        })
        .unwrap()
        .join()
        .unwrap();
    let e = out.unwrap_err();
    assert!(
        e.message.contains("nested too deeply to evaluate"),
        "{}",
        e.message
    );
    assert!(!e.message.contains("in function"), "{}", e.message);
}

#[test]
fn runaway_recursion_is_reported_once() {
    let mut reg = Registry::new();
    reg.define(parse_bindings("f(x) = f(x) + 1").unwrap().remove(0))
        .unwrap();
    let ev = Evaluator::new(&reg, 0.0f64);
    let e = ev.eval(&parse_expr("f(1)").unwrap()).unwrap_err();
    assert!(
        e.message.starts_with("recursion too deep in 'f'"),
        "{}",
        e.message
    );
    assert_eq!(
        e.message.matches('f').count(),
        1 + "recursion too deep in".matches('f').count()
    );
}

#[test]
fn sum_bounds_name_the_cause() {
    let reg = Registry::new();
    let ev = Evaluator::new(&reg, 0.0f64);
    let err = |s: &str| ev.eval(&parse_expr(s).unwrap()).unwrap_err().message;
    let m = err("sum(k, 1, 1e30, k)");
    assert!(
        m.contains("too large") && !m.contains("expected an integer"),
        "{m}"
    );
    assert!(err("sum(k, 1, 10^6, k)").contains("more than 100000 terms"));
    assert!(err("sum(k, 1, 1.5, k)").contains("expected an integer"));
}

// ---------- one known value per built-in ----------

/// Each case is an expression that is zero (or a zero vector/matrix) by a mathematical
/// identity or a known value; `x = 2` and `v = (1, 2, 3)` are bound.
const BUILTIN_CASES: &[&str] = &[
    "sqrt(16) - 4",
    "sqrt(cplx(-4, 0)) - 2*i",
    "abs(-3) - 3",
    "abs(cplx(3, 4)) - 5",
    "exp(ln(5)) - 5",
    "exp(i*pi) + 1",
    "ln(exp(2)) - 2",
    "sin(pi/6) - 1/2",
    "cos(pi/3) - 1/2",
    "tan(pi/4) - 1",
    "atan(1) - pi/4",
    "asin(1/2) - pi/6",
    "sinh(ln(2)) - 3/4",
    "cosh(ln(2)) - 5/4",
    "tanh(ln(2)) - 3/5",
    "asinh(3/4) - ln(2)",
    "atanh(3/5) - ln(2)",
    "floor(-2.5) + 3",
    "sign(-7) + 1",
    "atan2(1, -1) - 3*pi/4",
    "min(3, -1, 2) + 1",
    "max(3, -1, 2) - 3",
    "re(cplx(2, 3)) - 2",
    "im(cplx(2, 3)) - 3",
    "conj(cplx(2, 3)) - cplx(2, -3)",
    "arg(cplx(-1, 0)) - pi",
    "sn(0.3, 0) - sin(0.3)",
    "cn(0.3, 0) - cos(0.3)",
    "dn(0.3, 0) - 1",
    "sn(0.9, 0.7)^2 + cn(0.9, 0.7)^2 - 1",
    "dn(0.9, 0.7)^2 + 0.49*sn(0.9, 0.7)^2 - 1",
    "cd(0.3, 0) - cos(0.3)",
    "dc(0.3, 0) - 1/cos(0.3)",
    "ns(0.3, 0) - 1/sin(0.3)",
    "nc(0.3, 1) - cosh(0.3)",
    "nd(0.3, 1) - cosh(0.3)",
    "sc(0.3, 1) - sinh(0.3)",
    "sd(0.3, 1) - sinh(0.3)",
    "cs(0.3, 0) - 1/tan(0.3)",
    "ds(0.3, 1) - 1/sinh(0.3)",
    "am(0.4, 0) - 0.4",
    "sin(am(0.9, 0.7)) - sn(0.9, 0.7)",
    "K(0) - pi/2",
    "Kp(0.6) - K(0.8)",
    "F(pi/2, 0.6) - K(0.6)",
    "F(am(0.9, 0.7), 0.7) - 0.9",
    "jacobi_inverse(sn(0.7, 0.5), cn(0.7, 0.5), dn(0.7, 0.5), 0.5) - 0.7",
    "ellipe(0) - pi/2",
    "ellipeinc(pi/2, 0.6) - ellipe(0.6)",
    "ellippi(0, 1.2, 0.6) - F(1.2, 0.6)",
    "jacobizeta(pi/2, 0.6)",
    "heumanlambda(pi/2, 0.6) - 1",
    "nome(0)",
    "jtheta(3, 0, nome(0.6))^2 - 2*K(0.6)/pi",
    "vec(1, 2, 3) - [1, 2, 3]",
    "dot(vec(1, 2, 3), vec(4, 5, 6)) - 32",
    "cross(vec(1, 0, 0), vec(0, 1, 0)) - vec(0, 0, 1)",
    "norm2(vec(1, 2, 2)) - 9",
    "norm(vec(1, 2, 2)) - 3",
    "vnorm_inf(vec(1, -5, 2)) - 5",
    "transpose([[1, 2, 3], [4, 5, 6], [7, 8, 9]])[1, 2] - 4",
    "det([[2, 0, 0], [0, 3, 0], [0, 0, 4]]) - 24",
    "det(pauli(2)) + 1",
    "inv([[2, 1, 0], [0, 3, 1], [1, 0, 4]]) * [[2, 1, 0], [0, 3, 1], [1, 0, 4]] - I3",
    "tr([[1, 2, 3], [4, 5, 6], [7, 8, 9]]) - 15",
    "comm(pauli(1), pauli(2)) - 2*i*pauli(3)",
    "pauli(1)*pauli(1) - I2()",
    "I3() - diag(1, 1, 1)",
    "diag(vec(1, 2, 3))[2, 2] - 2",
    "skew(v) * vec(4, 5, 6) - cross(v, vec(4, 5, 6))",
    "unskew(skew(v)) - v",
    "sum(k, 1, 4, k^2) - 30",
    "prod(k, 1, 5, k) - 120",
    "d(x^3, x) - 3*x^2",
    "d(dot(v, v), v, 2) - 2*v[2]",
    "grad(dot(v, v), v) - 2*v",
];

/// The built-ins an expression uses.
fn builtins_used(e: &eulertop::claims::ast::Expr, out: &mut Vec<Builtin>) {
    use eulertop::claims::ast::ExprKind;
    e.walk(&mut |x| {
        let b = match &x.kind {
            ExprKind::Call(n, _) | ExprKind::Name(n) => Builtin::from_name(n),
            ExprKind::Sum { product, .. } => Some(if *product {
                Builtin::Prod
            } else {
                Builtin::Sum
            }),
            ExprKind::Deriv { .. } => Some(Builtin::D),
            ExprKind::Grad { .. } => Some(Builtin::Grad),
            _ => None,
        };
        out.extend(b);
    });
}

/// Evaluates every case with scalars like `like`; each must vanish to `2^(8 − bits)`.
fn run_cases<T: Backend>(like: T, bits: u32, used: &mut Vec<Builtin>) {
    let reg = Registry::new();
    let mut ev = Evaluator::new(&reg, like.clone());
    ev.bind("x", Value::Real(like.from_i64(2)));
    let v = Vec3::new(like.from_i64(1), like.from_i64(2), like.from_i64(3));
    ev.bind("v", Value::Vec3(v));
    for case in BUILTIN_CASES {
        let e = parse_expr(case).unwrap();
        builtins_used(&e, used);
        let r = ev
            .eval(&e)
            .unwrap_or_else(|err| panic!("{case}: {}", err.message));
        let tol = (8.0 - f64::from(bits)).exp2();
        assert!(r.magnitude() <= tol, "{case} = {r:?} at {bits} bits");
    }
}

#[test]
fn every_builtin_has_a_known_value() {
    let mut used = Vec::new();
    run_cases(0.0f64, 53, &mut used);
    run_cases(rug::Float::new(256), 256, &mut used);
    for b in Builtin::ALL {
        assert!(used.contains(b), "no case for the built-in {}", b.name());
    }
}

// ---------- names are checked at load time ----------

const HEAD: &str = "kind = \"identity\"\nexpect = \"holds\"\nvars = [[\"x\", \"uniform(1, 2)\"]]\n";

#[test]
fn undefined_names_are_load_errors_at_their_position() {
    // line 8 is `lhs = "x"`, line 10 the scale
    let e = load(&claim(&format!(
        "{HEAD}lhs = \"x\"\nrhs = \"x\"\nscale = \"Mzz\""
    )))
    .unwrap_err();
    assert!(e.starts_with("t.toml:10:10: unknown variable 'Mzz'"), "{e}");
    // a let binding sees only earlier bindings
    let e = load(&claim(&format!(
        "{HEAD}let = '''\na = b\nb = 1\n'''\nlhs = \"a\"\nrhs = \"1\""
    )))
    .unwrap_err();
    assert!(
        e.contains("unknown variable 'b'") && e.starts_with("t.toml:9:5:"),
        "{e}"
    );
    // d() needs a variable in scope
    let e = load(&claim(&format!("{HEAD}lhs = \"d(x^2, y)\"\nrhs = \"2*x\""))).unwrap_err();
    assert!(e.contains("'y' is not a variable in scope"), "{e}");
    // random primitives only in sampler expressions
    let e = load(&claim(&format!(
        "{HEAD}lhs = \"uniform(0, 1)\"\nrhs = \"x\""
    )))
    .unwrap_err();
    assert!(e.contains("only available in sampler expressions"), "{e}");
    // the number of arguments of a built-in
    let e = load(&claim(&format!("{HEAD}lhs = \"atan2(x)\"\nrhs = \"x\""))).unwrap_err();
    assert!(e.contains("atan2 takes 2 argument(s), got 1"), "{e}");
    // an unknown domain points at the domain's name
    let e = load(&claim(&format!(
        "{HEAD}domain = \"nosuch\"\nlhs = \"x\"\nrhs = \"x\""
    )))
    .unwrap_err();
    assert!(
        e.starts_with("t.toml:8:10: claim 'c': unknown domain 'nosuch'"),
        "{e}"
    );
}

#[test]
fn recursive_definitions_are_load_errors() {
    let def = |body: &str| {
        format!(
            "[[claim]]\nid = \"d\"\nlocation = \"l\"\nprinted = 'p'\nkind = \"definition\"\nenvironment = \"Section 2\"\nrole = \"statement\"\ndefine = '''\n{body}\n'''\n"
        )
    };
    let e = load(&def("f(M) = f(M)")).unwrap_err();
    assert!(
        e.starts_with("t.toml:9:1: recursive definition: f → f"),
        "{e}"
    );
    let e = load(&def("f(x) = g(x) + 1\ng(x) = 2*f(x)")).unwrap_err();
    assert!(e.contains("recursive definition: f → g → f"), "{e}");
    assert_eq!(e.matches("recursive").count(), 1, "{e}");
    assert!(load(&def("f(x) = g(x) + 1\ng(x) = 2*x")).is_ok());
}

#[test]
fn inner_claims_inherit_what_they_do_not_give() {
    let src = claim(
        "kind = \"negation\"\nexpect = \"holds\"\nvars = [[\"x\", \"uniform(0.5, 1)\"]]\nlet = \"y = 2*x\"\nsamples = 5\n[claim.inner]\nkind = \"identity\"\nlhs = \"sin(y)\"\nrhs = \"2*sin(x)\"\nseed = 3",
    );
    let cat = load(&src).unwrap();
    let outer = &cat.claims[0];
    let eulertop::claims::catalogue::Body::Negation(inner) = &outer.body else {
        panic!("not a negation");
    };
    assert_eq!(inner.id, "c.inner");
    assert_eq!((inner.samples, inner.seed, outer.seed), (5, 3, 0));
    assert_eq!(inner.vars.len(), 1);
    assert_eq!(inner.lets[0].name, "y");
    assert_eq!(inner.location, outer.location);
}

#[test]
fn out_of_range_fields_are_errors_not_clamped() {
    let e = load(&claim(&format!(
        "{HEAD}lhs = \"x\"\nrhs = \"x\"\nsamples = 0"
    )))
    .unwrap_err();
    assert!(
        e.contains("samples must be between 1 and 10000, not 0"),
        "{e}"
    );
    let e = load(&claim(
        "kind = \"independence\"\nexpect = \"holds\"\nvars = [[\"x\", \"uniform(1, 2)\"]]\nexpr = \"1\"\nwrt = \"x\"\nredraws = 1000",
    ))
    .unwrap_err();
    assert!(e.contains("redraws must be between 1 and 100"), "{e}");
}

#[test]
fn catalogue_paths_give_one_line_errors() {
    use eulertop::claims::catalogue::load_dir;
    let dir = std::env::temp_dir().join(format!("eulertop-paths-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let one_line = |r: Result<Catalogue, eulertop::claims::catalogue::LoadError>| {
        let e = r.unwrap_err().to_string();
        assert_eq!(e.lines().count(), 1, "{e}");
        e
    };
    assert!(one_line(load_dir(&dir, Registry::new())).contains("no catalogue files"));
    std::fs::write(dir.join("t.toml"), "").unwrap();
    assert!(one_line(load_dir(&dir, Registry::new())).contains("has no claims"));
    let missing = dir.join("nonexistent");
    let e = one_line(load_dir(&missing, Registry::new()));
    assert!(
        e.starts_with(&format!("{}: cannot read", missing.display())),
        "{e}"
    );
    std::fs::write(dir.join("t.toml"), b"[[claim]]\nid = \"\xff\"\n").unwrap();
    let e = one_line(load_dir(&dir, Registry::new()));
    assert!(
        e.ends_with("t.toml:2:7: not valid UTF-8 text (byte 0xff)"),
        "{e}"
    );
    // a single file is a catalogue too
    let file = dir.join("one.toml");
    std::fs::write(&file, claim(&format!("{HEAD}lhs = \"x\"\nrhs = \"x\""))).unwrap();
    assert_eq!(load_dir(&file, Registry::new()).unwrap().claims.len(), 1);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn jacobi_inverse_works_in_a_catalogue() {
    // |u| < 1 < K(k): the inverse of (sn, cn, dn) is u itself
    let r = verdict_of(
        &claim(
            "kind = \"identity\"\nexpect = \"holds\"\nvars = [[\"k\", \"uniform(0.1, 0.9)\"], [\"u\", \"uniform(-1, 1)\"]]\nlhs = \"jacobi_inverse(sn(u, k), cn(u, k), dn(u, k), k)\"\nrhs = \"u\"",
        ),
        &LADDER,
    );
    assert_eq!(r.verdict, Verdict::Holds, "{}", r.reason);
}

#[test]
fn repeated_calls_give_the_results_of_fresh_ones() {
    // an evaluation answers a repeated call of a catalogue function or a Jacobi function
    // from its earlier result: equal arguments only, at the evaluation's precision
    let mut reg = Registry::new();
    for b in
        parse_bindings("sq(x) = x*x\nphase(u, k) = sn(u, k) + 2*cn(u, k) + 3*dn(u, k)").unwrap()
    {
        reg.define(b).unwrap();
    }
    let fresh = |s: &str, bits: u32| {
        // each sub-expression in its own evaluation: nothing to recall
        let ev = Evaluator::new(&reg, rug::Float::new(bits));
        ev.eval(&parse_expr(s).unwrap()).unwrap().as_real().unwrap()
    };
    for bits in [53u32, 8192] {
        let ev = Evaluator::new(&reg, rug::Float::new(bits));
        let at = |s: &str| ev.eval(&parse_expr(s).unwrap()).unwrap().as_real().unwrap();
        // repeated and nearby arguments in one evaluation
        let both = at("sq(3) + sq(3) + sq(3.5) + phase(0.3, 0.5) - phase(0.3, 0.6) + sq(3)");
        let want =
            fresh("sq(3)", bits) * 3u32 + fresh("sq(3.5)", bits) + fresh("phase(0.3, 0.5)", bits)
                - fresh("phase(0.3, 0.6)", bits);
        assert_eq!(both, want, "at {bits} bits");
        // the twelve Jacobi functions share one triple, and each is still its own quotient
        let q = at("sn(0.7, 0.8) / cn(0.7, 0.8) - sc(0.7, 0.8)");
        assert!(q.is_zero(), "at {bits} bits");
        assert_eq!(at("dn(0.7, 0.8)"), fresh("dn(0.7, 0.8)", bits));
        assert_eq!(at("cd(0.7, 0.8)"), fresh("cd(0.7, 0.8)", bits));
    }
    // the same evaluator at another precision is another evaluation
    let ev = Evaluator::new(&reg, rug::Float::new(53));
    let low = ev
        .eval(&parse_expr("sn(0.7, 0.8)").unwrap())
        .unwrap()
        .as_real()
        .unwrap();
    assert_eq!(low.prec(), 53);
    assert_eq!(fresh("sn(0.7, 0.8)", 8192).prec(), 8192);
}
