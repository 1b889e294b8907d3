//! Quizzes: what a quiz block says, and how an answer is checked.

use std::fmt;

use serde::{Deserialize, Serialize};

use crate::document::Inline;
#[cfg(feature = "markdown")]
use crate::error::LessonError;

/// A question that checks understanding, with its explanation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Quiz {
    pub question: Inline,
    pub kind: QuizKind,
    /// Shown once the learner has answered, right or wrong.
    pub explain: Inline,
}

/// The kinds of question.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum QuizKind {
    /// Pick the one right option.
    Single {
        options: Vec<Inline>,
        correct: usize,
    },
    /// Tick every right option (and none of the wrong ones).
    Multiple {
        options: Vec<Inline>,
        correct: Vec<bool>,
    },
    /// Type a number; right when within `tolerance` of `answer`.
    Numeric {
        answer: f64,
        tolerance: f64,
        unit: Option<String>,
    },
    /// Place every item into one of the named bins.
    Sort {
        bins: Vec<String>,
        items: Vec<SortItem>,
    },
}

/// An item of a sorting question: its text, the bin it belongs in, and
/// why (shown beside it once checked).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SortItem {
    pub text: Inline,
    pub bin: usize,
    pub why: Option<Inline>,
}

/// A learner's answer.
#[derive(Debug, Clone, PartialEq)]
pub enum Answer {
    Single(usize),
    Multiple(Vec<bool>),
    Numeric(f64),
    /// The bin chosen for each item, in order.
    Sort(Vec<usize>),
}

/// Why an answer could not be checked.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum AnswerError {
    /// A single-choice answer for a numeric question, say.
    WrongKind,
    /// An option index past the end, or a tick list of the wrong length.
    OutOfRange,
    /// The number typed is NaN or infinite.
    NotFinite,
}

impl fmt::Display for AnswerError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            AnswerError::WrongKind => "this answer does not fit the kind of question",
            AnswerError::OutOfRange => "the answer names an option the question does not have",
            AnswerError::NotFinite => "the answer must be a finite number",
        })
    }
}

impl std::error::Error for AnswerError {}

impl Quiz {
    /// Whether `answer` is right.
    pub fn check(&self, answer: &Answer) -> Result<bool, AnswerError> {
        match (&self.kind, answer) {
            (QuizKind::Single { options, correct }, Answer::Single(pick)) => {
                if *pick >= options.len() {
                    return Err(AnswerError::OutOfRange);
                }
                Ok(pick == correct)
            }
            (QuizKind::Multiple { correct, .. }, Answer::Multiple(ticks)) => {
                if ticks.len() != correct.len() {
                    return Err(AnswerError::OutOfRange);
                }
                Ok(ticks == correct)
            }
            (
                QuizKind::Numeric {
                    answer, tolerance, ..
                },
                Answer::Numeric(value),
            ) => {
                if !value.is_finite() {
                    return Err(AnswerError::NotFinite);
                }
                // A hair of slack so that a tolerance of 0 still accepts the
                // decimal the author wrote.
                let slack = tolerance + 1e-9 * answer.abs().max(1.0);
                Ok((value - answer).abs() <= slack)
            }
            (QuizKind::Sort { .. }, Answer::Sort(_)) => {
                Ok(self.sort_marks(answer)?.iter().all(|right| *right))
            }
            _ => Err(AnswerError::WrongKind),
        }
    }

    /// For a sorting question, whether each item is in its bin.
    pub fn sort_marks(&self, answer: &Answer) -> Result<Vec<bool>, AnswerError> {
        match (&self.kind, answer) {
            (QuizKind::Sort { bins, items }, Answer::Sort(picks)) => {
                if picks.len() != items.len() || picks.iter().any(|p| *p >= bins.len()) {
                    return Err(AnswerError::OutOfRange);
                }
                Ok(items.iter().zip(picks).map(|(i, p)| i.bin == *p).collect())
            }
            _ => Err(AnswerError::WrongKind),
        }
    }

