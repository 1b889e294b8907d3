//! Best-first search over an occupancy grid, keeping the order in which
//! cells were expanded so a learner can watch the frontier grow.
//!
//! Dijkstra expands cells in order of their distance from the start; A*
//! in order of that distance plus the octile distance still to go, which
//! never overestimates an 8-connected grid's true cost (and is
//! consistent), so A* finds an equally short path while expanding no more
//! cells.

use std::collections::BinaryHeap;

use serde::Serialize;

use crate::grid::{Cell, Entry, Grid};

/// Which search.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Algorithm {
    Dijkstra,
    /// A* with the octile heuristic.
    AStar,
}

/// What a search found and the work it did.
#[derive(Debug, Clone, PartialEq)]
pub struct Search {
    /// The optimal path's length; `None` when the goal cannot be reached.
    pub cost: Option<f64>,
    /// The path's cells from start to goal (empty when there is none).
    pub path: Vec<Cell>,
    /// Every cell taken off the frontier, in order.
    pub expanded: Vec<Cell>,
}

/// The octile distance between two cells: diagonal steps first, then
/// straight ones.
pub fn octile(grid: &Grid, a: Cell, b: Cell) -> f64 {
    let dx = a.0.abs_diff(b.0) as f64;
    let dy = a.1.abs_diff(b.1) as f64;
    grid.cell * (dx.max(dy) + (std::f64::consts::SQRT_2 - 1.0) * dx.min(dy))
}

impl Grid {
    /// The shortest path from `start` to `goal` by `algorithm`. Both cells
    /// must be free (else there is no path). The work is bounded by the
    /// grid: each cell is expanded at most once.
    pub fn search(&self, start: Cell, goal: Cell, algorithm: Algorithm) -> Search {
        let mut searching = Searching::new(self, start, goal, algorithm);
        loop {
            if let Some(done) = searching.advance(self, usize::MAX) {
                return done;
            }
        }
    }
}

/// A search in progress, so its work can be spread over many frames or
/// charged as time: [`Searching::advance`] expands at most a given number
/// of cells and returns the result once the search is over. It must be
/// advanced on the grid it was started on.
#[derive(Debug, Clone)]
pub struct Searching {
    goal: Cell,
    algorithm: Algorithm,
    g: Vec<f64>,
    came: Vec<Option<Cell>>,
    closed: Vec<bool>,
    open: BinaryHeap<Entry>,
    expanded: Vec<Cell>,
    nx: usize,
}

impl Searching {
    /// A search from `start` to `goal` with nothing expanded yet.
    pub fn new(grid: &Grid, start: Cell, goal: Cell, algorithm: Algorithm) -> Self {
        let n = grid.nx * grid.ny;
        let mut s = Self {
            goal,
            algorithm,
            g: vec![f64::INFINITY; n],
            came: vec![None; n],
            closed: vec![false; n],
            open: BinaryHeap::new(),
            expanded: Vec::new(),
            nx: grid.nx,
        };
        if grid.is_free(start) && grid.is_free(goal) {
            let k = s.index(start);
            s.g[k] = 0.0;
            s.open.push(Entry(s.h(grid, start), start));
        }
        s
    }

    /// Cells expanded so far.
    pub fn expanded(&self) -> &[Cell] {
        &self.expanded
    }

    fn index(&self, (i, j): Cell) -> usize {
        j * self.nx + i
    }

    fn h(&self, grid: &Grid, c: Cell) -> f64 {
        match self.algorithm {
            Algorithm::Dijkstra => 0.0,
            Algorithm::AStar => octile(grid, c, self.goal),
        }
    }

    /// Expand up to `budget` more cells; `Some` once the goal is reached or
    /// the frontier is empty (no path).
    pub fn advance(&mut self, grid: &Grid, budget: usize) -> Option<Search> {
        let mut spent = 0;
        while spent < budget {
            let Some(Entry(_, c)) = self.open.pop() else {
                return Some(self.finish(None));
            };
            let k = self.index(c);
            if std::mem::replace(&mut self.closed[k], true) {
                continue;
            }
            spent += 1;
            self.expanded.push(c);
            if c == self.goal {
                return Some(self.finish(Some(self.g[k])));
            }
            for (m, step) in grid.moves(c) {
                let km = self.index(m);
                let through = self.g[k] + step;
                if !self.closed[km] && through < self.g[km] {
                    self.g[km] = through;
                    self.came[km] = Some(c);
                    self.open.push(Entry(through + self.h(grid, m), m));
                }
            }
        }
        None
    }

    fn finish(&mut self, cost: Option<f64>) -> Search {
        self.open.clear();
        let nx = self.nx;
        Search {
            cost,
            path: match cost {
                Some(_) => walk_back(&self.came, self.goal, |(i, j)| j * nx + i),
                None => Vec::new(),
            },
            expanded: std::mem::take(&mut self.expanded),
        }
    }
}

/// The path to `goal` by following each cell's predecessor back.
fn walk_back(came: &[Option<Cell>], goal: Cell, index: impl Fn(Cell) -> usize) -> Vec<Cell> {
    let mut path = vec![goal];
    let mut at = goal;
    while let Some(prev) = came[index(at)] {
        path.push(prev);
        at = prev;
        if path.len() > came.len() {
            break;
        }
    }
    path.reverse();
    path
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Rect, Vec2};

    /// A grid from rows of `#` (occupied) and `.` (free), top row last.
    fn grid(rows: &[&str]) -> Grid {
        let ny = rows.len();
        let nx = rows[0].len();
        let bounds = Rect::from([0.0, 0.0, nx as f64, ny as f64]);
        Grid::from_test(bounds, 1.0, |p: Vec2| {
            let (i, j) = (p.x.floor() as usize, p.y.floor() as usize);
            rows[j].as_bytes()[i] != b'#'
        })
        .unwrap()
    }

    #[test]
    fn a_star_and_dijkstra_agree_and_a_star_expands_less() {
        let g = grid(&[
            "..........",
            "..######..",
            ".......#..",
            "..####.#..",
            "..........",
        ]);
        let d = g.search((0, 0), (9, 4), Algorithm::Dijkstra);
        let a = g.search((0, 0), (9, 4), Algorithm::AStar);
        assert_eq!(d.cost, a.cost);
        assert!(
            a.expanded.len() < d.expanded.len(),
            "{} vs {}",
            a.expanded.len(),
            d.expanded.len()
        );
        let cost = d.cost.unwrap();
        // The walls close the middle: along the bottom row to column 8, one
        // diagonal past the wall's end, then up the last column.
        assert!(
            (cost - (11.0 + std::f64::consts::SQRT_2)).abs() < 1e-12,
            "{cost}"
        );
        assert_eq!(a.path.first(), Some(&(0, 0)));
        assert_eq!(a.path.last(), Some(&(9, 4)));
    }

    #[test]
    fn no_path_and_blocked_ends_say_none() {
        let g = grid(&["..#..", "..#..", "..#.."]);
        for algorithm in [Algorithm::Dijkstra, Algorithm::AStar] {
            let s = g.search((0, 0), (4, 2), algorithm);
            assert_eq!(s.cost, None);
            assert!(s.path.is_empty() && !s.expanded.is_empty());
            assert_eq!(g.search((2, 0), (4, 2), algorithm).cost, None);
        }
    }
}
