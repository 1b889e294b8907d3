//! Communication objects: what travels between components. Always a value
//! with a type name, copied on every hop (never a reference to another
//! component's data).

use serde::{Deserialize, Serialize};

/// A typed value. The type name is what wiring compares; the value is any
/// JSON the type's users agree on.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Object {
    #[serde(rename = "type")]
    pub kind: String,
    pub value: serde_json::Value,
}

/// The longest payload summary in a trace, in characters.
const SUMMARY: usize = 48;

impl Object {
    pub fn new(kind: &str, value: serde_json::Value) -> Self {
        Self {
            kind: kind.to_owned(),
            value,
        }
    }

    /// A number under `kind`.
    pub fn number(kind: &str, x: f64) -> Self {
        Self::new(kind, serde_json::json!(x))
    }

    /// The value as a number, when it is one (or an object's `value`).
    pub fn as_f64(&self) -> Option<f64> {
        self.value
            .as_f64()
            .or_else(|| self.value.get("value").and_then(serde_json::Value::as_f64))
    }

    /// A field of the value as a number.
    pub fn field(&self, name: &str) -> Option<f64> {
        self.value.get(name).and_then(serde_json::Value::as_f64)
    }

    /// A short line for traces and diagrams: the type and the start of the
    /// value, with long arrays counted instead of listed.
    pub fn summary(&self) -> String {
        let body = match &self.value {
            serde_json::Value::Array(items) => format!("[{} items]", items.len()),
            serde_json::Value::Object(map) => {
                let fields: Vec<String> = map
                    .iter()
                    .map(|(k, v)| match v {
                        serde_json::Value::Array(a) => format!("{k}: [{}]", a.len()),
                        serde_json::Value::String(s) if s.len() > 12 => format!("{k}: …"),
                        serde_json::Value::Number(n) => format!("{k}: {}", short(n)),
                        other => format!("{k}: {other}"),
                    })
                    .collect();
                fields.join(", ")
            }
            serde_json::Value::Number(n) => short(n),
            other => other.to_string(),
        };
        let mut text = format!("{} {body}", self.kind);
        if text.chars().count() > SUMMARY {
            text = text.chars().take(SUMMARY - 1).collect::<String>() + "…";
        }
        text
    }
}

/// A number with at most three decimals.
fn short(n: &serde_json::Number) -> String {
    match n.as_f64() {
        Some(x) if x.fract() != 0.0 => {
            let s = format!("{x:.3}");
            s.trim_end_matches('0').to_owned()
        }
        _ => n.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn summaries_are_short_and_name_the_type() {
        let scan = Object::new(
            "Scan",
            serde_json::json!({"ranges": [1.0, 2.0, 3.0], "t": 0.25}),
        );
        assert_eq!(scan.summary(), "Scan ranges: [3], t: 0.25");
        assert_eq!(Object::number("Count", 7.0).summary(), "Count 7.0");
        let long = Object::new(
            "Note",
            serde_json::json!({"text": "x".repeat(100), "a": 1, "b": 2, "c": 3, "d": 4, "e": 5, "f": 6}),
        );
        assert!(long.summary().chars().count() <= SUMMARY);
        assert_eq!(Object::number("Count", 2.5).as_f64(), Some(2.5));
    }
}
