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
    let (code, out, _) = run(&["prove", "sec4.eq-in-ell.g0"]);
    assert_eq!(code, 1);
    assert!(out.contains("not proved: "), "{out}");
}

#[test]
fn bad_ids_and_kinds_are_one_line_errors_with_status_2() {
    for (args, expected) in [
        (
            vec!["prove", "no.such.claim"],
            "no claim with id 'no.such.claim'",
        ),
        (
            vec!["prove", "sec7.delta12-asym.g1.up"],
            "only identities and independence claims are proved symbolically",
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
fn an_independence_claim_is_proved_by_its_derivative() {
    let path = std::env::temp_dir().join(format!("eulertop-indep-{}.cert", std::process::id()));
    let p = path.to_str().expect("utf-8 temp path");
    let (code, out, err) = run(&["prove", "sec7.prop6.g1-poisson.up", "--certificate", p]);
    assert!(out.contains("by sec7.master12.step.up"), "{out}");
    assert!(out.contains("normal form of lhs - rhs: 0: proved"), "{out}");
    // the proof decides dn > 0 of a real argument, which the certificate format does not
    // record: no certificate, and the one line says why
    assert_eq!(code, 1, "{out}{err}");
    assert!(!path.exists(), "a certificate was written");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("Jacobi functions"), "{err}");
    // a claim that uses the phase of the elliptic coordinates without such a fact: its
    // certificate has the `equiv` lines of the phase, and the phase step of the chart
    let (code, out, err) = run(&["prove", "sec6.discr-eq.corrected.up", "--certificate", p]);
    assert_eq!(code, 0, "{out}{err}");
    let cert = std::fs::read_to_string(&path).expect("certificate written");
    let _ = std::fs::remove_file(&path);
    assert!(
        cert.lines()
            .any(|l| l == "field delta param  # opaque symbol")
    );
}
