//! The three paradigms as controllers for one robot. Each reads only the
//! robot's percepts (its pose from odometry) and returns a command; each
//! shows what it believes, for drawing beside what is really there.

mod hierarchical;
mod hybrid;
mod reactive;
pub mod scripted;

pub use hierarchical::Hierarchical;
pub use hybrid::{Hybrid, Sequencer};
pub use reactive::Reactive;

use kinolab_common::angle::wrap;
use kinolab_common::trig;
use kinolab_world::sensors::{GoalPercept, Percepts};
use kinolab_world::{Body, Command, FieldError, Pose, Vec2, unit};
use serde::{Deserialize, Serialize};

use crate::follow::Follower;
use crate::map::Cartographer;
use crate::planner::{Pending, Plan};

/// The paradigms, told apart by their pattern of primitives.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Architecture {
    /// SENSE → PLAN → ACT in a loop, on one world model.
    Hierarchical,
    /// SENSE → ACT pairs (behaviours), no model.
    Reactive,
    /// PLAN slowly, alongside SENSE → ACT at full rate.
    Hybrid,
}

impl Architecture {
    pub const ALL: [Architecture; 3] = [
        Architecture::Hierarchical,
        Architecture::Reactive,
        Architecture::Hybrid,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Architecture::Hierarchical => "hierarchical",
            Architecture::Reactive => "reactive",
            Architecture::Hybrid => "hybrid",
        }
    }

    /// Read a name; the error names `field`.
    pub fn parse(field: &str, text: &str) -> Result<Self, FieldError> {
        Self::ALL
            .into_iter()
            .find(|a| a.name() == text)
            .ok_or_else(|| {
                FieldError::new(
                    field,
                    format!("`{text}` is not an architecture: hierarchical, reactive or hybrid"),
                )
            })
    }
}

/// What the robots share: their body and the planning cost; and a
/// learner's sequencer for the hybrid robot, when there is one.
#[derive(Debug, Clone, PartialEq)]
pub struct Settings {
    pub body: Body,
    /// Simulated planning time per expanded cell, s.
    pub planning_cost: f64,
    pub sequencer: Option<kinolab_script::Script>,
}

/// One step of a controller.
#[derive(Debug, Clone, PartialEq)]
pub struct Act {
    pub command: Command,
    /// What it is doing, in a few words ("planning", "avoid", …).
    pub activity: String,
    /// How old the sensing behind the plan it follows is, s (`None`: it
    /// acts on no model).
    pub model_age: Option<f64>,
}

/// What a controller believes, for drawing.
#[derive(Debug, Clone, Copy)]
pub struct Belief<'a> {
    pub map: Option<&'a Cartographer>,
    /// The waypoints still ahead.
    pub plan: &'a [[f64; 2]],
    pub planning: Option<&'a Pending>,
}

/// A controller of one of the three kinds.
#[derive(Debug, Clone)]
pub enum Controller {
    Hierarchical(Hierarchical),
    Reactive(Reactive),
    Hybrid(Hybrid),
}

impl Controller {
    /// A controller of `kind`, starting from `map` (ignored by the reactive one).
    pub fn new(
        kind: Architecture,
        settings: &Settings,
        map: Cartographer,
    ) -> Result<Self, FieldError> {
        Ok(match kind {
            Architecture::Hierarchical => {
                Controller::Hierarchical(Hierarchical::new(settings, map)?)
            }
            Architecture::Reactive => Controller::Reactive(Reactive::new(settings)),
            Architecture::Hybrid => Controller::Hybrid(Hybrid::new(settings, map)?),
        })
    }

    pub fn act(&mut self, p: &Percepts, dt: f64) -> Act {
        match self {
            Controller::Hierarchical(c) => c.act(p, dt),
            Controller::Reactive(c) => c.act(p, dt),
            Controller::Hybrid(c) => c.act(p, dt),
        }
    }

    pub fn belief(&self) -> Belief<'_> {
        match self {
            Controller::Hierarchical(c) => c.belief(),
            Controller::Reactive(_) => Belief {
                map: None,
                plan: &[],
                planning: None,
            },
            Controller::Hybrid(c) => c.belief(),
        }
    }

    /// Plans made after the first, and cells expanded in all.
    pub fn planner_work(&self) -> Option<crate::planner::PlannerWork> {
        match self {
            Controller::Hierarchical(c) => Some(c.planner.work),
            Controller::Reactive(_) => None,
            Controller::Hybrid(c) => Some(c.planner.work),
        }
    }

    /// The error that stopped a learner's sequencer, if one did.
    pub fn failed(&self) -> Option<&kinolab_script::ScriptError> {
        match self {
            Controller::Hybrid(c) => c.failed.as_deref(),
            _ => None,
        }
    }

    /// The learner's sequencer's last question and answer, if it has one.
    pub fn asked(&self) -> Option<&scripted::Asked> {
        match self {
            Controller::Hybrid(c) => c.asked.as_deref(),
            _ => None,
        }
    }

    /// Behaviour evaluations so far.
    pub fn evaluations(&self) -> usize {
        match self {
            Controller::Hierarchical(_) => 0,
            Controller::Reactive(c) => c.skills.evaluations,
            Controller::Hybrid(c) => c.skills.evaluations,
        }
    }
}

/// Where the goal is in the world, from odometry and the goal percept.
pub fn goal_point(p: &Percepts) -> Option<Vec2> {
    let g = p.goal?;
    let o = p.odometry;
    Some(Vec2::new(o.x, o.y) + unit(o.theta + g.bearing) * g.distance)
}

/// The percepts with the goal replaced by `target`: how a sequencer hands
/// a waypoint to skills that only know "the goal".
pub fn aimed_at(p: &Percepts, target: Vec2) -> Percepts {
    let o = p.odometry;
    let to = target - Vec2::new(o.x, o.y);
    Percepts {
        goal: Some(GoalPercept {
            bearing: wrap(trig::atan2(to.y, to.x) - o.theta),
            distance: to.norm(),
        }),
        ..p.clone()
    }
}

/// Drive straight for `target` at up to the body's top speed, slowing for
/// the last `slow_within` metres.
fn head_for(
    drive: &kinolab_behaviours::Drive,
    pose: Pose,
    target: Vec2,
    slow_within: f64,
) -> Command {
    let to = target - Vec2::new(pose.x, pose.y);
    let d = to.norm();
    if d < 1e-9 {
        return Command::STOP;
    }
    let speed = drive.body.max_speed() * (d / slow_within).min(1.0);
    let (s, c) = trig::sin_cos(-pose.theta);
    let local = Vec2::new(c * to.x - s * to.y, s * to.x + c * to.y);
    drive.follow(local / d * speed)
}

/// Follow a plan's waypoints: the target from `at`, within `reach` of a
/// waypoint counts as passing it.
fn plan_target(follower: &mut Option<Follower>, at: Vec2) -> Option<Vec2> {
    follower.as_mut().and_then(|f| f.target(at, REACH))
}

/// Within this distance (m) a waypoint counts as passed.
const REACH: f64 = 0.3;

/// The plan a controller has, and the age of the sensing behind it.
fn plan_age(plan: &Option<Plan>, now: f64) -> Option<f64> {
    plan.as_ref().map(|p| (now - p.sensed_at).max(0.0))
}
