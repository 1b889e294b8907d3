//! Mechanisms after the CLARAty mechanism model: one stateless tree of
//! bodies and joints describes an arm, a mast or a leg; the joint values
//! live apart, in a plain `&[f64]` state each user keeps for itself.
//!
//! - [`Model`] and [`ModelBuilder`] — bodies, joints (revolute, continuous,
//!   prismatic, fixed) and named frames, checked into one tree;
//! - [`dh`] — standard and modified DH tables turned into that tree;
//! - [`Model::place`], [`Model::pose`], [`Model::jacobian`] — forward
//!   kinematics by walking the tree, and the geometric Jacobian;
//! - [`Model::solve`] — numerical inverse kinematics over several goals;
//! - [`catalogue`] — built-in arms; [`file`] — model files; [`report`] —
//!   the JSON the command line prints.

pub mod catalogue;
pub mod dh;
mod error;
pub mod file;
mod ik;
mod kinematics;
mod model;
pub mod report;

pub use error::MechanismError;
pub use ik::{Goal, Options, Solution, Target};
pub use kinematics::Placement;
pub use model::{Body, Frame, FrameRef, Joint, JointKind, Model, ModelBuilder, Pose, WORLD};
pub use nalgebra::{UnitQuaternion, Vector3};
