//! Simon's ant on the beach. The ant knows one rule: a pebble ahead on the
//! right, turn left; on the left, turn right; otherwise head for the goal.
//! The beach is a seeded scatter of pebbles, many small and a few large.
//! The ant's body length sets which pebbles matter: it steps over any
//! pebble smaller than a quarter of its length, so a body a thousand times
//! larger meets no obstacle at all.

use kinolab_common::random::SplitMix64;
use kinolab_common::trig;
use serde::Serialize;

use crate::FieldError;

/// The beach: x from 0 to `LENGTH`, y within ±`HALF_WIDTH`, m.
pub const LENGTH: f64 = 1.0;
pub const HALF_WIDTH: f64 = 0.3;
/// An ant's body length at size 1, m.
pub const ANT: f64 = 0.004;
/// The largest size the model accepts (a 4 m body).
pub const MAX_SIZE: f64 = 1000.0;
/// The pebbles on the lab's beaches: about a fifth of the sand covered.
pub const DEFAULT_PEBBLES: usize = 1500;
/// Steps at most, whatever the beach.
pub const MAX_STEPS: usize = 20_000;
/// The turn per step, rad.
const TURN: f64 = 0.35;
/// Pebbles' centres keep this many times the sum of their radii apart, so
/// the gap between two is at least 0.4 of their radii together: narrow
/// enough to make an ant wind, wide enough that it is never walled in.
const GAP: f64 = 1.4;
/// Side of the buckets pebbles are filed in, m (the largest diameter).
const BUCKET: f64 = 0.12;

/// A pebble: centre and radius, m.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Pebble {
    pub x: f64,
    pub y: f64,
    pub r: f64,
}

/// A beach of pebbles, filed in buckets for quick lookups.
#[derive(Debug, Clone, PartialEq)]
pub struct Beach {
    pub seed: u64,
    pub pebbles: Vec<Pebble>,
    buckets: Vec<Vec<usize>>,
    nx: usize,
    ny: usize,
}

/// Where the ant starts and where it goes.
pub const START: [f64; 2] = [0.03, 0.0];
pub const GOAL: [f64; 2] = [0.97, 0.0];

impl Beach {
    /// Up to `count` pebbles (at most 5000) placed by `seed`: radii from
    /// 1 mm to 6 cm, mostly small, never crowded (see `GAP`); none covers the
    /// start or the goal.
    pub fn new(seed: u64, count: usize) -> Result<Self, FieldError> {
        if count > 5000 {
            return Err(FieldError::new(
                "pebbles",
                format!("at most 5000, got {count}"),
            ));
        }
        let mut rng = SplitMix64::new(seed);
        let mut pebbles: Vec<Pebble> = Vec::with_capacity(count);
        let mut placing = Placing::new();
        // Pebbles keep `GAP` apart, so no pocket is too narrow for an ant;
        // tries are bounded, so a crowded request gives fewer pebbles.
        for _ in 0..count * 40 {
            if pebbles.len() == count {
                break;
            }
            let p = Pebble::candidate(&mut rng);
            if p.clear_of_the_ends() && placing.apart(&p, &pebbles) {
                placing.file(&p, pebbles.len());
                pebbles.push(p);
            }
        }
        let nx = (LENGTH / BUCKET).ceil() as usize + 1;
        let ny = (2.0 * HALF_WIDTH / BUCKET).ceil() as usize + 1;
        let mut buckets = vec![Vec::new(); nx * ny];
        for (i, p) in pebbles.iter().enumerate() {
            let (bx, by) = bucket_of(p.x, p.y, nx, ny);
            buckets[by * nx + bx].push(i);
        }
        Ok(Self {
            seed,
            pebbles,
            buckets,
            nx,
            ny,
        })
    }

