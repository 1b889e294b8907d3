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

/// A number in a message: plain when of everyday size, in exponent form
/// when very small or very large (`5e-324`, not 324 digits; `1e6`).
pub fn shown(value: f64) -> String {
    let size = value.abs();
    if size != 0.0 && size.is_finite() && !(1e-4..1e6).contains(&size) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

/// [`finite`] for a field whose name must be built (`q[3]`): `field` is
/// only called when the value is bad, so checks in a hot loop do not
/// format a name per value.
#[inline]
pub fn finite_at(value: f64, field: impl FnOnce() -> String) -> Result<f64, FieldError> {
    if value.is_finite() && value.abs() <= MAGNITUDE_LIMIT {
        Ok(value)
    } else {
        finite(field(), value)
    }
}

/// `value` if it is a number the lab can compute with: finite, and no
/// larger than [`MAGNITUDE_LIMIT`] (whose squares and products stay
/// finite), else an error naming `field`. Every number read from a file,
/// an option or the JavaScript API passes through here or a stricter check.
pub fn finite(field: impl Into<String>, value: f64) -> Result<f64, FieldError> {
    in_range(field, value, -MAGNITUDE_LIMIT, MAGNITUDE_LIMIT)
}

/// "must be a finite number", for NaN and the infinities.
fn not_finite(field: impl Into<String>, value: f64) -> FieldError {
    FieldError::new(
        field,
        format!("must be a finite number, got {}", shown(value)),
    )
}

/// `value` if it is finite and greater than 0 (and, like every number, at
/// most [`MAGNITUDE_LIMIT`]), else an error naming `field`.
pub fn positive(field: impl Into<String>, value: f64) -> Result<f64, FieldError> {
    one_sided(field.into(), value, |v| v > 0.0, "must be greater than 0")
}

/// `value` if it is finite and not negative (and at most
/// [`MAGNITUDE_LIMIT`]), else an error naming `field`.
pub fn non_negative(field: impl Into<String>, value: f64) -> Result<f64, FieldError> {
    one_sided(field.into(), value, |v| v >= 0.0, "must not be negative")
}

/// A check with only a lower bound: `rule` fails with `wanted`; a number
/// that passes it but is too large says the upper limit it broke.
fn one_sided(
    field: String,
    value: f64,
    rule: impl Fn(f64) -> bool,
    wanted: &str,
) -> Result<f64, FieldError> {
    if !value.is_finite() {
        Err(not_finite(field, value))
    } else if !rule(value) {
        Err(FieldError::new(
            field,
            format!("{wanted}, got {}", shown(value)),
        ))
    } else if value > MAGNITUDE_LIMIT {
        Err(FieldError::new(
            field,
            format!(
                "must be at most {}, got {}",
                shown(MAGNITUDE_LIMIT),
                shown(value)
            ),
        ))
    } else {
        Ok(value)
    }
}

/// `value` if it is finite and within `[lo, hi]`, else an error naming
/// `field` and the range it broke (the lab's own [`MAGNITUDE_LIMIT`] when
/// that is narrower).
pub fn in_range(field: impl Into<String>, value: f64, lo: f64, hi: f64) -> Result<f64, FieldError> {
    let range = (lo.max(-MAGNITUDE_LIMIT), hi.min(MAGNITUDE_LIMIT));
    if !value.is_finite() {
        Err(not_finite(field, value))
    } else if (range.0..=range.1).contains(&value) {
        Ok(value)
    } else {
        Err(outside(field.into(), value, range, ""))
    }
}

/// "must be from `lo` to `hi`" (in `unit`), for `value` outside them.
fn outside(field: String, value: f64, (lo, hi): (f64, f64), unit: &str) -> FieldError {
    FieldError::new(
        field,
        format!(
            "must be from {}{unit} to {}{unit}, got {}",
            shown(lo),
            shown(hi),
            shown(value)
        ),
    )
}

/// The smallest and largest physical length the lab accepts, m: a micrometre
/// to a thousand kilometres. Outside this range products of lengths
/// overflow or vanish long before any robot is modelled.
pub const LENGTH_RANGE: (f64, f64) = (1e-6, 1e6);

/// `value` if it is a length the lab can compute with (within
/// [`LENGTH_RANGE`]), else an error naming `field`.
pub fn length(field: impl Into<String>, value: f64) -> Result<f64, FieldError> {
    let field = field.into();
    let (lo, hi) = LENGTH_RANGE;
    if !value.is_finite() || value <= 0.0 {
        positive(field, value)
    } else if (lo..=hi).contains(&value) {
        Ok(value)
    } else {
        Err(outside(field, value, LENGTH_RANGE, " m"))
    }
}

/// `value` if it is finite and at most `limit` in size, else an error
/// naming `field` (for speeds, gains and coordinates, whose products must
/// not overflow).
pub fn bounded(field: impl Into<String>, value: f64, limit: f64) -> Result<f64, FieldError> {
    in_range(field, value, -limit, limit)
}

/// The largest speed, spin, gain, coordinate or angle (in its unit) the lab
/// accepts: a million is beyond any robot, and far enough from overflow
/// that squares and products of such numbers stay finite.
pub const MAGNITUDE_LIMIT: f64 = 1e6;

/// Longest unbroken piece of a message (a quoted value, a key, a path),
/// in characters; longer ones are cut to [`WORD_KEPT`].
const WORD_LIMIT: usize = 80;
const WORD_KEPT: usize = 48;
/// Longest message, in characters.
const MESSAGE_LIMIT: usize = 400;

/// A message as one printable line: control characters escaped (a newline
/// in a file name or a key shows as `\\n`), any unbroken piece longer
/// than [`WORD_LIMIT`] cut (a 10 MB string from the input is not repeated
/// back), and the whole cut to [`MESSAGE_LIMIT`] characters. Every error
/// the command line prints and the JavaScript API throws goes through here.
pub fn one_line(message: &str) -> String {
    let words: Vec<String> = message
        .split(' ')
        .map(|word| {
            let mut kept: String = word.chars().take(WORD_LIMIT + 1).collect();
            if kept.chars().count() > WORD_LIMIT {
                kept = word.chars().take(WORD_KEPT).collect();
                kept.push('…');
            }
            let mut printable = String::new();
            for c in kept.chars() {
                if c.is_control() {
                    printable.extend(c.escape_default());
                } else {
                    printable.push(c);
                }
            }
            printable
        })
        .collect();
    let line = words.join(" ");
    if line.chars().count() > MESSAGE_LIMIT {
        let mut cut: String = line.chars().take(MESSAGE_LIMIT).collect();
        cut.push('…');
        cut
    } else {
        line
    }
}

/// Read JSON text into `T`. A problem names the JSON path of the value
/// (`wheels[2].gamma_deg`) and keeps serde's line and column, so syntax
/// errors can be found too.
#[cfg(feature = "paths")]
pub fn from_json<T: DeserializeOwned>(text: &str) -> Result<T, FieldError> {
    let de = &mut serde_json::Deserializer::from_str(text);
    serde_path_to_error::deserialize(de).map_err(|e| {
        let field = readable_path(&e.path().to_string());
        FieldError::new(field, plain_types(&e.into_inner().to_string()))
    })
}

/// Read JSON text into `T`; without the `paths` feature a problem keeps
/// serde's line and column but not the path.
#[cfg(not(feature = "paths"))]
pub fn from_json<T: DeserializeOwned>(text: &str) -> Result<T, FieldError> {
    serde_json::from_str(text).map_err(|e| FieldError::new("", plain_types(&e.to_string())))
}

/// serde's type names in words a file's author knows: "expected struct
/// WheelEntry" becomes "expected an object", "expected f64" "expected a
/// number".
fn plain_types(message: &str) -> String {
    const NAMED: [(&str, &str); 3] = [
        (
            "expected internally tagged enum ",
            "expected an object with a `kind`",
        ),
        ("expected struct ", "expected an object"),
        (
            "expected enum ",
            "expected one of the names this field takes",
        ),
    ];
    const PRIMITIVE: [(&str, &str); 6] = [
        ("expected f64", "expected a number"),
        ("expected usize", "expected a whole number, 0 or more"),
        ("expected u64", "expected a whole number, 0 or more"),
        ("expected u32", "expected a whole number, 0 or more"),
        ("expected a sequence", "expected a list"),
        ("expected a map", "expected an object"),
    ];
    let mut out = message.to_owned();
    for (serde, plain) in NAMED {
        if let Some(i) = out.find(serde) {
            let rest = &out[i + serde.len()..];
            let name_end = rest
                .find(|c: char| !c.is_alphanumeric() && c != '_')
                .unwrap_or(rest.len());
            out = format!("{}{plain}{}", &out[..i], &rest[name_end..]);
        }
    }
    for (serde, plain) in PRIMITIVE {
        out = out.replace(serde, plain);
    }
    out
}

/// A JSON path as a person reads it: no `.` for the whole document and no
/// `?` where the path could not be followed (inside an untagged value).
#[cfg(feature = "paths")]
fn readable_path(path: &str) -> String {
    let mut out = String::new();
    for part in path.split('.').filter(|p| !p.is_empty() && *p != "?") {
        let part = part.trim_end_matches("[?]");
        if !out.is_empty() && !part.starts_with('[') {
            out.push('.');
        }
        out.push_str(part);
    }
    out
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
    #[cfg(feature = "paths")]
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
    fn messages_are_one_short_line() {
        assert_eq!(one_line("a\nb\tc"), "a\\nb\\tc");
        let long = format!("unknown variant `{}`, expected `fixed`", "x".repeat(10_000));
        let line = one_line(&long);
        assert!(line.chars().count() < 90, "{line}");
        assert!(line.ends_with("… expected `fixed`"), "{line}");
        assert!(one_line("a `key\nwith a newline`").ends_with("`key\\nwith a newline`"));
        assert!(one_line(&"y".repeat(5000)).chars().count() <= 401);
    }

    #[test]
    #[cfg(feature = "paths")]
    fn paths_read_as_a_person_reads_them() {
        assert_eq!(readable_path("."), "");
        assert_eq!(readable_path("wheels[0].?.kind"), "wheels[0].kind");
        assert_eq!(readable_path("?.x"), "x");
    }

    #[test]
    fn serde_types_are_named_in_plain_words() {
        assert_eq!(
            plain_types(
                "invalid type: floating point `-2.1`, expected struct WheelEntry at line 1"
            ),
            "invalid type: floating point `-2.1`, expected an object at line 1"
        );
        assert_eq!(
            plain_types("invalid type: string \"x\", expected internally tagged enum Controller"),
            "invalid type: string \"x\", expected an object with a `kind`"
        );
        assert_eq!(
            plain_types("invalid type: map, expected f64 at line 2"),
            "invalid type: map, expected a number at line 2"
        );
    }

    #[test]
    fn lengths_are_physical() {
        assert_eq!(length("radius", 0.1), Ok(0.1));
        assert!(
            length("radius", 5e-324)
                .unwrap_err()
                .message
                .contains("from 1e-6 m")
        );
        assert!(length("radius", 1e300).is_err());
        assert!(length("radius", -1.0).is_err());
        assert_eq!(bounded("vx", -2.0, 10.0), Ok(-2.0));
        assert!(
            bounded("vx", 1e160, 1e6)
                .unwrap_err()
                .to_string()
                .starts_with("vx: must be from")
        );
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
    fn a_value_outside_a_range_hears_that_range_whatever_its_size() {
        let said = |r: Result<f64, FieldError>| r.unwrap_err().message;
        assert_eq!(
            said(in_range("duration", 1e308, 0.0, 600.0)),
            "must be from 0 to 600, got 1e308"
        );
        assert_eq!(
            said(in_range("duration", -5.0, 0.0, 600.0)),
            "must be from 0 to 600, got -5"
        );
        assert_eq!(
            said(in_range("cost", -1e300, 0.0, 1.0)),
            "must be from 0 to 1, got -1e300"
        );
        // A range wider than the lab's own limit is cut to it.
        assert_eq!(
            said(in_range("x", 2e9, -1e12, 1e12)),
            "must be from -1e6 to 1e6, got 2e9"
        );
        assert_eq!(
            said(positive("radius", 1e308)),
            "must be at most 1e6, got 1e308"
        );
        assert_eq!(
            said(positive("radius", -1e308)),
            "must be greater than 0, got -1e308"
        );
        assert_eq!(
            said(non_negative("noise", 1e9)),
            "must be at most 1e6, got 1e9"
        );
        assert_eq!(
            said(length("radius", 1e308)),
            "must be from 1e-6 m to 1e6 m, got 1e308"
        );
        assert!(said(in_range("x", f64::INFINITY, 0.0, 1.0)).contains("finite"));
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
        assert_eq!(finite("x", 5e-324).map_err(|e| e.message), Ok(5e-324));
        assert_eq!(
            finite("x", -2e6).unwrap_err().message,
            "must be from -1e6 to 1e6, got -2e6"
        );
    }
}
