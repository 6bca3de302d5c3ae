//! `eulertop report`: verifies the catalogue and writes the Markdown reports, the proof
//! pages of the paper's environments, figures, errata and conventions into `reports/`
//! (deterministic output).

use super::CliError;
use super::catalogue_arg::CatalogueSource;
use super::verify::{parse_bits, run_with_progress};
use crate::claims::catalogue::source::read_text;
use crate::claims::verdict::{ClaimResult, Options};
use crate::report::{Convention, ReportInput, Section, write_reports};
use clap::Parser;
use std::collections::BTreeMap;
use std::io::Write;
use std::path::Path;

/// Arguments of `eulertop report`.
#[derive(Parser, Debug)]
pub struct Args {
    /// Output directory.
    #[arg(long, default_value = "reports")]
    pub out: String,
    /// Precision ladder in bits.
    #[arg(
        long,
        default_value = "53,128,256,512,1024",
        allow_hyphen_values = true
    )]
    pub bits: String,
    /// Catalogue directory or file (default: the paper's catalogue, built into the
    /// binary).
    #[arg(long)]
    pub catalogue: Option<String>,
    /// Number of worker threads, 1..=1024 (default: all cores).
    #[arg(long, allow_negative_numbers = true, value_parser = super::whole::<usize>)]
    pub jobs: Option<usize>,
    /// A README whose verdict-count block (between `<!-- verdicts -->` and
    /// `<!-- /verdicts -->`) is rewritten; empty to skip.  Without it, `README.md` of the
    /// current directory is updated when it has such a block, and skipped otherwise.
    #[arg(long)]
    pub readme: Option<String>,
    /// The budget of every proof attempt.
    #[command(flatten)]
    pub budget: super::ProofBudgetArgs,
}

/// Reads `\newcommand{\name}{body}` lines from a LaTeX preamble.
pub fn parse_newcommands(tex: &str) -> BTreeMap<String, String> {
    let mut m = BTreeMap::new();
    for line in tex.lines() {
        let t = line.trim();
        let Some(rest) = t.strip_prefix("\\newcommand{\\") else {
            continue;
        };
        let Some(close) = rest.find('}') else {
            continue;
        };
        let name = &rest[..close];
        let body = rest[close + 1..].trim();
        if let Some(b) = body.strip_prefix('{').and_then(|b| b.strip_suffix('}')) {
            m.insert(name.to_string(), b.to_string());
        }
    }
    m
}

/// The `[[convention]]` tables of the catalogue's `conventions.toml` (none without it).
fn read_conventions(source: &CatalogueSource) -> Result<Vec<Convention>, CliError> {
    let Some(text) = source.text("conventions.toml")? else {
        return Ok(Vec::new());
    };
    let v: toml::Value = toml::from_str(&text)
        .map_err(|e| CliError(format!("{source}: conventions.toml: {}", e.message())))?;
    let list = v
        .get("convention")
        .and_then(|c| c.as_array())
        .cloned()
        .unwrap_or_default();
    let field =
        |c: &toml::Value, k: &str| c.get(k).and_then(|x| x.as_str()).unwrap_or("").to_string();
    Ok(list
        .iter()
        .map(|c| Convention {
            name: field(c, "name"),
            choice: field(c, "choice"),
            why: field(c, "why"),
        })
        .collect())
}

/// The README `--readme` names (none for `--readme ''`); without `--readme`,
/// `README.md` when it exists and has a verdict block, so that a report written outside
/// the repository skips it.
fn readme_of(arg: Option<&str>) -> Result<Option<ReadmeBlock>, CliError> {
    match arg {
        Some("") => Ok(None),
        Some(r) => read_readme(Path::new(r)).map(Some),
        None => Ok(read_readme(Path::new("README.md")).ok()),
    }
}

/// The verdict block of a README: its text and the byte range of the block (from the
/// opening marker to the end of the closing one).
pub struct ReadmeBlock {
    path: std::path::PathBuf,
    text: String,
    block: std::ops::Range<usize>,
}

/// Reads `path` and finds its verdict block (`<!-- verdicts -->` … `<!-- /verdicts -->`);
/// errors name `--readme`.
pub fn read_readme(path: &Path) -> Result<ReadmeBlock, CliError> {
    let shown = path.display();
    let skip = "pass --readme '' to skip the README update";
    let text = read_text(path).map_err(|e| CliError(format!("--readme {shown}: {e}; {skip}")))?;
    let (open, close) = ("<!-- verdicts -->", "<!-- /verdicts -->");
    let (Some(a), Some(b)) = (text.find(open), text.find(close)) else {
        return Err(CliError(format!(
            "--readme {shown}: no '{open}' … '{close}' block to update; {skip}"
        )));
    };
    if b < a {
        return Err(CliError(format!(
            "--readme {shown}: verdict block markers out of order"
        )));
    }
    Ok(ReadmeBlock {
        path: path.to_path_buf(),
        text,
        block: a..b + close.len(),
    })
}

