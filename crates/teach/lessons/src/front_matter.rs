//! The front-matter between two `---` lines at the top of a lesson.
//!
//! A deliberately small format: `key: value` lines, and `key:` followed by
//! `  - item` lines for lists. Unknown keys are errors, so typos surface.

use serde::{Deserialize, Serialize};

#[cfg(feature = "markdown")]
use crate::error::LessonError;

/// What a lesson says about itself.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct FrontMatter {
    pub title: String,
    /// Estimated reading and playing time.
    pub minutes: u32,
    pub objectives: Vec<String>,
}

#[cfg(feature = "markdown")]
/// Which keys a file must have: lessons need all three, a unit's `unit.md`
/// only a title.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Required {
    Lesson,
    Unit,
}

#[cfg(feature = "markdown")]
/// Split `source` into its front-matter and body. Returns the parsed
/// front-matter, the body, and the 1-based line on which the body starts.
pub(crate) fn split(
    file: &str,
    source: &str,
    required: Required,
) -> Result<(FrontMatter, String, usize), LessonError> {
    let mut lines = source.lines().enumerate();
    if !matches!(lines.next(), Some((_, first)) if first.trim_end() == "---") {
        return Err(LessonError::new(
            file,
            1,
            "a lesson must start with a front-matter block opened by `---`",
        ));
    }
    let mut reader = Reader::new(file);
    let mut close = None;
    for (index, raw) in lines {
        let line = raw.trim_end();
        if line == "---" {
            close = Some(index + 1);
            break;
        }
        reader.line(index + 1, line)?;
    }
    let Some(close_line) = close else {
        return Err(LessonError::new(
            file,
            1,
            "the front-matter opened on line 1 is never closed by `---`",
        ));
    };
    let fm = reader.finish(close_line, required)?;
    let body: Vec<&str> = source.lines().skip(close_line).collect();
    Ok((fm, body.join("\n"), close_line + 1))
}

#[cfg(feature = "markdown")]
/// Reads front-matter lines one at a time, remembering which keys it saw.
struct Reader<'a> {
    file: &'a str,
    fm: FrontMatter,
    seen_title: bool,
    seen_minutes: bool,
    in_objectives: bool,
}

#[cfg(feature = "markdown")]
impl<'a> Reader<'a> {
    fn new(file: &'a str) -> Self {
        Self {
            file,
            fm: FrontMatter::default(),
            seen_title: false,
            seen_minutes: false,
            in_objectives: false,
        }
    }

    fn error(&self, line: usize, message: impl Into<String>) -> LessonError {
        LessonError::new(self.file, line, message)
    }

    /// One line inside the block: a list item, a `key: value`, or blank.
    fn line(&mut self, line_no: usize, line: &str) -> Result<(), LessonError> {
        if line.trim().is_empty() {
            return Ok(());
        }
        if let Some(item) = line.trim_start().strip_prefix("- ") {
            if !self.in_objectives || !line.starts_with(' ') {
                return Err(self.error(
                    line_no,
                    "a list item here must be indented under `objectives:`",
                ));
            }
            self.fm.objectives.push(item.trim().to_owned());
            return Ok(());
        }
        self.in_objectives = false;
        let Some((key, value)) = line.split_once(':') else {
            return Err(self.error(
                line_no,
                format!("expected `key: value` in the front-matter, found `{line}`"),
            ));
        };
        self.key(line_no, key.trim(), value.trim())
    }

    fn key(&mut self, line_no: usize, key: &str, value: &str) -> Result<(), LessonError> {
        match key {
            "title" if value.is_empty() => Err(self.error(line_no, "`title` is empty")),
            "title" => {
                self.fm.title = value.to_owned();
                self.seen_title = true;
                Ok(())
            }
            "minutes" => {
                self.fm.minutes = value.parse().map_err(|_| {
                    self.error(
                        line_no,
                        format!("`minutes` must be a whole number, found `{value}`"),
                    )
                })?;
                self.seen_minutes = true;
                Ok(())
            }
            "objectives" if !value.is_empty() => Err(self.error(
                line_no,
                "`objectives` takes a list: put each item on its own `  - ` line",
            )),
            "objectives" => {
                self.in_objectives = true;
                Ok(())
            }
            other => Err(self.error(
                line_no,
                format!(
                    "unknown front-matter key `{other}` (expected title, minutes or objectives)"
                ),
            )),
        }
    }

    /// Check the required keys once the block is closed on `close_line`.
    fn finish(self, close_line: usize, required: Required) -> Result<FrontMatter, LessonError> {
        let missing = if !self.seen_title {
            Some("the front-matter has no `title`")
        } else if required == Required::Lesson && !self.seen_minutes {
            Some("the front-matter has no `minutes`")
        } else if required == Required::Lesson && self.fm.objectives.is_empty() {
            Some("the front-matter has no `objectives` (list at least one)")
        } else {
            None
        };
        match missing {
            Some(message) => Err(self.error(close_line, message)),
            None => Ok(self.fm),
        }
    }
}
