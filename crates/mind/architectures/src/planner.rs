//! The planner: A* on a snapshot of the world model, run as work that
//! takes time. Each step it may expand as many cells as the simulated
//! time allows (`dt / cost_per_cell`), so a costly plan arrives later and
//! describes the world as it was when it was asked for. The same budget
//! spreads the computer's work over frames.

use kinolab_world::grid::{Cell, Grid};
use kinolab_world::search::{Algorithm, Search, Searching};
use kinolab_world::{FieldError, Vec2};
use serde::Serialize;

use crate::follow::waypoints;
use crate::map::Cartographer;

/// A plan: waypoints to the goal and what it cost to make.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Plan {
    pub waypoints: Vec<[f64; 2]>,
    /// The path's length over the grid, m.
    pub cost: f64,
    /// When the sensing the plan was made from happened, s.
    pub sensed_at: f64,
    /// When the plan was ready, s.
    pub ready_at: f64,
    pub expanded: usize,
    pub goal: [f64; 2],
}

/// How a planning request ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    Found(Plan),
    /// The model holds no way through.
    NoPath {
        expanded: usize,
    },
}

/// A request being worked on.
#[derive(Debug, Clone)]
pub struct Pending {
    /// The model as it was when the request came: what the planner sees.
    pub grid: Grid,
    pub searching: Searching,
    pub sensed_at: f64,
    pub goal: Vec2,
}

/// The work a planner has done.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct PlannerWork {
    /// Searches finished (with or without a path).
    pub searches: usize,
    pub expanded: usize,
    /// Searches that found no path.
    pub failures: usize,
}

/// A planner whose searches take simulated time.
#[derive(Debug, Clone)]
pub struct Planner {
    /// Simulated seconds per expanded cell (0: plans are instant).
    pub cost_per_cell: f64,
    pub pending: Option<Pending>,
    pub work: PlannerWork,
    credit: f64,
}

/// How many rings of cells to look through for a free cell near a blocked
/// start or goal.
const NEAREST_FREE_RINGS: usize = 4;

/// A cell outside every grid.
const NOWHERE: Cell = (usize::MAX, usize::MAX);

impl Planner {
    pub fn new(cost_per_cell: f64) -> Result<Self, FieldError> {
        kinolab_common::error::in_range("planning_cost", cost_per_cell, 0.0, 1.0)?;
        Ok(Self {
            cost_per_cell,
            pending: None,
            work: PlannerWork::default(),
            credit: 0.0,
        })
    }

    pub fn busy(&self) -> bool {
        self.pending.is_some()
    }

    /// Start planning from `from` to `goal` on the model as it is now.
    /// A request while busy replaces the one in progress.
    pub fn request(
        &mut self,
        map: &Cartographer,
        from: Vec2,
        goal: Vec2,
        now: f64,
    ) -> Result<(), FieldError> {
        let grid = map.grid(Some(from))?;
        // A start or goal with no free cell near it makes a search that
        // finds nothing at once.
        let start = nearest_free(&grid, from).unwrap_or(NOWHERE);
        let end = nearest_free(&grid, goal).unwrap_or(NOWHERE);
        let searching = Searching::new(&grid, start, end, Algorithm::AStar);
        self.pending = Some(Pending {
            grid,
            searching,
            sensed_at: now,
            goal,
        });
        self.credit = 0.0;
        Ok(())
    }

    /// Spend `dt` seconds on the request in progress; the outcome once it
    /// is done.
    pub fn tick(&mut self, dt: f64, now: f64) -> Option<Outcome> {
        let pending = self.pending.as_mut()?;
        let budget = if self.cost_per_cell > 0.0 {
            self.credit += dt / self.cost_per_cell;
            let whole = self.credit.floor();
            self.credit -= whole;
            whole.min(usize::MAX as f64 / 2.0) as usize
        } else {
            usize::MAX
        };
        let done: Search = pending.searching.advance(&pending.grid, budget)?;
        let pending = self.pending.take()?;
        self.work.searches += 1;
        self.work.expanded += done.expanded.len();
        let Some(cost) = done.cost else {
            self.work.failures += 1;
            return Some(Outcome::NoPath {
                expanded: done.expanded.len(),
            });
        };
        let points = waypoints(&pending.grid, &done.path, pending.goal);
        Some(Outcome::Found(Plan {
            waypoints: points.iter().map(|p| [p.x, p.y]).collect(),
            cost,
            sensed_at: pending.sensed_at,
            ready_at: now,
            expanded: done.expanded.len(),
            goal: [pending.goal.x, pending.goal.y],
        }))
    }
}

/// The free cell nearest `p` within a few rings of its own cell.
fn nearest_free(grid: &Grid, p: Vec2) -> Option<Cell> {
    let (i, j) = grid.cell_of(p)?;
    if grid.is_free((i, j)) {
        return Some((i, j));
    }
    let mut best: Option<(f64, Cell)> = None;
    let r = NEAREST_FREE_RINGS as isize;
    for dj in -r..=r {
        for di in -r..=r {
            let (a, b) = (i as isize + di, j as isize + dj);
            if a < 0 || b < 0 {
                continue;
            }
            let c = (a as usize, b as usize);
            let d = (grid.centre(c) - p).norm();
            if grid.is_free(c) && best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, c));
            }
        }
    }
    best.map(|(_, c)| c)
}
