//! `eulertop jacobi` end to end: output format and precision, complex arguments, the
//! twelve functions (`--functions`), the parameter `m` (`--parameter`), `k ≥ 1`, and
//! one-line errors with the line number (exit status 2) for malformed, overflowing and
//! non-UTF-8 input and overlong lines.

use std::io::Write;
use std::process::{Command, Stdio};

fn run(args: &[&str], input: &[u8]) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_eulertop"))
        .arg("jacobi")
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let mut stdin = child.stdin.take().unwrap();
    // the child may stop reading early (overlong line): ignore a broken pipe
    let _ = stdin.write_all(input);
    drop(stdin);
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

fn numbers(s: &str) -> Vec<f64> {
    s.split_whitespace().map(|t| t.parse().unwrap()).collect()
}

/// mpmath: ellipfun('sn'|'cn'|'dn', 0.75, m=0.25):
/// sn = 0.67011132822387532999, cn = 0.74226060638163576636, dn = 0.94219833471860286803
#[test]
fn f64_and_mpfr_output() {
    let (code, out, err) = run(&[], b"# comment\n\n0.75 0.5\n");
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
    assert!(
        out.split_whitespace()
            .all(|t| t.split('e').next().unwrap().replace(['-', '.'], "").len() == 17)
    );

    let (code, out, _) = run(&["--bits", "256"], b"0.75 0.5\n");
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
    let (code, out, _) = run(&["--complex"], b"0.5 0.25 0.5\n0.1 -0.2 0\n");
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
fn help_names_the_modulus() {
    let out = Command::new(env!("CARGO_BIN_EXE_eulertop"))
        .args(["jacobi", "--help"])
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let first = text.lines().next().unwrap();
    assert!(first.contains("k the modulus"), "{first}");
}

/// mpmath: ellipfun(f, 0.7, m=-0.5) for sn, cd, ns = 0.66395932651367945152,
/// 0.67688118364789303415, 1.50611635392... ; ellipfun('sn', 0.7, m=2.25) =
/// 0.55428056884074893... (modulus 1.5); k = 1: tanh 0.7, sech 0.7.
#[test]
fn parameter_functions_and_moduli_beyond_one() {
    let (code, out, err) = run(&["--parameter", "--functions", "sn,cd,ns"], b"0.7 -0.5\n");
    assert_eq!(code, 0, "{err}");
    let v = numbers(&out);
    assert_eq!(v.len(), 3);
    assert!((v[0] - 0.6639593265136795).abs() < 1e-15);
    assert!((v[1] - 0.676881183647893).abs() < 1e-15);
    assert!((v[2] * v[0] - 1.0).abs() < 1e-15);
    let (code, out, _) = run(&["--functions", "sn,cn,dn"], b"0.7 1\n0.7 1.5\n");
    assert_eq!(code, 0);
    let v = numbers(&out);
    assert!((v[0] - 0.7f64.tanh()).abs() < 1e-16 && (v[1] - 1.0 / 0.7f64.cosh()).abs() < 1e-16);
    assert!((v[3] - 0.554_280_568_840_748_9).abs() < 1e-15);
}

#[test]
fn errors_are_one_line_with_the_line_number() {
    let long = vec![b'x'; 5_000_000];
    let cases: Vec<(Vec<&str>, Vec<u8>, &str)> = vec![
        (
            vec![],
            b"0.5 0.5\n1e309 0.5\n".to_vec(),
            "<stdin>:2:1: u = 1e309 overflows",
        ),
        (
            vec![],
            b"0.5 0.5\n\xff\xfe 0.5\n".to_vec(),
            "<stdin>:2:1: not valid UTF-8",
        ),
        (vec![], long, "<stdin>:1:1: longer than 4096 bytes"),
        (
            vec!["--functions", "ns"],
            b"0 0.5\n".to_vec(),
            "<stdin>:1:1: pole",
        ),
        (
            vec!["--complex"],
            b"0.5 0.5 -0.5\n".to_vec(),
            "<stdin>:1:9: modulus k = -5e-1",
        ),
        (
            vec!["--complex", "--parameter"],
            b"0.5 0.5 x\n".to_vec(),
            "<stdin>:1:9: malformed parameter m",
        ),
        (vec![], b"0.5 0.5\n0.1 0.2\n1 x\n".to_vec(), "<stdin>:3:"),
        (vec![], b"0.5 abc\n".to_vec(), "<stdin>:1:"),
        (vec![], b"0.5\n".to_vec(), "<stdin>:1:"),
        (vec!["--bits", "128"], b"0.5 -inf\n".to_vec(), "<stdin>:1:"),
        (vec!["--complex"], b"0.5 0.5\n".to_vec(), "<stdin>:1:"),
    ];
    for (args, input, want) in cases {
        let (code, _, err) = run(&args, &input);
        assert_eq!(code, 2, "{want}: {err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.len() < 200, "{err}");
        // an error about an input line starts with its position <stdin>:LINE:COL
        if want.starts_with("<stdin>:") {
            let pos = want.split(": ").next().unwrap_or(want);
            assert!(err.starts_with(&format!("eulertop: {pos}")), "{err}");
        }
        assert!(err.contains(want), "{want}: {err}");
    }
    let (code, _, err) = run(&["--functions", "sn,xy"], b"");
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("unknown function 'xy'"), "{err}");
}

/// Next to a pole a quotient is ill-conditioned: one warning line on standard error at
/// the end of the run (how many lines, the first one, its function and `κ_u`), the
/// values printed as always, exit status 0; nothing on standard error elsewhere, nor
/// for sn, cn, dn alone.  The point: k = 1 − 2⁻⁵³ and u = 19.408121051678471, 4·10⁻⁹
/// below K (tests/data/jacobi_ref_pole.csv: cn ≈ 6·10⁻¹⁷, κ_u(nc) = κ_u(dc) = 4.852·10⁹).
#[test]
fn warns_once_next_to_a_pole() {
    let near = "19.40812105167847079201237647794187068939208984375 0.99999999999999988897769753748434595763683319091796875\n";
    let input = format!("0.75 0.5\n{near}{near}");
    let (code, out, err) = run(&["--functions", "sn,nc,dc"], input.as_bytes());
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.lines().count(), 3);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with("eulertop: warning: 2 line(s)"), "{err}");
    // nc and dc have the same κ_u there to 16 digits (dn ≫ cn)
    assert!(
        err.contains("<stdin>:2, nc with κ_u = 4.85")
            || err.contains("<stdin>:2, dc with κ_u = 4.85"),
        "{err}"
    );
    // sn, cn, dn only, or away from the pole: no warning
    let (code, _, err) = run(&[], input.as_bytes());
    assert_eq!((code, err.as_str()), (0, ""));
    let (code, _, err) = run(&["--functions", "nc"], b"0.75 0.5\n");
    assert_eq!((code, err.as_str()), (0, ""));
    // at 256 bits the bound is 2^128: no warning
    let (code, _, err) = run(&["--bits", "256", "--functions", "nc"], near.as_bytes());
    assert_eq!((code, err.as_str()), (0, ""));
}
