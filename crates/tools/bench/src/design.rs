//! Software-stability kernels: the ant's walk across a beach, and the
//! three slots' matrix of all 24 combinations.

use std::hint::black_box;

use kinolab_design::ant::{Beach, DEFAULT_PEBBLES, walk};

/// An ant (size 1) across beach 1: its tortuosity.
pub fn ant_walk() -> f64 {
    static BEACH: std::sync::OnceLock<Option<Beach>> = std::sync::OnceLock::new();
    let Some(beach) = BEACH.get_or_init(|| Beach::new(1, DEFAULT_PEBBLES).ok()) else {
        return f64::NAN;
    };
    walk(beach, black_box(1.0)).map_or(f64::NAN, |w| w.tortuosity)
}

/// Every body × behaviour set × world, run: how many reach the goal.
pub fn slots_matrix() -> f64 {
    kinolab_design::slots::matrix()
        .map_or(f64::NAN, |m| m.iter().filter(|o| o.reached).count() as f64)
}