impl ReadmeBlock {
    /// Rewrites the block with the verdict counts of `results` (the file is left
    /// untouched when nothing changes).
    pub fn update(&self, results: &[ClaimResult]) -> Result<(), CliError> {
        let block = format!(
            "<!-- verdicts -->\n{}.\n<!-- /verdicts -->",
            crate::report::markdown::counts_line(results)
        );
        let (a, b) = (self.block.start, self.block.end);
        let new = format!("{}{}{}", &self.text[..a], block, &self.text[b..]);
        if new != self.text {
            std::fs::write(&self.path, new).map_err(super::write_error(self.path.display()))?;
        }
        Ok(())
    }
}

/// Checks `--out` before anything is written: not empty, not an existing file, and not
/// a directory whose `README.md` is the README given by `--readme`.
fn check_out(out: &Path, readme: Option<&ReadmeBlock>) -> Result<(), CliError> {
    if out.as_os_str().is_empty() {
        return Err(CliError("--out '' names no directory".into()));
    }
    if out.exists() && !out.is_dir() {
        return Err(CliError(format!(
            "--out {}: exists and is not a directory",
            out.display()
        )));
    }
    let same = |a: &Path, b: &Path| match (a.canonicalize(), b.canonicalize()) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    };
    if let Some(r) = readme
        && same(&out.join("README.md"), &r.path)
    {
        return Err(CliError(format!(
            "--out {} would overwrite the README given by --readme {}",
            out.display(),
            r.path.display()
        )));
    }
    Ok(())
}

fn sections(cat: &crate::claims::catalogue::Catalogue) -> Vec<Section> {
    cat.sections
        .iter()
        .map(|(file, number, title)| Section {
            stem: Path::new(file)
                .file_stem()
                .and_then(|s| s.to_str())
                .unwrap_or(file)
                .to_string(),
            number: number.clone(),
            title: title.clone(),
        })
        .collect()
}

/// Writes every page beside `out` first, then moves them in (the pages of an earlier
/// report that this one does not write are removed); with `model_figures`, the figures of
/// the model too.  Returns the files written.
fn stage_and_install(
    input: &ReportInput,
    out: &Path,
    model_figures: bool,
) -> Result<Vec<std::path::PathBuf>, CliError> {
    let staging = super::report_install::staging_dir(out)?;
    let staged = write_reports(input, &staging)
        .map_err(|e| CliError(format!("cannot write the report: {e}")))
        .and_then(|_| {
            if !model_figures {
                return Ok(());
            }
            crate::report::figures::model::write_all(&staging.join("figures"))
                .map_err(|e| CliError(format!("cannot write figures: {e}")))
        });
    if let Err(e) = staged {
        let _ = std::fs::remove_dir_all(&staging);
        return Err(e);
    }
    super::report_install::install(&staging, out)
}

/// Runs `eulertop report`: every argument is checked before anything is written.  The
/// model's figures are drawn for the paper of the built-in catalogue only.
pub fn run(args: Args) -> Result<i32, CliError> {
    args.budget.apply()?;
    let bits = parse_bits(&args.bits)?;
    super::check_jobs(args.jobs)?;
    let readme = readme_of(args.readme.as_deref())?;
    let out = Path::new(&args.out);
    check_out(out, readme.as_ref())?;
    let source = CatalogueSource::new(args.catalogue.as_deref());
    let cat = source.load()?;
    let macros = match source.text("paper-macros.tex")? {
        Some(t) => parse_newcommands(&t),
        None => BTreeMap::new(),
    };
    let conventions = read_conventions(&source)?;
    let environments = match source.text("environments.tex")? {
        Some(t) => crate::report::paper_text::parse(&t),
        None => BTreeMap::new(),
    };
    let places = cat
        .claims
        .iter()
        .filter_map(|c| crate::claims::structure::place(&cat, c).map(|p| (c.id.clone(), p)))
        .collect();
    let opts = Options {
        bits: bits.clone(),
        exact: true,
    };
    let results = run_with_progress(&cat, &opts, &|_| true, cat.claims.len(), args.jobs)?;
    let model_figures = crate::bindings::catalogue::is_this_paper(cat.paper.as_ref());
    let command = if args.bits == "53,128,256,512,1024" {
        "eulertop report".to_string()
    } else {
        format!("eulertop report --bits {}", args.bits)
    };
    let variables = crate::report::variables::definitions(&cat, &macros);
    let input = ReportInput {
        sections: sections(&cat),
        results: &results,
        conventions,
        macros,
        bits,
        command,
        extra_figures: if model_figures {
            crate::report::figures::model::FIGURES
                .iter()
                .map(|(f, c)| (f.to_string(), c.to_string()))
                .collect()
        } else {
            Vec::new()
        },
        places,
        paper_environments: cat.all_environments(),
        paper: cat.paper.clone(),
        environments,
        variables,
    };
    let written = stage_and_install(&input, out, model_figures)?;
    if let Some(r) = &readme {
        r.update(&results)?;
    }
    let summary = format!(
        "wrote {} files to {}; {}",
        written.len(),
        out.display(),
        crate::report::markdown::counts_line(&results)
    );
    let _ = writeln!(std::io::stderr(), "{summary}");
    Ok(0)
}
