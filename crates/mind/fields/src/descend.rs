//! Following a field: a point robot stepping down it, and a unicycle
//! steering along it with a heading controller.

use kinolab_common::angle::wrap;
use kinolab_common::error::{in_range, positive};
use kinolab_common::trig;
use kinolab_wheels::{Vector3, integrate};
use kinolab_world::Pose;
use serde::Serialize;

use crate::{Field, FieldError, Vec2};

/// How a descent ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Outcome {
    /// Within one step of the goal.
    Reached,
    /// The field vanished, or the robot stopped making progress.
    Trapped,
    /// Still going when the step budget ran out.
    MaxSteps,
}

/// A point robot's descent.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Descent {
    /// Every position, the start first.
    pub path: Vec<[f64; 2]>,
    pub outcome: Outcome,
    pub end: [f64; 2],
}

impl Descent {
    /// Steps taken.
    pub fn steps(&self) -> usize {
        self.path.len().saturating_sub(1)
    }
}

/// Step length and budget for a descent.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Steps {
    /// H, m.
    pub step: f64,
    pub max_steps: usize,
}

impl Default for Steps {
    fn default() -> Self {
        Self {
            step: 0.01,
            max_steps: 10_000,
        }
    }
}

/// The most steps any descent may take.
pub const MAX_STEPS: usize = 1_000_000;

impl Steps {
    pub fn check(&self) -> Result<(), FieldError> {
        positive("step", self.step)?;
        if self.max_steps == 0 || self.max_steps > MAX_STEPS {
            return Err(FieldError::new(
                "max_steps",
                format!("must be from 1 to {MAX_STEPS}, got {}", self.max_steps),
            ));
        }
        Ok(())
    }
}

/// What a robot follows: the field itself, or the field with a remedy.
pub trait Guide {
    /// The vector to follow at `p`, step `k`.
    fn vector(&mut self, field: &Field, p: Vec2, k: usize) -> Vec2;

    /// The robot is stuck at `p`: return `true` if the guide changed what
    /// it does (so the descent goes on), `false` if the robot is trapped.
    fn stuck(&mut self, _field: &Field, _p: Vec2) -> bool {
        false
    }
}

/// The field as it is.
#[derive(Debug)]
pub struct Plain;

impl Guide for Plain {
    fn vector(&mut self, field: &Field, p: Vec2, _k: usize) -> Vec2 {
        field.vector(p)
    }
}

/// Steps over which progress is judged, and the least net travel (in
/// steps) that counts as progress.
const WINDOW: usize = 50;
const PROGRESS: f64 = 5.0;

/// A point robot from `start`: p ← p + H · F/‖F‖ until it is within H of
/// the goal, the field vanishes (‖F‖ < 1e-9), the last 50 steps moved it
/// less than 5H net, or the budget runs out.
pub fn descend(field: &Field, start: Vec2, steps: Steps) -> Result<Descent, FieldError> {
    descend_with(field, start, steps, &mut Plain)
}

/// [`descend`], following `guide` instead of the bare field.
pub fn descend_with(
    field: &Field,
    start: Vec2,
    steps: Steps,
    guide: &mut dyn Guide,
) -> Result<Descent, FieldError> {
    steps.check()?;
    kinolab_common::error::finite("start[0]", start.x)?;
    kinolab_common::error::finite("start[1]", start.y)?;
    let h = steps.step;
    let mut path = vec![start];
    let mut p = start;
    let mut since_unstuck = 0;
    let reached = |p: Vec2| field.goal.is_some_and(|g| (g - p).norm() <= h);
    let mut outcome = Outcome::MaxSteps;
    for k in 0..steps.max_steps {
        if reached(p) {
            outcome = Outcome::Reached;
            break;
        }
        let f = guide.vector(field, p, k);
        let no_progress =
            since_unstuck >= WINDOW && (p - path[path.len() - 1 - WINDOW]).norm() < PROGRESS * h;
        // A NaN length counts as a vanished field.
        let vanished = f.norm().is_nan() || f.norm() < 1e-9;
        if vanished || no_progress {
            if guide.stuck(field, p) {
                since_unstuck = 0;
                continue;
            }
            outcome = Outcome::Trapped;
            break;
        }
        p += f * (h / f.norm());
        path.push(p);
        since_unstuck += 1;
    }
    if outcome == Outcome::MaxSteps && reached(p) {
        outcome = Outcome::Reached;
    }
    Ok(Descent {
        path: path.iter().map(|q| [q.x, q.y]).collect(),
        outcome,
        end: [p.x, p.y],
    })
}

/// The heading controller that makes a unicycle follow a vector `f`:
/// turn towards it at rate k · (heading error), and drive at
/// min(v_max, ‖f‖) · max(0, cos(error)), so it never drives away from it.
pub fn heading_command(f: Vec2, theta: f64, k: f64, v_max: f64) -> (f64, f64) {
    if f.norm().is_nan() || f.norm() <= 0.0 {
        return (0.0, 0.0);
    }
    let error = wrap(trig::atan2(f.y, f.x) - theta);
    (v_max.min(f.norm()) * trig::cos(error).max(0.0), k * error)
}

/// A unicycle that follows the field.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unicycle {
    /// k, 1/s.
    pub gain: f64,
    pub max_speed: f64,
    pub dt: f64,
    pub max_steps: usize,
    /// Within this distance of the goal counts as there, m.
    pub tolerance: f64,
}

impl Default for Unicycle {
    fn default() -> Self {
        Self {
            gain: 4.0,
            max_speed: 0.5,
            dt: 0.02,
            max_steps: 3_000,
            tolerance: 0.05,
        }
    }
}

/// A unicycle's run along a field.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Trail {
    pub poses: Vec<Pose>,
    pub outcome: Outcome,
}

/// Drive a unicycle from `start` with [`heading_command`] on the field,
/// integrating each step exactly (an arc), until it reaches the goal,
/// stops making progress, or runs out of steps.
pub fn follow(field: &Field, start: Pose, u: &Unicycle) -> Result<Trail, FieldError> {
    positive("gain", u.gain)?;
    positive("max_speed", u.max_speed)?;
    in_range("dt", u.dt, 1e-4, 1.0)?;
    positive("tolerance", u.tolerance)?;
    if u.max_steps == 0 || u.max_steps > MAX_STEPS {
        return Err(FieldError::new(
            "max_steps",
            format!("must be from 1 to {MAX_STEPS}"),
        ));
    }
    let window = ((2.0 / u.dt).round() as usize).max(10);
    let mut poses = vec![start];
    let mut pose = start;
    let at = |q: &Pose| Vec2::new(q.x, q.y);
    for _ in 0..u.max_steps {
        if field
            .goal
            .is_some_and(|g| (g - at(&pose)).norm() <= u.tolerance)
        {
            return Ok(Trail {
                poses,
                outcome: Outcome::Reached,
            });
        }
        if poses.len() > window
            && (at(&pose) - at(&poses[poses.len() - 1 - window])).norm() < 2.0 * u.max_speed * u.dt
        {
            return Ok(Trail {
                poses,
                outcome: Outcome::Trapped,
            });
        }
        let (v, omega) = heading_command(field.vector(at(&pose)), pose.theta, u.gain, u.max_speed);
        let [x, y, theta] = integrate(
            [pose.x, pose.y, pose.theta],
            Vector3::new(v, 0.0, omega),
            u.dt,
        );
        pose = Pose::new(x, y, theta);
        poses.push(pose);
    }
    Ok(Trail {
        poses,
        outcome: Outcome::MaxSteps,
    })
}
