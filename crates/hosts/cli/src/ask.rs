//! Asking the lab's API and saying its answer the command line's way.
//!
//! A file-like input given as `catalogue:<id>` (or `example:<id>`) goes to
//! the API by name; any other path is read here (see [`crate::input`]).
//! Problems name the file by its path and arguments as options
//! (`--heading-deg`).

use std::path::{Path, PathBuf};

use kinolab_api::{Error, Files, Operation, Place, Source};
use serde_json::Value;

use crate::{Failure, input};

/// The file-like input as the API takes it.
pub(crate) fn source(path: &Path) -> Result<Source, Failure> {
    let shown = path.display().to_string();
    if shown.starts_with("catalogue:") || shown.starts_with("example:") {
        Ok(Source::Named(shown))
    } else {
        input::read(path).map(Source::Text)
    }
}

/// Files beside the input: a model's mounts, relative to the file that
/// mounts them.
struct Beside {
    input: PathBuf,
}

impl Files for Beside {
    fn read(&mut self, by: &str, name: &str) -> Result<(String, String), String> {
        let by = if by.is_empty() {
            self.input.clone()
        } else {
            PathBuf::from(by)
        };
        let path = by
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_default()
            .join(name);
        let text = input::read(&path).map_err(|Failure(m)| m)?;
        Ok((path.display().to_string(), text))
    }
}

/// Ask `operation`, whose file-like input (if any) came from `input`.
pub(crate) fn ask<O: Operation>(operation: &O, input: Option<&Path>) -> Result<Value, Failure> {
    let mut files = Beside {
        input: input.map(Path::to_path_buf).unwrap_or_default(),
    };
    kinolab_api::answer(operation, &mut files).map_err(|e| failure(e, input))
}

/// Arguments the command line takes by position, not as `--options`.
const POSITIONAL: [&str; 3] = ["legs", "gains", "feeds"];

/// An API error as one line: the file's path or the option, then what is wrong.
pub(crate) fn failure(e: Error, input: Option<&Path>) -> Failure {
    let shown = |role: &str| input.map_or_else(|| role.to_owned(), |p| p.display().to_string());
    Failure(match e.place {
        Place::Input(role) => format!("{}: {}", shown(role), e.message),
        Place::Argument(name) if POSITIONAL.contains(&name.as_str()) => {
            format!("{name}: {}", e.message)
        }
        Place::Argument(name) => format!("--{}: {}", name.replace('_', "-"), e.message),
        Place::Result => format!("{}: {}", shown("result"), e.message),
        Place::Told => e.message,
    })
}
