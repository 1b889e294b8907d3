//! What went wrong, and in which of the inputs.
//!
//! The hosts name inputs their own way: the command line says the file's
//! path or `--option`, JavaScript the argument's name. An [`Error`] keeps
//! the input's role and the problem apart so each host can do that.

use std::fmt;

use kinolab_common::FieldError;

/// Which input a problem is in.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Place {
    /// A file-like input, by its role in the call: `robot`, `model`,
    /// `run`, `field`, `world`, `gait`, `cpg`, `system`, `lesson`.
    Input(&'static str),
    /// A plain argument, by its name (`q`, `twist`, `cell`, `heading_deg`):
    /// the command line writes it as an option (`--heading-deg`).
    Argument(String),
    /// The answer itself (a number that overflowed).
    Result,
    /// The message names its own place (a lesson file and its line).
    Told,
}

/// A problem with one input of a call.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error {
    pub place: Place,
    /// What is wrong; for an input, it starts with the field inside it
    /// (`wheels[0].radius: …`).
    pub message: String,
}

impl Error {
    /// A problem in the file-like input `role`.
    pub fn input(role: &'static str, problem: FieldError) -> Self {
        Self {
            place: Place::Input(role),
            message: problem.to_string(),
        }
    }

    /// A problem with the argument `name`.
    pub fn argument(name: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            place: Place::Argument(name.into()),
            message: message.into(),
        }
    }

    /// A core error whose field is the argument's own name (`cell`,
    /// `samples`); one with another field belongs to `role`'s input.
    pub fn argument_or_input(
        arguments: &[&str],
        role: &'static str,
    ) -> impl Fn(FieldError) -> Self {
        move |e: FieldError| match arguments.iter().find(|a| **a == e.field) {
            Some(name) => Self::argument(*name, e.message),
            None => Self::input(role, e),
        }
    }

    /// A problem whose message already says where it is.
    pub fn told(message: impl Into<String>) -> Self {
        Self {
            place: Place::Told,
            message: message.into(),
        }
    }

    /// A problem with the answer.
    pub fn result(message: impl Into<String>) -> Self {
        Self {
            place: Place::Result,
            message: message.into(),
        }
    }
}

impl fmt::Display for Error {
    /// The JavaScript way: `argument: message`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.place {
            Place::Input(role) => write!(f, "{role}: {}", self.message),
            Place::Argument(name) => write!(f, "{name}: {}", self.message),
            Place::Result => write!(f, "result: {}", self.message),
            Place::Told => write!(f, "{}", self.message),
        }
    }
}

impl std::error::Error for Error {}
