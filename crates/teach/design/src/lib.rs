//! Software stability (Brugali, after Fayad): how little of a design has to
//! change when requirements change. Three small models make it concrete:
//!
//! - [`ant`]: Simon's ant on a pebble beach. One rule, a complicated path;
//!   the complexity is the beach's, and a body a thousand times larger,
//!   with the same rule, goes almost straight.
//! - [`slots`]: a body, a behaviour set and a world, each swapped on its
//!   own; every combination run, and the failures explained.
//! - [`churn`]: a robot application as a graph of classes, and what must
//!   change when an industrial object is replaced, in a stable design and
//!   in a naive one.

pub mod ant;
pub mod churn;
pub mod exercise;
pub mod morphology;
pub mod slots;

pub use kinolab_common::FieldError;
