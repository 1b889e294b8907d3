//! Ways out of local minima, each a [`Guide`] a descent can follow, and a
//! wavefront navigation function that has no local minima to escape.

use kinolab_common::error::{non_negative, positive};
use kinolab_common::random::unit_hash;
use kinolab_common::trig;
use kinolab_world::grid::Grid;
use kinolab_world::{Obstacle, Rect};
use serde::{Deserialize, Serialize};

use crate::descend::{Descent, Guide, Outcome, Plain, Steps, descend_with};
use crate::primitive::{Primitive, Source, Spin};
use crate::{Field, FieldError, Vec2};

/// A remedy, as the lab's switches and run files name it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Remedy {
    /// Follow the field as it is.
    None,
    /// Add a random vector of up to `magnitude` every step.
    Noise { magnitude: f64, seed: u64 },
    /// Be pushed away from where the robot has been: each remembered
    /// point repels with `gain`, linearly over `range`.
    AvoidPast { gain: f64, range: f64 },
    /// Around each obstacle, a tangential field turning towards the side
    /// the goal is on, `gain` times the obstacle's own.
    Templates { gain: f64 },
    /// When stuck, follow the nearest obstacle's edge until the goal is
    /// nearer than where the robot got stuck and in plain view.
    WallFollowing,
}

impl Remedy {
    pub fn name(&self) -> &'static str {
        match self {
            Remedy::None => "none",
            Remedy::Noise { .. } => "noise",
            Remedy::AvoidPast { .. } => "avoid the past",
            Remedy::Templates { .. } => "navigation templates",
            Remedy::WallFollowing => "wall following",
        }
    }

    pub fn check(&self) -> Result<(), FieldError> {
        match *self {
            Remedy::Noise { magnitude, .. } => non_negative("magnitude", magnitude).map(|_| ()),
            Remedy::AvoidPast { gain, range } => {
                non_negative("gain", gain)?;
                positive("range", range).map(|_| ())
            }
            Remedy::Templates { gain } => non_negative("gain", gain).map(|_| ()),
            Remedy::None | Remedy::WallFollowing => Ok(()),
        }
    }

    /// The guide that applies this remedy to `field`.
    pub fn guide(&self, field: &Field) -> Box<dyn Guide> {
        match *self {
            Remedy::None => Box::new(Plain),
            Remedy::Noise { magnitude, seed } => Box::new(Noise {
                magnitude,
                seed,
                retries: 0,
            }),
            Remedy::AvoidPast { gain, range } => Box::new(AvoidPast {
                gain,
                range,
                memory: Vec::new(),
            }),
            Remedy::Templates { gain } => Box::new(Templates { gain }),
            Remedy::WallFollowing => Box::new(WallFollowing::new(field)),
        }
    }
}

/// A descent from `start` with `remedy` switched on.
pub fn escape(
    field: &Field,
    start: Vec2,
    steps: Steps,
    remedy: &Remedy,
) -> Result<Descent, FieldError> {
    remedy.check().map_err(|e| e.within("remedy"))?;
    descend_with(field, start, steps, remedy.guide(field).as_mut())
}

#[derive(Debug)]
struct Noise {
    magnitude: f64,
    seed: u64,
    /// Times the robot stalled and the noise was given another chance.
    retries: usize,
}

/// How often a noisy robot may stall before it counts as trapped: near a
/// saddle the noise alone wanders, slowly, before the field takes over.
const NOISE_RETRIES: usize = 40;

impl Guide for Noise {
    fn vector(&mut self, field: &Field, p: Vec2, k: usize) -> Vec2 {
        let r = self.magnitude * unit_hash(self.seed, k as u64, 0).sqrt();
        let a = std::f64::consts::TAU * unit_hash(self.seed, k as u64, 1);
        field.vector(p) + Vec2::new(trig::cos(a), trig::sin(a)) * r
    }

