//! The commands outside the repository: with the paper's catalogue built into the binary
//! they run from any directory; `init` starts a new catalogue there, and the example
//! catalogue of `examples/dlmf-jacobi` verifies with exit status 0.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// A fresh directory outside the repository.
fn elsewhere(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("eulertop-anywhere-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs the binary in `dir`.
fn run_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_eulertop"))
        .args(args)
        .current_dir(dir)
        .env_remove("EULERTOP_PAPER")
        .output()
        .expect("the binary runs")
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

#[test]
fn verify_prove_and_audit_use_the_built_in_catalogue() {
    let dir = elsewhere("built-in");
    let o = run_in(&dir, &["verify", "--only", "Lemma 1", "--bits", "53,128"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert!(text(&o.stdout).contains("0 not as expected"));
    let o = run_in(&dir, &["prove", "bg.dlmf-22.6.1.sn-cn"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let o = run_in(&dir, &["audit", "bg.dlmf-22.6.1.sn-cn", "--bits", "64,128"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    // nothing was written where they ran
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_example_catalogue_verifies() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/dlmf-jacobi");
    let dir = elsewhere("example");
    let o = run_in(
        &dir,
        &[
            "verify",
            "--catalogue",
            examples.to_str().unwrap(),
            "--jobs",
            "1",
        ],
    );
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}{}",
        text(&o.stdout),
        text(&o.stderr)
    );
    assert!(text(&o.stdout).contains("0 not as expected"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn report_outside_the_repository_skips_the_readme() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/dlmf-jacobi");
    let dir = elsewhere("report");
    let args = [
        "report",
        "--catalogue",
        examples.to_str().unwrap(),
        "--jobs",
        "1",
    ];
    let o = run_in(&dir, &args);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let index = std::fs::read_to_string(dir.join("reports/README.md")).unwrap();
    assert!(
        index
            .starts_with("# Verification report: Reinhardt, Walker, *Jacobian Elliptic Functions*")
    );
    assert!(dir.join("reports/proofs/22-6.md").exists());
    // the figures of the Euler-top model belong to its paper's report only
    assert!(
        dir.join("reports/figures/residuals-22.6-double-argument.svg")
            .exists()
    );
    assert!(!dir.join("reports/figures/orbits.svg").exists());
    assert!(!index.contains("orbits.svg"));
    assert!(!dir.join("README.md").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn init_starts_a_catalogue_that_verifies() {
    let dir = elsewhere("init");
    let o = run_in(&dir, &["init", "mine", "--title", "On squares"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let paper = std::fs::read_to_string(dir.join("mine/paper.toml")).unwrap();
    assert!(paper.contains("title = \"On squares\""));
    let o = run_in(&dir, &["verify", "--catalogue", "mine", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let verdicts: Vec<&str> = v["claims"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["verdict"].as_str().unwrap())
        .collect();
    assert_eq!(verdicts, ["proved", "refuted"]);
    // a second init overwrites nothing: one line, status 2, the files unchanged
    std::fs::write(dir.join("mine/claims.toml"), "# edited\n").unwrap();
    let o = run_in(&dir, &["init", "mine"]);
    assert_eq!(o.status.code(), Some(2));
    let err = text(&o.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("paper.toml: exists"), "{err}");
    assert_eq!(
        std::fs::read_to_string(dir.join("mine/paper.toml")).unwrap(),
        paper
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("mine/claims.toml")).unwrap(),
        "# edited\n"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
