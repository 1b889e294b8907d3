use std::fmt;

/// Bad input to a wheeled-robot computation. `field` is the path of the
/// offending value (`wheels[2].radius`, `twist`, `layout`), so a message can
/// always say exactly what to fix.
#[derive(Debug, Clone, PartialEq)]
pub struct WheelsError {
    pub field: String,
    pub message: String,
}

impl WheelsError {
    pub(crate) fn new(field: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            field: field.into(),
            message: message.into(),
        }
    }
}

impl fmt::Display for WheelsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.field.is_empty() {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.field, self.message)
        }
    }
}

impl std::error::Error for WheelsError {}

/// `value` if it is a finite number, else an error naming `field`.
pub(crate) fn finite(field: impl Into<String>, value: f64) -> Result<f64, WheelsError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(WheelsError::new(
            field,
            format!("must be a finite number, got {value}"),
        ))
    }
}
