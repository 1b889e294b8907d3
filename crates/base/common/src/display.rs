//! Numbers for people: rounding noise never prints as "−0.00".

/// `x` with `decimals` digits after the point; a value that would round to
/// zero prints as "0.00", never "−0.00".
pub fn fixed(x: f64, decimals: usize) -> String {
    format!("{:.*}", decimals, quiet(x, decimals))
}

/// Like [`fixed`] with an explicit sign ("+0.25", "−…" as "-0.25"); zero
/// prints as "+0.00".
pub fn signed(x: f64, decimals: usize) -> String {
    format!("{:+.*}", decimals, quiet(x, decimals))
}

/// `x`, or 0 when it would round to zero at `decimals` digits (so its sign
/// is not shown).
pub fn quiet(x: f64, decimals: usize) -> f64 {
    let half_step = 0.5 * 10f64.powi(-(decimals.min(15) as i32));
    if x.abs() < half_step { 0.0 } else { x }
}

/// Rounding noise (|x| < 1e-12) and −0 as 0, for machine-readable reports:
/// cos 90° is 0, not 6.1e-17.
pub fn tidy(x: f64) -> f64 {
    if x.abs() < 1e-12 { 0.0 } else { x }
}

/// [`tidy`] applied to every number in a JSON value.
pub fn tidy_json(value: serde_json::Value) -> serde_json::Value {
    use serde_json::Value;
    match value {
        Value::Number(n) => match n.as_f64() {
            Some(x) if n.is_f64() && x.abs() < 1e-12 => Value::from(0.0),
            _ => Value::Number(n),
        },
        Value::Array(items) => Value::Array(items.into_iter().map(tidy_json).collect()),
        Value::Object(mut map) => {
            // In place: collecting a new map would sort its keys again.
            for v in map.values_mut() {
                *v = tidy_json(std::mem::take(v));
            }
            Value::Object(map)
        }
        other => other,
    }
}

/// A report as JSON with rounding noise removed: what the command line
/// prints and the JavaScript API returns, so both give the same numbers.
/// A number that is not finite (JSON would print it as `null`) is an error
/// naming where it is: an answer that overflowed is never shown as one.
pub fn tidy_report(report: &impl serde::Serialize) -> Result<serde_json::Value, crate::FieldError> {
    if let Some(path) = crate::finite::first_non_finite(report) {
        return Err(crate::FieldError::new(
            "",
            format!(
                "the result's `{path}` is not a finite number: the computation overflowed; \
                 try smaller values"
            ),
        ));
    }
    serde_json::to_value(report)
        .map(tidy_json)
        .map_err(|e| crate::FieldError::new("", format!("the result cannot be written: {e}")))
}

/// Digits in groups of three with thin spaces: 39 916 800.
pub fn group_digits(n: u128) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push('\u{2009}');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_negatives_print_as_zero_at_every_precision() {
        assert_eq!(fixed(-0.004, 2), "0.00");
        assert_eq!(fixed(-0.005, 2), "-0.01");
        assert_eq!(fixed(-0.4, 0), "0");
        assert_eq!(fixed(-0.6, 0), "-1");
        assert_eq!(signed(-1e-9, 3), "+0.000");
        assert_eq!(signed(0.25, 2), "+0.25");
        assert_eq!(fixed(f64::NAN, 1), "NaN");
    }

    #[test]
    fn tidy_cleans_reports() {
        let v = serde_json::json!({"a": [6.1e-17, -0.0, 1.5], "b": {"c": -1e-13}, "n": 3});
        assert_eq!(
            tidy_json(v).to_string(),
            r#"{"a":[0.0,0.0,1.5],"b":{"c":0.0},"n":3}"#
        );
        assert_eq!(tidy(-0.0).to_string(), "0");
    }

    #[test]
    fn digits_are_grouped() {
        assert_eq!(group_digits(39_916_800), "39\u{2009}916\u{2009}800");
        assert_eq!(group_digits(120), "120");
        assert_eq!(group_digits(5040), "5\u{2009}040");
    }
}
