//! Bad input is a [`FieldError`] naming the field, shared by every crate.

pub use kinolab_common::FieldError;
pub(crate) use kinolab_common::error::{MAGNITUDE_LIMIT, finite, finite_at};
