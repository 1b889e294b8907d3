//! Component communication: the component lab (a system running on the
//! simulated clock, wired and rewired by hand) and the "which pattern?"
//! exercise.

pub mod lab;
pub mod which_pattern;
