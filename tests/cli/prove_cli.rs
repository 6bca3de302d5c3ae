//! Command-line tests of `eulertop prove`: the derivation a reader follows, the
//! certificate (prescribed elliptic bases included), and the exit statuses.

use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_eulertop"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("eulertop runs");
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn a_hinted_proof_prints_its_route_and_ends_in_zero() {
    let (code, out, err) = run(&["prove", "sec6.prop4.g1"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("ideal membership with the hint's multipliers"),
        "{out}"
    );
    assert!(
        out.trim_end()
            .ends_with("normal form of lhs - rhs: 0: proved"),
        "{out}"
    );
}

#[test]
fn a_prescribed_base_gets_a_certificate_with_its_value() {
    let path = std::env::temp_dir().join(format!("eulertop-u0-{}.cert", std::process::id()));
    let p = path.to_str().unwrap();
    let (code, _, err) = run(&["prove", "sec5.u0.corrected.rho-real", "--certificate", p]);
    assert_eq!(code, 0, "{err}");
    let cert = std::fs::read_to_string(&path).expect("certificate written");
    let _ = std::fs::remove_file(&path);
    assert!(cert.starts_with("# eulertop certificate 1"), "{cert}");
    // sn of F(asin x, k) is x itself: the base's s is a value, not a symbol of its own
    let prescribed = cert.lines().filter(|l| l.starts_with("base ")).any(|l| {
        let s = l
            .split(" s=")
            .nth(1)
            .and_then(|r| r.split(' ').next())
            .unwrap_or("");
        s.starts_with('(')
    });
    assert!(prescribed, "no prescribed base in the certificate:\n{cert}");
    assert!(cert.lines().any(|l| l.starts_with("claim ")), "{cert}");
}

#[test]
fn an_identity_without_a_proof_exits_1_with_its_reason() {
    let (code, out, _) = run(&["prove", "sec5.gamma-positive"]);
    assert_eq!(code, 1);
    assert!(out.contains("not proved: "), "{out}");
}

#[test]
fn a_negation_is_proved_by_a_witness_with_its_certificate() {
    let path = std::env::temp_dir().join(format!("eulertop-negation-{}.cert", std::process::id()));
    let p = path.to_str().expect("utf-8 temp path");
    let (code, out, err) = run(&["prove", "sec6.aux3.gamma0.up", "--certificate", p]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("proved by a witness"), "{out}");
    assert!(!out.contains("not proved"), "{out}");
    let cert = std::fs::read_to_string(&path).expect("certificate written");
    let _ = std::fs::remove_file(&path);
    // the inner identity's sides, not claimed equal, and the point
    assert!(
        cert.contains("\nside t") && !cert.contains("\nclaim t"),
        "{cert}"
    );
    assert!(cert.contains("\nwitness component 1\n"), "{cert}");
    assert!(cert.contains("\nat sn_1 = "), "{cert}");
}

#[test]
fn a_refuted_identity_writes_its_witness_certificate_and_exits_1() {
    let path = std::env::temp_dir().join(format!("eulertop-refuted-{}.cert", std::process::id()));
    let p = path.to_str().expect("utf-8 temp path");
    let (code, out, _) = run(&["prove", "sec2.ET-v.printed", "--certificate", p]);
    assert_eq!(code, 1, "{out}");
    let cert = std::fs::read_to_string(&path).expect("certificate written");
    let _ = std::fs::remove_file(&path);
    assert!(cert.contains("\nwitness component "), "{cert}");
    // a refutation has no Coq proof
    let coq = std::env::temp_dir().join(format!("eulertop-refuted-{}.v", std::process::id()));
    let (code, _, err) = run(&[
        "prove",
        "sec2.ET-v.printed",
        "--coq",
        coq.to_str().expect("utf-8"),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("no Coq proof"), "{err}");
    assert!(!coq.exists());
}

#[test]
fn bad_ids_and_kinds_are_one_line_errors_with_status_2() {
    for (args, expected) in [
        (
            vec!["prove", "no.such.claim"],
            "no claim id, environment or label 'no.such.claim'",
        ),
        (
            vec!["prove", "sec2.def.Omega"],
            "only identities, independence, asymptotic, existence and negation claims are proved symbolically",
        ),
    ] {
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{args:?}");
        assert!(out.is_empty(), "{out}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(expected), "{err}");
    }
}

#[test]
fn an_asymptotic_claim_is_proved_by_power_series_with_a_certificate() {
    let path = std::env::temp_dir().join(format!("eulertop-series-{}.cert", std::process::id()));
    let p = path.to_str().expect("utf-8 temp path");
    let (code, out, err) = run(&["prove", "sec7.delta12-asym.g1.up", "--certificate", p]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("proved by exact power series"), "{out}");
    let cert = std::fs::read_to_string(&path).expect("certificate written");
    let _ = std::fs::remove_file(&path);
    // every series operation is recorded, the phase step's chart and the claimed coefficients
    assert!(
        cert.contains("\nseries h step 1 order 2 precision "),
        "{cert}"
    );
    assert!(cert.contains("\nschart delta1("), "{cert}");
    assert!(cert.contains("\nsclaim s"), "{cert}");
    assert!(!cert.contains("\nclaim t"), "{cert}");
}

#[test]
fn an_independence_claim_is_proved_by_its_derivative() {
    let path = std::env::temp_dir().join(format!("eulertop-indep-{}.cert", std::process::id()));
    let p = path.to_str().expect("utf-8 temp path");
    let (code, out, err) = run(&["prove", "sec7.prop6.g1-poisson.up", "--certificate", p]);
    assert!(out.contains("by sec7.master12.step.up"), "{out}");
    assert!(out.contains("normal form of lhs - rhs: 0: proved"), "{out}");
    // the proof needs the derivative of the phase step δ in φ, which the chart implies:
    // the certificate states it and the value of h in the chart, which it holds fixed
    assert_eq!(code, 0, "{out}{err}");
    let cert = std::fs::read_to_string(&path).expect("certificate written");
    assert!(cert.lines().any(|l| l == "dvar phi delta = (0)/(1)"));
    assert_eq!(lines_of(&cert, "coord h").len(), 1, "{cert}");
    let _ = std::fs::remove_file(&path);
    // a proof with a step the format does not record (a shift by a third of K): no
    // certificate, and the one line says why
    let (code, _, err) = run(&[
        "prove",
        "dlmf.22.9.13.s3",
        "--catalogue",
        "examples/dlmf-jacobi",
        "--certificate",
        p,
    ]);
    assert_eq!(code, 1, "{err}");
    assert!(!path.exists(), "a certificate was written");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("a shift by a third of K"), "{err}");
    // a claim that uses the phase of the elliptic coordinates without such a fact: its
    // certificate has the `equiv` lines of the phase, and the phase step of the chart,
    // a real parameter
    let (code, out, err) = run(&["prove", "sec6.discr-eq.corrected.up", "--certificate", p]);
    assert_eq!(code, 0, "{out}{err}");
    let cert = std::fs::read_to_string(&path).expect("certificate written");
    let _ = std::fs::remove_file(&path);
    assert!(
        cert.lines()
            .any(|l| l == "field delta param real  # opaque symbol")
    );
}

/// The certificate's lines that start with `word `.
fn lines_of<'a>(cert: &'a str, word: &str) -> Vec<&'a str> {
    cert.lines()
        .filter(|l| l.starts_with(&format!("{word} ")))
        .collect()
}

