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
        let mut none = Search {
            cost: None,
            path: Vec::new(),
            expanded: Vec::new(),
        };
        if !self.is_free(start) || !self.is_free(goal) {
            return none;
        }
        let h = |c: Cell| match algorithm {
            Algorithm::Dijkstra => 0.0,
            Algorithm::AStar => octile(self, c, goal),
        };
        let n = self.nx * self.ny;
        let index = |(i, j): Cell| j * self.nx + i;
        let mut g = vec![f64::INFINITY; n];
        let mut came: Vec<Option<Cell>> = vec![None; n];
        let mut closed = vec![false; n];
        g[index(start)] = 0.0;
        let mut open = BinaryHeap::from([Entry(h(start), start)]);
        while let Some(Entry(_, c)) = open.pop() {
            if std::mem::replace(&mut closed[index(c)], true) {
                continue;
            }
            none.expanded.push(c);
            if c == goal {
                return Search {
                    cost: Some(g[index(goal)]),
                    path: walk_back(&came, goal, index),
                    expanded: none.expanded,
                };
            }
            for (m, step) in self.moves(c) {
                let k = index(m);
                let through = g[index(c)] + step;
                if !closed[k] && through < g[k] {
                    g[k] = through;
                    came[k] = Some(c);
                    open.push(Entry(through + h(m), m));
                }
            }
        }
        none
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
