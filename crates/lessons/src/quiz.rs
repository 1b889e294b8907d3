//! Quizzes: what a quiz block says, and how an answer is checked.

use std::fmt;

use crate::document::Inline;
use crate::error::LessonError;

/// A question that checks understanding, with its explanation.
#[derive(Debug, Clone, PartialEq)]
pub struct Quiz {
    pub question: Inline,
    pub kind: QuizKind,
    /// Shown once the learner has answered, right or wrong.
    pub explain: Inline,
}

/// The three kinds of question.
#[derive(Debug, Clone, PartialEq)]
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
}

/// A learner's answer.
#[derive(Debug, Clone, PartialEq)]
pub enum Answer {
    Single(usize),
    Multiple(Vec<bool>),
    Numeric(f64),
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
            _ => Err(AnswerError::WrongKind),
        }
    }

    /// The options of a choice question (empty for numeric ones).
    pub fn options(&self) -> &[Inline] {
        match &self.kind {
            QuizKind::Single { options, .. } | QuizKind::Multiple { options, .. } => options,
            QuizKind::Numeric { .. } => &[],
        }
    }
}

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
}

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
            other => {
                return Err(LessonError::new(
                    file,
                    line_no,
                    format!(
                        "unknown quiz key `{other}` (expected kind, question, explain, answer, tolerance or unit)"
                    ),
                ));
            }
        };
        *slot = Some(value);
    }
    Ok(raw)
}
