//! Legged locomotion, computed: how many ways legs can lift and land, when
//! a standing robot is statically stable, how a periodic gait moves its
//! feet and keeps (or loses) its balance through the cycle, how coupled
//! oscillators settle into a gait, which gait suits a speed, and how
//! efficiently anything moves.
//!
//! The geometry is small and exact enough to write out: a monotone-chain
//! convex hull and point-to-segment distances.

pub mod balance;
pub mod cpg;
mod error;
mod events;
pub mod exercise;
pub mod gait;
pub mod network;
pub mod report;
pub mod speed;
mod stability;
mod transport;
pub mod walker;

pub use cpg::Cpg;
pub use error::FieldError;
pub use events::{MAX_LEGS_EXACT, leg_events, leg_events_f64};
pub use gait::{Gait, HEXAPOD_IDS, Leg, NAMED_IDS, QUADRUPED_IDS, named, named_ids};
pub use stability::{Point, Stability, convex_hull, longitudinal_margins, static_stability};
pub use transport::{STANDARD_GRAVITY, cost_of_transport, cost_of_transport_at_speed};