#[test]
fn a_certificate_states_its_claim_as_the_catalogue_writes_it() {
    let dir = std::env::temp_dir().join(format!("eulertop-bound-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("et.cert");
    let p = path.to_str().unwrap();
    let (code, out, err) = run(&["prove", "sec2.ET-v.corrected", "--certificate", p]);
    assert_eq!(code, 0, "{out}{err}");
    let cert = std::fs::read_to_string(&path).expect("certificate written");
    let source = lines_of(&cert, "source");
    assert_eq!(source[0], r#"source id "sec2.ET-v.corrected""#, "{cert}");
    assert!(
        source.contains(&r#"source claim.lhs "ETrhs(M, A, B, C)""#),
        "{cert}"
    );
    assert!(
        source.contains(&r#"source claim.rhs "cross(OmP(M, A, B, C), M)""#),
        "{cert}"
    );
    // the definitions the formulas call, and the domain
    assert!(
        source
            .iter()
            .any(|l| l.starts_with("source define.sec2.def.ET \"ETrhs(M, A, B, C) = "))
    );
    assert!(source.iter().any(|l| l.starts_with("source domain.top {")));
    // three components, three claim lines, announced
    assert_eq!(lines_of(&cert, "claims"), ["claims 3"]);
    assert_eq!(lines_of(&cert, "claim").len(), 3);
    // a claim resting on a solution branch states it as a premise, with its source
    let path2 = dir.join("m.cert");
    let (code, out, err) = run(&[
        "prove",
        "sec7.master12.g1.up",
        "--certificate",
        path2.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{out}{err}");
    let cert = std::fs::read_to_string(&path2).expect("certificate written");
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        lines_of(&cert, "premise")
            .iter()
            .any(|l| l.starts_with("premise branch hypothesis.branch-delta1 \"")),
        "{cert}"
    );
    assert!(
        lines_of(&cert, "assume")
            .iter()
            .any(|l| l.starts_with("assume branch delta1 \""))
    );
    assert!(!cert.contains("# assumption"), "{cert}");
}

#[test]
fn an_environment_name_proves_its_statement_claims_in_order() {
    let (code, out, err) = run(&["prove", "Theorem 2"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("Theorem 2 (statement): 1 claim"), "{out}");
    assert!(out.contains("claim sec8.thm2.gammaMV\n"), "{out}");
    assert!(!out.contains("claim sec8.thm2.gammaMV.model"), "{out}");
    assert!(
        out.trim_end()
            .ends_with("normal form of lhs - rhs: 0: proved"),
        "{out}"
    );
}

#[test]
fn a_paper_label_proves_the_claims_carrying_it() {
    for label in ["(gammaMV)", "gammaMV"] {
        let (code, out, err) = run(&["prove", label]);
        assert_eq!(code, 0, "{label}: {err}");
        assert!(out.starts_with("label (gammaMV): "), "{out}");
        let ids: Vec<&str> = out
            .lines()
            .filter_map(|l| l.strip_prefix("claim "))
            .collect();
        // catalogue order; the definition among them is named, not proved
        let thm = ids.iter().position(|i| *i == "sec8.thm2.gammaMV");
        let model = ids.iter().position(|i| *i == "sec8.thm2.gammaMV.model");
        assert!(thm.is_some() && thm < model, "{ids:?}");
        assert!(out.contains("skipped: of kind definition"), "{out}");
    }
}

#[test]
fn a_misspelled_id_or_name_gets_one_did_you_mean_line() {
    for (args, closest) in [
        (vec!["prove", "sec8.thm2.gammaMW"], "sec8.thm2.gammaMV"),
        (vec!["prove", "Theorm 2"], "Theorem 2"),
        (vec!["audit", "(gammaMW)"], "(gammaMV)"),
        (vec!["verify", "--only", "Lema 2"], "Lemma 2"),
    ] {
        let (code, out, err) = run(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(out.is_empty(), "{out}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains("did you mean"), "{err}");
        assert!(err.contains(closest), "{args:?}: {err}");
    }
}

#[test]
fn a_certificate_needs_a_single_claim() {
    let (code, out, err) = run(&["prove", "gammaMV", "--certificate", "x.cert"]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty(), "{out}");
    assert!(err.contains("--certificate needs one claim"), "{err}");
}
