//! What a graded exercise says back to the learner.

use std::fmt;

use serde::Serialize;

/// The verdict on one attempt: whether the goal is met, and a sentence that
/// says what is right or what is still missing.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Feedback {
    pub met: bool,
    pub message: String,
}

impl Feedback {
    /// The goal is met.
    pub fn met(message: impl Into<String>) -> Self {
        Self {
            met: true,
            message: message.into(),
        }
    }

    /// Not yet: `message` says what is still missing.
    pub fn not_yet(message: impl Into<String>) -> Self {
        Self {
            met: false,
            message: message.into(),
        }
    }

    /// The attempt could not be checked (bad input): never counts as met.
    pub fn from_error(error: &impl fmt::Display) -> Self {
        Self::not_yet(error.to_string())
    }

    /// Met when `met`, with the message that fits.
    pub fn when(met: bool, yes: impl Into<String>, no: impl Into<String>) -> Self {
        if met {
            Self::met(yes)
        } else {
            Self::not_yet(no)
        }
    }
}

impl<E: fmt::Display> From<Result<Feedback, E>> for Feedback {
    fn from(result: Result<Feedback, E>) -> Self {
        result.unwrap_or_else(|e| Feedback::from_error(&e))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_never_count_as_met() {
        let bad: Result<Feedback, String> = Err("gains.k_rho: must be greater than 0".into());
        let f = Feedback::from(bad);
        assert!(!f.met);
        assert_eq!(f.message, "gains.k_rho: must be greater than 0");
        assert!(Feedback::when(true, "yes", "no").met);
        assert_eq!(Feedback::when(false, "yes", "no").message, "no");
    }
}
