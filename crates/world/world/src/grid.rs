//! Occupancy grids over a world and shortest distances across them.
//!
//! Square cells of side s cover the bounds; a cell is free when its centre
//! is farther than a clearance from every obstacle. Moves go to the eight
//! neighbours: straight ones cost s, diagonal ones s√2 and only when both
//! cells they cut past are free. One Dijkstra sweep from the goal gives
//! every cell its distance to go (a wavefront navigation function with no
//! local minima), and descending it from any start gives a shortest path;
//! a single start-to-goal path comes from [`crate::search`] (Dijkstra or
//! A*, with the cells each expanded).

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use kinolab_common::error::{non_negative, positive};
use serde::Serialize;

use crate::{FieldError, Rect, Vec2, World};

/// The most cells a grid may have, so no request can exhaust memory.
pub const MAX_CELLS: usize = 4_000_000;

/// An occupancy grid.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    pub bounds: Rect,
    pub cell: f64,
    pub nx: usize,
    pub ny: usize,
    free: Vec<bool>,
}

/// A cell's column and row.
pub type Cell = (usize, usize);

/// A shortest path over a grid.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GridPath {
    pub cost: f64,
    pub cells: Vec<[usize; 2]>,
    pub points: Vec<[f64; 2]>,
    /// How many cells the search expanded on the way.
    pub expanded: usize,
}

const STEPS: [(isize, isize); 8] = [
    (1, 0),
    (-1, 0),
    (0, 1),
    (0, -1),
    (1, 1),
    (1, -1),
    (-1, 1),
    (-1, -1),
];

impl Grid {
    /// The grid of `world` with cells of side `cell`, free where the centre
    /// is more than `clearance` from every obstacle there at the start.
    pub fn new(world: &World, cell: f64, clearance: f64) -> Result<Self, FieldError> {
        Self::from_test(world.bounds, cell, |p| {
            world.obstacle_distance(p, 0.0) > clearance
        })
        .and_then(|g| non_negative("clearance", clearance).map(|_| g))
    }

    /// A grid whose free cells are those where `is_free(centre)` holds.
    pub fn from_test(
        bounds: Rect,
        cell: f64,
        is_free: impl Fn(Vec2) -> bool,
    ) -> Result<Self, FieldError> {
        let cell = positive("cell", cell)?;
        let nx = (bounds.width() / cell).floor();
        let ny = (bounds.height() / cell).floor();
        if nx < 1.0 || ny < 1.0 {
            return Err(FieldError::new(
                "cell",
                format!("{cell} m is larger than the bounds"),
            ));
        }
        if nx * ny > MAX_CELLS as f64 {
            return Err(FieldError::new(
                "cell",
                format!("{cell} m makes {} cells; the most is {MAX_CELLS}", nx * ny),
            ));
        }
        let (nx, ny) = (nx as usize, ny as usize);
        let mut grid = Self {
            bounds,
            cell,
            nx,
            ny,
            free: Vec::with_capacity(nx * ny),
        };
        for j in 0..ny {
            for i in 0..nx {
                grid.free.push(is_free(grid.centre((i, j))));
            }
        }
        Ok(grid)
    }

    /// The centre of cell (i, j).
    pub fn centre(&self, (i, j): Cell) -> Vec2 {
        Vec2::new(
            self.bounds.x_min + (i as f64 + 0.5) * self.cell,
            self.bounds.y_min + (j as f64 + 0.5) * self.cell,
        )
    }

    /// The cell containing `p`, if it is inside the grid.
    pub fn cell_of(&self, p: Vec2) -> Option<Cell> {
        let x = (p.x - self.bounds.x_min) / self.cell;
        let y = (p.y - self.bounds.y_min) / self.cell;
        // From zero up, truncating is rounding down (and no call to
        // `floor`, which is a library call on some targets: this runs
        // for every sample of every ray).
        if !(x >= 0.0 && y >= 0.0) {
            return None;
        }
        let (i, j) = (x as usize, y as usize);
        (i < self.nx && j < self.ny).then_some((i, j))
    }

    pub fn is_free(&self, (i, j): Cell) -> bool {
        i < self.nx && j < self.ny && self.free[j * self.nx + i]
    }

    fn index(&self, (i, j): Cell) -> usize {
        j * self.nx + i
    }

    /// The cell whose entry is at `index` in [`Grid::distances_to`]'s list.
    pub fn cell_at(&self, index: usize) -> Cell {
        (index % self.nx, index / self.nx)
    }

