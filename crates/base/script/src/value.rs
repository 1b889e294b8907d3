//! Values between the lab and a script: numbers, lists of numbers and
//! maps in, checked shapes out.

use rhai::{Dynamic, Map};

use crate::error::{ScriptError, When};
use crate::script::Signature;

/// A number as a script sees it.
pub fn number(x: f64) -> Dynamic {
    Dynamic::from_float(x)
}

/// A list of numbers.
pub fn numbers(xs: &[f64]) -> Dynamic {
    Dynamic::from_array(xs.iter().map(|x| number(*x)).collect())
}

/// A map from names to values.
pub fn map<'a>(entries: impl IntoIterator<Item = (&'a str, Dynamic)>) -> Dynamic {
    // Inserted one by one: collecting would sort, and put a sort in the
    // lab's wasm for every caller's iterator.
    let mut map = Map::new();
    for (k, v) in entries {
        map.insert(k.into(), v);
    }
    Dynamic::from_map(map)
}

/// `value` as a float (an integer counts), if it is a number.
pub fn float(value: &Dynamic) -> Option<f64> {
    value
        .as_float()
        .ok()
        .or_else(|| value.as_int().ok().map(|n| n as f64))
}

/// `value` as text, if it is a string.
pub fn text(value: &Dynamic) -> Option<String> {
    value.is_string().then(|| value.to_string())
}

/// `value` as `N` finite numbers (`names` says what each one is), or why
/// not: the wrong shape, or a number that is not finite.
pub fn finite<const N: usize>(
    value: &Dynamic,
    names: [&str; N],
    signature: Signature,
    at: impl Into<When>,
) -> Result<[f64; N], ScriptError> {
    let at = at.into();
    let wanted = format!("[{}], {} numbers", names.join(", "), N);
    let shape = || ScriptError::shape(signature, &wanted, &describe(value), at);
    let items = value.as_array_ref().map_err(|_| shape())?;
    if items.len() != N {
        return Err(shape());
    }
    let mut out = [0.0; N];
    for (k, item) in items.iter().enumerate() {
        let x = float(item).ok_or_else(shape)?;
        if !x.is_finite() {
            return Err(ScriptError::not_finite(signature, names[k], x, at));
        }
        out[k] = x;
    }
    Ok(out)
}

/// A value as the stepper shows it: short, one line.
pub fn describe(value: &Dynamic) -> String {
    let text = value.to_string();
    if text.chars().count() > 120 {
        format!("{}…", text.chars().take(119).collect::<String>())
    } else {
        text
    }
}
