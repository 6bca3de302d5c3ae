//! `eulertop verify`: runs the claim catalogue on the precision ladder and prints a table
//! (or JSON); exit 0 iff every verdict equals its `expect`.

use super::CliError;
use crate::claims::catalogue::lookup::{self, NotFound, Scope};
use crate::claims::catalogue::{Catalogue, latex_labels};
use crate::claims::verdict::{ClaimResult, Options, Rung, Verdict, coverage_table, verify};
use clap::Parser;
use serde::Serialize;
use std::collections::BTreeSet;
use std::io::{IsTerminal, Write};
use std::path::Path;

/// Arguments of `eulertop verify`.
#[derive(Parser, Debug)]
pub struct Args {
    /// Precision ladder in bits (53 = IEEE double, others MPFR).
    #[arg(
        long,
        default_value = "53,128,256,512,1024",
        allow_hyphen_values = true
    )]
    pub bits: String,
    /// Only the claims of this environment ("Lemma 2"), of this paper label ("(J)"), or
    /// whose id contains this text (`*` matches any run of characters).
    #[arg(long)]
    pub only: Option<String>,
    /// Output format: text or json.
    #[arg(long, default_value = "text")]
    pub format: String,
    /// Number of worker threads, 1..=1024 (default: all cores).
    #[arg(long, allow_negative_numbers = true, value_parser = super::whole::<usize>)]
    pub jobs: Option<usize>,
    /// Catalogue directory or file (default: the paper's catalogue, built into the
    /// binary).
    #[arg(long)]
    pub catalogue: Option<String>,
    /// Print the coverage table (paper label → claim ids → verdicts).
    #[arg(long)]
    pub coverage: bool,
    /// Combined with each claim's own seed (0, the default, keeps the catalogue's
    /// seeds): the samples change, and the set of proved claims must not.
    #[arg(long, default_value_t = 0, allow_negative_numbers = true, value_parser = super::whole::<u64>)]
    pub seed: u64,
    /// The budget of every proof attempt.
    #[command(flatten)]
    pub budget: super::ProofBudgetArgs,
}

/// Loads the catalogue `--catalogue` names (the built-in one without it).
pub fn load(catalogue: Option<&str>) -> Result<Catalogue, CliError> {
    super::catalogue_arg::CatalogueSource::new(catalogue).load()
}

/// The ids of the claims `--only QUERY` selects: every claim of the environment QUERY
/// names (ignoring case); else the claims carrying the label "(QUERY)"; else those whose
/// id matches the pattern QUERY ([`matches_pattern`]); else those carrying the label
/// QUERY.  Nothing matched is an error that names the closest ids, environments and
/// labels.
pub fn only(cat: &Catalogue, query: &str) -> Result<BTreeSet<String>, NotFound> {
    let ids = |claims: Vec<&crate::claims::catalogue::Claim>| {
        claims.into_iter().map(|c| c.id.clone()).collect()
    };
    if let Some(s) =
        lookup::environment(cat, query, Scope::Whole).or_else(|| lookup::label(cat, query, true))
    {
        return Ok(ids(s.claims));
    }
    let by_id: BTreeSet<String> = cat
        .claims
        .iter()
        .filter(|c| matches_pattern(&c.id, query))
        .map(|c| c.id.clone())
        .collect();
    if !by_id.is_empty() {
        return Ok(by_id);
    }
    match lookup::label(cat, query, false) {
        Some(s) => Ok(ids(s.claims)),
        None => Err(lookup::not_found(cat, query)),
    }
}

/// Simple pattern match: substring, with `*` as a wildcard.
pub fn matches_pattern(id: &str, pat: &str) -> bool {
    if !pat.contains('*') {
        return id.contains(pat);
    }
    let parts: Vec<&str> = pat.split('*').collect();
    let mut rest = id;
    for (j, p) in parts.iter().enumerate() {
        if p.is_empty() {
            continue;
        }
        match rest.find(p) {
            Some(k) if j > 0 || k == 0 => rest = &rest[k + p.len()..],
            _ => return false,
        }
    }
    parts.last().is_none_or(|l| l.is_empty() || id.ends_with(l))
}

