//! Legs: how many ways they can lift and land, when a standing walker is
//! statically stable, and how a gait keeps (or loses) that through its cycle.

pub mod cpg_lab;
pub mod gait_studio;
pub mod leg_events;
pub mod support_polygon;
pub mod walker;
pub mod zmp;
