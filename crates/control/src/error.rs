use std::fmt;

/// Bad input to a motion-control computation. `field` is the path of the
/// offending value (`gains.k_beta`, `start.theta_deg`, `dt`), so a message
/// always says exactly what to fix.
#[derive(Debug, Clone, PartialEq)]
pub struct ControlError {
    pub field: String,
    pub message: String,
}

impl ControlError {
    pub(crate) fn new(field: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            field: field.into(),
            message: message.into(),
        }
    }
}

impl fmt::Display for ControlError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.field.is_empty() {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.field, self.message)
        }
    }
}

impl std::error::Error for ControlError {}

impl From<kinolab_wheels::WheelsError> for ControlError {
    fn from(e: kinolab_wheels::WheelsError) -> Self {
        Self::new(format!("robot.{}", e.field), e.message)
    }
}

/// `value` if it is a finite number, else an error naming `field`.
pub(crate) fn finite(field: &str, value: f64) -> Result<f64, ControlError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ControlError::new(
            field,
            format!("must be a finite number, got {value}"),
        ))
    }
}

/// `value` if it is finite and > 0, else an error naming `field`.
pub(crate) fn positive(field: &str, value: f64) -> Result<f64, ControlError> {
    if finite(field, value)? > 0.0 {
        Ok(value)
    } else {
        Err(ControlError::new(
            field,
            format!("must be greater than 0, got {value}"),
        ))
    }
}