/// The one precision range of every command: 2 to 1048576 bits (53 is IEEE double,
/// any other MPFR).
pub fn check_precision(b: u32) -> Result<(), CliError> {
    if !(2..=1 << 20).contains(&b) {
        return Err(CliError(format!(
            "precision {b} bits is out of range 2..=1048576 (53 = f64, others MPFR)"
        )));
    }
    Ok(())
}

/// Parses and checks a precision ladder.
pub fn parse_bits(s: &str) -> Result<Vec<u32>, CliError> {
    let bits: Vec<u32> = super::parse_list(s, "precision")?;
    for &b in &bits {
        check_precision(b)?;
    }
    if bits.is_empty() {
        return Err(CliError("empty precision list".into()));
    }
    Ok(bits)
}

/// Formats a residual compactly: `2^-140.2`, `0` (exactly zero).
pub fn fmt_log2(l: Option<f64>) -> String {
    match l {
        None => "0".to_string(),
        Some(x) => format!("2^{x:.1}"),
    }
}

#[derive(Serialize)]
struct Summary {
    claims: usize,
    holds: usize,
    refuted: usize,
    proved: usize,
    construction: usize,
    inconclusive: usize,
    defined: usize,
    unexpected: Vec<String>,
    failed_samples: usize,
    bits: Vec<u32>,
}

#[derive(Serialize)]
struct Report<'a> {
    claims: &'a [ClaimResult],
    summary: Summary,
    #[serde(skip_serializing_if = "Option::is_none")]
    coverage: Option<Vec<CoverageRow>>,
}

#[derive(Serialize)]
struct CoverageRow {
    label: String,
    claims: Vec<CoverageEntry>,
}

#[derive(Serialize)]
struct CoverageEntry {
    id: String,
    verdict: Verdict,
}

fn summary(results: &[ClaimResult], bits: &[u32]) -> Summary {
    let n = |v: Verdict| results.iter().filter(|r| r.verdict == v).count();
    Summary {
        claims: results.len(),
        holds: n(Verdict::Holds),
        refuted: n(Verdict::Refuted),
        proved: n(Verdict::Proved),
        construction: n(Verdict::Construction),
        inconclusive: n(Verdict::Inconclusive),
        defined: n(Verdict::Defined),
        unexpected: results
            .iter()
            .filter(|r| !r.as_expected)
            .map(|r| r.id.clone())
            .collect(),
        failed_samples: results.iter().map(|r| r.failures.len()).sum(),
        bits: bits.to_vec(),
    }
}

/// A selected claim whose domain yields no point is a data error naming the claim and
/// the cause, found before the run (one draw of its sampler each): `where` constraints
/// that no point satisfies ("the domain is unreachable"), or a sampled variable that
/// cannot be drawn, such as `uniform(1, 0)` ("the domain cannot be sampled").  Either
/// would end the claim at its first sample.
pub fn check_domains_reachable(
    cat: &Catalogue,
    select: &(dyn Fn(&crate::claims::catalogue::Claim) -> bool + Sync),
) -> Result<(), CliError> {
    use crate::claims::sampler::{Sampler, Stream};
    for c in cat.claims.iter().filter(|c| select(c)) {
        let Ok(mut s) = Sampler::new(cat, c, Stream::Samples) else {
            continue;
        };
        if let Err(m) = s.draw() {
            // a constraint that fails to evaluate everywhere is not a thin domain
            let what = if m.starts_with("domain too thin") && !m.contains("cannot be evaluated") {
                "the domain is unreachable"
            } else {
                "the domain cannot be sampled"
            };
            return Err(CliError(format!(
                "{}: claim {}: {what}: {}",
                c.position,
                c.id,
                super::printable(&m)
            )));
        }
    }
    Ok(())
}

