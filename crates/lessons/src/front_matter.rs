//! The front-matter between two `---` lines at the top of a lesson.
//!
//! A deliberately small format: `key: value` lines, and `key:` followed by
//! `  - item` lines for lists. Unknown keys are errors, so typos surface.

use crate::error::LessonError;

/// What a lesson says about itself.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct FrontMatter {
    pub title: String,
    /// Estimated reading and playing time.
    pub minutes: u32,
    pub objectives: Vec<String>,
}

/// Which keys a file must have: lessons need all three, a unit's `unit.md`
/// only a title.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Required {
    Lesson,
    Unit,
}

/// Split `source` into its front-matter and body. Returns the parsed
/// front-matter, the body, and the 1-based line on which the body starts.
pub(crate) fn split(
    file: &str,
    source: &str,
    required: Required,
) -> Result<(FrontMatter, String, usize), LessonError> {
    let mut lines = source.lines().enumerate();
    match lines.next() {
        Some((_, first)) if first.trim_end() == "---" => {}
        _ => {
            return Err(LessonError::new(
                file,
                1,
                "a lesson must start with a front-matter block opened by `---`",
            ));
        }
    }
    let mut fm = FrontMatter::default();
    let mut seen_title = false;
    let mut seen_minutes = false;
    let mut in_objectives = false;
    let mut close = None;
    for (index, raw) in lines.by_ref() {
        let line_no = index + 1;
        let line = raw.trim_end();
        if line == "---" {
            close = Some(line_no);
            break;
        }
        if line.trim().is_empty() {
            continue;
        }
        if let Some(item) = line.trim_start().strip_prefix("- ") {
            if !in_objectives || !line.starts_with(' ') {
                return Err(LessonError::new(
                    file,
                    line_no,
                    "a list item here must be indented under `objectives:`",
                ));
            }
            fm.objectives.push(item.trim().to_owned());
            continue;
        }
        in_objectives = false;
        let Some((key, value)) = line.split_once(':') else {
            return Err(LessonError::new(
                file,
                line_no,
                format!("expected `key: value` in the front-matter, found `{line}`"),
            ));
        };
        let value = value.trim();
        match key.trim() {
            "title" => {
                if value.is_empty() {
                    return Err(LessonError::new(file, line_no, "`title` is empty"));
                }
                fm.title = value.to_owned();
                seen_title = true;
            }
            "minutes" => {
                fm.minutes = value.parse().map_err(|_| {
                    LessonError::new(
                        file,
                        line_no,
                        format!("`minutes` must be a whole number, found `{value}`"),
                    )
                })?;
                seen_minutes = true;
            }
            "objectives" => {
                if !value.is_empty() {
                    return Err(LessonError::new(
                        file,
                        line_no,
                        "`objectives` takes a list: put each item on its own `  - ` line",
                    ));
                }
                in_objectives = true;
            }
            other => {
                return Err(LessonError::new(
                    file,
                    line_no,
                    format!(
                        "unknown front-matter key `{other}` (expected title, minutes or objectives)"
                    ),
                ));
            }
        }
    }
    let Some(close_line) = close else {
        return Err(LessonError::new(
            file,
            1,
            "the front-matter opened on line 1 is never closed by `---`",
        ));
    };
    if !seen_title {
        return Err(LessonError::new(
            file,
            close_line,
            "the front-matter has no `title`",
        ));
    }
    if required == Required::Lesson {
        if !seen_minutes {
            return Err(LessonError::new(
                file,
                close_line,
                "the front-matter has no `minutes`",
            ));
        }
        if fm.objectives.is_empty() {
            return Err(LessonError::new(
                file,
                close_line,
                "the front-matter has no `objectives` (list at least one)",
            ));
        }
    }
    let body: Vec<&str> = source.lines().skip(close_line).collect();
    Ok((fm, body.join("\n"), close_line + 1))
}
