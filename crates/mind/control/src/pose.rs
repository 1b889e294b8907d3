//! Poses in the plane: the lab's one [`Pose`], from the common crate.

pub use kinolab_common::geometry::Pose;
