//! Bad input is a [`FieldError`] naming the field, shared by every crate.

pub use kinolab_common::FieldError;
pub(crate) use kinolab_common::error::{MAGNITUDE_LIMIT, finite, finite_at};

/// Every value of `values` finite and within [`MAGNITUDE_LIMIT`], else an
/// error naming `field[i]` for the first that is not. The name is only
/// written out when something is wrong: hot paths check every call.
pub(crate) fn all_finite(field: &str, values: &[f64]) -> Result<(), FieldError> {
    match values
        .iter()
        .position(|v| !v.is_finite() || v.abs() > MAGNITUDE_LIMIT)
    {
        Some(i) => finite_at(values[i], || format!("{field}[{i}]")).map(|_| ()),
        None => Ok(()),
    }
}
