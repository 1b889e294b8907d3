//! Legs: how many ways they can lift and land, and when a standing walker
//! is statically stable.

pub mod leg_events;
pub mod support_polygon;
