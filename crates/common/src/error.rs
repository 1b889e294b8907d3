//! Bad input, named by where it is.
//!
//! Every file and option the lab reads reports problems as a [`FieldError`]:
//! the path of the offending value as the file spells it
//! (`wheels[2].radius`, `controller.k_rho`, `twist`) and what is wrong with
//! it, so a message always says exactly what to fix.

use std::fmt;

use serde::de::DeserializeOwned;

/// A problem with one input value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FieldError {
    /// Where the value is, as the input spells it; empty for the input as a whole.
    pub field: String,
    pub message: String,
}

impl FieldError {
    pub fn new(field: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            field: field.into(),
            message: message.into(),
        }
    }

    /// The same problem seen from a containing value: `robot` turns
    /// `wheels[0].radius` into `robot.wheels[0].radius`.
    pub fn within(self, parent: &str) -> Self {
        let field = match (parent.is_empty(), self.field.is_empty()) {
            (true, _) => self.field,
            (false, true) => parent.to_owned(),
            (false, false) if self.field.starts_with('[') => format!("{parent}{}", self.field),
            (false, false) => format!("{parent}.{}", self.field),
        };
        Self { field, ..self }
    }

    /// The same problem with its field renamed when it starts with `from`
    /// (say `start` → `starts[3]`, for one run of a batch).
    pub fn renamed(self, from: &str, to: &str) -> Self {
        match self.field.strip_prefix(from) {
            Some(rest) => Self {
                field: format!("{to}{rest}"),
                ..self
            },
            None => self,
        }
    }
}

impl fmt::Display for FieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.field.is_empty() {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.field, self.message)
        }
    }
}

impl std::error::Error for FieldError {}

/// `value` if it is a finite number, else an error naming `field`.
pub fn finite(field: impl Into<String>, value: f64) -> Result<f64, FieldError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(FieldError::new(
            field,
            format!("must be a finite number, got {value}"),
        ))
    }
}

/// `value` if it is finite and greater than 0, else an error naming `field`.
pub fn positive(field: impl Into<String>, value: f64) -> Result<f64, FieldError> {
    let field = field.into();
    if finite(field.as_str(), value)? > 0.0 {
        Ok(value)
    } else {
        Err(FieldError::new(
            field,
            format!("must be greater than 0, got {value}"),
        ))
    }
}

/// `value` if it is finite and not negative, else an error naming `field`.
pub fn non_negative(field: impl Into<String>, value: f64) -> Result<f64, FieldError> {
    let field = field.into();
    if finite(field.as_str(), value)? >= 0.0 {
        Ok(value)
    } else {
        Err(FieldError::new(
            field,
            format!("must not be negative, got {value}"),
        ))
    }
}

/// `value` if it is finite and within `[lo, hi]`, else an error naming `field`.
pub fn in_range(field: impl Into<String>, value: f64, lo: f64, hi: f64) -> Result<f64, FieldError> {
    let field = field.into();
    if (lo..=hi).contains(&finite(field.as_str(), value)?) {
        Ok(value)
    } else {
        Err(FieldError::new(
            field,
            format!("must be from {lo} to {hi}, got {value}"),
        ))
    }
}

/// Read JSON text into `T`. A problem names the JSON path of the value
/// (`wheels[2].gamma_deg`) and keeps serde's line and column, so syntax
/// errors can be found too.
pub fn from_json<T: DeserializeOwned>(text: &str) -> Result<T, FieldError> {
    let de = &mut serde_json::Deserializer::from_str(text);
    serde_path_to_error::deserialize(de).map_err(|e| {
        let path = e.path().to_string();
        let field = if path == "." { String::new() } else { path };
        FieldError::new(field, e.into_inner().to_string())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Wheel {
        radius: f64,
    }

    #[derive(Debug, serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Robot {
        wheels: Vec<Wheel>,
    }

    #[test]
    fn json_errors_name_the_path_and_the_position() {
        let e = from_json::<Robot>(r#"{"wheels": [{"radius": 1}, {"radius": "x"}]}"#).unwrap_err();
        assert_eq!(e.field, "wheels[1].radius");
        assert!(e.message.contains("line 1 column"), "{e}");
        let e = from_json::<Robot>("{\"wheels\": [\n{\"radius\": 1,}]}").unwrap_err();
        assert!(e.message.contains("line 2"), "{e}");
        let e = from_json::<Robot>(r#"{"wheel": []}"#).unwrap_err();
        assert!(e.to_string().contains("unknown field `wheel`"), "{e}");
    }

    #[test]
    fn paths_nest_and_rename() {
        let e = FieldError::new("wheels[0].radius", "must be greater than 0, got 0");
        assert_eq!(
            e.clone().within("robot").to_string(),
            "robot.wheels[0].radius: must be greater than 0, got 0"
        );
        assert_eq!(FieldError::new("[2]", "x").within("q").field, "q[2]");
        assert_eq!(FieldError::new("", "x").within("robot").field, "robot");
        assert_eq!(e.within("").field, "wheels[0].radius");
        assert_eq!(
            FieldError::new("start.x", "bad")
                .renamed("start", "starts[3]")
                .field,
            "starts[3].x"
        );
        assert_eq!(FieldError::new("", "whole").to_string(), "whole");
    }

    #[test]
    fn number_checks_name_the_field() {
        assert_eq!(finite("dt", 0.5), Ok(0.5));
        assert_eq!(
            positive("dt", 0.0).unwrap_err().to_string(),
            "dt: must be greater than 0, got 0"
        );
        assert!(finite("dt", f64::NAN).unwrap_err().message.contains("NaN"));
        assert!(non_negative("slip", -1.0).is_err());
        assert_eq!(in_range("slip", 0.5, 0.0, 0.9), Ok(0.5));
        assert_eq!(
            in_range("slip", 1.0, 0.0, 0.9).unwrap_err().message,
            "must be from 0 to 0.9, got 1"
        );
    }
}
