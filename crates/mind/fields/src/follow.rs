//! A point robot that takes the field as its velocity: where the field is
//! long the robot hurries, where it is short it creeps, and it never goes
//! faster than its top speed. Unlike [`crate::descend`], which steps a
//! fixed length along the field's direction to map where a field leads,
//! this robot feels the field's size, and it may not pass through an
//! obstacle: a pull so strong that it overrides a push walks the robot
//! into the thing that pushed.

use kinolab_common::error::positive;
use kinolab_world::Obstacle;
use serde::Serialize;

use crate::{Field, FieldError, Vec2};

/// The robot's clock and speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pace {
    /// Time per step, s.
    pub dt: f64,
    /// Top speed, m/s: a longer field vector is cut to this.
    pub max_speed: f64,
    pub max_steps: usize,
    /// Within this distance of the goal counts as there, m.
    pub tolerance: f64,
}

impl Default for Pace {
    fn default() -> Self {
        Self {
            dt: 0.05,
            max_speed: 0.5,
            max_steps: 1_200,
            tolerance: 0.05,
        }
    }
}

/// How a walk ended.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Ended {
    /// Within the tolerance of the goal.
    Reached,
    /// The field vanished, or the robot moved less than [`STALL_DISTANCE`]
    /// in the last [`STALL_STEPS`] steps.
    Stalled,
    /// The step from the point before ran into obstacle `obstacle`.
    Hit { obstacle: usize },
    /// Still going when the steps ran out.
    OutOfSteps,
}

/// A robot's walk along a field.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Walk {
    /// Every position, the start first (the last is where it ended or hit).
    pub path: Vec<[f64; 2]>,
    pub ended: Ended,
    /// The fastest it went, m/s.
    pub top_speed: f64,
}

/// Steps over which a stall is judged, and the least net travel, m.
pub const STALL_STEPS: usize = 100;
pub const STALL_DISTANCE: f64 = 0.01;

/// The robot from `start`: p ← p + dt · F, with ‖dt · F‖ at most
/// dt · max_speed, until it is within the tolerance of the goal, hits one
/// of the field's obstacles, stalls, or runs out of steps.
pub fn follow(field: &Field, start: Vec2, pace: Pace) -> Result<Walk, FieldError> {
    positive("dt", pace.dt)?;
    positive("max_speed", pace.max_speed)?;
    positive("tolerance", pace.tolerance)?;
    kinolab_common::error::finite("start[0]", start.x)?;
    kinolab_common::error::finite("start[1]", start.y)?;
    let obstacles: Vec<Obstacle> = field.obstacles().into_iter().map(Obstacle::new).collect();
    let reached = |p: Vec2| field.goal.is_some_and(|g| (g - p).norm() <= pace.tolerance);
    let mut path = vec![[start.x, start.y]];
    let (mut p, mut top) = (start, 0.0_f64);
    let mut ended = Ended::OutOfSteps;
    for _ in 0..pace.max_steps.min(crate::descend::MAX_STEPS) {
        if reached(p) {
            ended = Ended::Reached;
            break;
        }
        let f = field.vector(p);
        let speed = f.norm();
        let stalled = path.len() > STALL_STEPS
            && (p - Vec2::from(path[path.len() - 1 - STALL_STEPS])).norm() < STALL_DISTANCE;
        // A NaN length counts as a vanished field.
        if speed.is_nan() || speed < 1e-9 || stalled {
            ended = Ended::Stalled;
            break;
        }
        let speed_here = speed.min(pace.max_speed);
        let next = p + f * (pace.dt * speed_here / speed);
        top = top.max(speed_here);
        if let Some(obstacle) = hit(&obstacles, p, next) {
            path.push([next.x, next.y]);
            ended = Ended::Hit { obstacle };
            break;
        }
        p = next;
        path.push([p.x, p.y]);
    }
    if ended == Ended::OutOfSteps && reached(p) {
        ended = Ended::Reached;
    }
    Ok(Walk {
        path,
        ended,
        top_speed: top,
    })
}

/// The first obstacle the step from `a` to `b` runs into.
fn hit(obstacles: &[Obstacle], a: Vec2, b: Vec2) -> Option<usize> {
    let along = b - a;
    let length = along.norm();
    obstacles.iter().position(|o| {
        o.distance(b, 0.0) <= 0.0
            || (length > 0.0 && o.ray(a, along / length, length, 0.0).is_some())
    })
}
