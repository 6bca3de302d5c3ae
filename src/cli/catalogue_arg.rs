//! Where a command's catalogue comes from: the directory (or file) given by
//! `--catalogue`, or, without it, the paper's catalogue built into the binary
//! ([`crate::bindings::catalogue`]), so that the commands work from any directory.
//!
//! ```
//! use eulertop::cli::catalogue_arg::CatalogueSource;
//! let built_in = CatalogueSource::new(None);
//! assert_eq!(built_in.to_string(), "the paper's built-in catalogue");
//! let cat = built_in.load().unwrap();
//! assert!(cat.environment("Theorem 3").is_some());
//! assert!(built_in.text("paper-macros.tex").unwrap().is_some());
//! let e = CatalogueSource::new(Some("no-such-directory")).load().unwrap_err();
//! assert!(e.to_string().starts_with("no-such-directory: cannot read the catalogue"), "{e}");
//! ```

use super::CliError;
use super::cert_source::RawCatalogue;
use crate::claims::catalogue::source::read_text;
use crate::claims::catalogue::{Catalogue, load_dir, load_sources};
use std::path::PathBuf;

/// A catalogue directory or file, or the built-in catalogue.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CatalogueSource {
    /// `--catalogue DIR|FILE`.
    Path(PathBuf),
    /// The paper's catalogue, built into the binary.
    BuiltIn,
}

impl std::fmt::Display for CatalogueSource {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CatalogueSource::Path(p) => write!(f, "{}", p.display()),
            CatalogueSource::BuiltIn => write!(f, "the paper's built-in catalogue"),
        }
    }
}

impl CatalogueSource {
    /// The source `--catalogue` names, or the built-in catalogue without it.
    pub fn new(arg: Option<&str>) -> CatalogueSource {
        match arg {
            Some(p) => CatalogueSource::Path(PathBuf::from(p)),
            None => CatalogueSource::BuiltIn,
        }
    }

    /// Loads the catalogue with the model's functions; load errors become [`CliError`].
    pub fn load(&self) -> Result<Catalogue, CliError> {
        let reg = crate::bindings::euler_top::registry().map_err(CliError::new)?;
        match self {
            CatalogueSource::Path(p) => load_dir(p, reg),
            CatalogueSource::BuiltIn => load_sources(&crate::bindings::catalogue::sources(), reg),
        }
        .map_err(|e| CliError(e.to_string()))
    }

    /// The text of the catalogue's file `name` (`paper-macros.tex`), `None` when the
    /// catalogue has no such file (or is one file).
    pub fn text(&self, name: &str) -> Result<Option<String>, CliError> {
        let dir = match self {
            CatalogueSource::BuiltIn => {
                return Ok(crate::bindings::catalogue::text(name).map(str::to_string));
            }
            CatalogueSource::Path(p) => p,
        };
        let path = dir.join(name);
        if !dir.is_dir() || (!path.exists() && path.symlink_metadata().is_err()) {
            return Ok(None);
        }
        read_text(&path)
            .map(Some)
            .map_err(|e| CliError(format!("{}: {e}", path.display())))
    }

    /// The catalogue's files read as TOML values (the source lines of a certificate).
    pub fn raw(&self) -> Result<RawCatalogue, CliError> {
        match self {
            CatalogueSource::Path(p) => RawCatalogue::read(&p.display().to_string()),
            CatalogueSource::BuiltIn => {
                RawCatalogue::from_sources(&crate::bindings::catalogue::sources())
            }
        }
    }
}
