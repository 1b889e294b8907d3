//! Legged locomotion, computed: how many ways legs can lift and land, when
//! a standing robot is statically stable, and how efficiently anything moves.
//!
//! The geometry is small and exact enough to write out: a monotone-chain
//! convex hull and point-to-segment distances.

mod error;
mod gait;
pub mod report;
mod stability;
mod transport;

pub use error::FieldError;
pub use gait::{MAX_LEGS_EXACT, leg_events, leg_events_f64};
pub use stability::{Point, Stability, static_stability};
pub use transport::{STANDARD_GRAVITY, cost_of_transport};
