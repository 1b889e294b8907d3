//! From a path of cells to waypoints, and following them.
//!
//! A cell path zig-zags in steps of 45°. Pulling it tight keeps only the
//! cells where the line of sight over free cells breaks, so the robot
//! drives straight lines between a few waypoints.

use kinolab_world::Vec2;
use kinolab_world::grid::{Cell, Grid};
use serde::Serialize;

/// Whether the straight segment from `a` to `b` crosses only free cells.
pub fn clear_line(grid: &Grid, a: Vec2, b: Vec2) -> bool {
    let span = b - a;
    let samples = (span.norm() / (0.25 * grid.cell)).ceil().min(1e5) as usize;
    (0..=samples).all(|k| {
        let p = a + span * (k as f64 / samples.max(1) as f64);
        grid.cell_of(p).is_some_and(|c| grid.is_free(c))
    })
}

/// Waypoints along `path` (first cell: where the robot is), ending at
/// `goal` when the last cell can see it, else at the last cell's centre.
pub fn waypoints(grid: &Grid, path: &[Cell], goal: Vec2) -> Vec<Vec2> {
    let centres: Vec<Vec2> = path.iter().map(|&c| grid.centre(c)).collect();
    let mut out = Vec::new();
    let mut from = 0;
    while from + 1 < centres.len() {
        let mut to = from + 1;
        while to + 1 < centres.len() && clear_line(grid, centres[from], centres[to + 1]) {
            to += 1;
        }
        out.push(centres[to]);
        from = to;
    }
    match out.last().copied().or(centres.first().copied()) {
        Some(last) if clear_line(grid, last, goal) => {
            if out
                .last()
                .is_some_and(|l| (l - goal).norm() < 0.5 * grid.cell)
            {
                out.pop();
            }
            out.push(goal);
        }
        Some(last) if out.is_empty() => out.push(last),
        _ => {}
    }
    out
}

/// Which waypoint a robot is heading for.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Follower {
    pub waypoints: Vec<[f64; 2]>,
    pub next: usize,
}

impl Follower {
    pub fn new(waypoints: Vec<[f64; 2]>) -> Self {
        Self { waypoints, next: 0 }
    }

    /// The waypoint to head for from `at`: the current one, or a later
    /// one once the robot is within `reach` of it. `None` for an empty plan.
    pub fn target(&mut self, at: Vec2, reach: f64) -> Option<Vec2> {
        let point = |k: usize| self.waypoints.get(k).map(|&[x, y]| Vec2::new(x, y));
        while self.next + 1 < self.waypoints.len()
            && point(self.next).is_some_and(|w| (w - at).norm() < reach)
        {
            self.next += 1;
        }
        point(self.next)
    }

    /// The waypoints still ahead.
    pub fn ahead(&self) -> &[[f64; 2]] {
        self.waypoints.get(self.next..).unwrap_or(&[])
    }
}
