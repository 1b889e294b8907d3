use std::fmt;

/// Bad input to a mechanism computation. `field` is the path of the
/// offending value (`joints[2].alpha_deg`, `q`, `frame`), so a message
/// always says exactly what to fix.
#[derive(Debug, Clone, PartialEq)]
pub struct MechanismError {
    pub field: String,
    pub message: String,
}

impl MechanismError {
    pub fn new(field: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            field: field.into(),
            message: message.into(),
        }
    }
}

impl fmt::Display for MechanismError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.field.is_empty() {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.field, self.message)
        }
    }
}

impl std::error::Error for MechanismError {}

/// `value` if it is a finite number, else an error naming `field`.
pub(crate) fn finite(field: &str, value: f64) -> Result<f64, MechanismError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(MechanismError::new(
            field,
            format!("must be a finite number, got {value}"),
        ))
    }
}
