use std::fmt;

/// Bad input to a locomotion computation; the message names the field.
#[derive(Debug, Clone, PartialEq)]
pub struct LocomotionError {
    pub field: &'static str,
    pub message: String,
}

impl LocomotionError {
    pub(crate) fn new(field: &'static str, message: impl Into<String>) -> Self {
        Self {
            field,
            message: message.into(),
        }
    }

    /// An error for a value that must be finite and positive.
    pub(crate) fn check_positive(field: &'static str, value: f64) -> Result<f64, Self> {
        if value.is_finite() && value > 0.0 {
            Ok(value)
        } else {
            Err(Self::new(
                field,
                format!("must be a finite number above 0, got {value}"),
            ))
        }
    }
}

impl fmt::Display for LocomotionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.field, self.message)
    }
}

impl std::error::Error for LocomotionError {}
