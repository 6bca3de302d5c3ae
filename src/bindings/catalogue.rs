//! The paper's catalogue, built into the binary: every `*.toml` and `*.tex` file of
//! `identities/` as it was when the binary was built, so that `eulertop verify`, `prove`,
//! `audit` and `report` check the paper from any directory.  The files keep the names
//! they have in the repository (`identities/02-euler-top.toml`), so that positions and
//! reports are the same as those of `--catalogue identities`.
//!
//! ```
//! use eulertop::bindings::catalogue::{FILES, text};
//! assert!(FILES.iter().any(|(name, _)| *name == "identities/paper.toml"));
//! assert!(text("paper-macros.tex").is_some());
//! assert!(text("README.md").is_none());
//! ```

/// `(name, text)` of a file of `identities/`.
macro_rules! catalogue_file {
    ($name:literal) => {
        (
            concat!("identities/", $name),
            include_str!(concat!("../../identities/", $name)),
        )
    };
}

/// The built-in files, `(name, text)`, sorted by name as the loader reads a directory.
pub const FILES: &[(&str, &str)] = &[
    catalogue_file!("02-euler-top.toml"),
    catalogue_file!("03-discretizations.toml"),
    catalogue_file!("04-elliptic-coordinates.toml"),
    catalogue_file!("05-lax-su2.toml"),
    catalogue_file!("06-poisson.toml"),
    catalogue_file!("07-first-examples.toml"),
    catalogue_file!("08-veselov-moser.toml"),
    catalogue_file!("appendix.toml"),
    catalogue_file!("background.toml"),
    catalogue_file!("conventions.toml"),
    catalogue_file!("domains.toml"),
    catalogue_file!("environments.tex"),
    catalogue_file!("hypotheses.toml"),
    catalogue_file!("paper-macros.tex"),
    catalogue_file!("paper.toml"),
];

/// The text of the built-in file `name` (a file name, `conventions.toml`), if there is one.
pub fn text(name: &str) -> Option<&'static str> {
    FILES
        .iter()
        .find(|(n, _)| n.strip_prefix("identities/") == Some(name))
        .map(|(_, t)| *t)
}

/// Whether `paper` (a catalogue's `[paper]` table) is the paper of the built-in catalogue,
/// the one the model illustrates: the same title, authors and year.  The report draws the
/// model's figures only for it.
///
/// ```
/// use eulertop::bindings::catalogue::{is_this_paper, sources};
/// use eulertop::claims::catalogue::load_sources;
/// use eulertop::claims::registry::Registry;
/// let cat = load_sources(&sources(), eulertop::bindings::euler_top::registry().unwrap()).unwrap();
/// assert!(is_this_paper(cat.paper.as_ref()));
/// let mut other = cat.paper.clone().unwrap();
/// other.title = "Another paper".into();
/// assert!(!is_this_paper(Some(&other)));
/// assert!(!is_this_paper(None));
/// ```
pub fn is_this_paper(paper: Option<&crate::claims::catalogue::paper::Paper>) -> bool {
    let Some(p) = paper else {
        return false;
    };
    let Some(table) = text("paper.toml").and_then(|t| t.parse::<toml::Table>().ok()) else {
        return false;
    };
    let ours = &table["paper"];
    let authors: Vec<&str> = (ours.get("authors").and_then(|a| a.as_array()))
        .map(|a| a.iter().filter_map(|x| x.as_str()).collect())
        .unwrap_or_default();
    ours.get("title").and_then(|t| t.as_str()) == Some(p.title.as_str())
        && ours.get("year").and_then(|y| y.as_integer()) == Some(p.year)
        && authors == p.authors
}

/// The built-in `*.toml` files, `(name, text)`, for the loader.
pub fn sources() -> Vec<(String, String)> {
    FILES
        .iter()
        .filter(|(n, _)| n.ends_with(".toml"))
        .map(|(n, t)| (n.to_string(), t.to_string()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::FILES;

    /// Every `*.toml` and `*.tex` file of `identities/` is built in: a file added there
    /// and not here fails this test.
    #[test]
    fn every_catalogue_file_is_built_in() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("identities");
        let mut on_disk: Vec<String> = std::fs::read_dir(&dir)
            .unwrap()
            .filter_map(|e| e.ok())
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|n| n.ends_with(".toml") || n.ends_with(".tex"))
            .map(|n| format!("identities/{n}"))
            .collect();
        on_disk.sort();
        let built_in: Vec<String> = FILES.iter().map(|(n, _)| n.to_string()).collect();
        assert_eq!(built_in, on_disk);
    }
}