/// Paper labels, the rows of the coverage table: from the LaTeX source named by the
/// environment variable `EULERTOP_PAPER` when it is set, else the `labels` of the
/// catalogue's `[paper]` table, else the labels its claims carry (in catalogue order).  A
/// source that cannot be read or has no `\label` is an error naming the variable.
pub fn paper_labels(cat: &Catalogue) -> Result<Vec<String>, CliError> {
    if let Some(p) = std::env::var_os("EULERTOP_PAPER") {
        let shown = Path::new(&p).display().to_string();
        let t = crate::claims::catalogue::source::read_text(Path::new(&p))
            .map_err(|e| CliError(format!("EULERTOP_PAPER={shown}: {e}")))?;
        let l = latex_labels(&t);
        if l.is_empty() {
            return Err(CliError(format!(
                "EULERTOP_PAPER={shown}: no \\label in the file"
            )));
        }
        return Ok(l);
    }
    if let Some(p) = cat.paper.as_ref().filter(|p| !p.labels.is_empty()) {
        return Ok(p.labels.clone());
    }
    let mut out: Vec<String> = Vec::new();
    for l in cat.claims.iter().flat_map(|c| &c.labels) {
        if !out.contains(l) {
            out.push(l.clone());
        }
    }
    Ok(out)
}

/// Verifies the selected claims on `jobs` worker threads (default: all cores), with a
/// progress bar on standard error when it is a terminal.  Shared by `verify` and `report`.
pub fn run_with_progress(
    cat: &Catalogue,
    opts: &Options,
    select: &(dyn Fn(&crate::claims::catalogue::Claim) -> bool + Sync),
    total: usize,
    jobs: Option<usize>,
) -> Result<Vec<ClaimResult>, CliError> {
    let bar = if std::io::stderr().is_terminal() {
        let b = indicatif::ProgressBar::new(total as u64);
        b.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} claims {elapsed}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        Some(b)
    } else {
        None
    };
    let done = |_: &ClaimResult| {
        if let Some(b) = &bar {
            b.inc(1);
        }
    };
    super::check_jobs(jobs)?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs.unwrap_or(0))
        .build()
        .map_err(|e| CliError(format!("cannot start worker threads: {e}")))?;
    let results = pool.install(|| verify(cat, opts, select, &done));
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    Ok(results)
}

/// Runs `eulertop verify`.
pub fn run(args: Args) -> Result<i32, CliError> {
    args.budget.apply()?;
    let bits = parse_bits(&args.bits)?;
    if args.format != "text" && args.format != "json" {
        return Err(CliError(format!(
            "unknown format '{}' (text or json)",
            args.format
        )));
    }
    let mut cat = load(args.catalogue.as_deref())?;
    cat.reseed(args.seed);
    let opts = Options {
        bits: bits.clone(),
        exact: true,
    };
    let chosen = match &args.only {
        None => None,
        Some(q) => Some(only(&cat, q).map_err(CliError::new)?),
    };
    let select = move |c: &crate::claims::catalogue::Claim| {
        chosen.as_ref().is_none_or(|ids| ids.contains(&c.id))
    };
    let total = cat.claims.iter().filter(|c| select(c)).count();
    if total == 0 {
        return Err(CliError("the catalogue has no claims".to_string()));
    }
    check_domains_reachable(&cat, &select)?;
    // the labels are read before the run, so a bad EULERTOP_PAPER costs nothing
    let labels = if args.coverage {
        paper_labels(&cat)?
    } else {
        Vec::new()
    };
    let results = run_with_progress(&cat, &opts, &select, total, args.jobs)?;
    let sum = summary(&results, &bits);
    let code = i32::from(!sum.unexpected.is_empty());
    if args.format == "json" {
        let coverage = args.coverage.then(|| {
            coverage_table(&labels, &results)
                .into_iter()
                .map(|(label, ids)| CoverageRow {
                    label,
                    claims: ids
                        .into_iter()
                        .map(|(id, verdict)| CoverageEntry { id, verdict })
                        .collect(),
                })
                .collect()
        });
        let rep = Report {
            claims: &results,
            summary: sum,
            coverage,
        };
        let s = serde_json::to_string_pretty(&rep).map_err(|e| CliError(e.to_string()))?;
        super::print(&s)?;
    } else {
        let mut out = super::stdout();
        let written = print_text(&mut out, &results, &bits, &sum).and_then(|()| {
            if args.coverage {
                print_coverage(&mut out, &labels, &results)?;
            }
            out.flush()
        });
        written.map_err(super::write_error("standard output"))?;
    }
    Ok(code)
}

