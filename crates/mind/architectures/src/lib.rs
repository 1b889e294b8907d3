//! Robot architectures: how sensing, planning and acting are organised.
//!
//! - [`map`]: the cartographer, a world model kept as evidence per cell;
//! - [`planner`]: A* on a snapshot of the model, as work that takes time;
//! - [`follow`]: from a cell path to waypoints, and following them;
//! - [`skills`]: a reactive behaviour stack (avoid over go-to-goal);
//! - [`paradigm`]: the hierarchical, reactive and hybrid controllers;
//! - [`surprise`]: a door that closes, a person, a wrong map, noise, a
//!   goal that moves, glass; [`placing`]: the first three placed from any
//!   world's geometry;
//! - [`arena`]: robots of each kind on one clock in copies of one world,
//!   with their scores; [`run`]: one robot's run as the CLI prints it;
//! - [`routes`]: sensing routes, and the paradigm a wiring amounts to;
//! - [`exercise`]: graded tasks the lab's widgets check.

pub mod arena;
pub mod exercise;
pub mod follow;
pub mod map;
pub mod paradigm;
pub mod placing;
pub mod planner;
pub mod routes;
pub mod run;
pub mod skills;
pub mod surprise;

pub use arena::{Arena, ArenaSetup, Scores};
pub use kinolab_common::FieldError;
pub use paradigm::Architecture;
pub use surprise::Surprise;
