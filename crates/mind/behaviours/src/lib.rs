//! Intelligence as behaviour: ρ = C(G · B(S)).
//!
//! - [`Response`]: what a behaviour asks for: a vector (a motor schema), a
//!   twist, or wheel speeds;
//! - [`library`]: the behaviours (avoid, go to the goal, wander, follow a
//!   wall, stay in a corridor, seek light, flee, dock) and their releasers;
//! - [`braitenberg`]: vehicles wired straight or crossed, excitatory or
//!   inhibitory, and the four classic characters;
//! - [`coordinate`]: the coordination functions C: vector summation,
//!   subsumption (suppress and inhibit nodes with hold times), voting over
//!   candidate arcs, and a finite-state sequencer;
//! - [`run`]: a robot, its behaviours and a coordinator in a world, run
//!   for a time from a seed, with the timeline of who had control;
//! - [`frog`]: blending against choosing, with a frog and two flies;
//! - [`exercise`]: graded tasks the lab's widgets check.

pub mod braitenberg;
pub mod coordinate;
pub mod exercise;
pub mod frog;
pub mod library;
mod response;
pub mod run;
pub mod script;

pub use kinolab_common::FieldError;
pub use kinolab_world::Vec2;
pub use library::{Behaviour, Named};
pub use response::{Drive, Response};