/// The reason, counterexample and failed samples of a claim not as expected.
fn print_unexpected(w: &mut impl Write, r: &ClaimResult) -> std::io::Result<()> {
    writeln!(w, "    reason: {}", super::printable(&r.reason))?;
    if let Some(c) = &r.counterexample {
        let pt: Vec<String> = c
            .point
            .iter()
            .map(|n| format!("{} = {}", n.name, n.value))
            .collect();
        writeln!(w, "    counterexample: {}", pt.join(", "))?;
        writeln!(w, "      lhs = {}\n      rhs = {}", c.lhs, c.rhs)?;
    }
    for f in r.failures.iter().take(2) {
        writeln!(w, "    failed sample ({} bits): {}", f.bits, f.message)?;
    }
    Ok(())
}

/// Width of the location column of the text table; longer locations wrap onto
/// continuation lines.
const LOCATION_WIDTH: usize = 40;

/// The legend above the text table: what each column means.
const LEGEND: &str = "\
columns: form: printed (as in the paper) or corrected (a corrected version of a printed
         claim); verdict: marked ! when it differs from expect, the verdict the catalogue
         expects; g: bits of precision lost to conditioning, the smallest g >= 0 with
         residual <= 2^(-p+g) at every precision p; N bits: the largest scaled residual
         |lhs - rhs| over the samples at N bits (0 = exactly zero), or for an asymptotic
         claim \"slope s\": its order of convergence in h, the smallest slope over the
         samples of log2 |residual| against log2 h.  A refuted or inconclusive claim is
         followed by its reason.
";

/// Splits `text` into lines of at most `width` characters, at spaces where possible (a
/// word longer than `width` is cut).  Always at least one line.
pub fn wrap_text(text: &str, width: usize) -> Vec<String> {
    let width = width.max(1);
    let mut lines = Vec::new();
    let mut cur = String::new();
    for word in text.split(' ') {
        let mut word: Vec<char> = word.chars().collect();
        loop {
            let used = cur.chars().count();
            let sep = usize::from(used > 0);
            if used + sep + word.len() <= width {
                if sep == 1 {
                    cur.push(' ');
                }
                cur.extend(word.iter());
                break;
            }
            if used > 0 {
                lines.push(std::mem::take(&mut cur));
                continue;
            }
            cur.extend(word.drain(..width));
            lines.push(std::mem::take(&mut cur));
        }
    }
    if !cur.is_empty() || lines.is_empty() {
        lines.push(cur);
    }
    lines
}

