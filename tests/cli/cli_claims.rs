//! Command-line tests of `eulertop verify`, `audit` and `eval`: exit statuses, JSON
//! shape, error positions, determinism.

use std::path::PathBuf;
use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_eulertop"))
}

fn temp_catalogue(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("eulertop-claims-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("t.toml"), text).unwrap();
    dir
}

const TWO: &str = r#"
[[claim]]
id = "true.one"
location = "test"
printed = 'x'
kind = "identity"
expect = "holds"
vars = [["x", "uniform(-1, 1)"]]
lhs = "exp(x) * exp(-x)"
rhs = "1"
environment = "Section 2"
role = "statement"

[[claim]]
id = "false.one"
location = "test"
printed = 'x'
kind = "identity"
expect = "holds"
vars = [["x", "uniform(0.5, 1)"]]
lhs = "exp(2*x)"
rhs = "2*exp(x)"
environment = "Section 2"
role = "statement"
"#;

#[test]
fn verify_exit_status_and_json() {
    let dir = temp_catalogue("two", TWO);
    let out = bin()
        .args([
            "verify",
            "--format",
            "json",
            "--bits",
            "53,128",
            "--catalogue",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1), "a verdict differs from expect");
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let claims = v["claims"].as_array().unwrap();
    assert_eq!(claims.len(), 2);
    for f in [
        "id",
        "labels",
        "location",
        "kind",
        "form",
        "expect",
        "verdict",
        "residuals",
        "samples",
        "loss_bits",
    ] {
        assert!(claims[0].get(f).is_some(), "field {f}");
    }
    assert_eq!(claims[0]["verdict"], "holds");
    assert_eq!(claims[1]["verdict"], "refuted");
    assert_eq!(claims[0]["residuals"][1]["bits"], 128);
    assert!(claims[1]["counterexample"]["point"][0]["name"] == "x");
    assert_eq!(v["summary"]["unexpected"][0], "false.one");
    // only the true claim: exit 0
    let out = bin()
        .args([
            "verify",
            "--only",
            "true.*",
            "--bits",
            "53,128",
            "--catalogue",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("true.one") && !text.contains("false.one"));
}

#[test]
fn verify_output_is_deterministic_across_thread_counts() {
    let dir = temp_catalogue("det", TWO);
    let run = |jobs: &str| {
        bin()
            .args([
                "verify",
                "--format",
                "json",
                "--bits",
                "53,256",
                "--jobs",
                jobs,
                "--catalogue",
            ])
            .arg(&dir)
            .output()
            .unwrap()
            .stdout
    };
    // everything but the wall times is deterministic
    let strip = |out: Vec<u8>| {
        let mut v: serde_json::Value = serde_json::from_slice(&out).unwrap();
        for c in v["claims"].as_array_mut().unwrap() {
            assert!(c["elapsed_ms"].as_f64().is_some_and(|t| t >= 0.0), "{c}");
            c["proof"]["ms"] = serde_json::Value::Null;
            c["elapsed_ms"] = serde_json::Value::Null;
        }
        v
    };
    let a = strip(run("1"));
    assert!(!a["claims"].as_array().unwrap().is_empty());
    assert_eq!(a, strip(run("2")));
    assert_eq!(a, strip(run("2")));
}

#[test]
fn bad_input_exits_2_with_position() {
    let dir = temp_catalogue(
        "bad",
        &TWO.replace("lhs = \"exp(2*x)\"", "lhs = \"exp(2*x))\""),
    );
    let out = bin()
        .args(["verify", "--catalogue"])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("t.toml:21:16: syntax error") && err.contains('^'),
        "{err}"
    );
    let out = bin().args(["verify", "--bits", "53,abc"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let out = bin()
        .args(["verify", "--catalogue", "/nonexistent/dir"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let out = bin().args(["eval", "1 +"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let out = bin().args(["eval", "x", "--set", "x"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn eval_and_audit() {
    let out = bin().args(["eval", "K(0) * 2 / pi"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let v: f64 = String::from_utf8(out.stdout)
        .unwrap()
        .trim()
        .parse()
        .unwrap();
    assert!((v - 1.0).abs() < 1e-15);
    let out = bin()
        .args(["eval", "sqrt(x) - 2", "--set", "x=4", "--bits", "300"])
        .output()
        .unwrap();
    let s = String::from_utf8(out.stdout).unwrap();
    assert_eq!(s.trim(), "0");
    let dir = temp_catalogue("audit", TWO);
    let out = bin()
        .args(["audit", "true.one", "--bits", "64,256,1024", "--catalogue"])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let s = String::from_utf8(out.stdout).unwrap();
    let slope: f64 = s
        .lines()
        .find_map(|l| l.strip_prefix("fitted slope: "))
        .and_then(|l| l.split_whitespace().next())
        .and_then(|x| x.parse().ok())
        .unwrap();
    assert!((slope - 1.0).abs() < 0.05, "{s}");
    let out = bin()
        .args(["audit", "nope", "--catalogue"])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

/// `--coverage` lists the labels of the catalogue's `[paper]` table (the paper's 96),
/// and, for a catalogue without one, the labels its claims carry.
#[test]
fn coverage_lists_the_labels_of_the_catalogue() {
    let rows = |args: &[&str], dir: Option<&PathBuf>| -> Vec<serde_json::Value> {
        let mut cmd = bin();
        cmd.args(["verify", "--format", "json", "--coverage", "--bits", "53"])
            .args(args)
            .env_remove("EULERTOP_PAPER");
        if let Some(d) = dir {
            cmd.arg("--catalogue").arg(d);
        }
        let out = cmd.output().unwrap();
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        v["coverage"].as_array().unwrap().clone()
    };
    let paper = rows(&["--only", "sec2.def.M2"], None);
    assert_eq!(paper.len(), 96);
    assert_eq!(paper[0]["label"], "ET");
    let with_claims: Vec<&serde_json::Value> = paper
        .iter()
        .filter(|r| !r["claims"].as_array().unwrap().is_empty())
        .collect();
    assert_eq!(with_claims.len(), 1);
    assert_eq!(with_claims[0]["label"], "M2");
    let labelled = TWO.replace(
        "environment = \"Section 2\"",
        "labels = [\"x\"]\nenvironment = \"Section 2\"",
    );
    let dir = temp_catalogue("cov", &labelled);
    let own = rows(&[], Some(&dir));
    assert_eq!(own.len(), 1);
    assert_eq!(own[0]["label"], "x");
    assert_eq!(own[0]["claims"].as_array().unwrap().len(), 2);
}

#[test]
fn eval_sees_catalogue_definitions() {
    let dir = temp_catalogue(
        "defs",
        "[[claim]]\nid = \"d\"\nlocation = \"l\"\nprinted = 'p'\nenvironment = \"Section 2\"\nrole = \"statement\"\nkind = \"definition\"\ndefine = '''\ncube(x) = x^3\n'''\n",
    );
    let out = bin()
        .args(["eval", "cube(3) - 27", "--catalogue"])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let v: f64 = String::from_utf8(out.stdout)
        .unwrap()
        .trim()
        .parse()
        .unwrap();
    assert_eq!(v, 0.0);
    let out = bin().args(["eval", "cube(3)"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2), "unknown without the catalogue");
}

/// `verify --only` with an environment name runs that environment's claims and no other.
#[test]
fn verify_only_an_environment_runs_its_claims() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_eulertop"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args([
            "verify", "--only", "Lemma 2", "--bits", "53", "--format", "json",
        ])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let claims = v["claims"].as_array().unwrap();
    let got: Vec<&str> = claims.iter().map(|c| c["id"].as_str().unwrap()).collect();
    let mut files: Vec<PathBuf> =
        std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/identities"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
    files.sort();
    let mut expected = Vec::new();
    for f in files {
        let t: toml::Value = toml::from_str(&std::fs::read_to_string(f).unwrap()).unwrap();
        for c in t
            .get("claim")
            .and_then(|c| c.as_array())
            .into_iter()
            .flatten()
        {
            if c.get("environment").and_then(|e| e.as_str()) == Some("Lemma 2") {
                expected.push(c["id"].as_str().unwrap().to_string());
            }
        }
    }
    assert!(expected.len() > 1);
    assert_eq!(got, expected);
}

const LONG: &str = r#"
[[claim]]
id = "long.refuted"
location = "Section 9, a deliberately long location that runs past forty characters to its very end"
printed = 'x'
kind = "identity"
expect = "refuted"
vars = [["x", "uniform(0.5, 1)"]]
lhs = "exp(2*x)"
rhs = "2*exp(x)"
environment = "Section 2"
role = "statement"
"#;

#[test]
fn verify_text_has_a_legend_the_full_location_and_a_reason_line() {
    let dir = temp_catalogue("long", LONG);
    let out = bin()
        .args(["verify", "--bits", "53,128", "--catalogue"])
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "refuted as expected");
    let s = String::from_utf8(out.stdout).unwrap();
    // the legend explains every column, g included, before the table
    let head = s.find("\nid ").expect("a header row");
    let legend = &s[..head];
    for col in [
        "form:",
        "verdict:",
        "expect",
        "g: bits of precision lost",
        "N bits:",
    ] {
        assert!(legend.contains(col), "{col} not explained: {s}");
    }
    assert!(legend.contains("slope s"), "{s}");
    // the location is shown whole, wrapped at 40 characters
    let words: Vec<&str> = s[head..]
        .lines()
        .skip(1)
        .take_while(|l| !l.starts_with("    reason:"))
        .flat_map(|l| l.split_whitespace())
        .collect();
    let text = words.join(" ");
    assert!(text.contains("to its very end"), "{s}");
    let row = s[head + 1..].lines().nth(1).unwrap();
    assert!(row.starts_with("long.refuted"), "{s}");
    assert!(!row.contains("very end"), "wrapped: {s}");
    // one line of reason under the refuted claim
    let reasons: Vec<&str> = s
        .lines()
        .filter(|l| l.starts_with("    reason: "))
        .collect();
    assert_eq!(reasons.len(), 1, "{s}");
    assert!(reasons[0].len() > "    reason: ".len() + 10, "{s}");
}
