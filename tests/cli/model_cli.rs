//! The `step` and `orbit` subcommands: output shape, agreement of `--matrix` with the
//! implicit γ_VM map, and one-line errors with exit status 2 on bad input.

use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let o = Command::new(env!("CARGO_BIN_EXE_eulertop"))
        .args(args)
        .output()
        .expect("binary runs");
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn parse_lines(s: &str) -> Vec<[f64; 3]> {
    s.lines()
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect()
}

#[test]
fn matrix_agrees_with_implicit_vm() {
    let base = ["step", "--inertia", "3,2,1", "--h", "0.1", "--steps", "5"];
    let (c1, o1, _) = run(&[&base[..], &["--gamma", "vm", "0.3", "-0.7", "1.1"]].concat());
    let (c2, o2, _) = run(&[&base[..], &["--matrix", "0.3", "-0.7", "1.1"]].concat());
    assert_eq!((c1, c2), (0, 0));
    let (a, b) = (parse_lines(&o1), parse_lines(&o2));
    assert_eq!(a.len(), 5);
    for (x, y) in a.iter().zip(&b) {
        for k in 0..3 {
            assert!((x[k] - y[k]).abs() < 1e-13);
        }
    }
}

#[test]
fn high_precision_digits_and_negative_inputs() {
    let (c, o, _) = run(&[
        "step",
        "--inertia",
        "3,2,1",
        "--gamma",
        "2",
        "--h=-0.05",
        "--bits",
        "256",
        "-0.3",
        "-0.7",
        "-1.1",
    ]);
    assert_eq!(c, 0);
    let first = o.split_whitespace().next().unwrap();
    assert!(first.len() > 70, "{first}");
}

#[test]
fn bad_inputs_exit_2_with_one_line() {
    let cases: Vec<Vec<&str>> = vec![
        vec!["step", "--inertia", "1,2,3", "--h", "0.1", "1", "2", "3"],
        vec!["step", "--inertia", "3,2,1", "--h", "abc", "1", "2", "3"],
        vec!["step", "--inertia", "3,2,1", "--h", "0.1", "1", "x", "3"],
        vec![
            "step",
            "--inertia",
            "3,2,1",
            "--h",
            "40",
            "0.3",
            "-0.7",
            "1.1",
        ],
        vec!["step", "--inertia", "3,2,1", "--h", "0.1", "0", "0", "0"],
        vec![
            "step",
            "--inertia",
            "3,2,1",
            "--gamma",
            "7",
            "--h",
            "0.1",
            "1",
            "2",
            "3",
        ],
        vec!["orbit", "--inertia", "3,2,1", "--h", "0.1", "0", "0", "2"],
    ];
    for c in cases {
        let (code, _, err) = run(&c);
        assert_eq!(code, 2, "{c:?}");
        assert_eq!(err.trim_end().lines().count(), 1, "{c:?}: {err}");
        assert!(err.starts_with("eulertop: "));
    }
}

#[test]
fn orbit_writes_csv_and_svg() {
    let dir = std::env::temp_dir().join(format!("eulertop-orbit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("o.csv");
    let svg = dir.join("o.svg");
    let (c, o, e) = run(&[
        "orbit",
        "--inertia",
        "3,2,1",
        "--gamma",
        "1",
        "--h",
        "0.1",
        "--steps",
        "20",
        "--csv",
        csv.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
        "0.3",
        "-0.7",
        "1.1",
    ]);
    assert_eq!(c, 0, "{e}");
    assert_eq!(o.lines().count(), 20);
    let table = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(table.lines().count(), 22);
    // γ₁ is Poisson: all Δφ equal
    let d: Vec<f64> = table
        .lines()
        .skip(2)
        .map(|l| l.rsplit(',').next().unwrap().parse().unwrap())
        .collect();
    for x in &d {
        assert!((x - d[0]).abs() < 1e-12);
    }
    let figure = std::fs::read_to_string(&svg).unwrap();
    assert!(figure.contains("<svg"));
    // every tick label is readable: Δφ is constant to many digits, and the lower panel
    // draws its deviation from δ, so no label repeats along an axis
    let labels: Vec<&str> = figure
        .split("<text")
        .skip(1)
        .filter_map(|t| t.split_once('>').and_then(|(_, r)| r.split_once("</text>")))
        .map(|(l, _)| l.trim())
        .collect();
    assert!(labels.len() > 10, "{figure}");
    for l in &labels {
        let n = labels.iter().filter(|m| *m == l).count();
        assert!(n <= 3, "tick label {l} drawn {n} times: {labels:?}");
    }
    assert!(figure.contains("dphi - delta"), "{figure}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn orbit_prints_the_iterates_of_step_and_accepts_options_last() {
    let base = [
        "--inertia",
        "3,2,1",
        "--gamma",
        "2",
        "--h",
        "0.07",
        "--steps",
        "12",
    ];
    let (c1, o1, e1) = run(&[&["step"], &base[..], &["0.3", "-0.7", "1.1"]].concat());
    let dir = std::env::temp_dir().join(format!("eulertop-orbit-last-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("o.csv");
    // options after the start point (a negative one among them) are options, not values
    let tail = ["0.3", "-0.7", "1.1", "--csv", csv.to_str().unwrap()];
    let (c2, o2, e2) = run(&[&["orbit"], &base[..], &tail[..]].concat());
    assert_eq!((c1, c2), (0, 0), "{e1}{e2}");
    assert_eq!(o1, o2);
    // the CSV columns M1..M3 of rows 1..N are the printed iterates, digit for digit
    let table = std::fs::read_to_string(&csv).unwrap();
    let from_csv: Vec<String> = table
        .lines()
        .skip(2)
        .map(|l| l.split(',').skip(2).take(3).collect::<Vec<_>>().join(" "))
        .collect();
    assert_eq!(from_csv, o1.lines().collect::<Vec<_>>());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn step_and_orbit_refuse_the_same_start_points() {
    let cases: [&[&str]; 4] = [
        &["--inertia", "3,2,1", "--h", "0.1", "1e200", "1", "1"],
        &[
            "--inertia",
            "3,2,1",
            "--h",
            "0.1",
            "1e-170",
            "1e-170",
            "1e-170",
        ],
        &["--inertia", "1e308,2,1", "--h", "0.1", "1", "2", "3"],
        &["--inertia", "3,2,1", "--h", "1e999", "1", "2", "3"],
    ];
    for c in cases {
        let (cs, _, es) = run(&[&["step"], c].concat());
        let (co, _, eo) = run(&[&["orbit"], c].concat());
        assert_eq!((cs, co), (2, 2), "{c:?}");
        assert_eq!(es, eo, "{c:?}");
        assert_eq!(es.trim_end().lines().count(), 1, "{es}");
    }
}
