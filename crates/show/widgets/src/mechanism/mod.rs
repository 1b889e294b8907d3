//! Mechanisms: one DH link built motion by motion, and the mechanism
//! viewer for whole models.

pub mod dh_link;
pub mod viewer;