    /// Pebbles whose bucket is next to the point's.
    fn near(&self, x: f64, y: f64) -> impl Iterator<Item = &Pebble> + '_ {
        let (bx, by) = bucket_of(x, y, self.nx, self.ny);
        let (nx, ny) = (self.nx, self.ny);
        (by.saturating_sub(1)..=(by + 1).min(ny - 1))
            .flat_map(move |j| {
                (bx.saturating_sub(1)..=(bx + 1).min(nx - 1)).map(move |i| j * nx + i)
            })
            .flat_map(move |k| self.buckets[k].iter().map(move |&i| &self.pebbles[i]))
    }
}

impl Pebble {
    /// Whether the square round the pebble reaching `gap` past its edge
    /// (a little more, for rounding) holds the point: a cheap test that
    /// every point within `gap` of its edge passes.
    fn within(&self, x: f64, y: f64, gap: f64) -> bool {
        let reach = (self.r + gap) * (1.0 + 1e-9);
        (self.x - x).abs() <= reach && (self.y - y).abs() <= reach
    }

    /// A pebble where `rng` puts it: radius from 1 mm to 6 cm, mostly small.
    fn candidate(rng: &mut SplitMix64) -> Self {
        let r = 0.001 * 60f64.powf(rng.unit().powi(3));
        Pebble {
            x: rng.range(0.0, LENGTH),
            y: rng.range(-HALF_WIDTH, HALF_WIDTH),
            r,
        }
    }

    /// Whether it leaves the start and the goal free.
    fn clear_of_the_ends(&self) -> bool {
        let clear = |q: [f64; 2]| (self.x - q[0]).hypot(self.y - q[1]) > self.r + 0.02;
        clear(START) && clear(GOAL)
    }
}

/// Pebbles placed so far, filed in cells at least as wide as two pebbles
/// can be too close (`GAP` times the largest diameter), so a new pebble
/// need only be checked against the cells around its own.
struct Placing {
    cells: Vec<Vec<usize>>,
    nx: usize,
    ny: usize,
}

/// A placing cell's side, m: at least `GAP` × the largest diameter (0.168 m).
const PLACING: f64 = 0.17;
const _: () = assert!(GAP * 2.0 * 0.06 <= PLACING);

impl Placing {
    fn new() -> Self {
        let nx = (LENGTH / PLACING).ceil() as usize + 1;
        let ny = (2.0 * HALF_WIDTH / PLACING).ceil() as usize + 1;
        Self {
            cells: vec![Vec::new(); nx * ny],
            nx,
            ny,
        }
    }

    fn cell(&self, p: &Pebble) -> (usize, usize) {
        let i = (p.x / PLACING).floor().clamp(0.0, (self.nx - 1) as f64) as usize;
        let j = ((p.y + HALF_WIDTH) / PLACING)
            .floor()
            .clamp(0.0, (self.ny - 1) as f64) as usize;
        (i, j)
    }

    /// Whether `p` keeps `GAP` from every pebble placed.
    fn apart(&self, p: &Pebble, placed: &[Pebble]) -> bool {
        let (ci, cj) = self.cell(p);
        (cj.saturating_sub(1)..=(cj + 1).min(self.ny - 1)).all(|j| {
            (ci.saturating_sub(1)..=(ci + 1).min(self.nx - 1)).all(|i| {
                self.cells[j * self.nx + i].iter().all(|&k| {
                    let o = &placed[k];
                    (o.x - p.x).hypot(o.y - p.y) > GAP * (o.r + p.r)
                })
            })
        })
    }

    fn file(&mut self, p: &Pebble, index: usize) {
        let (i, j) = self.cell(p);
        self.cells[j * self.nx + i].push(index);
    }
}

fn bucket_of(x: f64, y: f64, nx: usize, ny: usize) -> (usize, usize) {
    let i = (x / BUCKET).floor().clamp(0.0, (nx - 1) as f64) as usize;
    let j = ((y + HALF_WIDTH) / BUCKET)
        .floor()
        .clamp(0.0, (ny - 1) as f64) as usize;
    (i, j)
}

