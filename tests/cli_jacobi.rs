//! `eulertop jacobi` end to end: output format, precision, errors (exit status 2).

use std::io::Write;
use std::process::{Command, Stdio};

fn run(args: &[&str], input: &str) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_eulertop"))
        .arg("jacobi")
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// mpmath: ellipfun('sn'|'cn'|'dn', 0.75, m=0.25):
/// sn = 0.67011132822387532999, cn = 0.74226060638163576636, dn = 0.94219833471860286803
#[test]
fn f64_and_mpfr_output() {
    let (code, out, err) = run(&[], "# comment\n\n0.75 0.5\n");
    assert_eq!(code, 0, "{err}");
    let v: Vec<f64> = out.split_whitespace().map(|t| t.parse().unwrap()).collect();
    assert_eq!(v.len(), 3);
    let sn = v[0];
    for (got, want) in v
        .iter()
        .zip([0.6701113282238753, 0.7422606063816358, 0.9421983347186029])
    {
        assert!((got - want).abs() < 5e-16, "{got} vs {want}");
    }
    assert!((sn * sn + v[1] * v[1] - 1.0).abs() < 1e-15);
    assert!((v[2] * v[2] + 0.25 * sn * sn - 1.0).abs() < 1e-15);
    // 17 significant digits per value
    assert!(out.split_whitespace().all(|t| t
        .split('e')
        .next()
        .unwrap()
        .replace(['-', '.'], "")
        .len()
        == 17));

    let (code, out, _) = run(&["--bits", "256"], "0.75 0.5\n");
    assert_eq!(code, 0);
    let toks: Vec<&str> = out.split_whitespace().collect();
    assert_eq!(toks.len(), 3);
    // ceil(256·log10 2) + 2 = 80 digits
    let mant = toks[0].split('e').next().unwrap().replace(['-', '.'], "");
    assert_eq!(mant.len(), 80);
    assert!(
        toks[0].starts_with("6.701113282238753299945023434"),
        "{}",
        toks[0]
    );
}

#[test]
fn complex_output() {
    let (code, out, _) = run(&["--complex"], "0.5 0.25 0.5\n0.1 -0.2 0\n");
    assert_eq!(code, 0);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.len(), 2);
    let v: Vec<f64> = lines[0]
        .split_whitespace()
        .map(|t| t.parse().unwrap())
        .collect();
    assert_eq!(v.len(), 6);
    // mpmath: ellipfun('sn', mpc(0.5,0.25), m=0.25) = 0.492218840478357096 + 0.215722356526344565j
    assert!(
        (v[0] - 0.4922188404783571).abs() < 1e-15 && (v[1] - 0.21572235652634456).abs() < 1e-15
    );
}

#[test]
fn errors_exit_2_with_line_number() {
    for (args, input, what) in [
        (&[][..], "0.5 0.5\n0.1 0.2\n1 -1\n", "line 3"),
        (&[][..], "0.5 abc\n", "line 1"),
        (&[][..], "0.5\n", "line 1"),
        (&["--bits", "128"][..], "0.5 -0.5\n", "line 1"),
        (&["--complex"][..], "0.5 0.5\n", "line 1"),
    ] {
        let (code, _, err) = run(args, input);
        assert_eq!(code, 2, "{input:?}");
        assert!(err.starts_with(&format!("eulertop: {what}:")), "{err}");
        assert_eq!(err.lines().count(), 1);
    }
}
