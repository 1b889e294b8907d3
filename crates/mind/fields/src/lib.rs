//! Potential fields: motion as the sum of simple vector fields.
//!
//! - [`primitive`]: the five primitives (uniform, attractive, repulsive,
//!   tangential, perpendicular) and their profiles, each with its exact
//!   Jacobian;
//! - [`Field`]: a sum of primitives and a goal, read from field files;
//! - [`minima`]: the stable equilibria of a field, found by Newton's method
//!   from a grid of starts and kept only where the Jacobian says "stable";
//! - [`descend`]: a point robot stepping down the field, and a unicycle
//!   following it with a heading controller;
//! - [`follow`]: a point robot that takes the field as its velocity, up
//!   to a top speed, and may not pass through an obstacle;
//! - [`remedy`]: ways out of local minima (noise, avoid-the-past,
//!   navigation templates, wall following) and a wavefront navigation
//!   function with no local minima at all;
//! - [`basin`]: which starts reach the goal and which are trapped where;
//! - [`catalogue`]: the classic fields and their failures.

pub mod basin;
pub mod catalogue;
pub mod custom;
pub mod descend;
pub mod exercise;
mod field;
pub mod file;
pub mod follow;
pub mod minima;
pub mod primitive;
pub mod remedy;
pub mod report;

pub use field::Field;
pub use kinolab_common::FieldError;
pub use kinolab_world::Vec2;
pub use primitive::{Primitive, Profile, Sense, Source, Spin};

/// A 2 × 2 matrix: a field's Jacobian ∂F/∂p.
pub type Mat2 = nalgebra::Matrix2<f64>;