/// An ant's walk as a file (`*.ant.json`): the beach's seed and how many
/// pebbles it has, and the ant's size (1 = an ant).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BeachWalk {
    pub seed: u64,
    #[serde(default = "kinolab_common::defaults::count::<DEFAULT_PEBBLES>")]
    pub pebbles: usize,
    pub size: f64,
}

impl BeachWalk {
    /// Read a walk file; errors name the field.
    pub fn from_json(text: &str) -> Result<Self, FieldError> {
        kinolab_common::error::from_json(text)
    }

    /// The walk.
    pub fn walk(&self) -> Result<Walk, FieldError> {
        walk(&Beach::new(self.seed, self.pebbles)?, self.size)
    }
}

/// One walk across the beach.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Walk {
    pub size: f64,
    /// Positions, every step (at most [`MAX_STEPS`] + 1).
    pub path: Vec<[f64; 2]>,
    pub length: f64,
    /// Path length over the straight distance from start to end.
    pub tortuosity: f64,
    /// How many times an obstacle made the ant start turning.
    pub turns: usize,
    pub reached: bool,
    /// Pebbles big enough to matter at this size.
    pub obstacles: usize,
}

/// The ant's walk at body `size` (1 = an ant, 4 mm; up to 1000).
pub fn walk(beach: &Beach, size: f64) -> Result<Walk, FieldError> {
    let size = kinolab_common::error::in_range("size", size, 1.0, MAX_SIZE)?;
    let body = ANT * size;
    let matters = |p: &Pebble| p.r > 0.25 * body;
    let (reach, half) = (body, body / 4.0);
    let step = (0.5 * body).min(0.01);
    let [mut x, mut y] = START;
    let mut heading = 0.0f64;
    let mut path = vec![START];
    let (mut turns, mut avoiding) = (0, false);
    // The side the ant last turned to, to keep turning that way when stuck.
    let mut side = 1.0;
    // Steps left before the ant heads for the goal again after being
    // blocked (so it does not turn straight back into the pebble).
    let mut hold = 0;
    // Recent blocks: the more often blocked, the longer it keeps to the
    // pebble's edge before trying the goal again (a way out of pockets).
    let mut blocks = 0usize;
    // A little seeded wobble among pebbles: it breaks the symmetric loops a
    // pure rule can fall into, and the same beach and size always wobble
    // the same way.
    let mut wobble = SplitMix64::new(beach.seed ^ size.to_bits());
    for _ in 0..MAX_STEPS {
        if x >= GOAL[0] {
            break;
        }
        // The nearest pebble that matters within reach, ahead of the ant.
        let ahead = beach
            .near(x, y)
            .filter(|p| matters(p) && p.within(x, y, reach))
            .filter_map(|p| {
                let (dx, dy) = (p.x - x, p.y - y);
                let gap = dx.hypot(dy) - p.r;
                let bearing = kinolab_common::angle::wrap(trig::atan2(dy, dx) - heading);
                (gap < reach && bearing.abs() < 1.6).then_some((gap, bearing))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0));
        match ahead {
            Some((_, bearing)) => {
                // The side is chosen when a pebble first looms, and kept
                // while pebbles keep looming: it follows their edge.
                if !avoiding {
                    side = if bearing < 0.0 { 1.0 } else { -1.0 };
                }
                heading += side * TURN;
                if !avoiding {
                    turns += 1;
                }
                avoiding = true;
            }
            None if hold > 0 => {
                hold -= 1;
            }
            None => {
                let to_goal = trig::atan2(GOAL[1] - y, GOAL[0] - x);
                heading += kinolab_common::angle::wrap(to_goal - heading).clamp(-TURN, TURN);
                avoiding = false;
            }
        }
        if avoiding || hold > 0 {
            heading += 0.2 * (wobble.unit() - 0.5);
        }
        let (nx, ny) = (x + step * trig::cos(heading), y + step * trig::sin(heading));
        let blocked = beach.near(nx, ny).any(|p| {
            matters(p) && p.within(nx, ny, half) && (p.x - nx).hypot(p.y - ny) < p.r + half
        });
        if blocked {
            heading += side * TURN;
            blocks = (blocks + 2).min(60);
            hold = 3 + blocks;
        } else {
            (x, y) = (nx, ny);
            path.push([x, y]);
            if ahead.is_none() && hold == 0 {
                blocks = blocks.saturating_sub(1);
            }
        }
    }
    let length: f64 = path
        .windows(2)
        .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
        .sum();
    let last = path.last().copied().unwrap_or(START);
    let displacement = (last[0] - START[0]).hypot(last[1] - START[1]);
    Ok(Walk {
        size,
        reached: x >= GOAL[0],
        tortuosity: if displacement > 0.0 {
            length / displacement
        } else {
            f64::INFINITY
        },
        length,
        turns,
        obstacles: beach.pebbles.iter().filter(|p| matters(p)).count(),
        path,
    })
}