    fn stuck(&mut self, _field: &Field, _p: Vec2) -> bool {
        self.retries += 1;
        self.retries <= NOISE_RETRIES
    }
}

/// Remember one point in this many steps, and at most this many points.
const MEMORY_EVERY: usize = 5;
const MEMORY_SIZE: usize = 400;

#[derive(Debug)]
struct AvoidPast {
    gain: f64,
    range: f64,
    memory: Vec<Vec2>,
}

impl Guide for AvoidPast {
    fn vector(&mut self, field: &Field, p: Vec2, k: usize) -> Vec2 {
        let mut f = field.vector(p);
        for q in &self.memory {
            let w = p - q;
            let d = w.norm();
            if d > 1e-12 && d < self.range {
                f += w * (self.gain * (1.0 - d / self.range) / d);
            }
        }
        if k.is_multiple_of(MEMORY_EVERY) {
            if self.memory.len() == MEMORY_SIZE {
                self.memory.remove(0);
            }
            self.memory.push(p);
        }
        f
    }
}

/// The spin that takes a robot at `p` round an obstacle at `c` on the side
/// the goal `g` is on (counter-clockwise when the goal is dead ahead).
pub fn template_spin(p: Vec2, c: Vec2, g: Vec2) -> Spin {
    // Goal to the left of the line robot → obstacle: pass on the left,
    // which is a clockwise turn round the obstacle.
    if (c - p).perp(&(g - p)) > 0.0 {
        Spin::Cw
    } else {
        Spin::Ccw
    }
}

#[derive(Debug)]
struct Templates {
    gain: f64,
}

impl Guide for Templates {
    fn vector(&mut self, field: &Field, p: Vec2, _k: usize) -> Vec2 {
        let mut f = field.vector(p);
        let Some(goal) = field.goal else { return f };
        for q in &field.primitives {
            match q.source {
                Source::Repulsive { centre, radius } => {
                    let spin = template_spin(p, centre, goal);
                    let around = Primitive {
                        source: Source::Tangential {
                            centre,
                            radius,
                            spin,
                        },
                        gain: q.gain * self.gain,
                        ..*q
                    };
                    f += around.vector(p);
                }
                Source::Perpendicular { from, to, .. } => {
                    // Along the segment, towards the end nearer the goal,
                    // as strong as the segment's own push.
                    let push = q.vector(p).norm();
                    let along = if (from - goal).norm() < (to - goal).norm() {
                        from - to
                    } else {
                        to - from
                    };
                    f += along.normalize() * (push * self.gain);
                }
                _ => {}
            }
        }
        f
    }
}

/// The edge follower: where it got stuck and which way it goes round.
#[derive(Debug)]
struct WallFollowing {
    obstacles: Vec<Obstacle>,
    /// Distance to the goal when it got stuck, and the turning sense.
    following: Option<(f64, Spin)>,
}

impl WallFollowing {
    fn new(field: &Field) -> Self {
        Self {
            obstacles: field.obstacles().into_iter().map(Obstacle::new).collect(),
            following: None,
        }
    }

    fn nearest(&self, p: Vec2) -> Option<(Vec2, f64)> {
        self.obstacles
            .iter()
            .filter_map(|o| o.nearest(p, 0.0))
            .min_by(|a, b| a.1.total_cmp(&b.1))
    }

    fn clear_view(&self, p: Vec2, goal: Vec2) -> bool {
        let span = goal - p;
        let length = span.norm();
        length < 1e-9
            || self
                .obstacles
                .iter()
                .all(|o| o.ray(p, span / length, length, 0.0).is_none())
    }
}

