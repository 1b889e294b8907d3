//! Mechanisms after the CLARAty mechanism model: one stateless tree of
//! bodies and joints describes an arm, a mast or a leg; the joint values
//! live apart, in a plain `&[f64]` state each user keeps for itself.
//!
//! - [`Model`] and [`ModelBuilder`] — bodies, joints (revolute, continuous,
//!   prismatic, fixed) and named frames, checked into one tree;
//! - [`dh`] — standard and modified DH tables turned into that tree;
//! - [`Model::place`], [`Model::pose`], [`Model::jacobian`] — forward
//!   kinematics by walking the tree, and the geometric Jacobian;
//! - [`Model::solve`] — numerical inverse kinematics over several goals,
//!   in the world or relative to another frame; [`special`] — closed-form
//!   solvers plugged in as commands that the generic one is checked against;
//! - mounting one model on another (a hexapod from one leg), couplings
//!   (`q_f = ratio · q_l + offset`) and loop closure (a four-bar);
//! - [`Model::collisions`] — bounding capsules, coarse to fine, tested in a
//!   plane on parry2d;
//! - [`catalogue`] — built-in arms and rigs; [`file`] — model files in DH,
//!   transforms or zero-position form; [`urdf`] — robots described in URDF,
//!   the format ROS and its tools read; [`report`] — the JSON the command
//!   line and the JS API print.

pub mod catalogue;
mod compose;
pub mod dh;
pub mod dynamics;
mod error;
pub mod exercise;
pub mod file;
mod ik;
mod inertial;
mod kinematics;
mod model;
pub mod report;
mod shapes;
pub mod special;
mod steps;
pub mod urdf;

pub use compose::{Closure, Coupling, Group, LoopClosure};
pub use dynamics::Dynamics;
pub use error::FieldError;
pub use ik::{Goal, Options, Solution, Target};
pub use inertial::Inertial;
pub use kinematics::{Placement, Workspace};
pub use model::{
    Body, Frame, FrameRef, Joint, JointKind, MAX_JOINTS, Model, ModelBuilder, OutsideLimit, Pose,
    WORLD,
};
pub use nalgebra::{Matrix4, UnitQuaternion, Vector3};
pub use shapes::{Collisions, Obstacle, Part, Plane, Shape};