    /// The moves from `c`: each free neighbour and the step's length.
    pub fn moves(&self, c: Cell) -> impl Iterator<Item = (Cell, f64)> + '_ {
        STEPS.iter().filter_map(move |&(di, dj)| {
            let n = (c.0.checked_add_signed(di)?, c.1.checked_add_signed(dj)?);
            if !self.is_free(n) {
                return None;
            }
            if di != 0 && dj != 0 {
                // No cutting corners: both cells beside the diagonal are free.
                if !self.is_free((n.0, c.1)) || !self.is_free((c.0, n.1)) {
                    return None;
                }
                return Some((n, self.cell * std::f64::consts::SQRT_2));
            }
            Some((n, self.cell))
        })
    }

    /// Every cell's shortest distance to `goal` (infinite where blocked or
    /// cut off), by Dijkstra.
    pub fn distances_to(&self, goal: Cell) -> Vec<f64> {
        let mut dist = vec![f64::INFINITY; self.nx * self.ny];
        if !self.is_free(goal) {
            return dist;
        }
        dist[self.index(goal)] = 0.0;
        let mut queue = BinaryHeap::from([Entry(0.0, goal)]);
        while let Some(Entry(d, c)) = queue.pop() {
            if d > dist[self.index(c)] {
                continue;
            }
            for (n, step) in self.moves(c) {
                let k = self.index(n);
                if d + step < dist[k] {
                    dist[k] = d + step;
                    queue.push(Entry(d + step, n));
                }
            }
        }
        dist
    }

    /// Follow `dist` (from [`Grid::distances_to`]) downhill from `start`.
    pub fn descend(&self, dist: &[f64], start: Cell) -> Option<Vec<Cell>> {
        let mut at = start;
        let mut cells = vec![at];
        if !dist.get(self.index(at))?.is_finite() {
            return None;
        }
        for _ in 0..self.nx * self.ny {
            let here = dist[self.index(at)];
            if here == 0.0 {
                return Some(cells);
            }
            let next = self
                .moves(at)
                .map(|(n, step)| (n, dist[self.index(n)] + step))
                .min_by(|a, b| a.1.total_cmp(&b.1))?;
            at = next.0;
            cells.push(at);
        }
        None
    }

    /// The shortest path from `from` to `to`; `Ok(None)` when there is none.
    /// A point outside the bounds or in an occupied cell is an error naming
    /// `from` or `to`.
    pub fn plan(
        &self,
        from: Vec2,
        to: Vec2,
        algorithm: crate::search::Algorithm,
    ) -> Result<Option<GridPath>, FieldError> {
        let cell = |p: Vec2, field: &str| -> Result<Cell, FieldError> {
            let c = self.cell_of(p).ok_or_else(|| {
                FieldError::new(field, format!("({}, {}) is outside the bounds", p.x, p.y))
            })?;
            if self.is_free(c) {
                Ok(c)
            } else {
                Err(FieldError::new(
                    field,
                    format!("({}, {}) is in an occupied cell", p.x, p.y),
                ))
            }
        };
        let (start, goal) = (cell(from, "from")?, cell(to, "to")?);
        let found = self.search(start, goal, algorithm);
        let expanded = found.expanded.len();
        Ok(found.cost.map(|cost| GridPath {
            expanded,
            cost,
            points: found
                .path
                .iter()
                .map(|&c| self.centre(c))
                .map(|p| [p.x, p.y])
                .collect(),
            cells: found.path.iter().map(|&(i, j)| [i, j]).collect(),
        }))
    }
}

/// A queue entry ordered so the heap pops the smallest distance first.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Entry(pub(crate) f64, pub(crate) Cell);

impl PartialEq for Entry {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Entry {}

impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Entry {
    fn cmp(&self, other: &Self) -> Ordering {
        other
            .0
            .total_cmp(&self.0)
            .then_with(|| other.1.cmp(&self.1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::obstacle::{Obstacle, Shape};
    use crate::search::Algorithm;

    #[test]
    fn an_empty_room_costs_the_octile_distance() {
        let world = World::empty("room", Rect::from([0.0, 0.0, 10.0, 6.0]));
        let grid = Grid::new(&world, 1.0, 0.2).unwrap();
        assert_eq!((grid.nx, grid.ny), (10, 6));
        let path = grid
            .plan(Vec2::new(0.5, 0.5), Vec2::new(9.5, 3.5), Algorithm::AStar)
            .unwrap()
            .unwrap();
        // 9 across and 3 up: 3 diagonal steps and 6 straight ones.
        assert!((path.cost - (6.0 + 3.0 * 2f64.sqrt())).abs() < 1e-12);
        assert_eq!(path.cells.len(), 10);
        assert_eq!(path.points[0], [0.5, 0.5]);
    }

    #[test]
    fn walls_block_and_corners_are_not_cut() {
        let mut world = World::empty("split", Rect::from([0.0, 0.0, 5.0, 3.0]));
        world.obstacles.push(Obstacle::new(Shape::Wall {
            from: Vec2::new(2.5, 0.0),
            to: Vec2::new(2.5, 3.0),
            thickness: 0.1,
        }));
        let grid = Grid::new(&world, 1.0, 0.2).unwrap();
        let start = Vec2::new(0.5, 0.5);
        assert_eq!(
            grid.plan(start, Vec2::new(4.5, 0.5), Algorithm::AStar)
                .unwrap(),
            None
        );
        let e = grid
            .plan(start, Vec2::new(2.5, 1.5), Algorithm::AStar)
            .unwrap_err();
        assert_eq!(e.field, "to");
        let e = grid
            .plan(Vec2::new(-1.0, 0.5), start, Algorithm::AStar)
            .unwrap_err();
        assert_eq!(e.field, "from");
        // One blocked cell at (1, 1): every diagonal from (0, 0) towards
        // (2, 2) cuts past it, so the path goes round the edge: 4 straight steps.
        let g = Grid::from_test(Rect::from([0.0, 0.0, 3.0, 3.0]), 1.0, |p| {
            (p - Vec2::new(1.5, 1.5)).norm() > 0.1
        })
        .unwrap();
        let path = g
            .plan(Vec2::new(0.5, 0.5), Vec2::new(2.5, 2.5), Algorithm::AStar)
            .unwrap()
            .unwrap();
        assert!((path.cost - 4.0).abs() < 1e-12, "{}", path.cost);
    }

    #[test]
    fn silly_cells_are_refused() {
        let world = World::empty("room", Rect::from([0.0, 0.0, 10.0, 6.0]));
        assert_eq!(Grid::new(&world, 0.0, 0.1).unwrap_err().field, "cell");
        assert_eq!(Grid::new(&world, 20.0, 0.1).unwrap_err().field, "cell");
        assert_eq!(Grid::new(&world, 1e-4, 0.1).unwrap_err().field, "cell");
        assert_eq!(Grid::new(&world, 1.0, -0.1).unwrap_err().field, "clearance");
    }
}
