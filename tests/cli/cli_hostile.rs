//! Hostile input to the command-line tool, one test per row of the robustness table:
//! every row ends with exit 0 and correct output, or exit 2 and one line naming the cause
//! on standard error (data errors: `file:line:col: message`, optionally followed by the
//! source excerpt and a caret line).  No row may panic, abort, or lose output with exit 0.

use std::io::{BufRead, BufReader, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// The outcome of one run.
struct Outcome {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_eulertop"))
}

fn run_in(dir: Option<&Path>, args: &[&str], stdin: &[u8], stdout: Stdio) -> Outcome {
    let mut cmd = bin();
    cmd.args(args)
        .stdin(Stdio::piped())
        .stdout(stdout)
        .stderr(Stdio::piped());
    if let Some(d) = dir {
        cmd.current_dir(d);
    }
    let mut child = cmd.spawn().expect("binary runs");
    let mut input = child.stdin.take().expect("stdin piped");
    // a closed stdin (the tool stopped reading early) is not an error of the test
    let _ = input.write_all(stdin);
    drop(input);
    let o = child.wait_with_output().expect("binary finishes");
    Outcome {
        code: o.status.code(),
        stdout: String::from_utf8_lossy(&o.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&o.stderr).into_owned(),
    }
}

fn run(args: &[&str]) -> Outcome {
    run_in(None, args, b"", Stdio::piped())
}

fn dev_full() -> Stdio {
    Stdio::from(
        std::fs::OpenOptions::new()
            .write(true)
            .open("/dev/full")
            .expect("/dev/full exists"),
    )
}

fn temp_dir(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("hostile-{name}"));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

fn catalogue(name: &str, text: &[u8]) -> PathBuf {
    let d = temp_dir(name);
    std::fs::write(d.join("t.toml"), text).expect("catalogue written");
    d
}

/// Exit 2 and exactly one line `eulertop: …` on standard error containing every needle.
fn assert_one_line_error(o: &Outcome, needles: &[&str], what: &str) {
    assert_eq!(o.code, Some(2), "{what}: exit status; stderr: {}", o.stderr);
    let lines: Vec<&str> = o.stderr.lines().collect();
    assert_eq!(lines.len(), 1, "{what}: not one line: {:?}", o.stderr);
    assert!(lines[0].starts_with("eulertop: "), "{what}: {}", lines[0]);
    for n in needles {
        assert!(lines[0].contains(n), "{what}: '{n}' not in: {}", lines[0]);
    }
}

/// Exit 2 with a data error: a first line `eulertop: FILE:LINE:COL: message` (line and
/// column from 1), optionally followed by the excerpt and a caret line.
fn assert_data_error(o: &Outcome, needles: &[&str], what: &str) {
    assert_eq!(o.code, Some(2), "{what}: exit status; stderr: {}", o.stderr);
    let lines: Vec<&str> = o.stderr.lines().collect();
    assert!(
        lines.len() == 1 || lines.len() == 3,
        "{what}: {:?}",
        o.stderr
    );
    let first = lines[0];
    assert!(!first.contains(":0:"), "{what}: position 0 in {first}");
    for n in needles {
        assert!(first.contains(n), "{what}: '{n}' not in: {first}");
    }
    if lines.len() == 3 {
        let pos = first.split(": ").nth(1).unwrap_or("");
        let nums: Vec<&str> = pos.rsplitn(3, ':').take(2).collect();
        assert!(
            nums.len() == 2 && nums.iter().all(|n| n.parse::<u32>().is_ok_and(|v| v > 0)),
            "{what}: no file:line:col in {first}"
        );
        assert!(!lines[1].trim().is_empty(), "{what}: empty excerpt");
        assert!(
            lines[2].trim().chars().all(|c| c == '^') && lines[2].contains('^'),
            "{what}: no caret line: {:?}",
            lines[2]
        );
    }
}

/// Not killed by a signal, no panic, and at most one line on standard error.
fn assert_no_crash(o: &Outcome, what: &str) {
    assert!(o.code.is_some(), "{what}: killed by a signal");
    assert_ne!(o.code, Some(101), "{what}: panicked: {}", o.stderr);
    assert!(!o.stderr.contains("panicked"), "{what}: {}", o.stderr);
    assert!(o.stderr.lines().count() <= 1, "{what}: {}", o.stderr);
}

fn wait_for(mut child: Child, secs: u64) -> Outcome {
    let start = Instant::now();
    loop {
        if let Some(_status) = child.try_wait().expect("wait") {
            let o = child.wait_with_output().expect("output");
            return Outcome {
                code: o.status.code(),
                stdout: String::from_utf8_lossy(&o.stdout).into_owned(),
                stderr: String::from_utf8_lossy(&o.stderr).into_owned(),
            };
        }
        if start.elapsed() > Duration::from_secs(secs) {
            let _ = child.kill();
            panic!("still running after {secs} s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Peak resident memory of a running process in kB (Linux), if readable.
fn peak_rss_kb(pid: u32) -> Option<u64> {
    let s = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let line = s.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

/// Reads `n` lines of a long run, checks its memory, closes the pipe: the run must
/// stop with exit 2 (the closed pipe) or quietly, and never panic.
fn stream_then_close(args: &[&str], n: usize) {
    let mut child = bin()
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let mut r = BufReader::new(child.stdout.take().expect("stdout piped"));
    let mut line = String::new();
    for j in 0..n {
        line.clear();
        r.read_line(&mut line).expect("read");
        assert_eq!(line.split_whitespace().count(), 3, "line {j}: {line:?}");
    }
    // the rows arrive while the run goes on, and memory does not grow with --steps
    if let Some(kb) = peak_rss_kb(child.id()) {
        assert!(kb < 64 * 1024, "{args:?}: peak RSS {kb} kB");
    }
    drop(r);
    let o = wait_for(child, 60);
    assert_no_crash(&o, &format!("{args:?}"));
    assert_eq!(o.code, Some(2), "{args:?}: {}", o.stderr);
}

// -- row 1: long flat chains ---------------------------------------------------------

#[test]
fn row01_long_flat_sum_in_eval() {
    let expr = format!("{}1", "1+".repeat(8400));
    let o = run(&["eval", &expr]);
    assert_no_crash(&o, "eval 1+1+…");
    if o.code == Some(0) {
        let v: f64 = o.stdout.trim().parse().expect("a number");
        assert_eq!(v, 8401.0);
    } else {
        assert_one_line_error(&o, &[], "eval 1+1+…");
    }
}

#[test]
fn row01_long_flat_sum_in_a_catalogue() {
    let lhs = format!("{}x", "x+".repeat(2999));
    let text = format!(
        "[[claim]]\nid = \"t.flat\"\nlocation = \"test\"\nprinted = 'x'\nkind = \"identity\"\n\
         environment = \"Section 2\"\nrole = \"statement\"\n\
         expect = \"holds\"\nvars = [[\"x\", \"uniform(1, 2)\"]]\nlhs = \"{lhs}\"\nrhs = \"3000*x\"\n"
    );
    let dir = catalogue("flat", text.as_bytes());
    let o = run(&[
        "verify",
        "--bits",
        "53",
        "--catalogue",
        dir.to_str().unwrap(),
    ]);
    assert!(o.code.is_some(), "verify killed by a signal: {}", o.stderr);
    if o.code == Some(2) {
        assert_data_error(&o, &["t.toml"], "flat chain in a catalogue");
    } else {
        assert_eq!(o.code, Some(0), "{}{}", o.stdout, o.stderr);
    }
}

// -- row 2: step and orbit stream their rows ------------------------------------------

#[test]
fn row02_step_streams_a_billion_steps() {
    let base = ["--inertia", "3,2,1", "--h", "0.1", "--steps", "1000000000"];
    stream_then_close(&[&["step"], &base[..], &["1", "2", "3"]].concat(), 1000);
    stream_then_close(&[&["orbit"], &base[..], &["1", "2", "3"]].concat(), 1000);
}

#[test]
fn row02_steps_at_usize_max_never_panic() {
    let args = [
        "--inertia",
        "3,2,1",
        "--h",
        "0.1",
        "--steps",
        "18446744073709551615",
        "1",
        "2",
        "3",
    ];
    stream_then_close(&[&["step"], &args[..]].concat(), 5);
    stream_then_close(&[&["orbit"], &args[..]].concat(), 5);
    // --svg keeps every row: refused before anything is computed
    let mut svg = vec!["orbit", "--svg", "unused.svg"];
    svg.extend_from_slice(&args);
    let o = run(&svg);
    assert_one_line_error(
        &o,
        &["--svg", "--steps"],
        "orbit --svg with usize::MAX steps",
    );
}

// -- rows 3 and 4: writes to a full disk or a closed pipe -----------------------------

#[test]
fn row03_eval_to_a_full_disk() {
    let o = run_in(None, &["eval", "1"], b"", dev_full());
    assert_one_line_error(&o, &["standard output", "No space"], "eval 1 >/dev/full");
}

#[test]
fn row03_verify_json_into_head() {
    // Section 5's report (about 200 KB of JSON) is larger than a pipe's buffer, so the
    // writes after the reader has gone fail
    let mut child = bin()
        .args([
            "verify", "--format", "json", "--bits", "53", "--only", "sec5",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let mut r = BufReader::new(child.stdout.take().expect("stdout piped"));
    let mut line = String::new();
    r.read_line(&mut line).expect("read");
    assert_eq!(line.trim(), "{");
    drop(r);
    let o = wait_for(child, 120);
    assert_no_crash(&o, "verify --format json | head -1");
    assert_eq!(o.code, Some(2), "{}", o.stderr);
}

#[test]
fn row04_step_and_orbit_to_a_full_disk() {
    let step = [
        "step",
        "--inertia",
        "3,2,1",
        "--h",
        "0.1",
        "--steps",
        "20",
        "1",
        "2",
        "3",
    ];
    let o = run_in(None, &step, b"", dev_full());
    assert_one_line_error(&o, &["standard output", "No space"], "step >/dev/full");
    let mut orbit = step.to_vec();
    orbit[0] = "orbit";
    let o = run_in(None, &orbit, b"", dev_full());
    assert_one_line_error(&o, &["standard output", "No space"], "orbit >/dev/full");
    for opt in ["--csv", "--svg"] {
        let mut a = orbit.clone();
        a.extend_from_slice(&[opt, "/dev/full"]);
        let o = run(&a);
        assert_one_line_error(&o, &["/dev/full", "No space"], opt);
    }
}

// -- rows 5 and 6: the real cause of an out-of-range start point ----------------------

#[test]
fn row05_overflow_and_underflow_of_m2() {
    for cmd in ["orbit", "step"] {
        let o = run(&[
            cmd,
            "--inertia",
            "3,2,1",
            "--h",
            "0.1",
            "1e200",
            "1e200",
            "1e200",
        ]);
        assert_one_line_error(&o, &["M²", "overflows", "53 bits"], cmd);
        let o = run(&[
            cmd,
            "--inertia",
            "3,2,1",
            "--h",
            "0.1",
            "1e-200",
            "1e-200",
            "1e-200",
        ]);
        assert_one_line_error(&o, &["M²", "underflows"], cmd);
        assert!(!o.stderr.contains("M = 0"), "{}", o.stderr);
    }
    // at 256 bits (MPFR) the same start points are fine, and |M| is preserved
    let o = run(&[
        "step",
        "--bits",
        "256",
        "--inertia",
        "3,2,1",
        "--h",
        "1e-201",
        "1e200",
        "1e200",
        "1e200",
    ]);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    let m: Vec<f64> = o
        .stdout
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    let norm = m.iter().map(|x| (x / 1e200).powi(2)).sum::<f64>().sqrt();
    assert!((norm - 3f64.sqrt()).abs() < 1e-12, "{m:?}");
}

#[test]
fn row06_modulus_that_cannot_be_formed() {
    for cmd in ["orbit", "step"] {
        let o = run(&[
            cmd,
            "--inertia",
            "1e308,2,1",
            "--h",
            "0.1",
            "--steps",
            "3",
            "1",
            "2",
            "3",
        ]);
        assert_one_line_error(&o, &["modulus k cannot be formed", "1e308,2,1"], cmd);
        assert!(o.stdout.is_empty(), "{cmd}: {}", o.stdout);
    }
}

// -- row 7: undefined names and recursion are load errors -----------------------------

const CLAIM_HEAD: &str = "[[claim]]\nid = \"t.c\"\nlocation = \"test\"\nprinted = 'x'\n\
    environment = \"Section 2\"\nrole = \"statement\"\n\
    kind = \"identity\"\nexpect = \"holds\"\nvars = [[\"x\", \"uniform(1, 2)\"]]\n";

#[test]
fn row07_undefined_scale_name_is_a_load_error() {
    let text = format!("{CLAIM_HEAD}lhs = \"x\"\nrhs = \"x\"\nscale = \"Mzz\"\n");
    let dir = catalogue("scale", text.as_bytes());
    let o = run(&[
        "verify",
        "--bits",
        "53",
        "--catalogue",
        dir.to_str().unwrap(),
    ]);
    assert_data_error(&o, &["t.toml:", "Mzz"], "scale = Mzz");
}

#[test]
fn row07_recursive_definition_is_a_load_error() {
    let text = format!(
        "[[claim]]\nid = \"t.f\"\nlocation = \"test\"\nprinted = 'f'\nkind = \"definition\"\n\
         environment = \"Section 2\"\nrole = \"definition\"\n\
         define = '''f(M) = f(M)'''\n\n{CLAIM_HEAD}lhs = \"f(x)\"\nrhs = \"x\"\n"
    );
    let dir = catalogue("recursion", text.as_bytes());
    let o = run(&[
        "verify",
        "--bits",
        "53",
        "--catalogue",
        dir.to_str().unwrap(),
    ]);
    assert_data_error(&o, &["t.toml:", "recursi"], "f(M) = f(M)");
    assert!(o.stderr.matches("in function").count() <= 1, "{}", o.stderr);
}

// -- row 8: overflow is named as overflow ---------------------------------------------

#[test]
fn row08_overflow_is_not_called_malformed() {
    let o = run_in(None, &["jacobi"], b"1e309 0.5\n", Stdio::piped());
    assert_one_line_error(&o, &["<stdin>:1:1"], "jacobi 1e309");
    assert!(!o.stderr.contains("malformed"), "{}", o.stderr);
}

#[test]
fn row08_a_huge_sum_bound_is_named_too_large() {
    let o = run(&["eval", "sum(k,1,1e30,k)"]);
    assert_one_line_error(&o, &["1e30", "too large"], "sum(k,1,1e30,k)");
    assert!(!o.stderr.contains("expected an integer"), "{}", o.stderr);
}

// -- row 9: jacobi's stdin: invalid UTF-8 and huge lines ------------------------------

#[test]
fn row09_non_utf8_and_huge_lines() {
    let o = run_in(None, &["jacobi"], b"0.5 0.5\n0.5 \xff\n", Stdio::piped());
    assert_one_line_error(&o, &["<stdin>:2:"], "non-UTF-8 line");
    let mut big = b"0.5 0.5\n".to_vec();
    big.extend(std::iter::repeat_n(b'x', 5 << 20));
    big.push(b'\n');
    let o = run_in(None, &["jacobi"], &big, Stdio::piped());
    assert_one_line_error(&o, &["<stdin>:2:"], "5 MB line");
    assert!(o.stderr.len() < 400, "message of {} bytes", o.stderr.len());
}

// -- row 10: --jobs is bounded --------------------------------------------------------

#[test]
fn row10_jobs_bounded() {
    let start = Instant::now();
    let o = run(&["verify", "--jobs", "100000", "--only", "sec2"]);
    assert_one_line_error(&o, &["--jobs", "100000"], "verify --jobs 100000");
    assert!(start.elapsed() < Duration::from_secs(10));
    let o = run(&["report", "--jobs", "0", "--out", "unused"]);
    assert_one_line_error(&o, &["--jobs"], "report --jobs 0");
}

// -- row 11: report checks its arguments before writing -------------------------------

#[test]
fn row11_report_outside_the_repository() {
    // without --readme, a directory without README.md: the pages are written, the README
    // skipped without an error
    let dir = temp_dir("report-outside");
    let cat = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/dlmf-jacobi");
    let args = [
        "report",
        "--catalogue",
        cat.to_str().unwrap(),
        "--out",
        "out",
    ];
    let o = run_in(Some(&dir), &args, b"", Stdio::piped());
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    assert!(dir.join("out/README.md").exists());
    assert!(!dir.join("README.md").exists());
    // a README named by --readme must exist: checked before anything is written
    let _ = std::fs::remove_dir_all(dir.join("out"));
    let mut named = args.to_vec();
    named.extend(["--readme", "README.md"]);
    let o = run_in(Some(&dir), &named, b"", Stdio::piped());
    assert_one_line_error(&o, &["--readme", "README.md"], "report without README");
    assert!(
        !dir.join("out").exists(),
        "reports written before the check"
    );
}

#[test]
fn row11_report_out_empty_or_onto_the_readme() {
    let dir = temp_dir("report-out");
    let readme = "# r\n<!-- verdicts -->\nold\n<!-- /verdicts -->\n";
    std::fs::write(dir.join("README.md"), readme).unwrap();
    let cat = Path::new(env!("CARGO_MANIFEST_DIR")).join("identities");
    for out in ["", "."] {
        let args = ["report", "--catalogue", cat.to_str().unwrap(), "--out", out];
        let o = run_in(Some(&dir), &args, b"", Stdio::piped());
        assert_one_line_error(&o, &["--out"], &format!("report --out '{out}'"));
        let now = std::fs::read_to_string(dir.join("README.md")).unwrap();
        assert_eq!(now, readme, "README.md changed");
        assert!(
            !dir.join("errata.md").exists(),
            "reports written into --out '{out}'"
        );
    }
}

// -- row 12: empty catalogues ---------------------------------------------------------

#[test]
fn row12_empty_catalogue() {
    let empty = temp_dir("empty");
    let o = run(&["verify", "--catalogue", empty.to_str().unwrap()]);
    assert_one_line_error(&o, &[], "empty directory");
    assert!(!o.stderr.contains("no claim matches ''"), "{}", o.stderr);
    let dir = catalogue("empty-file", b"");
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert_one_line_error(&o, &[], "empty file");
    assert!(!o.stderr.contains("no claim matches ''"), "{}", o.stderr);
}

// -- row 13: catalogue errors without a position --------------------------------------

#[test]
fn row13_errors_without_position_have_no_empty_excerpt() {
    let o = run(&["verify", "--catalogue", "/nonexistent"]);
    assert_one_line_error(&o, &["/nonexistent"], "missing catalogue");
    assert!(!o.stderr.contains(":0:0:"), "{}", o.stderr);
    let dir = catalogue("non-utf8", b"[[claim]]\nid = \"\xff\xfe\"\n");
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert_data_error(&o, &["t.toml"], "non-UTF-8 catalogue");
    let text = format!("{CLAIM_HEAD}domain = \"nosuch\"\nlhs = \"x\"\nrhs = \"x\"\n");
    let dir = catalogue("domain", text.as_bytes());
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert_data_error(&o, &["t.toml:", "nosuch"], "unknown domain");
}

// -- row 14: malformed command lines -------------------------------------------------

/// A malformed command line is a usage error on one line that names the cause (clap's
/// message with its continuation and tips); help and version still print in full.
#[test]
fn row14_usage_errors_are_one_line() {
    let o = run(&["verify", "--jobs", "abc"]);
    assert_one_line_error(&o, &["--jobs", "abc"], "malformed --jobs");
    let o = run(&["eval", "1", "--bits", "4294967296"]);
    assert_one_line_error(&o, &["--bits", "4294967296"], "--bits beyond u32");
    let o = run(&["step", "--h", "0.1", "1", "2", "3"]);
    assert_one_line_error(&o, &["required", "--inertia"], "missing --inertia");
    let o = run(&["frobnicate"]);
    assert_one_line_error(&o, &["frobnicate", "orbit"], "unknown command with a tip");
    let o = run(&["verify", "--nope"]);
    assert_one_line_error(&o, &["--nope"], "unknown option");
    let o = run(&["--help"]);
    assert_eq!(o.code, Some(0), "--help: {}", o.stderr);
    assert!(o.stdout.contains("Usage: eulertop"), "{}", o.stdout);
    let o = run(&[]);
    assert_eq!(o.code, Some(2), "no command: {}", o.stderr);
    assert!(o.stderr.contains("Usage: eulertop"), "{}", o.stderr);
}

// -- R2: every proof attempt has a budget ---------------------------------------------

/// A claim with the arithmetic-geometric mean written out as a `let` chain: twelve
/// nested square roots, whose norms the prover's square-root search multiplies out
/// (several GB in minutes without a budget); numerically it is verified at once.
fn agm_catalogue(name: &str) -> PathBuf {
    let n = 12;
    let mut lets = vec!["a0 = 1".to_string(), "b0 = sqrt(1 - k^2)".to_string()];
    for j in 1..=n {
        lets.push(format!("a{j} = (a{} + b{})/2", j - 1, j - 1));
        lets.push(format!("b{j} = sqrt(a{}*b{})", j - 1, j - 1));
    }
    // a_n² − b_n² = (a_{n−1} − b_{n−1})²/4 exactly
    let text = format!(
        "[[claim]]\nid = \"t.agm\"\nlocation = \"test\"\nprinted = 'x'\n\
         environment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\n\
         expect = \"holds\"\nvars = [[\"k\", \"uniform(0.1, 0.9)\"]]\n\
         let = '''\n{}\n'''\nlhs = \"a{n}^2 - b{n}^2\"\nrhs = \"(a{m} - b{m})^2/4\"\n",
        lets.join("\n"),
        m = n - 1
    );
    catalogue(name, text.as_bytes())
}

#[test]
fn r2_a_proof_stops_at_its_time_budget_and_keeps_the_numerical_verdict() {
    let dir = agm_catalogue("agm");
    let cat = dir.to_str().unwrap();
    let start = Instant::now();
    let child = bin()
        .args([
            "prove",
            "t.agm",
            "--catalogue",
            cat,
            "--proof-budget-ms",
            "1500",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let o = wait_for(child, 60);
    assert!(
        start.elapsed() < Duration::from_secs(30),
        "{:?}",
        start.elapsed()
    );
    assert!(
        o.stdout
            .contains("not proved: the proof exceeded its budget (1500 ms"),
        "{}{}",
        o.stdout,
        o.stderr
    );
    let child = bin()
        .args([
            "verify",
            "--catalogue",
            cat,
            "--bits",
            "53,128",
            "--format",
            "json",
            "--proof-budget-ms",
            "1500",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let o = wait_for(child, 60);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    let v: serde_json::Value = serde_json::from_str(&o.stdout).expect("JSON");
    let c = &v["claims"][0];
    assert_eq!(c["verdict"], "holds", "{c}");
    assert!(
        c.to_string().contains("exceeded its budget"),
        "no budget reason in {c}"
    );
}

#[test]
fn r2_a_memory_ceiling_stops_the_proof() {
    let dir = agm_catalogue("agm-memory");
    let child = bin()
        .args([
            "prove",
            "t.agm",
            "--catalogue",
            dir.to_str().unwrap(),
            "--proof-memory-mb",
            "64",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let o = wait_for(child, 60);
    assert!(
        o.stdout.contains("exceeded its budget") && o.stdout.contains("MiB"),
        "{}{}",
        o.stdout,
        o.stderr
    );
}

#[test]
fn r2_the_time_budget_applies_to_catalogue_proofs() {
    // this proof takes tens of milliseconds: one millisecond is not enough, and the
    // claim keeps its numerical verdict
    let o = run(&[
        "verify",
        "--only",
        "sec4.prop3.constructed.poisson",
        "--bits",
        "53,128",
        "--format",
        "json",
        "--proof-budget-ms",
        "1",
    ]);
    let v: serde_json::Value = serde_json::from_str(&o.stdout).expect("JSON");
    let c = &v["claims"][0];
    assert_eq!(c["verdict"], "holds", "{c}");
    assert!(c.to_string().contains("exceeded its budget (1 ms"), "{c}");
    for bad in [["--proof-budget-ms", "0"], ["--proof-memory-mb", "1"]] {
        let o = run(&["prove", "sec2.x", bad[0], bad[1]]);
        assert_one_line_error(&o, &[bad[0]], bad[0]);
    }
}

// -- H1, W4, W5, M10: sums and products ------------------------------------------------

#[test]
fn h1_nested_sums_are_bounded_in_all() {
    let start = Instant::now();
    let o = run(&["eval", "sum(k,1,100000,sum(j,1,100000,j))"]);
    assert!(start.elapsed() < Duration::from_secs(20));
    assert_one_line_error(&o, &["nested", "10000000000", "1000000"], "nested sums");
    // through a function of a claim too
    let text = format!(
        "{CLAIM_HEAD}let = '''\nf(a) = sum(j, 1, 100000, a*j)\n'''\n\
         lhs = \"sum(k, 1, 100000, f(k))\"\nrhs = \"x\"\n"
    );
    let dir = catalogue("nested-sum", text.as_bytes());
    let start = Instant::now();
    let o = run(&[
        "verify",
        "--bits",
        "53",
        "--catalogue",
        dir.to_str().unwrap(),
    ]);
    assert!(start.elapsed() < Duration::from_secs(30));
    assert_ne!(o.code, Some(0), "{}", o.stdout);
    assert!(o.stdout.contains("nested sums"), "{}{}", o.stdout, o.stderr);
    // within the bound: Σ_{k=1}^{1000} Σ_{j=1}^{1000} 1 = 10⁶
    let o = run(&["eval", "sum(k,1,1000,sum(j,1,1000,1))"]);
    assert_eq!(
        o.stdout.trim().parse::<f64>().ok(),
        Some(1e6),
        "{}",
        o.stderr
    );
}

#[test]
fn w5_the_term_limit_is_exact_and_m10_names_prod() {
    let o = run(&["eval", "sum(k,1,100001,1)"]);
    assert_one_line_error(&o, &["sum", "100001 terms", "100000"], "100001 terms");
    let o = run(&["eval", "sum(k,1,100000,1)"]);
    assert_eq!(
        o.stdout.trim().parse::<f64>().ok(),
        Some(1e5),
        "{}",
        o.stderr
    );
    let o = run(&["eval", "prod(k,1,1000000,1)"]);
    assert_one_line_error(&o, &["prod range"], "prod of 10⁶ terms");
    assert!(!o.stderr.contains("sum"), "{}", o.stderr);
}

#[test]
fn w4_a_sum_has_the_type_of_its_body() {
    // Σ_{k=1}^{3} (k, k, k) = (6, 6, 6)
    let o = run(&["eval", "sum(k,1,3,vec(k,k,k))"]);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    let v: Vec<f64> = o
        .stdout
        .trim()
        .trim_matches(['[', ']'])
        .split(',')
        .map(|x| x.trim().parse().unwrap())
        .collect();
    assert_eq!(v, vec![6.0, 6.0, 6.0]);
    // an empty sum of vectors is the zero vector: adding a vector to it works
    let o = run(&["eval", "sum(k,1,0,vec(k,k,k)) + vec(1,2,3)"]);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    assert!(o.stdout.starts_with('['), "{}", o.stdout);
}

// -- H2, R1: only regular files of bounded size are read ------------------------------

#[test]
fn h2_a_fifo_or_device_is_not_a_catalogue_file() {
    let dir = temp_dir("fifo");
    let fifo = dir.join("a.toml");
    let made = Command::new("mkfifo").arg(&fifo).status();
    if made.is_ok_and(|s| s.success()) {
        let child = bin()
            .args(["verify", "--catalogue", dir.to_str().unwrap()])
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("binary runs");
        let o = wait_for(child, 20);
        assert_one_line_error(&o, &["a.toml", "not a regular file", "FIFO"], "FIFO");
    }
    let dir = temp_dir("device");
    std::os::unix::fs::symlink("/dev/zero", dir.join("a.toml")).expect("symlink");
    let child = bin()
        .args(["verify", "--catalogue", dir.to_str().unwrap()])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let o = wait_for(child, 20);
    assert_one_line_error(&o, &["a.toml", "not a regular file"], "/dev/zero");
}

#[test]
fn r1_files_are_refused_above_their_size_limit() {
    let dir = temp_dir("big");
    // a sparse file of 17 MiB: refused before a byte is read
    let f = std::fs::File::create(dir.join("a.toml")).unwrap();
    f.set_len(17 << 20).unwrap();
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert_one_line_error(&o, &["a.toml", "above the limit", "16 MiB"], "17 MiB file");
    let child = bin()
        .args(["report", "--readme", "/dev/zero", "--out", "unused"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("binary runs");
    let o = wait_for(child, 20);
    assert_one_line_error(
        &o,
        &["--readme", "not a regular file"],
        "--readme /dev/zero",
    );
    let o = run(&[
        "report",
        "--readme",
        dir.join("a.toml").to_str().unwrap(),
        "--out",
        "unused",
    ]);
    assert_one_line_error(&o, &["--readme", "above the limit"], "--readme 17 MiB");
}

#[test]
fn m21_an_unreadable_paper_source_is_an_error() {
    let mut cmd = bin();
    cmd.args(["verify", "--coverage", "--only", "sec2.ET"])
        .env("EULERTOP_PAPER", "/nonexistent/paper.tex")
        .current_dir(env!("CARGO_MANIFEST_DIR"));
    let o = cmd.output().expect("runs");
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("EULERTOP_PAPER=/nonexistent/paper.tex"),
        "{err}"
    );
}

// -- L1, M25: a closed or full standard output is reported ----------------------------

/// Runs the binary with standard output closed (`>&-`).
fn run_stdout_closed(args: &[&str], stdin: &[u8]) -> Outcome {
    use std::os::unix::process::CommandExt;
    let mut cmd = bin();
    cmd.args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    // SAFETY: close(2) is async-signal-safe; it runs in the child before exec.
    unsafe {
        cmd.pre_exec(|| {
            libc::close(1);
            Ok(())
        });
    }
    let mut child = cmd.spawn().expect("binary runs");
    let mut input = child.stdin.take().expect("stdin piped");
    let _ = input.write_all(stdin);
    drop(input);
    let o = child.wait_with_output().expect("binary finishes");
    Outcome {
        code: o.status.code(),
        stdout: String::new(),
        stderr: String::from_utf8_lossy(&o.stderr).into_owned(),
    }
}

#[test]
fn l1_a_closed_standard_output_is_an_error() {
    let cases: [(&[&str], &[u8]); 8] = [
        (
            &["step", "--inertia", "3,2,1", "--h", "0.1", "1", "2", "3"],
            b"",
        ),
        (&["jacobi"], b"0.5 0.5\n"),
        (&["eval", "1"], b""),
        (&["verify", "--only", "sec2.ET", "--bits", "53"], b""),
        (
            &["orbit", "--inertia", "3,2,1", "--h", "0.1", "1", "2", "3"],
            b"",
        ),
        (&["prove", "sec2.ET-v.printed"], b""),
        (&["audit", "sec2.ET-v.printed", "--bits", "64,128"], b""),
        (&["--version"], b""),
    ];
    for (args, input) in cases {
        let o = run_stdout_closed(args, input);
        assert_one_line_error(&o, &["standard output", "closed"], &format!("{args:?} >&-"));
    }
}

#[test]
fn m25_help_and_version_to_a_full_disk() {
    for args in [
        &["--help"][..],
        &["--version"],
        &["help", "step"],
        &["step", "--help"],
    ] {
        let o = run_in(None, args, b"", dev_full());
        assert_one_line_error(&o, &["standard output", "No space"], &format!("{args:?}"));
    }
}

// -- L2: one file for two outputs -----------------------------------------------------

#[test]
fn l2_csv_and_svg_on_one_file_are_refused() {
    let dir = temp_dir("same-out");
    let base = ["orbit", "--inertia", "3,2,1", "--h", "0.1", "--steps", "5"];
    for (csv, svg) in [("same.out", "same.out"), ("same.out", "./same.out")] {
        let mut a = base.to_vec();
        a.extend_from_slice(&["--csv", csv, "--svg", svg, "1", "2", "3"]);
        let o = run_in(Some(&dir), &a, b"", Stdio::piped());
        assert_one_line_error(
            &o,
            &["--csv", "--svg", "same file"],
            &format!("{csv} {svg}"),
        );
        assert!(!dir.join("same.out").exists(), "written before the check");
    }
}

// -- L3, M19: the certificate ---------------------------------------------------------

#[test]
fn l3_no_stale_certificate_and_m19_the_path_is_checked_first() {
    let dir = agm_catalogue("stale-cert");
    let cert = dir.join("c.py");
    std::fs::write(&cert, "# an older certificate\n").unwrap();
    let o = run(&[
        "prove",
        "t.agm",
        "--catalogue",
        dir.to_str().unwrap(),
        "--proof-budget-ms",
        "200",
        "--certificate",
        cert.to_str().unwrap(),
    ]);
    assert_eq!(o.code, Some(1), "{}", o.stderr);
    assert!(!cert.exists(), "the older certificate is still there");
    assert_eq!(o.stderr.lines().count(), 1, "{}", o.stderr);
    assert!(
        o.stderr.contains("no certificate written") && o.stderr.contains("removed"),
        "{}",
        o.stderr
    );
    for bad in ["", "/nonexistent/dir/c.py"] {
        let start = Instant::now();
        let o = run(&[
            "prove",
            "sec4.prop3.constructed.poisson",
            "--certificate",
            bad,
        ]);
        assert_one_line_error(&o, &["--certificate"], &format!("--certificate '{bad}'"));
        assert!(start.elapsed() < Duration::from_secs(5));
    }
}

// -- L4, M20: report replaces the pages of an earlier report --------------------------

fn small_catalogue(name: &str) -> PathBuf {
    let text = format!("{CLAIM_HEAD}lhs = \"x + x\"\nrhs = \"2*x\"\n");
    catalogue(name, text.as_bytes())
}

#[test]
fn l4_report_removes_the_pages_of_an_earlier_report() {
    let cat = small_catalogue("report-cat");
    let out = temp_dir("report-stale");
    std::fs::create_dir_all(out.join("proofs")).unwrap();
    let old = "# Section 9\n\n[← report index](README.md) · generated by `eulertop report`\n";
    std::fs::write(out.join("09-old.md"), old).unwrap();
    std::fs::write(out.join("proofs/lemma-9.md"), old).unwrap();
    std::fs::write(out.join("notes.md"), "# my notes\n").unwrap();
    let args = [
        "report",
        "--catalogue",
        cat.to_str().unwrap(),
        "--readme",
        "",
        "--out",
        out.to_str().unwrap(),
    ];
    let o = run(&args);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    assert!(!out.join("09-old.md").exists(), "old section page kept");
    assert!(
        !out.join("proofs/lemma-9.md").exists(),
        "old proof page kept"
    );
    assert!(
        out.join("notes.md").exists(),
        "a page not written by report removed"
    );
    assert!(out.join("README.md").exists());
}

#[test]
fn m20_report_names_the_file_in_the_way_and_changes_nothing() {
    let cat = small_catalogue("report-cat2");
    let out = temp_dir("report-blocked");
    std::fs::create_dir_all(out.join("README.md")).unwrap();
    std::fs::write(out.join("errata.md"), "old").unwrap();
    let args = [
        "report",
        "--catalogue",
        cat.to_str().unwrap(),
        "--readme",
        "",
        "--out",
        out.to_str().unwrap(),
    ];
    let o = run(&args);
    assert_one_line_error(&o, &["README.md", "directory"], "README.md a directory");
    assert_eq!(
        std::fs::read_to_string(out.join("errata.md")).unwrap(),
        "old"
    );
    // a dangling link where a page goes (the catalogue's one environment has a page
    // in proofs/; without a [paper] table of the model's paper, figures/ gets none)
    let out = temp_dir("report-dangling");
    std::os::unix::fs::symlink("/nonexistent/proofs", out.join("proofs")).unwrap();
    let mut a = args.to_vec();
    a[6] = out.to_str().unwrap();
    let o = run(&a);
    assert_one_line_error(&o, &["proofs", "symbolic link"], "dangling proofs");
    assert!(!out.join("README.md").exists(), "partial report written");
}

// -- W1, W2, W6, the rounded modulus: jacobi computes what was asked ------------------

fn jacobi_values(args: &[&str], input: &str) -> Vec<f64> {
    let mut a = vec!["jacobi"];
    a.extend_from_slice(args);
    let o = run_in(None, &a, input.as_bytes(), Stdio::piped());
    assert_eq!(o.code, Some(0), "{args:?} {input}: {}", o.stderr);
    o.stdout
        .split_whitespace()
        .map(|x| x.parse().expect("a number"))
        .collect()
}

#[test]
fn w1_cd_and_dc_at_k_equal_to_one_are_one() {
    // k = 1: cn = dn = sech u, so cd = dc = 1 wherever sech u underflows too
    assert_eq!(
        jacobi_values(&["--functions", "cd,dc"], "800 1\n"),
        [1.0, 1.0]
    );
    assert_eq!(
        jacobi_values(&["--functions", "cd,dc", "--parameter"], "800 1\n"),
        [1.0, 1.0]
    );
    assert_eq!(
        jacobi_values(&["--functions", "cd,dc", "--bits", "256"], "1e9 1\n"),
        [1.0, 1.0]
    );
    // and they are not next to a pole: no warning about their condition
    for input in ["800 1\n", "3 1\n"] {
        let o = run_in(
            None,
            &["jacobi", "--functions", "cd,dc"],
            input.as_bytes(),
            Stdio::piped(),
        );
        assert_eq!(o.code, Some(0), "{}", o.stderr);
        assert!(!o.stderr.contains("warning"), "{input}: {}", o.stderr);
    }
    for f in ["cd", "dc"] {
        let o = run(&["eval", &format!("{f}(1e3, 1)")]);
        assert_eq!(o.code, Some(0), "{}", o.stderr);
        assert_eq!(
            o.stdout.trim().parse::<f64>().ok(),
            Some(1.0),
            "{}",
            o.stdout
        );
    }
    // nc = cosh u really overflows
    let o = run_in(
        None,
        &["jacobi", "--functions", "nc"],
        b"800 1\n",
        Stdio::piped(),
    );
    assert_one_line_error(&o, &["overflows"], "nc(800, 1)");
}

#[test]
fn w2_a_huge_modulus_with_a_tiny_argument() {
    // k = 1e200, u = 1e-300: k·u = 1e-100, so sn = u(1 + O(1e-200)), cn = dn = 1
    let v = jacobi_values(&[], "1e-300 1e200\n");
    assert!((v[0] / 1e-300 - 1.0).abs() < 1e-15, "{v:?}");
    assert_eq!(&v[1..], [1.0, 1.0]);
}

#[test]
fn w6_one_number_grammar_everywhere() {
    for bits in ["53", "256"] {
        let o = run_in(
            None,
            &["jacobi", "--bits", bits],
            b"1_000 0.8\n",
            Stdio::piped(),
        );
        assert_one_line_error(
            &o,
            &["malformed u", "1_000"],
            &format!("jacobi --bits {bits}"),
        );
        let o = run(&[
            "step",
            "--bits",
            bits,
            "--inertia",
            "3,2,1",
            "--h",
            "0.1",
            "1_0",
            "1",
            "1",
        ]);
        assert_one_line_error(&o, &["1_0"], &format!("step --bits {bits}"));
        for bad in ["inf", "nan", "0x10", "1e", "--1"] {
            let input = format!("{bad} 0.5\n");
            let o = run_in(
                None,
                &["jacobi", "--bits", bits],
                input.as_bytes(),
                Stdio::piped(),
            );
            assert_one_line_error(&o, &["malformed u"], &format!("{bad} at {bits} bits"));
        }
    }
    let o = run(&["eval", "1_000"]);
    assert_eq!(o.code, Some(2), "{}", o.stdout);
}

#[test]
fn a_modulus_rounded_to_one_is_refused() {
    let o = run_in(
        None,
        &["jacobi"],
        b"100 0.99999999999999999999999\n",
        Stdio::piped(),
    );
    assert_one_line_error(
        &o,
        &["<stdin>:1:5", "rounds to 1", "53 bits"],
        "k = 1 - 1e-23",
    );
    // at 128 bits k < 1: k' = √(1 − k²) ≈ 4.5e-12, K ≈ ln(4/k') ≈ 27.5, so u = 100 is
    // a few quarter periods and cn is not sech(100) = 7.4e-44
    let v = jacobi_values(&["--bits", "128"], "100 0.99999999999999999999999\n");
    assert!(v[1].abs() > 1e-20, "{v:?}");
    // k given as exactly 1 in another spelling is fine
    let v = jacobi_values(&["--functions", "cn"], "1 1.000\n");
    assert!((v[0] - 1.0 / 1f64.cosh()).abs() < 1e-15, "{v:?}");
}

// -- M1–M3, M5–M7: jacobi's messages --------------------------------------------------

#[test]
fn m1_m2_m3_messages_name_the_input() {
    let o = run_in(
        None,
        &["jacobi", "--parameter"],
        b"0.5 1e300\n",
        Stdio::piped(),
    );
    assert_one_line_error(&o, &["given u = 5e-1"], "M1");
    let o = run_in(
        None,
        &["jacobi", "--functions", "ns"],
        b"1e-400 0.5\n",
        Stdio::piped(),
    );
    assert_one_line_error(&o, &["u = 1e-400 underflows", "53 bits"], "M2");
    assert!(!o.stderr.contains("pole"), "{}", o.stderr);
    let o = run_in(
        None,
        &["jacobi", "--bits", "256"],
        b"1e999999999999 1\n",
        Stdio::piped(),
    );
    assert_one_line_error(&o, &["overflows at 256 bits"], "M3");
    assert!(!o.stderr.contains("f64"), "{}", o.stderr);
}

#[test]
fn m5_m6_m7_positions_control_characters_and_standard_output() {
    let o = run_in(None, &["jacobi"], b"0.5 0.5\n0.5 x\n", Stdio::piped());
    assert_one_line_error(&o, &["<stdin>:2:5:", "malformed modulus k 'x'"], "M5");
    let o = run_in(None, &["jacobi"], b"0.5 0.8\0\n", Stdio::piped());
    assert_one_line_error(&o, &["\\u{0}"], "M6 NUL");
    assert!(!o.stderr.contains('\0'), "{:?}", o.stderr);
    let o = run_in(None, &["jacobi"], b"0.5 0.8\x1b[31m\n", Stdio::piped());
    assert!(!o.stderr.contains('\x1b'), "{:?}", o.stderr);
    let o = run_in(None, &["jacobi"], b"0.5 0.5\n", dev_full());
    assert_one_line_error(&o, &["standard output", "No space"], "M7");
}

// -- W3, W7, X1: the language and the domain ------------------------------------------

#[test]
fn w3_the_determinant_of_a_two_by_two_literal() {
    // det [[1, 2], [3, 4]] = 1·4 − 2·3 = −2
    let o = run(&["eval", "re(det([[1,2],[3,4]]))"]);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    assert_eq!(
        o.stdout.trim().parse::<f64>().ok(),
        Some(-2.0),
        "{}",
        o.stdout
    );
    let text = format!("{CLAIM_HEAD}lhs = \"re(det([[x, 2], [3, 4]]))\"\nrhs = \"4*x - 6\"\n");
    let dir = catalogue("det2", text.as_bytes());
    let o = run(&[
        "verify",
        "--bits",
        "53,128",
        "--catalogue",
        dir.to_str().unwrap(),
    ]);
    assert!(o.code == Some(0) || o.code == Some(1), "{}", o.stderr);
    assert!(
        o.stdout.contains(" holds ") || o.stdout.contains(" proved "),
        "{}",
        o.stdout
    );
}

#[test]
fn w7_a_duplicate_parameter_is_a_load_error() {
    let text = format!("{CLAIM_HEAD}let = '''\ng(y, y) = y\n'''\nlhs = \"g(1, 2)\"\nrhs = \"2\"\n");
    let dir = catalogue("dup-param", text.as_bytes());
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert_data_error(&o, &["t.toml:", "duplicate parameter 'y'"], "g(y, y)");
}

#[test]
fn x1_an_unreachable_domain_is_an_error_naming_the_where() {
    let text = "[[claim]]\nid = \"t.c\"\nlocation = \"test\"\nprinted = 'x'\n\
        environment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\n\
        expect = \"holds\"\nvars = [[\"x\", \"uniform(0.1, 1)\"]]\nwhere = [\"x > 2\"]\n\
        lhs = \"x\"\nrhs = \"x\"\n";
    let dir = catalogue("unreachable", text.as_bytes());
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert_one_line_error(
        &o,
        &["t.toml", "t.c", "unreachable", "x > 2"],
        "where x > 2",
    );
}

// -- M4, M8, M9, M11, M18, M22, M24 and eval's output ---------------------------------

#[test]
fn m4_out_of_range_is_not_malformed() {
    let o = run(&["verify", "--bits", "99999999999999999999999"]);
    assert_one_line_error(&o, &["out of range"], "--bits 1e23");
    assert!(!o.stderr.contains("malformed"), "{}", o.stderr);
    let o = run(&["eval", "1e309"]);
    assert_one_line_error(&o, &["1e309", "out of range", "overflows"], "eval 1e309");
    let o = run(&["eval", "uniform(0, 1e309)"]);
    assert!(!o.stderr.contains("malformed"), "{}", o.stderr);
}

#[test]
fn m8_a_negative_precision_is_named() {
    for cmd in ["verify", "eval", "jacobi"] {
        let mut a = vec![cmd, "--bits", "-53"];
        if cmd == "eval" {
            a.push("1");
        }
        let o = run(&a);
        assert_one_line_error(&o, &["-53"], &format!("{cmd} --bits -53"));
        assert!(!o.stderr.contains("'-5'"), "{}", o.stderr);
    }
}

#[test]
fn m9_nesting_limit_is_stated_and_parentheses_count_once() {
    let deep = |n: usize| format!("{}1{}", "(".repeat(n), ")".repeat(n));
    let o = run(&["eval", &deep(150)]);
    assert_eq!(
        o.stdout.trim().parse::<f64>().ok(),
        Some(1.0),
        "{}",
        o.stderr
    );
    let o = run(&["eval", &deep(250)]);
    assert_eq!(o.code, Some(2));
    assert!(o.stderr.contains("more than 200 levels"), "{}", o.stderr);
    let o = run(&["eval", "--", &format!("{}1", "-".repeat(201))]);
    assert!(o.stderr.contains("more than 200 levels"), "{}", o.stderr);
}

#[test]
fn m11_m18_m22_messages_name_the_cause() {
    let o = run(&["eval", "sum(i,1,3,i)"]);
    assert!(o.stderr.contains("imaginary unit"), "{}", o.stderr);
    let o = run(&["eval", "step_gamma1(vec(0,0,0),0.1,3,2,1)"]);
    assert_one_line_error(&o, &["M = 0"], "M18");
    assert!(!o.stderr.contains("h too large"), "{}", o.stderr);
    let o = run(&["eval", "pi", "--set", "pi=3"]);
    assert_one_line_error(&o, &["pi", "constant"], "M22");
}

#[test]
fn m24_one_precision_range_and_eval_output() {
    // 2 bits: 0.3 rounds to 0.25 (binary 0.01)
    let o = run(&["eval", "--bits", "2", "0.3"]);
    assert_eq!(
        o.stdout.trim().parse::<f64>().ok(),
        Some(0.25),
        "{}",
        o.stderr
    );
    let o = run(&["eval", "--bits", "1", "0.3"]);
    assert_one_line_error(&o, &["2..=1048576"], "--bits 1");
    // 17 digits read back to the same double
    let o = run(&["eval", "0.1"]);
    assert_eq!(
        o.stdout.trim().parse::<f64>().ok(),
        Some(0.1),
        "{}",
        o.stdout
    );
    let o = run(&["eval", "1/3"]);
    assert_eq!(
        o.stdout.trim().parse::<f64>().ok(),
        Some(1.0 / 3.0),
        "{}",
        o.stdout
    );
    let o = run(&["eval", "cplx(1,-2)"]);
    assert!(
        o.stdout.contains(" - 2") && !o.stdout.contains("+ -"),
        "{}",
        o.stdout
    );
    let o = run(&["eval", "2i"]);
    assert!(o.stderr.contains("2*i"), "{}", o.stderr);
}

// -- M12, M23: catalogue values and text ----------------------------------------------

#[test]
fn m12_range_errors_point_at_the_field_and_read_well() {
    let text = format!("{CLAIM_HEAD}max_loss_bits = inf\nlhs = \"x\"\nrhs = \"x\"\n");
    let dir = catalogue("loss-inf", text.as_bytes());
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    // the field is on line 10 of the file, its value from column 17
    assert_data_error(
        &o,
        &["t.toml:10:17:", "finite", "inf"],
        "max_loss_bits = inf",
    );
    let asym = "[[claim]]\nid = \"t.a\"\nlocation = \"test\"\nprinted = 'x'\n\
        environment = \"Section 2\"\nrole = \"statement\"\nkind = \"asymptotic\"\n\
        expect = \"holds\"\nvars = [[\"x\", \"uniform(1, 2)\"]]\nvar = \"h\"\n\
        expr = \"h\"\norder = 1\nh0 = 1e-320\n";
    let dir = catalogue("h0-tiny", asym.as_bytes());
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert_eq!(o.code, Some(2), "{}", o.stderr);
    assert!(o.stderr.len() < 400, "{}", o.stderr);
    assert!(o.stderr.contains("h0"), "{}", o.stderr);
}

#[test]
fn m23_control_characters_of_a_location_are_escaped() {
    let text = "[[claim]]\nid = \"t.c\"\nlocation = \"loc\\u001b[31mred\"\nprinted = 'x'\n\
        environment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\n\
        expect = \"holds\"\nvars = [[\"x\", \"uniform(1, 2)\"]]\nlhs = \"x\"\nrhs = \"x\"\n";
    let dir = catalogue("escape", text.as_bytes());
    let o = run(&[
        "verify",
        "--bits",
        "53",
        "--catalogue",
        dir.to_str().unwrap(),
    ]);
    assert!(o.stdout.contains("loc\\u{1b}[31mred"), "{}", o.stdout);
    assert!(!o.stdout.contains('\x1b'), "{:?}", o.stdout);
}

// -- M17: orbit near the separatrix ---------------------------------------------------

#[test]
fn m17_an_iterate_without_a_phase_does_not_stop_the_orbit() {
    // M = (3, 1, √3) with inertia (3, 2, 1): 2E = 9/3 + 1/2 + 3 = 6.5, M² = 13, so
    // 2E/M² = 1/2 = 1/B: the start is on the separatrix to the precision of the input
    let dir = temp_dir("separatrix");
    let args = [
        "orbit",
        "--inertia",
        "3,2,1",
        "--h",
        "0.1",
        "--gamma",
        "1",
        "--steps",
        "200",
        "--csv",
        "o.csv",
        "3",
        "1",
        "1.7320508075688772",
    ];
    let o = run_in(Some(&dir), &args, b"", Stdio::piped());
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    assert_eq!(o.stdout.lines().count(), 200);
    // |M| is conserved by the map (the norm of every iterate stays √13)
    for line in o.stdout.lines() {
        let m: Vec<f64> = line
            .split_whitespace()
            .map(|x| x.parse().unwrap())
            .collect();
        let n = m.iter().map(|x| x * x).sum::<f64>();
        assert!((n - 13.0).abs() < 1e-9, "{line}");
    }
    if !o.stderr.is_empty() {
        assert_eq!(o.stderr.lines().count(), 1, "{}", o.stderr);
        assert!(o.stderr.contains("phase is undefined"), "{}", o.stderr);
    }
    let csv = std::fs::read_to_string(dir.join("o.csv")).unwrap();
    assert_eq!(csv.lines().count(), 202);
}

// -- R4: a negative modulus ------------------------------------------------------------

#[test]
fn r4_sn_of_a_negative_modulus_is_that_of_its_absolute_value() {
    // DLMF 22.17.1: sn, cn, dn depend on k² only
    let o = run(&[
        "eval",
        "sn(0.5,-0.3) - sn(0.5,0.3) + cd(1.2,-0.9) - cd(1.2,0.9)",
    ]);
    assert_eq!(
        o.stdout.trim().parse::<f64>().ok(),
        Some(0.0),
        "{}",
        o.stderr
    );
    let neg = jacobi_values(&["--bits", "128"], "0.5 -0.3\n");
    let pos = jacobi_values(&["--bits", "128"], "0.5 0.3\n");
    assert_eq!(neg, pos);
}

#[test]
fn a_literal_that_underflows_is_not_silently_zero() {
    let o = run(&["eval", "1.5e-324"]);
    assert_one_line_error(&o, &["1.5e-324", "underflows", "53 bits"], "eval 1.5e-324");
    // at 100 bits it is representable (MPFR's exponent range is far wider)
    let o = run(&["eval", "--bits", "100", "1.5e-324 * 1e324"]);
    let v: f64 = o.stdout.trim().parse().expect("a number");
    assert!((v - 1.5).abs() < 1e-15, "{v}");
    let o = run(&["eval", "0e5"]);
    assert_eq!(
        o.stdout.trim().parse::<f64>().ok(),
        Some(0.0),
        "{}",
        o.stderr
    );
}

// -- M16: a refutation judged on rungs below 128 bits ------------------------------------

#[test]
fn m16_a_refutation_below_128_bits_names_the_rungs_it_was_judged_on() {
    let o = run(&[
        "verify",
        "--bits",
        "53,64",
        "--only",
        "sec5.u0.printed",
        "--format",
        "json",
    ]);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    assert!(o.stdout.contains("\"refuted\""), "{}", o.stdout);
    assert!(
        o.stdout
            .contains("at every rung run (53, 64 bits; none of 128 bits or more)"),
        "{}",
        o.stdout
    );
    assert!(!o.stdout.contains("every rung ≥ 128 bits"), "{}", o.stdout);
}

#[test]
fn m16_audit_of_an_asymptotic_claim_explains_the_missing_fit() {
    let o = run(&["audit", "sec3.as.g1.printed", "--bits", "64,128"]);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    assert!(!o.stdout.contains("fewer than two rungs"), "{}", o.stdout);
    // the slopes stand under a slope header, never under "residual"
    let header = o.stdout.lines().nth(1).unwrap_or("");
    assert!(header.contains("slope in h"), "{}", o.stdout);
    assert!(!header.contains("residual"), "{}", o.stdout);
    assert!(!o.stdout.contains("fitted slope: n/a"), "{}", o.stdout);
    assert!(
        o.stdout.contains("slope in h: ") && o.stdout.contains("order of convergence in h"),
        "{}",
        o.stdout
    );
}

// -- M17: an orbit from a point whose modulus rounds to 1 ------------------------------

#[test]
fn m17_an_orbit_from_within_rounding_of_the_separatrix_runs() {
    for (bits, start) in [
        ("53", ["1e-10", "1", "1e-10"]),
        ("256", ["1e-40", "1", "1e-40"]),
        ("53", ["3", "1", "1.7320508075688772"]),
    ] {
        let mut args = vec![
            "orbit",
            "--inertia",
            "3,2,1",
            "--h",
            "0.1",
            "--gamma",
            "1",
            "--steps",
            "50",
            "--bits",
            bits,
        ];
        args.extend(start);
        let o = run(&args);
        assert_eq!(o.code, Some(0), "{args:?}: {}", o.stderr);
        assert!(
            !o.stderr.contains("outside [0, 1)"),
            "{args:?}: {}",
            o.stderr
        );
        assert_eq!(o.stdout.lines().count(), 50, "{args:?}: {}", o.stdout);
    }
}

// -- R2: a proof that must evaluate pi fails at once -------------------------------------

#[test]
fn r2_a_proof_that_evaluates_pi_fails_before_the_work() {
    let n = 12;
    let mut lets = vec!["a0 = 1".to_string(), "b0 = sqrt(1 - k^2)".to_string()];
    for j in 1..=n {
        lets.push(format!("a{j} = (a{} + b{})/2", j - 1, j - 1));
        lets.push(format!("b{j} = sqrt(a{}*b{})", j - 1, j - 1));
    }
    let text = format!(
        "[[claim]]\nid = \"t.pi\"\nlocation = \"test\"\nprinted = 'x'\n\
         environment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\n\
         expect = \"holds\"\nvars = [[\"k\", \"uniform(0.1, 0.9)\"]]\n\
         let = '''\n{}\n'''\nlhs = \"a{n}^2 - b{n}^2 + pi\"\nrhs = \"(a{m} - b{m})^2/4 + pi\"\n",
        lets.join("\n"),
        m = n - 1
    );
    let dir = catalogue("pi-fast", text.as_bytes());
    let start = Instant::now();
    let o = run(&["prove", "t.pi", "--catalogue", dir.to_str().unwrap()]);
    assert!(
        start.elapsed() < Duration::from_secs(5),
        "{:?}",
        start.elapsed()
    );
    assert!(
        o.stdout.contains("pi is not algebraic"),
        "{}{}",
        o.stdout,
        o.stderr
    );
}

// -- R4: second derivatives -------------------------------------------------------------

#[test]
fn r4_a_derivative_of_a_derivative_is_the_second_derivative() {
    // DLMF 22.13: sn'' = −(1 + k²) sn + 2k² sn³; at k = 0.5: −1.25 sn + 0.5 sn³
    for bits in ["53", "256"] {
        let o = run(&[
            "eval",
            "--bits",
            bits,
            "--set",
            "u=0.3",
            "d(d(sn(u,0.5),u),u) + 1.25*sn(u,0.5) - 0.5*sn(u,0.5)^3",
        ]);
        let v: f64 = o.stdout.trim().parse().unwrap_or(f64::NAN);
        assert!(v.abs() < 1e-14, "{bits}: {} {}", o.stdout, o.stderr);
    }
    // mixed partials: d/dy d/dx (x³y²) = 6x²y = 72 at (2, 3); of a vec3 component too
    let o = run(&["eval", "--set", "x=2", "--set", "y=3", "d(d(x^3*y^2,x),y)"]);
    assert_eq!(
        o.stdout.trim().parse::<f64>().ok(),
        Some(72.0),
        "{}",
        o.stderr
    );
    let o = run(&["eval", "--set", "M=vec(1,2,3)", "d(d(M[1]^2*M[2],M,1),M,2)"]);
    assert_eq!(
        o.stdout.trim().parse::<f64>().ok(),
        Some(2.0),
        "{}",
        o.stderr
    );
    // a third derivative is refused by its order
    let o = run(&["eval", "--set", "x=2", "d(d(d(x^3,x),x),x)"]);
    assert_one_line_error(&o, &["order 3"], "third derivative");
}

#[test]
fn r4_a_second_derivative_in_a_claim_is_checked_and_proved() {
    let claim = |id: &str, sign: &str| {
        format!(
            "[[claim]]\nid = \"{id}\"\nlocation = \"test\"\nprinted = 'x'\n\
             environment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\n\
             expect = \"holds\"\nvars = [[\"k\", \"uniform(0.1, 0.9)\"], [\"u\", \"uniform(0.2, 1.5)\"]]\n\
             lhs = \"d(d(sn(u, k), u), u)\"\nrhs = \"-(1 + k^2) * sn(u, k) {sign} 2 * k^2 * sn(u, k)^3\"\n\n"
        )
    };
    let text = claim("t.right", "+") + &claim("t.wrong", "-");
    let dir = catalogue("second-derivative", text.as_bytes());
    let o = run(&["prove", "t.right", "--catalogue", dir.to_str().unwrap()]);
    assert!(o.stdout.contains(": proved"), "{}{}", o.stdout, o.stderr);
    let o = run(&[
        "verify",
        "--catalogue",
        dir.to_str().unwrap(),
        "--format",
        "json",
    ]);
    assert_no_crash(&o, "verify");
    let verdict = |id: &str| {
        let at = o
            .stdout
            .find(&format!("\"{id}\""))
            .expect("claim in the json");
        let rest = &o.stdout[at..];
        let v = rest.find("\"verdict\"").expect("verdict");
        rest[v..].split('"').nth(3).unwrap_or("").to_string()
    };
    assert_eq!(verdict("t.right"), "proved", "{}", o.stdout);
    assert_eq!(verdict("t.wrong"), "refuted", "{}", o.stdout);
}

// -- M14: the excerpt of a parenthesised expression ---------------------------------------

#[test]
fn m14_the_excerpt_of_a_power_keeps_its_parenthesis() {
    let text = "[[claim]]\nid = \"t.pow\"\nlocation = \"test\"\nprinted = 'x'\n\
                environment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\n\
                expect = \"holds\"\nvars = [[\"x\", \"uniform(0.1, 1)\"]]\n\
                lhs = \"(1+x)^100000\"\nrhs = \"1\"\n";
    let dir = catalogue("m14", text.as_bytes());
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert!(o.stdout.contains("at '(1+x)^100000'"), "{}", o.stdout);
}

// -- R3: the prover's messages on false and on complex-argument claims -------------------

fn jacobi_claim(id: &str, expect: &str, vars: &str, lhs: &str, rhs: &str) -> String {
    format!(
        "[[claim]]\nid = \"{id}\"\nlocation = \"test\"\nprinted = 'x'\n\
         environment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\n\
         expect = \"{expect}\"\nvars = {vars}\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"\n\n"
    )
}

#[test]
fn r3_a_false_addition_formula_is_not_called_zero() {
    let uv =
        r#"[["k", "uniform(0.1, 0.9)"], ["u", "uniform(0.2, 1.5)"], ["v", "uniform(0.2, 1.5)"]]"#;
    let text = jacobi_claim(
        "t.cd",
        "refuted",
        uv,
        "cd(u + v, k)",
        "(cd(u,k)*cd(v,k) - (1-k^2)*sd(u,k)*nd(u,k)*sd(v,k)*nd(v,k)) / (1 + k^2*cd(u,k)^2*cd(v,k)^2)",
    ) + &jacobi_claim(
        "t.nd",
        "refuted",
        uv,
        "nd(u + v, k)",
        "(nd(u,k)*nd(v,k) + k^2*sd(u,k)*cd(u,k)*sd(v,k)*cd(v,k)) / (1 + k^2*sn(u,k)^2*sn(v,k)^2)",
    );
    let dir = catalogue("r3-addition", text.as_bytes());
    for id in ["t.cd", "t.nd"] {
        let o = run(&["prove", id, "--catalogue", dir.to_str().unwrap()]);
        let last = o.stdout.lines().last().unwrap_or("");
        assert!(
            last.starts_with("not proved"),
            "{id}: {}{}",
            o.stdout,
            o.stderr
        );
        assert!(!last.contains("vanishes numerically"), "{id}: {last}");
        assert!(last.contains("differ at domain point"), "{id}: {last}");
    }
}

#[test]
fn r3_claims_at_k_plus_i_k_prime_and_on_sd_are_proved() {
    let ku = r#"[["k", "uniform(0.1, 0.9)"], ["u", "uniform(-1.5, 1.5)"]]"#;
    let text = jacobi_claim(
        "t.kk",
        "holds",
        ku,
        "sn(u + K(k) + cplx(0,1)*K(sqrt(1-k^2)), k)",
        "dc(u,k)/k",
    ) + &jacobi_claim(
        "t.sd",
        "holds",
        ku,
        "sd(u,k)^2*(1-k^2)",
        "(1-k^2)*sn(u,k)^2/(1-k^2*sn(u,k)^2)",
    );
    let dir = catalogue("r3-kk-sd", text.as_bytes());
    for id in ["t.kk", "t.sd"] {
        let o = run(&["prove", id, "--catalogue", dir.to_str().unwrap()]);
        assert!(
            o.stdout.lines().last().unwrap_or("").ends_with(": proved"),
            "{id}: {}{}",
            o.stdout,
            o.stderr
        );
        assert!(!o.stdout.contains("internal inconsistency"), "{}", o.stdout);
        assert!(!o.stdout.contains("overflows"), "{}", o.stdout);
    }
}

// -- Whole-number options, sampled variables, output paths --------------------------------

#[test]
fn whole_number_options_name_a_negative_or_malformed_value() {
    let cases: [(&[&str], &[&str]); 6] = [
        (&["verify", "--seed", "-5"], &["--seed", "-5 is negative"]),
        (&["verify", "--jobs", "-1"], &["--jobs", "-1 is negative"]),
        (
            &["prove", "x", "--proof-budget-ms", "-1"],
            &["--proof-budget-ms", "negative"],
        ),
        (
            &[
                "step",
                "--inertia",
                "3,2,1",
                "--h",
                "0.1",
                "--steps",
                "1e3",
                "1",
                "1",
                "1",
            ],
            &["--steps", "'1e3' is not a whole number"],
        ),
        (
            &["eval", "--bits", "1.5", "1"],
            &["--bits", "not a whole number"],
        ),
        (
            &["eval", "--bits", "99999999999999999999", "1"],
            &["--bits", "too large"],
        ),
    ];
    for (args, needles) in cases {
        assert_one_line_error(&run(args), needles, &args.join(" "));
    }
    let dir = temp_dir("init-year");
    for year in ["-5", "99999"] {
        let target = dir.join(year);
        let o = run(&["init", target.to_str().unwrap(), "--year", year]);
        assert_one_line_error(&o, &["--year", year, "1000..=9999"], "init --year");
        assert!(
            !target.exists(),
            "init --year {year} wrote {}",
            target.display()
        );
    }
}

fn one_var_claim(vars: &str) -> String {
    format!(
        "[[claim]]\nid = \"t.v\"\nlocation = \"test\"\nprinted = 'x'\n\
         environment = \"Section 2\"\nrole = \"statement\"\nkind = \"identity\"\n\
         expect = \"holds\"\nvars = {vars}\nlhs = \"x\"\nrhs = \"x\"\n"
    )
}

#[test]
fn a_variable_sampled_twice_is_a_load_error() {
    let dir = catalogue(
        "sampled-twice",
        one_var_claim(r#"[["x", "uniform(0, 1)"], ["x", "uniform(2, 3)"]]"#).as_bytes(),
    );
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert_data_error(&o, &["t.toml:", "'x' is sampled twice"], "vars x twice");
}

#[test]
fn a_domain_that_cannot_be_sampled_stops_verify() {
    let dir = catalogue(
        "unsampleable",
        one_var_claim(r#"[["x", "uniform(1, 0)"]]"#).as_bytes(),
    );
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert_one_line_error(
        &o,
        &["claim t.v", "cannot be sampled", "uniform(1, 0)"],
        "uniform(1, 0)",
    );
    // a constraint that is not a condition is not a thin domain
    let text = one_var_claim(r#"[["x", "uniform(0, 1)"]]"#) + "where = [\"x\"]\n";
    let dir = catalogue("where-not-bool", text.as_bytes());
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert_one_line_error(
        &o,
        &["claim t.v", "cannot be sampled", "expected a bool"],
        "where = [\"x\"]",
    );
}

#[test]
fn output_paths_are_checked_before_the_work() {
    let dir = temp_dir("output-paths");
    let missing = dir.join("no-such-dir").join("x.svg");
    let o = run(&[
        "orbit",
        "--inertia",
        "3,2,1",
        "--h",
        "0.1",
        "--steps",
        "5",
        "--svg",
        missing.to_str().unwrap(),
        "1",
        "1",
        "1",
    ]);
    assert_one_line_error(&o, &["--svg", "no directory"], "orbit --svg into nowhere");
    assert!(
        o.stdout.is_empty(),
        "rows printed before the refusal: {}",
        o.stdout
    );
    // one file for the certificate and the Coq script: refused, nothing written
    let cat = catalogue(
        "cert-coq-same",
        one_var_claim(r#"[["x", "uniform(0, 1)"]]"#).as_bytes(),
    );
    let f = dir.join("c.out");
    let f = f.to_str().unwrap();
    let o = run(&[
        "prove",
        "t.v",
        "--catalogue",
        cat.to_str().unwrap(),
        "--certificate",
        f,
        "--coq",
        f,
    ]);
    assert_one_line_error(
        &o,
        &["--certificate", "--coq", "same file"],
        "one file twice",
    );
    assert!(!Path::new(f).exists(), "{f} written");
}

#[test]
fn a_derivative_component_is_named_in_words() {
    let o = run(&["eval", "--set", "x=1", "d(x^2, x, 2)"]);
    assert_one_line_error(&o, &["component 2 of a real variable"], "d(x^2, x, 2)");
    assert!(!o.stderr.contains("Some("), "{}", o.stderr);
    let o = run(&["eval", "--set", "M=vec(1,2,3)", "d(M[1], M, 4)"]);
    assert_one_line_error(&o, &["component 4", "1, 2 and 3"], "d(M[1], M, 4)");
}

#[test]
fn an_expression_may_start_with_a_minus_sign() {
    for (args, want) in [
        (&["eval", "-1"][..], -1.0),
        (&["eval", "-x^2", "--set", "x=3"][..], -9.0),
        (&["eval", "--bits", "64", "-2*3"][..], -6.0),
    ] {
        let o = run(args);
        assert_eq!(
            o.stdout.trim().parse::<f64>().ok(),
            Some(want),
            "{args:?}: {}",
            o.stderr
        );
    }
    // the absolute value of a negative zero is +0
    let o = run(&["eval", "abs(-0)"]);
    assert_eq!(o.code, Some(0), "{}", o.stderr);
    assert!(!o.stdout.starts_with('-'), "{}", o.stdout);
}

#[test]
fn randint_names_its_range_limit() {
    let dir = catalogue(
        "randint-wide",
        one_var_claim(r#"[["x", "randint(1, 1000000000000000000)"]]"#).as_bytes(),
    );
    let o = run(&["verify", "--catalogue", dir.to_str().unwrap()]);
    assert_one_line_error(
        &o,
        &["randint", "at most 10^12", "a = 1, b = 1000000000000000000"],
        "randint",
    );
}

#[test]
fn an_infinite_derivative_is_named_as_such() {
    for (expr, name) in [("d(sqrt(x), x)", "sqrt"), ("d(d(sqrt(x), x), x)", "sqrt")] {
        let o = run(&["eval", "--set", "x=0", expr]);
        assert_one_line_error(&o, &[&format!("derivative of {name}"), "not finite"], expr);
    }
    let o = run(&["eval", "--set", "x=1", "d(asin(x), x)"]);
    assert_one_line_error(&o, &["derivative of asin"], "d(asin(x), x) at 1");
}

#[test]
fn a_step_from_a_start_point_whose_m2_overflows_names_it() {
    for f in ["step_gamma1", "step_vm"] {
        let o = run(&["eval", &format!("{f}(vec(1e300,2,3), 0.1, 3, 2, 1)")]);
        assert_one_line_error(&o, &["M²", "overflows", "rescale M"], f);
        assert!(!o.stderr.contains("too large?"), "{}", o.stderr);
    }
}

#[test]
fn a_complex_argument_too_large_names_its_part() {
    let o = run(&["eval", "sn(cplx(1e300, 1), 0.5)"]);
    assert_one_line_error(&o, &["|Re u|/K", "Re u = 1e300"], "Re u huge");
    let o = run(&["eval", "sn(cplx(1, 1e300), 0.5)"]);
    assert_one_line_error(&o, &["|Im u|/K'", "Im u = 1e300"], "Im u huge");
    let o = run_in(
        None,
        &["jacobi", "--complex"],
        b"0.5 1e300 0.8\n",
        Stdio::piped(),
    );
    assert_data_error(&o, &["<stdin>:1:", "Im u = 1e300"], "jacobi --complex");
}