/// The sizes of the tortuosity-against-size plot: 1 to 1000, evenly on a
/// log scale.
pub fn sizes() -> impl Iterator<Item = f64> {
    (0..=12).map(|k| 10f64.powf(k as f64 / 4.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The beach as placing every pebble against every other would make it.
    fn brute_force(seed: u64, count: usize) -> Vec<Pebble> {
        let mut rng = SplitMix64::new(seed);
        let mut pebbles: Vec<Pebble> = Vec::new();
        for _ in 0..count * 40 {
            if pebbles.len() == count {
                break;
            }
            let p = Pebble::candidate(&mut rng);
            let apart = pebbles
                .iter()
                .all(|o| (o.x - p.x).hypot(o.y - p.y) > GAP * (o.r + p.r));
            if p.clear_of_the_ends() && apart {
                pebbles.push(p);
            }
        }
        pebbles
    }

    #[test]
    fn placing_by_cells_makes_the_same_beach_as_checking_every_pebble() {
        for (seed, count) in [(0, DEFAULT_PEBBLES), (7, 300), (42, 5000)] {
            let beach = Beach::new(seed, count).unwrap();
            assert_eq!(beach.pebbles, brute_force(seed, count), "seed {seed}");
        }
    }

    #[test]
    fn the_same_seed_gives_the_same_beach_and_path() {
        let a = walk(&Beach::new(4, DEFAULT_PEBBLES).unwrap(), 1.0).unwrap();
        let b = walk(&Beach::new(4, DEFAULT_PEBBLES).unwrap(), 1.0).unwrap();
        assert_eq!(a, b);
        let c = walk(&Beach::new(5, DEFAULT_PEBBLES).unwrap(), 1.0).unwrap();
        assert_ne!(a.path, c.path);
    }

    #[test]
    fn a_giant_goes_straight_and_an_ant_winds() {
        let beach = Beach::new(1, DEFAULT_PEBBLES).unwrap();
        let giant = walk(&beach, 1000.0).unwrap();
        assert_eq!(giant.obstacles, 0);
        assert!(
            giant.reached && (giant.tortuosity - 1.0).abs() < 1e-9,
            "{}",
            giant.tortuosity
        );
        assert_eq!(giant.turns, 0);
        let ant = walk(&beach, 1.0).unwrap();
        assert!(ant.reached, "{} steps", ant.path.len());
        assert!(
            ant.tortuosity > 1.05 && ant.turns > 10,
            "{} {}",
            ant.tortuosity,
            ant.turns
        );
    }

    #[test]
    fn bad_input_names_the_field() {
        assert_eq!(
            walk(&Beach::new(1, 10).unwrap(), 0.5).unwrap_err().field,
            "size"
        );
        assert_eq!(
            walk(&Beach::new(1, 10).unwrap(), f64::NAN)
                .unwrap_err()
                .field,
            "size"
        );
        assert_eq!(Beach::new(1, 6000).unwrap_err().field, "pebbles");
    }
}