    /// The options of a choice question (empty for numeric ones).
    pub fn options(&self) -> &[Inline] {
        match &self.kind {
            QuizKind::Single { options, .. } | QuizKind::Multiple { options, .. } => options,
            QuizKind::Numeric { .. } | QuizKind::Sort { .. } => &[],
        }
    }
}

#[cfg(feature = "markdown")]
/// The raw lines of a quiz block, before inline Markdown is parsed.
#[derive(Debug, Default)]
pub(crate) struct RawQuiz {
    pub kind: Option<String>,
    pub question: Option<String>,
    pub explain: Option<String>,
    pub answer: Option<(String, usize)>,
    pub tolerance: Option<(String, usize)>,
    pub unit: Option<String>,
    /// Option text and whether it is right.
    pub options: Vec<(String, bool)>,
    /// Sorting: the bins, and each item as (text, bin name, why, line).
    pub bins: Option<(String, usize)>,
    pub items: Vec<SortLine>,
}

#[cfg(feature = "markdown")]
/// A sorting item as written: `- text => bin :: why`.
#[derive(Debug)]
pub(crate) struct SortLine {
    pub text: String,
    pub bin: String,
    pub why: Option<String>,
    pub line: usize,
}

#[cfg(feature = "markdown")]
/// Read a quiz block's lines. `first_line` is the file line of the block's
/// first content line.
pub(crate) fn read_raw(file: &str, body: &str, first_line: usize) -> Result<RawQuiz, LessonError> {
    let mut raw = RawQuiz::default();
    for (offset, line) in body.lines().enumerate() {
        let line_no = first_line + offset;
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        if let Some(rest) = line.strip_prefix("- [") {
            let (mark, text) = rest.split_at_checked(2).unwrap_or(("", ""));
            let right = match mark {
                "x]" | "X]" => true,
                " ]" => false,
                _ => {
                    return Err(LessonError::new(
                        file,
                        line_no,
                        "an option must start with `- [ ]` (wrong) or `- [x]` (right)",
                    ));
                }
            };
            let text = text.trim();
            if text.is_empty() {
                return Err(LessonError::new(file, line_no, "an option has no text"));
            }
            raw.options.push((text.to_owned(), right));
            continue;
        }
        if let Some(rest) = line.strip_prefix("- ") {
            let Some((text, target)) = rest.split_once("=>") else {
                return Err(LessonError::new(
                    file,
                    line_no,
                    "a sorting item is `- text => bin` (optionally `:: why`)",
                ));
            };
            let (bin, why) = match target.split_once("::") {
                Some((bin, why)) => (bin, Some(why.trim().to_owned())),
                None => (target, None),
            };
            raw.items.push(SortLine {
                text: text.trim().to_owned(),
                bin: bin.trim().to_owned(),
                why,
                line: line_no,
            });
            continue;
        }
        let Some((key, value)) = line.split_once(':') else {
            return Err(LessonError::new(
                file,
                line_no,
                format!("expected `key: value` or an option `- [ ] …` in the quiz, found `{line}`"),
            ));
        };
        let value = value.trim().to_owned();
        let slot = match key.trim() {
            "kind" => &mut raw.kind,
            "question" => &mut raw.question,
            "explain" => &mut raw.explain,
            "unit" => &mut raw.unit,
            "answer" => {
                raw.answer = Some((value, line_no));
                continue;
            }
            "tolerance" => {
                raw.tolerance = Some((value, line_no));
                continue;
            }
            "bins" => {
                raw.bins = Some((value, line_no));
                continue;
            }
            other => {
                return Err(LessonError::new(
                    file,
                    line_no,
                    format!(
                        "unknown quiz key `{other}` (expected kind, question, explain, answer, tolerance, unit or bins)"
                    ),
                ));
            }
        };
        *slot = Some(value);
    }
    Ok(raw)
}
