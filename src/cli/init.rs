//! `eulertop init DIR`: starts the catalogue of a new paper: `DIR/paper.toml` (the
//! `[paper]` table) and `DIR/claims.toml` (a domain and two claims, one proved and one
//! refuted, each with comments), which `eulertop verify --catalogue DIR` runs with exit
//! status 0.  Existing files are never overwritten: if either file exists, nothing is
//! written and the exit status is 2.
//!
//! ```
//! use eulertop::cli::init::{files, Args};
//! let args = Args { dir: "my-paper".into(), title: Some("On squares".into()), author: vec![], year: Some(2024) };
//! let written = files(&args);
//! assert_eq!(written[0].0, "paper.toml");
//! assert!(written[0].1.contains("title = \"On squares\""));
//! assert!(written[1].1.contains("expect = \"refuted\""));
//! ```

use super::CliError;
use clap::Parser;
use std::path::Path;

/// Arguments of `eulertop init`.
#[derive(Parser, Debug)]
pub struct Args {
    /// The catalogue directory to write (created if it does not exist).
    pub dir: String,
    /// The paper's title.
    #[arg(long)]
    pub title: Option<String>,
    /// An author of the paper (repeat for several).
    #[arg(long)]
    pub author: Vec<String>,
    /// The year of publication, 1000..=9999 (default: this year).
    #[arg(long, allow_negative_numbers = true)]
    pub year: Option<i64>,
}

/// The years `--year` accepts.
pub const YEARS: std::ops::RangeInclusive<i64> = 1000..=9999;

/// The `[paper]` table; `{TITLE}`, `{AUTHORS}` and `{YEAR}` are filled in.
const PAPER: &str = r#"# The paper this catalogue checks (identities/README.md of eulertop, "Checking your
# own paper").  `environments` lists, in the order the paper prints them, every name a
# claim's `environment` may take: theorem-like environments ("Lemma 1") and, marked
# `section = true`, the text of a section outside them.

[paper]
title = {TITLE}
authors = {AUTHORS}
year = {YEAR}
environments = [
  { name = "Section 1", section = true },
  "Lemma 1",
]
"#;

/// The claims file.
const CLAIMS: &str = r#"# The claims of the paper, one [[claim]] table per formula.  Run them with
#   eulertop verify --catalogue DIR
# (exit status 0 when every verdict is the one `expect` names).

[section]
number = "1"
title = "Introduction"

# A sampling domain: the variables every claim with `domain = "plane"` draws.
[domain.plane]
vars = [
  ["a", "uniform(-2, 2)"],
  ["b", "uniform(-2, 2)"],
  ["c", "uniform(-2, 2)"],
  ["d", "uniform(-2, 2)"],
]

# A true statement: a polynomial identity, so the symbolic prover proves it (the normal
# form of lhs - rhs is 0); `exact = true` also evaluates it over the rationals.
[[claim]]
id = "lemma1.two-squares"
environment = "Lemma 1"
role = "statement"
labels = []
location = "Lemma 1"
printed = '''(a^2+b^2)(c^2+d^2)=(ac-bd)^2+(ad+bc)^2'''
kind = "identity"
expect = "proved"
domain = "plane"
lhs = "(a^2 + b^2) * (c^2 + d^2)"
rhs = "(a*c - b*d)^2 + (a*d + b*c)^2"
exact = true

# A false statement, as a paper might print it by mistake: verify finds a counterexample.
# `expect = "refuted"` records that this is known, so it does not make verify fail.
[[claim]]
id = "sec1.square-slip"
environment = "Section 1"
role = "statement"
labels = []
location = "Section 1, the displayed formula"
printed = '''(a+b)^2=a^2+b^2'''
kind = "identity"
expect = "refuted"
note = "The cross term 2ab is missing."
domain = "plane"
lhs = "(a + b)^2"
rhs = "a^2 + b^2"
"#;

/// The files `init` writes: `(file name, text)`.
pub fn files(args: &Args) -> Vec<(&'static str, String)> {
    let quote = |s: &str| toml::Value::String(s.to_string()).to_string();
    let title = args.title.as_deref().unwrap_or("Untitled paper");
    let authors: Vec<String> = args.author.iter().map(|a| quote(a)).collect();
    let paper = PAPER
        .replace("{TITLE}", &quote(title))
        .replace("{AUTHORS}", &format!("[{}]", authors.join(", ")))
        .replace("{YEAR}", &args.year.unwrap_or_else(this_year).to_string());
    vec![("paper.toml", paper), ("claims.toml", CLAIMS.to_string())]
}

/// The current year (UTC), from the system clock.
fn this_year() -> i64 {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs() as i64);
    // days since 1970-01-01 to the civil year (Howard Hinnant's algorithm)
    let z = secs.div_euclid(86_400) + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    yoe + era * 400 + i64::from(mp >= 10)
}

/// Runs `eulertop init`: checks that no file would be overwritten, then writes them.
pub fn run(args: Args) -> Result<i32, CliError> {
    let dir = Path::new(&args.dir);
    if args.dir.is_empty() {
        return Err(CliError("init: the directory name is empty".into()));
    }
    if let Some(y) = args.year
        && !YEARS.contains(&y)
    {
        return Err(CliError(format!(
            "--year {y} is outside {}..={} (the year of publication)",
            YEARS.start(),
            YEARS.end()
        )));
    }
    if dir.exists() && !dir.is_dir() {
        return Err(CliError(format!(
            "{}: exists and is not a directory",
            dir.display()
        )));
    }
    let files = files(&args);
    for (name, _) in &files {
        let p = dir.join(name);
        if p.exists() || p.symlink_metadata().is_ok() {
            return Err(CliError(format!(
                "{}: exists; init never overwrites a file (nothing written)",
                p.display()
            )));
        }
    }
    std::fs::create_dir_all(dir).map_err(super::write_error(dir.display()))?;
    for (name, text) in &files {
        let p = dir.join(name);
        let err = super::write_error(p.display());
        let mut f = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&p)
            .map_err(&err)?;
        std::io::Write::write_all(&mut f, text.as_bytes()).map_err(&err)?;
    }
    super::print(&format!(
        "wrote {0}/paper.toml and {0}/claims.toml; check them with: eulertop verify --catalogue {0}",
        dir.display()
    ))?;
    Ok(0)
}
