//! Behaviours: the arena where a robot's behaviours are coordinated,
//! Braitenberg's vehicles, and the frog that blends or chooses.

pub mod arena;
pub mod braitenberg;
pub mod frog;
pub(crate) mod world_view;
