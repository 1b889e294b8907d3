//! Mechanisms: one DH link built motion by motion, the mechanism viewer
//! for whole models, an arm held still against gravity and loads, and an
//! arm let go.

pub mod dh_link;
pub mod falling;
pub mod holding;
pub mod viewer;