impl Guide for WallFollowing {
    fn vector(&mut self, field: &Field, p: Vec2, _k: usize) -> Vec2 {
        let Some((hit, spin)) = self.following else {
            return field.vector(p);
        };
        let goal = field.goal.unwrap_or(p);
        if (goal - p).norm() < hit - 1e-6 && self.clear_view(p, goal) {
            self.following = None;
            return field.vector(p);
        }
        let Some((edge, _)) = self.nearest(p) else {
            return field.vector(p);
        };
        let out = (p - edge).try_normalize(1e-12).unwrap_or_else(Vec2::zeros);
        let tangent = match spin {
            Spin::Ccw => Vec2::new(-out.y, out.x),
            Spin::Cw => Vec2::new(out.y, -out.x),
        };
        tangent + out * 0.2
    }

    fn stuck(&mut self, field: &Field, p: Vec2) -> bool {
        let (Some(goal), Some((edge, _)), None) = (field.goal, self.nearest(p), self.following)
        else {
            return false;
        };
        self.following = Some(((goal - p).norm(), template_spin(p, edge, goal)));
        true
    }
}

/// A wavefront navigation function: every free cell's shortest distance
/// to the goal's cell. Its only minimum is the goal.
#[derive(Debug, Clone, PartialEq)]
pub struct Wavefront {
    pub grid: Grid,
    /// Distance to go per cell (row by row); infinite where blocked or cut off.
    pub distance: Vec<f64>,
}

impl Wavefront {
    /// Cells of side `cell` over `area`, blocked within `clearance` of the
    /// field's obstacles, the distance spreading from the goal.
    pub fn new(field: &Field, area: &Rect, cell: f64, clearance: f64) -> Result<Self, FieldError> {
        let goal = field.goal.ok_or_else(|| {
            FieldError::new(
                "goal",
                "a wavefront spreads from the goal; the field has none",
            )
        })?;
        non_negative("clearance", clearance)?;
        let obstacles: Vec<Obstacle> = field.obstacles().into_iter().map(Obstacle::new).collect();
        let grid = Grid::from_test(area.checked("box")?, cell, |c| {
            obstacles.iter().all(|o| o.distance(c, 0.0) > clearance)
        })?;
        let goal_cell = grid
            .cell_of(goal)
            .ok_or_else(|| FieldError::new("goal", "the goal is outside the box"))?;
        let distance = grid.distances_to(goal_cell);
        Ok(Self { grid, distance })
    }

    /// Descend the navigation function from `start`: cell centres to the
    /// goal's cell, `Trapped` when the start is blocked or cut off.
    pub fn descend(&self, start: Vec2) -> Descent {
        let cells = self
            .grid
            .cell_of(start)
            .and_then(|c| self.grid.descend(&self.distance, c));
        match cells {
            Some(cells) => {
                let mut path = vec![[start.x, start.y]];
                path.extend(cells.iter().skip(1).map(|&c| {
                    let q = self.grid.centre(c);
                    [q.x, q.y]
                }));
                let end = path.last().copied().unwrap_or([start.x, start.y]);
                Descent {
                    path,
                    outcome: Outcome::Reached,
                    end,
                }
            }
            None => Descent {
                path: vec![[start.x, start.y]],
                outcome: Outcome::Trapped,
                end: [start.x, start.y],
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitive::Profile;

    #[test]
    fn templates_pass_on_the_goal_side() {
        let p = Vec2::new(0.0, 0.0);
        let c = Vec2::new(2.0, 0.0);
        assert_eq!(template_spin(p, c, Vec2::new(4.0, 1.0)), Spin::Cw);
        assert_eq!(template_spin(p, c, Vec2::new(4.0, -1.0)), Spin::Ccw);
        // Clockwise round (2, 0), on the robot's side of it, heads up (+y):
        // the robot passes above, where the goal is.
        let around = Primitive::new(
            Source::Tangential {
                centre: c,
                radius: 0.3,
                spin: Spin::Cw,
            },
            1.0,
            Profile::Constant,
            Some(1.0),
        )
        .unwrap();
        assert!(around.vector(Vec2::new(1.5, 0.0)).y > 0.0);
    }
}
