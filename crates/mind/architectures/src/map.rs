//! The cartographer: a world model kept as evidence per grid cell.
//!
//! Every range reading is a ray of evidence: the cells it crosses were
//! free (one count against), the cell where it ended is occupied (two
//! counts for). Counts are clamped, so the model can change its mind when
//! a door closes, and many readings average the noise of any one. A
//! bumper's touch is different: rays never refute it (glass lets them
//! through), so felt cells stay occupied until the robot's own body has
//! been there.
//!
//! Planning needs a grid for a point robot: [`Cartographer::grid`] grows
//! every occupied cell by the robot's clearance, as the planning lesson
//! grows obstacles.

use kinolab_world::grid::{Cell, Grid};
use kinolab_world::sensors::Percepts;
use kinolab_world::{FieldError, Pose, Rect, Vec2, World, unit};

/// Evidence is clamped to ±this many counts.
const CLAMP: i8 = 6;
/// A cell on the map the robot was given starts with this much evidence.
const PRIOR: i8 = 4;
/// The most cells a map may have (the planner's grids are this small).
pub const MAX_MAP_CELLS: usize = 250_000;

/// A world model: occupancy evidence per cell.
#[derive(Debug, Clone, PartialEq)]
pub struct Cartographer {
    pub bounds: Rect,
    pub cell: f64,
    pub nx: usize,
    pub ny: usize,
    /// How far (m) planned paths keep from anything occupied.
    pub clearance: f64,
    evidence: Vec<i8>,
    felt: Vec<bool>,
    /// The cells' geometry (every cell free): one way to place cells.
    lattice: Grid,
}

impl Cartographer {
    /// An empty map: nothing known to be anywhere.
    pub fn empty(bounds: Rect, cell: f64, clearance: f64) -> Result<Self, FieldError> {
        let cell = kinolab_common::error::in_range("cell", cell, 0.02, 2.0)?;
        let clearance = kinolab_common::error::in_range("clearance", clearance, 0.0, 5.0)?;
        let nx = (bounds.width() / cell).floor();
        let ny = (bounds.height() / cell).floor();
        if nx < 1.0 || ny < 1.0 || nx * ny > MAX_MAP_CELLS as f64 {
            return Err(FieldError::new(
                "cell",
                format!(
                    "{cell} m makes {} cells; a map needs 1 to {MAX_MAP_CELLS}",
                    nx.max(0.0) * ny.max(0.0)
                ),
            ));
        }
        let n = nx as usize * ny as usize;
        Ok(Self {
            bounds,
            cell,
            nx: nx as usize,
            ny: ny as usize,
            clearance,
            evidence: vec![0; n],
            felt: vec![false; n],
            lattice: Grid::from_test(bounds, cell, |_| true)?,
        })
    }

    /// A map drawn from `world` as it stands at the start, leaving out the
    /// obstacles `known` says no to (a wrong map), everything that moves
    /// and everything that appears later.
    pub fn from_world(
        world: &World,
        cell: f64,
        clearance: f64,
        known: impl Fn(usize) -> bool,
    ) -> Result<Self, FieldError> {
        let mut map = Self::empty(world.bounds, cell, clearance)?;
        let half_diagonal = cell * std::f64::consts::FRAC_1_SQRT_2;
        for j in 0..map.ny {
            for i in 0..map.nx {
                let c = map.centre((i, j));
                let occupied = world.obstacles.iter().enumerate().any(|(k, o)| {
                    known(k)
                        && o.is_static()
                        && o.appear_at <= 0.0
                        && o.box_distance(c, 0.0) <= half_diagonal
                        && o.distance(c, 0.0) <= half_diagonal
                });
                if occupied {
                    map.evidence[j * map.nx + i] = PRIOR;
                }
            }
        }
        Ok(map)
    }

    /// The centre of cell `c`.
    pub fn centre(&self, c: Cell) -> Vec2 {
        self.lattice.centre(c)
    }

    /// The cell containing `p`, if it is inside the map.
    pub fn cell_of(&self, p: Vec2) -> Option<Cell> {
        self.lattice.cell_of(p)
    }

    /// Whether the model holds cell `c` occupied.
    pub fn occupied(&self, (i, j): Cell) -> bool {
        let k = j * self.nx + i;
        i < self.nx && j < self.ny && (self.felt[k] || self.evidence[k] > 0)
    }

    /// The evidence for cell `c` (positive: occupied) and whether a
    /// bumper felt it.
    pub fn evidence(&self, (i, j): Cell) -> (i8, bool) {
        let k = j * self.nx + i;
        match (self.evidence.get(k), self.felt.get(k)) {
            (Some(e), Some(f)) if i < self.nx => (*e, *f),
            _ => (0, false),
        }
    }

