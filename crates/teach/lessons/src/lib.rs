//! Kinolab's lessons: the file format and the lessons themselves.
//!
//! A lesson is a Markdown file with a small front-matter (see
//! `lessons/README.md`). This crate turns it into a [`Lesson`]: a list of
//! [`Block`]s that a user interface can render without knowing Markdown,
//! with formulas already parsed ([`math`]), widgets named ([`WidgetSpec`])
//! and quizzes ready to check ([`Quiz::check`]). It is pure Rust, so it runs
//! natively, in the browser and in the command-line tool alike.
//!
//! The web lab reads no Markdown (the `markdown` feature is off there): its
//! course comes prepared, parsed and checked when the site is built.

pub mod bundled;
mod course;
mod document;
mod error;
#[cfg(feature = "pack")]
mod folder;
mod front_matter;
mod pack;
#[cfg(feature = "markdown")]
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
#[cfg(feature = "pack")]
pub use pack::web_pack;
#[cfg(feature = "markdown")]
pub use parse::{parse_inline, parse_lesson};
pub use quiz::{Answer, AnswerError, Quiz, QuizKind, SortItem};
