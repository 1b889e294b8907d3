//! Architectures: the deliberative layer's planner on an occupancy grid,
//! the three paradigms raced in one arena, and sensing routes.

pub mod arena;
pub mod grid_planner;
pub mod routes;
