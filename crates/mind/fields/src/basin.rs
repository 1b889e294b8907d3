//! Basin maps: from a grid of starts, which reach the goal and which are
//! trapped, and where.

use kinolab_world::Rect;
use serde::Serialize;

use crate::descend::{Outcome, Steps, descend};
use crate::minima::Minimum;
use crate::{Field, Vec2};

/// Where a start ends up.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case", tag = "ends")]
pub enum Basin {
    Goal,
    /// At the minimum with this index.
    Trap {
        minimum: usize,
    },
    /// Stopped somewhere that is not a minimum (a saddle, or where the
    /// field vanishes).
    Stalled,
    /// Still moving when the steps ran out.
    Wandering,
}

/// The starts of a basin map: cell centres of an `nx` × `ny` grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Starts {
    pub area: Rect,
    pub nx: usize,
    pub ny: usize,
}

impl Starts {
    /// The most starts a map may have.
    pub const MAX: usize = 10_000;

    pub fn new(area: Rect, nx: usize, ny: usize) -> Self {
        let nx = nx.clamp(1, 100);
        let ny = ny.clamp(1, Self::MAX / nx);
        Self { area, nx, ny }
    }

    pub fn len(&self) -> usize {
        self.nx * self.ny
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Start number `k`, row by row from the bottom left.
    pub fn start(&self, k: usize) -> Vec2 {
        let (i, j) = (k % self.nx, k / self.nx);
        Vec2::new(
            self.area.x_min + (i as f64 + 0.5) * self.area.width() / self.nx as f64,
            self.area.y_min + (j as f64 + 0.5) * self.area.height() / self.ny as f64,
        )
    }
}

/// Where start `k` ends up, given the field's minima.
pub fn basin(field: &Field, starts: &Starts, k: usize, steps: Steps, minima: &[Minimum]) -> Basin {
    let Ok(d) = descend(field, starts.start(k), steps) else {
        return Basin::Stalled;
    };
    let end = Vec2::new(d.end[0], d.end[1]);
    match d.outcome {
        Outcome::Reached => Basin::Goal,
        Outcome::MaxSteps => Basin::Wandering,
        Outcome::Trapped => minima
            .iter()
            .enumerate()
            .filter(|(_, m)| (m.at() - end).norm() <= 5.0 * steps.step)
            .min_by(|a, b| (a.1.at() - end).norm().total_cmp(&(b.1.at() - end).norm()))
            .map_or(Basin::Stalled, |(i, m)| {
                if m.goal {
                    Basin::Goal
                } else {
                    Basin::Trap { minimum: i }
                }
            }),
    }
}

/// The whole map, row by row.
pub fn basin_map(field: &Field, starts: &Starts, steps: Steps, minima: &[Minimum]) -> Vec<Basin> {
    (0..starts.len())
        .map(|k| basin(field, starts, k, steps, minima))
        .collect()
}
