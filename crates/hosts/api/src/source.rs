//! How a file-like input arrives: by name (a catalogue id) or as text.
//!
//! The command line reads a file into [`Source::Text`] and passes
//! `catalogue:<id>` (or `example:<id>`) on as [`Source::Named`]; JavaScript
//! passes an object or JSON text as text and any other string as a name.
//! Each kind of input has one loader here, so a name means the same thing
//! to both hosts.

use kinolab_common::FieldError;

use crate::Error;

/// A file-like input.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Source {
    /// A catalogue id, with or without its `catalogue:` (or `example:`)
    /// prefix; for robots also a compact layout code.
    Named(String),
    /// A file's text.
    Text(String),
}

/// The largest input text: far above any file a person writes.
pub const MAX_TEXT_BYTES: usize = 4 * 1024 * 1024;

/// Reads the files an input names (a model's mounts), for hosts that have
/// files.
pub trait Files {
    /// The file `name` that the file called `by` names (`by` is empty for
    /// the call's own input): the name to report it by, and its text.
    fn read(&mut self, by: &str, name: &str) -> Result<(String, String), String>;
}

/// A host without files: every file named is refused.
#[derive(Debug, Default, Clone, Copy)]
pub struct NoFiles;

impl Files for NoFiles {
    fn read(&mut self, _by: &str, name: &str) -> Result<(String, String), String> {
        Err(format!(
            "cannot open the file `{name}` here; mount `catalogue:<id>` instead"
        ))
    }
}

impl Source {
    /// The id of a name, without `prefix` (`catalogue:`).
    fn id<'a>(name: &'a str, prefix: &str) -> &'a str {
        let name = name.trim();
        name.strip_prefix(prefix).unwrap_or(name)
    }

    /// Load the input with `read` (its text) or `named` (its id without
    /// `prefix`); problems belong to the input `role`.
    pub(crate) fn load<T>(
        &self,
        role: &'static str,
        prefix: &str,
        read: impl FnOnce(&str) -> Result<T, FieldError>,
        named: impl FnOnce(&str) -> Result<T, FieldError>,
    ) -> Result<T, Error> {
        match self {
            // A compact code names the part of it that is wrong; a field
            // that only repeats the input's role says nothing more.
            Source::Named(name) => named(Self::id(name, prefix)).map_err(|e| {
                if e.field == role {
                    FieldError::new("", e.message)
                } else {
                    e
                }
            }),
            Source::Text(text) => within_bound(text).and_then(|()| read(text)),
        }
        .map_err(|e| Error::input(role, e))
    }

    /// Load an input that has no catalogue: a name is refused.
    pub(crate) fn file_only<T>(
        &self,
        role: &'static str,
        what: &str,
        read: impl FnOnce(&str) -> Result<T, FieldError>,
    ) -> Result<T, Error> {
        self.load(role, "", read, |name| {
            Err(FieldError::new(
                "",
                format!("`{name}` is not {what}; give the file's text"),
            ))
        })
    }
}

/// Text within [`MAX_TEXT_BYTES`].
fn within_bound(text: &str) -> Result<(), FieldError> {
    if text.len() > MAX_TEXT_BYTES {
        Err(FieldError::new(
            "",
            format!(
                "larger than the input bound of {} MB",
                MAX_TEXT_BYTES / (1024 * 1024)
            ),
        ))
    } else {
        Ok(())
    }
}

/// A named catalogue entry that does not exist, listing those that do.
pub(crate) fn unknown(what: &str, id: &str, known: &[&str]) -> FieldError {
    FieldError::new(
        "",
        format!("no {what} called `{id}` (known: {})", known.join(", ")),
    )
}

/// The most script files one input may name.
const MAX_SCRIPT_FILES: usize = 64;

impl Source {
    /// The input with every learner's script it names by file read in:
    /// an object `{"kind": "script", "path": "law.rhai"}` anywhere in it
    /// becomes `{"kind": "script", "source": "<the file's text>"}`, the
    /// file found by `files` beside the input. Text that is not JSON is
    /// left for the input's own reader to refuse.
    pub(crate) fn with_scripts(
        &self,
        role: &'static str,
        files: &mut dyn Files,
    ) -> Result<Source, Error> {
        let Source::Text(text) = self else {
            return Ok(self.clone());
        };
        let Ok(mut value) = serde_json::from_str::<serde_json::Value>(text) else {
            return Ok(self.clone());
        };
        let mut read = 0;
        inline(&mut value, "", files, &mut read).map_err(|e| Error::input(role, e))?;
        Ok(if read == 0 {
            self.clone()
        } else {
            Source::Text(value.to_string())
        })
    }
}

fn inline(
    value: &mut serde_json::Value,
    at: &str,
    files: &mut dyn Files,
    read: &mut usize,
) -> Result<(), FieldError> {
    use serde_json::Value;
    match value {
        Value::Object(map) => {
            let script = map.get("kind").and_then(Value::as_str) == Some("script");
            if let (true, Some(Value::String(path))) = (script, map.get("path")) {
                let field = format!("{at}.path").trim_start_matches('.').to_owned();
                if map.contains_key("source") {
                    return Err(FieldError::new(field, "give `source` or `path`, not both"));
                }
                *read += 1;
                if *read > MAX_SCRIPT_FILES {
                    return Err(FieldError::new(
                        field,
                        format!("more than {MAX_SCRIPT_FILES} script files"),
                    ));
                }
                let (_, text) = files
                    .read("", path)
                    .map_err(|e| FieldError::new(field, e))?;
                map.remove("path");
                map.insert("source".into(), Value::String(text));
                return Ok(());
            }
            for (key, v) in map.iter_mut() {
                inline(v, &format!("{at}.{key}"), files, read)?;
            }
        }
        Value::Array(items) => {
            for (i, v) in items.iter_mut().enumerate() {
                inline(v, &format!("{at}[{i}]"), files, read)?;
            }
        }
        _ => {}
    }
    Ok(())
}
