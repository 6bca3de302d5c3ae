//! The `[paper]` table: the source a catalogue checks (title, authors, year, where it
//! appeared) and the ordered list of its environments, the only names a claim's
//! `environment` may take.  An entry is a name (`"Theorem 2"`) or a table
//! `{ name = "Section 3", section = true, no_statement = "why" }`: a *section* is text
//! outside the theorem-like environments (it gets no proof page and keeps no order), and
//! `no_statement` says why an environment may have claims but no `statement` claim.
//! `labels` lists the `\label` names of the source, the rows of the coverage table.
//!
//! A catalogue without a `[paper]` table (a scratch file) accepts any environment name;
//! its environments are the names its claims use, in order of first use.
//!
//! ```
//! use eulertop::claims::catalogue::load_sources;
//! use eulertop::claims::registry::Registry;
//! let toml = r#"
//! [paper]
//! title = "A note on double angles"
//! authors = ["A. Author"]
//! year = 2024
//! environments = [{ name = "Section 1", section = true }, "Lemma 1"]
//!
//! [[claim]]
//! id = "double"
//! location = "Lemma 1"
//! printed = 'sin 2x = 2 sin x cos x'
//! environment = "Lemma 1"
//! role = "statement"
//! kind = "identity"
//! expect = "holds"
//! vars = [["x", "uniform(-3, 3)"]]
//! lhs = "sin(2*x)"
//! rhs = "2*sin(x)*cos(x)"
//! "#;
//! let cat = load_sources(&[("t.toml".into(), toml.into())], Registry::new()).unwrap();
//! let paper = cat.paper.as_ref().unwrap();
//! assert_eq!((paper.title.as_str(), paper.year), ("A note on double angles", 2024));
//! assert_eq!(cat.environments[1].name, "Lemma 1");
//! assert!(cat.environments[0].section);
//! // a name the table does not list is an error that names the list
//! let bad = toml.replace("environment = \"Lemma 1\"", "environment = \"Lemma 2\"");
//! let e = load_sources(&[("t.toml".into(), bad)], Registry::new()).unwrap_err();
//! assert!(e.message.contains("did you mean Lemma 1?"), "{e}");
//! ```

use super::source::{LoadError, SourceFile};
use std::sync::Arc;
use toml::Spanned;

/// The source a catalogue checks, from its `[paper]` table.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Paper {
    /// Title.
    pub title: String,
    /// Authors, as printed.
    pub authors: Vec<String>,
    /// Year of publication.
    pub year: i64,
    /// Where it appeared (journal, book, chapter, URL), if given.
    pub source: Option<String>,
    /// The `\label` names of its LaTeX source, in order (empty if not given): the rows
    /// of the coverage table.
    pub labels: Vec<String>,
    /// `file:line` of the table.
    pub position: String,
}

/// One entry of the environment list.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EnvironmentSpec {
    /// The name claims give in `environment`.
    pub name: String,
    /// Text of a section outside the theorem-like environments.
    pub section: bool,
    /// Why the environment may have claims without a `statement` claim.
    pub no_statement: Option<String>,
}

/// `[paper]` as written.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PaperToml {
    title: String,
    authors: Vec<String>,
    year: i64,
    source: Option<String>,
    environments: Vec<Spanned<toml::Value>>,
    #[serde(default)]
    labels: Vec<String>,
}

/// Reads a `[paper]` table: the paper and its environments, in order.  The list is not
/// empty and names no environment twice; every entry has a name.
pub fn read(
    file: &Arc<SourceFile>,
    t: &Spanned<PaperToml>,
) -> Result<(Paper, Vec<EnvironmentSpec>), LoadError> {
    let p = t.get_ref();
    let at = |s: &Spanned<toml::Value>, m: String| file.error_at(s.span().start, s.span().end, m);
    let mut envs: Vec<EnvironmentSpec> = Vec::new();
    for e in &p.environments {
        let spec = entry(e.get_ref()).map_err(|m| at(e, m))?;
        if envs.iter().any(|x| x.name == spec.name) {
            return Err(at(
                e,
                format!("environment '{}' is listed twice in [paper]", spec.name),
            ));
        }
        let page = stem(&spec.name, '-');
        if let Some(x) = envs.iter().find(|x| stem(&x.name, '-') == page) {
            return Err(at(
                e,
                format!(
                    "environments '{}' and '{}' would share the report page '{page}': rename one",
                    x.name, spec.name
                ),
            ));
        }
        envs.push(spec);
    }
    if envs.is_empty() {
        let s = t.span().start;
        return Err(file.error_at(
            s,
            s + 1,
            "[paper] needs at least one name in 'environments'",
        ));
    }
    let paper = Paper {
        title: p.title.clone(),
        authors: p.authors.clone(),
        year: p.year,
        source: p.source.clone(),
        labels: p.labels.clone(),
        position: file.position(t.span().start),
    };
    Ok((paper, envs))
}