    /// Every occupied cell.
    pub fn occupied_cells(&self) -> impl Iterator<Item = Cell> + '_ {
        (0..self.ny)
            .flat_map(move |j| (0..self.nx).map(move |i| (i, j)))
            .filter(|c| self.occupied(*c))
    }

    fn add(&mut self, c: Cell, delta: i8) {
        let k = c.1 * self.nx + c.0;
        self.evidence[k] = (self.evidence[k] + delta).clamp(-CLAMP, CLAMP);
    }

    /// Fuse one reading of the range rays and bumpers taken at `pose`.
    /// Where the robot's body is, nothing else can be.
    pub fn update(&mut self, pose: Pose, percepts: &Percepts, radius: f64) {
        let origin = Vec2::new(pose.x, pose.y);
        for c in self.cells_within(origin, radius - 0.5 * self.cell) {
            let k = c.1 * self.nx + c.0;
            self.felt[k] = false;
            self.evidence[k] = self.evidence[k].min(0);
        }
        for r in &percepts.rays {
            self.ray(origin, pose.theta + r.angle, r.range.max(0.0), r.hit);
        }
        // The front bumper stops a robot driving into something: it is
        // somewhere across the bumper's arc ahead. (Side and back bumpers
        // say too little about where.)
        if percepts.bumpers[0] {
            for bearing in [-0.5, 0.0, 0.5] {
                let at = origin + unit(pose.theta + bearing) * (radius + 0.5 * self.cell);
                if let Some((i, j)) = self.cell_of(at) {
                    self.felt[j * self.nx + i] = true;
                }
            }
        }
    }

    /// One ray: free along it, occupied where it ended on something.
    fn ray(&mut self, origin: Vec2, angle: f64, range: f64, hit: bool) {
        let dir = unit(angle);
        let end = self.cell_of(origin + dir * range);
        let step = 0.5 * self.cell;
        let samples = (range / step).ceil().min(4.0 * (self.nx + self.ny) as f64) as usize;
        let mut last = None;
        for s in 0..samples {
            let Some(c) = self.cell_of(origin + dir * (s as f64 * step)) else {
                break;
            };
            if Some(c) != last && !(hit && Some(c) == end) {
                self.add(c, -1);
                last = Some(c);
            }
        }
        if hit && let Some(c) = end {
            self.add(c, 2);
        }
    }

    /// The cells whose centres lie within `r` of `p`.
    fn cells_within(&self, p: Vec2, r: f64) -> Vec<Cell> {
        let reach = (r.max(0.0) / self.cell).ceil() as isize + 1;
        let Some((i, j)) = self.cell_of(p) else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for dj in -reach..=reach {
            for di in -reach..=reach {
                let (a, b) = (i as isize + di, j as isize + dj);
                if a >= 0 && b >= 0 && (a as usize) < self.nx && (b as usize) < self.ny {
                    let c = (a as usize, b as usize);
                    if (self.centre(c) - p).norm() <= r {
                        out.push(c);
                    }
                }
            }
        }
        out
    }

    /// The planning grid: free where no occupied cell lies within the
    /// clearance and the fence is farther than it. When `start` (the
    /// robot) is closer to something than that, every cell around it that
    /// is not itself occupied is freed, so the robot can plan its way out.
    pub fn grid(&self, start: Option<Vec2>) -> Result<Grid, FieldError> {
        let reach = (self.clearance / self.cell).ceil() as isize;
        let mut blocked = vec![false; self.nx * self.ny];
        for (i, j) in self.occupied_cells() {
            for dj in -reach..=reach {
                for di in -reach..=reach {
                    let (a, b) = (i as isize + di, j as isize + dj);
                    let gap = ((di * di + dj * dj) as f64).sqrt() * self.cell - 0.5 * self.cell;
                    if a >= 0
                        && b >= 0
                        && (a as usize) < self.nx
                        && (b as usize) < self.ny
                        && gap <= self.clearance
                    {
                        blocked[b as usize * self.nx + a as usize] = true;
                    }
                }
            }
        }
        let b = self.bounds;
        for j in 0..self.ny {
            for i in 0..self.nx {
                let p = self.centre((i, j));
                let fence = (p.x - b.x_min)
                    .min(b.x_max - p.x)
                    .min(p.y - b.y_min)
                    .min(b.y_max - p.y);
                if fence <= self.clearance {
                    blocked[j * self.nx + i] = true;
                }
            }
        }
        let stuck = start
            .and_then(|p| self.cell_of(p))
            .is_some_and(|(i, j)| blocked[j * self.nx + i]);
        if let Some(p) = start.filter(|_| stuck) {
            for c in self.cells_within(p, self.clearance + self.cell) {
                if !self.occupied(c) {
                    blocked[c.1 * self.nx + c.0] = false;
                }
            }
        }
        Grid::from_test(self.bounds, self.cell, |p| {
            self.cell_of(p)
                .is_some_and(|(i, j)| !blocked[j * self.nx + i])
        })
    }
}
