//! The hierarchical robot: SENSE → PLAN → ACT in a loop.
//!
//! SENSE fuses every range ray and bumper into the world model; PLAN runs
//! A* on that model and takes simulated time for every cell it expands;
//! ACT carries the plan out with no reflexes of its own. While a plan is
//! being made the robot goes on executing the previous one, so it always
//! acts on a model that is at least one planning time old.

use kinolab_behaviours::Drive;
use kinolab_world::sensors::Percepts;
use kinolab_world::{Command, FieldError, Vec2};

use super::{Act, Belief, Settings, goal_point, head_for, plan_age, plan_target};
use crate::follow::Follower;
use crate::map::Cartographer;
use crate::planner::{Outcome, Plan, Planner};

#[derive(Debug, Clone)]
pub struct Hierarchical {
    pub map: Cartographer,
    pub planner: Planner,
    pub plan: Option<Plan>,
    follower: Option<Follower>,
    drive: Drive,
    radius: f64,
}

impl Hierarchical {
    pub fn new(settings: &Settings, map: Cartographer) -> Result<Self, FieldError> {
        Ok(Self {
            map,
            planner: Planner::new(settings.planning_cost)?,
            plan: None,
            follower: None,
            drive: Drive {
                body: settings.body.clone(),
                heading_gain: 3.0,
            },
            radius: settings.body.radius(),
        })
    }

    pub fn act(&mut self, p: &Percepts, dt: f64) -> Act {
        let pose = p.odometry;
        let at = Vec2::new(pose.x, pose.y);
        let goal = goal_point(p);
        if !self.planner.busy()
            && let Some(goal) = goal
        {
            // SENSE: everything into the one model; then start PLAN on it.
            self.map.update(pose, p, self.radius);
            if self.planner.request(&self.map, at, goal, p.time).is_err() {
                self.planner.pending = None;
            }
        }
        match self.planner.tick(dt, p.time) {
            Some(Outcome::Found(plan)) => {
                self.follower = Some(Follower::new(plan.waypoints.clone()));
                self.plan = Some(plan);
            }
            Some(Outcome::NoPath { .. }) => {
                self.follower = None;
                self.plan = None;
            }
            None => {}
        }
        // ACT: drive the plan, whatever has happened since it was made.
        let at_goal = p.goal.is_some_and(|g| g.distance < 0.05);
        let command = match plan_target(&mut self.follower, at) {
            Some(target) if !at_goal => head_for(&self.drive, pose, target, 0.5),
            _ => Command::STOP,
        };
        let activity = match (&self.plan, self.planner.busy()) {
            (None, true) => "planning, standing still",
            (None, false) => "no plan",
            (Some(_), true) => "acting on the last plan while planning",
            (Some(_), false) => "acting",
        };
        Act {
            command,
            activity: activity.into(),
            model_age: plan_age(&self.plan, p.time).filter(|_| command != Command::STOP),
        }
    }

    pub fn belief(&self) -> Belief<'_> {
        Belief {
            map: Some(&self.map),
            plan: self.follower.as_ref().map_or(&[], |f| f.ahead()),
            planning: self.planner.pending.as_ref(),
        }
    }
}
