//! The hybrid robot in its three-layer form.
//!
//! - the **planner** (deliberative layer) runs A* on the cartographer's
//!   map, slowly and in the background: the robot keeps moving meanwhile;
//! - the **sequencer** (executive) holds the plan, hands the next waypoint
//!   to the skills and watches progress: no progress for a while, a
//!   waypoint the map now shows blocked, or a goal that moved, and it asks
//!   for a new plan;
//! - the **skills** (reactive layer) run every step on fresh percepts.

use kinolab_world::sensors::Percepts;
use kinolab_world::{FieldError, Vec2};

use super::{Act, Belief, Settings, aimed_at, goal_point, plan_age, plan_target, scripted};
use crate::follow::Follower;
use crate::map::Cartographer;
use crate::planner::{Outcome, Plan, Planner};
use crate::skills::Skills;

/// Seconds without getting 0.1 m closer to the waypoint before a replan.
pub const PATIENCE: f64 = 3.0;
/// A goal this far (m) from the one planned for counts as moved.
const MOVED: f64 = 0.3;

/// The executive: the plan being carried out and how it is going.
#[derive(Debug, Clone, Default)]
pub struct Sequencer {
    pub plan: Option<Plan>,
    follower: Option<Follower>,
    best: f64,
    stalled: f64,
    /// Why the last new plan was asked for.
    pub reason: Option<&'static str>,
}

impl Sequencer {
    /// Take a new plan.
    fn adopt(&mut self, plan: Plan) {
        self.follower = Some(Follower::new(plan.waypoints.clone()));
        self.plan = Some(plan);
        self.best = f64::INFINITY;
        self.stalled = 0.0;
    }

    /// Whether (and why) a new plan is needed, looking at the map, the
    /// goal and the progress towards the waypoint.
    fn needs_plan(
        &mut self,
        map: &Cartographer,
        at: Vec2,
        goal: Vec2,
        dt: f64,
    ) -> Option<&'static str> {
        let Some(plan) = &self.plan else {
            return Some("no plan yet");
        };
        if (Vec2::new(plan.goal[0], plan.goal[1]) - goal).norm() > MOVED {
            return Some("the goal moved");
        }
        let target = plan_target(&mut self.follower, at)?;
        if blocked(map, at, target) {
            return Some("the way to the waypoint is blocked");
        }
        let d = (target - at).norm();
        if d < self.best - 0.1 {
            self.best = d;
            self.stalled = 0.0;
        } else {
            self.stalled += dt;
        }
        (self.stalled > PATIENCE).then_some("no progress")
    }
}

/// Whether the map holds an occupied cell on the segment from `a` to `b`
/// (ignoring the robot's own cell).
fn blocked(map: &Cartographer, a: Vec2, b: Vec2) -> bool {
    let span = b - a;
    let samples = (span.norm() / (0.5 * map.cell)).ceil().min(1e5) as usize;
    let own = map.cell_of(a);
    (1..=samples).any(|k| {
        map.cell_of(a + span * (k as f64 / samples as f64))
            .is_some_and(|c| Some(c) != own && map.occupied(c))
    })
}

#[derive(Debug, Clone)]
pub struct Hybrid {
    pub map: Cartographer,
    pub planner: Planner,
    pub sequencer: Sequencer,
    pub skills: Skills,
    radius: f64,
    /// A learner's sequencer in place of the built-in one, the error that
    /// stopped it, and whether the last search found no way.
    script: Option<Box<kinolab_script::Script>>,
    pub failed: Option<Box<kinolab_script::ScriptError>>,
    /// The learner's sequencer's last question and answer.
    pub asked: Option<Box<scripted::Asked>>,
    no_path: bool,
}

impl Hybrid {
    pub fn new(settings: &Settings, map: Cartographer) -> Result<Self, FieldError> {
        Ok(Self {
            map,
            planner: Planner::new(settings.planning_cost)?,
            sequencer: Sequencer::default(),
            skills: Skills::avoid_and_go(&settings.body),
            radius: settings.body.radius(),
            script: settings.sequencer.clone().map(Box::new),
            failed: None,
            asked: None,
            no_path: false,
        })
    }

