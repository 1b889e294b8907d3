//! The world a robot is situated in, and the robot's body and senses.
//!
//! - [`obstacle`]: discs, polygons (concave too) and walls, standing still,
//!   moving along a scripted path, or appearing at a given time;
//! - [`World`]: bounds, obstacles, lights, a start pose and a goal, read from
//!   world files ([`World::from_json`]); distances and ray casts on parry2d;
//! - [`body`]: a differential drive (built on the wheels crate) and a
//!   holonomic point robot, with their speed limits;
//! - [`sensors`]: range rays, a sonar cone, bumpers, two light sensors, the
//!   goal's bearing and distance, odometry with drift, all with seeded noise;
//! - [`Sim`]: a fixed-step simulation: same world and seed, same run; the
//!   robot stops at contact and never passes through a wall;
//! - [`grid`]: occupancy grids and shortest distances over them.
//!
//! Conventions: metres, seconds, radians; world frame x right, y up; a
//! robot's own frame has x forward and y to its left.

use kinolab_common::trig;

pub mod body;
pub mod catalogue;
mod file;
pub mod grid;
pub mod obstacle;
pub mod search;
pub mod sensors;
mod sim;
mod world;

pub use body::{Body, Command, DiffDrive, PointRobot};
pub use kinolab_common::FieldError;
pub use kinolab_common::geometry::{Pose, Rect};
pub use obstacle::{Obstacle, Shape};
pub use sensors::{Percepts, Sensors};
pub use sim::{Event, EventKind, Sim, Step};
pub use world::{Light, World};

/// A point or a vector in the plane.
pub type Vec2 = nalgebra::Vector2<f64>;

/// The vector at `angle` with length 1.
pub fn unit(angle: f64) -> Vec2 {
    let (s, c) = trig::sin_cos(angle);
    Vec2::new(c, s)
}
