//! The small things every Kinolab crate shares, each written exactly once.
//!
//! - [`angle`]: wrapping angles into (−π, π], degrees, snapping;
//! - [`defaults`]: the values of fields a file may leave out;
//! - [`display`]: numbers for people, never "−0.00";
//! - [`random`]: one seeded generator, as a stream and as a hash;
//! - [`error`]: [`FieldError`], bad input named by its path in the file,
//!   and every message kept to one printable line;
//! - [`finite`]: the first NaN or infinity in a report, by its path;
//! - [`feedback`]: [`Feedback`], what a graded exercise says back;
//! - [`geometry`]: a pose in the plane and an axis-aligned rectangle;
//! - [`order`]: sorting by numeric keys, one sort for every caller;
//! - [`trig`]: sine, cosine and atan2, the same bits natively and in wasm;
//! - [`trajectory`]: one instant of a run in the plane, as reports write it.
//!
//! Nothing here knows about robots; the domain crates build on it.

pub mod angle;
pub mod defaults;
pub mod display;
pub mod error;
pub mod feedback;
pub mod finite;
pub mod geometry;
pub mod order;
pub mod random;
pub mod trajectory;
pub mod trig;

pub use error::FieldError;
pub use feedback::Feedback;
pub use random::SplitMix64;