    pub fn act(&mut self, p: &Percepts, dt: f64) -> Act {
        if self.script.is_some() {
            return self.act_scripted(p, dt);
        }
        let pose = p.odometry;
        let at = Vec2::new(pose.x, pose.y);
        // The cartographer listens all the time.
        self.map.update(pose, p, self.radius);
        if let Some(goal) = goal_point(p)
            && let Some(reason) = self.sequencer.needs_plan(&self.map, at, goal, dt)
            && self
                .planner
                .pending
                .as_ref()
                .is_none_or(|busy| reason == "the goal moved" && (busy.goal - goal).norm() > MOVED)
        {
            self.sequencer.reason = Some(reason);
            self.sequencer.stalled = 0.0;
            if self.planner.request(&self.map, at, goal, p.time).is_err() {
                self.planner.pending = None;
            }
        }
        match self.planner.tick(dt, p.time) {
            Some(Outcome::Found(plan)) => self.sequencer.adopt(plan),
            Some(Outcome::NoPath { .. }) => {
                self.sequencer.plan = None;
                self.sequencer.follower = None;
            }
            None => {}
        }
        // The skills chase the waypoint, or the goal itself before any plan.
        let aimed = match plan_target(&mut self.sequencer.follower, at) {
            Some(target) => aimed_at(p, target),
            None => p.clone(),
        };
        let step = self.skills.act(&aimed, dt);
        Act {
            command: step.command,
            activity: step.in_control.unwrap_or_else(|| "idle".into()),
            model_age: plan_age(&self.sequencer.plan, p.time),
        }
    }

    /// A step with the learner's sequencer deciding.
    fn act_scripted(&mut self, p: &Percepts, dt: f64) -> Act {
        let pose = p.odometry;
        let at = Vec2::new(pose.x, pose.y);
        self.map.update(pose, p, self.radius);
        let goal = goal_point(p);
        let next = plan_target(&mut self.sequencer.follower, at);
        let ahead = self
            .sequencer
            .follower
            .as_ref()
            .map_or(&[][..], |f| f.ahead());
        let situation = scripted::Situation {
            t: p.time,
            at,
            goal,
            plan: ahead,
            planned_for: self.sequencer.plan.as_ref().map(|plan| plan.goal),
            planning: self.planner.pending.is_some(),
            no_path: self.no_path,
            blocked: next.is_some_and(|w| blocked(&self.map, at, w)),
        };
        let decision = match self
            .script
            .as_mut()
            .map(|s| scripted::decide(s, &situation))
        {
            Some(Ok((d, asked))) => {
                self.asked = Some(Box::new(asked));
                d
            }
            Some(Err(e)) => {
                self.failed = Some(Box::new(e));
                self.script = None;
                return stopped();
            }
            None => return stopped(),
        };
        if decision.replan
            && self.planner.pending.is_none()
            && let Some(goal) = goal
        {
            self.sequencer.reason = Some("your sequencer asked");
            if self.planner.request(&self.map, at, goal, p.time).is_err() {
                self.planner.pending = None;
            }
        }
        match self.planner.tick(dt, p.time) {
            Some(Outcome::Found(plan)) => {
                self.no_path = false;
                self.sequencer.adopt(plan);
            }
            Some(Outcome::NoPath { .. }) => self.no_path = true,
            None => {}
        }
        let aimed = match decision.target.or(goal) {
            Some(target) => aimed_at(p, target),
            None => p.clone(),
        };
        let step = self.skills.act(&aimed, dt);
        Act {
            command: step.command,
            activity: step.in_control.unwrap_or_else(|| "idle".into()),
            model_age: plan_age(&self.sequencer.plan, p.time),
        }
    }

    pub fn belief(&self) -> Belief<'_> {
        Belief {
            map: Some(&self.map),
            plan: self.sequencer.follower.as_ref().map_or(&[], |f| f.ahead()),
            planning: self.planner.pending.as_ref(),
        }
    }
}

/// What a robot does once its learner's sequencer has failed: stand still.
fn stopped() -> Act {
    Act {
        command: kinolab_world::Command::STOP,
        activity: "stopped: the sequencer failed".into(),
        model_age: None,
    }
}
