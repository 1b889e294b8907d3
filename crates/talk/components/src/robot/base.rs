//! The base server: takes velocity commands (send), drives the simulated
//! robot, pushes odometry at a fixed rate (push timed), and tells a client
//! when the robot is within reach of a goal it named (event).

use kinolab_world::{Command, Pose};

use crate::FieldError;
use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, ServiceSpec, Signature};
use crate::runtime::Ctx;

/// Without a fresh command for this long, the base stops (a watchdog), s.
const WATCHDOG: f64 = 0.5;

#[derive(Debug, Clone)]
pub struct Base {
    period: f64,
    command: Command,
    commanded_at: f64,
    pose: Option<Pose>,
    travelled: f64,
}

impl Base {
    pub fn new(p: super::Periodic) -> Result<Self, FieldError> {
        Ok(Self {
            period: p.check()?,
            command: Command::STOP,
            commanded_at: f64::NEG_INFINITY,
            pose: None,
            travelled: 0.0,
        })
    }
}

impl Component for Base {
    fn interface(&self) -> Interface {
        Interface {
            services: vec![
                ServiceSpec::new("velocity", Pattern::Send, Signature::one("Twist")),
                ServiceSpec::new("odometry", Pattern::PushTimed, Signature::one("Pose")),
                ServiceSpec::new("arrived", Pattern::Event, Signature::two("Goal", "Pose")),
            ],
            ports: Vec::new(),
            master: false,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        self.pose = cx.world().map(|s| s.pose);
        if let Some(p) = self.pose {
            cx.publish("odometry", super::pose_object(p));
        }
        cx.start_timed("odometry", self.period);
        let dt = cx.world().map_or(0.05, |s| s.dt);
        cx.after(dt, 0);
    }

    fn command(&mut self, _service: &str, object: &Object, cx: &mut Ctx<'_>) {
        let v = object.field("v").unwrap_or(0.0);
        let w = object.field("omega").unwrap_or(0.0);
        self.command = Command::unicycle(v, w);
        self.commanded_at = cx.now();
    }

    fn timer(&mut self, _tag: u32, cx: &mut Ctx<'_>) {
        let fresh = cx.now() - self.commanded_at <= WATCHDOG;
        let command = if fresh { self.command } else { Command::STOP };
        let Some(sim) = cx.world() else { return };
        let step = sim.advance(command);
        let (pose, dt) = (sim.pose, sim.dt);
        self.travelled += step.moved;
        self.pose = Some(pose);
        cx.publish("odometry", super::pose_object(pose));
        self.activated("arrived", cx);
        cx.after(dt, 0);
    }

    fn activated(&mut self, _service: &str, cx: &mut Ctx<'_>) {
        let Some(pose) = self.pose else { return };
        cx.test_events("arrived", &|goal: &Object| {
            let (x, y) = (goal.field("x")?, goal.field("y")?);
            let within = goal.field("within").unwrap_or(0.25);
            ((pose.x - x).hypot(pose.y - y) <= within).then(|| super::pose_object(pose))
        });
    }

    fn status(&self) -> String {
        match self.pose {
            Some(p) => format!(
                "at ({:.2}, {:.2}), {:.2} m driven",
                p.x, p.y, self.travelled
            ),
            None => "no world".to_owned(),
        }
    }
}
