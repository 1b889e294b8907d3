//! Kinolab's lessons: the file format and the lessons themselves.
//!
//! A lesson is a Markdown file with a small front-matter (see
//! `lessons/README.md`). This crate turns it into a [`Lesson`]: a list of
//! [`Block`]s that a user interface can render without knowing Markdown,
//! with formulas already parsed ([`math`]), widgets named ([`WidgetSpec`])
//! and quizzes ready to check ([`Quiz::check`]). It is pure Rust, so it runs
//! natively, in the browser and in the command-line tool alike.

pub mod bundled;
mod course;
mod document;
mod error;
mod front_matter;
mod pack;
mod parse;
mod quiz;
pub mod summary;

/// Formulas, parsed by the formula crate.
pub use kinolab_formula as math;

pub use course::{Course, Lesson, Unit, address_part, image_path};
pub use document::{Align, Block, Inline, Span, TextStyle, WidgetSpec, plain_text};
pub use error::LessonError;
pub use front_matter::FrontMatter;
pub use pack::LessonFiles;
pub use parse::{parse_inline, parse_lesson};
pub use quiz::{Answer, AnswerError, Quiz, QuizKind, SortItem};