/// One entry: a name, or a table with `name`, `section` and `no_statement`.
fn entry(v: &toml::Value) -> Result<EnvironmentSpec, String> {
    let spec = match v {
        toml::Value::String(s) => EnvironmentSpec {
            name: s.clone(),
            section: false,
            no_statement: None,
        },
        toml::Value::Table(t) => {
            if let Some(k) = t
                .keys()
                .find(|k| !["name", "section", "no_statement"].contains(&k.as_str()))
            {
                return Err(format!(
                    "unknown field '{k}' in an environment of [paper] (name, section, no_statement)"
                ));
            }
            let name = match t.get("name") {
                Some(toml::Value::String(s)) => s.clone(),
                _ => return Err("an environment of [paper] needs a string 'name'".into()),
            };
            let section = match t.get("section") {
                None => false,
                Some(toml::Value::Boolean(b)) => *b,
                Some(_) => return Err(format!("'{name}': 'section' is true or false")),
            };
            let no_statement = match t.get("no_statement") {
                None => None,
                Some(toml::Value::String(s)) if !s.trim().is_empty() => Some(s.clone()),
                Some(_) => {
                    return Err(format!(
                        "'{name}': 'no_statement' is a text saying why the environment has no statement claim"
                    ));
                }
            };
            EnvironmentSpec {
                name,
                section,
                no_statement,
            }
        }
        _ => {
            return Err(
                "an environment of [paper] is a name or a table { name = \"…\", section = true }"
                    .into(),
            );
        }
    };
    if spec.name.trim().is_empty() {
        return Err("an environment of [paper] has an empty name".into());
    }
    Ok(spec)
}

/// An environment name as a file stem or identifier: lower case, every run of characters
/// other than letters and digits one `sep`, none at the ends (`environment` if nothing is
/// left).
///
/// ```
/// use eulertop::claims::catalogue::paper::stem;
/// assert_eq!(stem("Proposition 6", '-'), "proposition-6");
/// assert_eq!(stem("§22.6", '_'), "22_6");
/// assert_eq!(stem("§", '-'), "environment");
/// ```
pub fn stem(name: &str, sep: char) -> String {
    let mut out = String::new();
    for w in name
        .to_lowercase()
        .split(|c: char| !c.is_alphanumeric())
        .filter(|w| !w.is_empty())
    {
        if !out.is_empty() {
            out.push(sep);
        }
        out.push_str(w);
    }
    if out.is_empty() {
        out.push_str("environment");
    }
    out
}

/// The environments of a catalogue without a `[paper]` table: the names its claims use,
/// in order of first use.
///
/// ```
/// use eulertop::claims::catalogue::paper::implicit;
/// let envs = implicit(["Lemma 2", "Section 1", "Lemma 2"]);
/// let names: Vec<&str> = envs.iter().map(|e| e.name.as_str()).collect();
/// assert_eq!(names, ["Lemma 2", "Section 1"]);
/// assert!(envs.iter().all(|e| !e.section && e.no_statement.is_none()));
/// ```
pub fn implicit<'a>(names: impl IntoIterator<Item = &'a str>) -> Vec<EnvironmentSpec> {
    let mut out: Vec<EnvironmentSpec> = Vec::new();
    for n in names {
        if !out.iter().any(|e| e.name == n) {
            out.push(EnvironmentSpec {
                name: n.to_string(),
                section: false,
                no_statement: None,
            });
        }
    }
    out
}