/// One table row of a claim (the first line of its location) and the continuation lines
/// that carry the rest of its location.
fn claim_rows(r: &ClaimResult, bits: &[u32], idw: usize, locw: usize) -> Vec<String> {
    // control characters of the catalogue's text never reach the terminal
    let loc = wrap_text(&super::printable(&r.location), locw);
    let mark = if r.as_expected { "" } else { " !" };
    let g = r.loss_bits.map_or("-".to_string(), |g| format!("{g:.1}"));
    let mut line = format!(
        "{:idw$}  {:locw$}  {:9}  {:12}  {:12}  {:>5}",
        r.id,
        loc[0],
        r.form,
        format!("{}{mark}", r.verdict.name()),
        r.expect.map_or("-", |v| v.name()),
        g
    );
    for (j, _) in bits.iter().enumerate() {
        let cell = match r.residuals.get(j) {
            None => "-".to_string(),
            Some(Rung::Slope { slope, .. }) => format!("slope {slope:.2}"),
            Some(x) => fmt_log2(x.log2()),
        };
        line.push_str(&format!("  {cell:>10}"));
    }
    let mut rows = vec![line];
    rows.extend(
        loc[1..]
            .iter()
            .map(|l| format!("{:idw$}  {l}", "").trim_end().to_string()),
    );
    rows
}

fn print_text(
    w: &mut impl Write,
    results: &[ClaimResult],
    bits: &[u32],
    sum: &Summary,
) -> std::io::Result<()> {
    let idw = results.iter().map(|r| r.id.len()).max().unwrap_or(2).max(2);
    let locw = results
        .iter()
        .map(|r| super::printable(&r.location).chars().count())
        .max()
        .unwrap_or(8)
        .clamp(8, LOCATION_WIDTH);
    writeln!(w, "{LEGEND}")?;
    let mut head = format!(
        "{:idw$}  {:locw$}  {:9}  {:12}  {:12}  {:>5}",
        "id", "location", "form", "verdict", "expect", "g"
    );
    for b in bits {
        head.push_str(&format!("  {:>10}", format!("{b} bits")));
    }
    writeln!(w, "{head}")?;
    for r in results {
        for row in claim_rows(r, bits, idw, locw) {
            writeln!(w, "{row}")?;
        }
        if !r.as_expected {
            print_unexpected(w, r)?;
        } else if matches!(r.verdict, Verdict::Refuted | Verdict::Inconclusive) {
            writeln!(w, "    reason: {}", super::printable(&r.reason))?;
        }
    }
    if sum.failed_samples > 0 {
        writeln!(
            w,
            "\nsamples that could not be evaluated (reported, replaced, never counted):"
        )?;
        for r in results.iter().filter(|r| !r.failures.is_empty()) {
            writeln!(
                w,
                "  {}: {} (first: {})",
                r.id,
                r.failures.len(),
                r.failures[0].message
            )?;
        }
    }
    print_counts(w, results, sum)
}

/// The count line and the line of certified verdicts that end the text output.
fn print_counts(w: &mut impl Write, results: &[ClaimResult], sum: &Summary) -> std::io::Result<()> {
    writeln!(
        w,
        "\n{} claims: {} holds, {} proved, {} by construction, {} refuted, {} inconclusive, {} definitions; {} not as expected{}",
        sum.claims,
        sum.holds,
        sum.proved,
        sum.construction,
        sum.refuted,
        sum.inconclusive,
        sum.defined,
        sum.unexpected.len(),
        if sum.unexpected.is_empty() {
            String::new()
        } else {
            format!(": {}", sum.unexpected.join(", "))
        }
    )?;
    writeln!(w, "{}", crate::report::markdown::certified_line(results))
}

fn print_coverage(
    w: &mut impl Write,
    labels: &[String],
    results: &[ClaimResult],
) -> std::io::Result<()> {
    let table = coverage_table(labels, results);
    let covered = table.iter().filter(|(_, ids)| !ids.is_empty()).count();
    writeln!(
        w,
        "\nCoverage: {covered} of {} paper labels have claims",
        labels.len()
    )?;
    for (l, ids) in &table {
        if ids.is_empty() {
            writeln!(w, "  {l:24}  (no claim)")?;
        } else {
            let s: Vec<String> = ids
                .iter()
                .map(|(i, v)| format!("{i} [{}]", v.name()))
                .collect();
            writeln!(w, "  {l:24}  {}", s.join(", "))?;
        }
    }
    Ok(())
}
