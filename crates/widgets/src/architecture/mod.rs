//! Architectures: the deliberative layer's planner on an occupancy grid.

pub mod grid_planner;
