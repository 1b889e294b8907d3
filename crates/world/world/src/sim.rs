//! The fixed-step simulation of one robot in a world.
//!
//! Motion uses conservative advancement: within a step the robot moves at
//! most as far as the gap to the nearest thing, then looks again, so it
//! cannot pass through a wall however thin or however fast it goes. A
//! robot pushing into something slides along it (the push is lost; it may
//! turn or back away) and its bumper raises an event.

use kinolab_common::random::gaussian_hash;
use kinolab_common::trig;
use kinolab_wheels::{Vector3, integrate};
use serde::Serialize;

use crate::body::{Body, Command};
use crate::sensors::{Percepts, Reading, Sensors, bumper};
use crate::{FieldError, Pose, Vec2, World};

/// A gap this small (m) counts as touching.
pub const CONTACT: f64 = 1e-3;

/// At most this many look-and-move rounds within one step.
const MAX_ROUNDS: usize = 64;

/// Channel for odometry noise (see [`crate::sensors`]).
const ODOMETRY_CHANNEL: u64 = 3_000;

/// Something that happened during a run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Event {
    pub t: f64,
    #[serde(flatten)]
    pub kind: EventKind,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum EventKind {
    /// The robot touched something; `bumper` names the side.
    Bump {
        bumper: &'static str,
    },
    GoalReached,
    /// An obstacle appeared (its index in the world file).
    Appeared {
        obstacle: usize,
    },
}

/// What one step did.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Step {
    /// The twist the body drove (after its limits).
    pub driven: Command,
    /// How far the robot's centre moved, m.
    pub moved: f64,
    /// The gap to the nearest thing afterwards, m.
    pub clearance: f64,
    pub events: Vec<Event>,
}

/// One robot in one world, stepped at a fixed rate.
#[derive(Debug, Clone)]
pub struct Sim {
    pub world: World,
    pub body: Body,
    pub sensors: Sensors,
    pub pose: Pose,
    pub odometry: Pose,
    pub time: f64,
    pub dt: f64,
    pub seed: u64,
    /// Steps taken so far.
    pub steps: u64,
    /// Within this distance of the goal counts as reaching it, m.
    pub goal_tolerance: f64,
    pub goal_reached: bool,
    bumpers: [bool; 4],
    speed: [f64; 2],
}

impl Sim {
    /// A robot at the world's start pose. Errors name the field: a bad
    /// step, bad sensors, or a start inside an obstacle.
    pub fn new(
        world: World,
        body: Body,
        sensors: Sensors,
        dt: f64,
        seed: u64,
    ) -> Result<Self, FieldError> {
        kinolab_common::error::in_range("dt", dt, 1e-4, 0.5)?;
        sensors.check().map_err(|e| e.within("sensors"))?;
        let start = world.start;
        let (gap, _) = world.nearest(Vec2::new(start.x, start.y), 0.0);
        if gap < body.radius() {
            return Err(FieldError::new(
                "start",
                format!(
                    "the robot (radius {} m) does not fit at the start: something is {gap:.3} m away",
                    body.radius()
                ),
            ));
        }
        Ok(Self {
            world,
            body,
            sensors,
            pose: start,
            odometry: start,
            time: 0.0,
            dt,
            seed,
            steps: 0,
            goal_tolerance: 0.1,
            goal_reached: false,
            bumpers: [false; 4],
            speed: [0.0; 2],
        })
    }

    pub fn position(&self) -> Vec2 {
        Vec2::new(self.pose.x, self.pose.y)
    }

    /// The gap between the robot's rim and the nearest thing, m.
    pub fn clearance(&self) -> f64 {
        self.world.nearest(self.position(), self.time).0 - self.body.radius()
    }

    /// Read every sensor now.
    pub fn sense(&self) -> Percepts {
        let reading = Reading {
            world: &self.world,
            pose: self.pose,
            radius: self.body.radius(),
            time: self.time,
            step: self.steps,
            seed: self.seed,
        };
        Percepts {
            time: self.time,
            rays: self
                .sensors
                .rays
                .map(|r| reading.rays(&r))
                .unwrap_or_default(),
            sonar: self.sensors.sonar.and_then(|s| reading.sonar(&s)),
            bumpers: self.bumpers,
            light: self
                .sensors
                .lights
                .map(|l| reading.lights(&l))
                .unwrap_or_default(),
            goal: reading.goal(),
            odometry: self.odometry,
            speed: self.speed,
        }
    }

    /// Drive `command` for one step.
    pub fn advance(&mut self, command: Command) -> Step {
        let driven = self.body.limit(command);
        let start = self.position();
        let mut events = Vec::new();
        let was = self.bumpers;
        self.bumpers = self.move_safely(driven);
        for (i, (now, before)) in self.bumpers.iter().zip(was).enumerate() {
            if *now && !before {
                events.push(self.event(EventKind::Bump {
                    bumper: crate::sensors::BUMPERS[i],
                }));
            }
        }
        self.update_odometry(driven);
        let appeared_before = self.time;
        self.time = (self.steps + 1) as f64 * self.dt;
        self.steps += 1;
        for (i, o) in self.world.obstacles.iter().enumerate() {
            if o.appear_at > appeared_before && o.appear_at <= self.time {
                events.push(self.event(EventKind::Appeared { obstacle: i }));
            }
        }
        if let Some(goal) = self.world.goal
            && !self.goal_reached
            && (goal - self.position()).norm() <= self.goal_tolerance
        {
            self.goal_reached = true;
            events.push(self.event(EventKind::GoalReached));
        }
        let moved = (self.position() - start).norm();
        self.speed = [moved / self.dt * driven.vx.signum(), driven.omega];
        Step {
            driven,
            moved,
            clearance: self.clearance(),
            events,
        }
    }

    fn event(&self, kind: EventKind) -> Event {
        Event { t: self.time, kind }
    }

    /// Move along the step's arc in rounds no longer than the gap; returns
    /// the bumpers pressed at the end.
    fn move_safely(&mut self, twist: Command) -> [bool; 4] {
        let radius = self.body.radius();
        let speed = twist.speed();
        let mut remaining = self.dt;
        let mut bumpers = [false; 4];
        for _ in 0..MAX_ROUNDS {
            if remaining <= 0.0 {
                break;
            }
            let here = self.position();
            let gap = self.world.nearest(here, self.time).0 - radius;
            if gap <= CONTACT {
                // Touching: press the bumpers, and slide along whatever is
                // touched (the push into it is lost). Everything else is
                // farther than a contact width, so one contact width is safe.
                let (s, c) = trig::sin_cos(self.pose.theta);
                let mut velocity =
                    Vec2::new(c * twist.vx - s * twist.vy, s * twist.vx + c * twist.vy);
                let contacts = self.world.touching(here, radius + CONTACT, self.time);
                for _ in 0..2 {
                    for at in &contacts {
                        let n = (at - here).try_normalize(1e-12).unwrap_or_else(Vec2::zeros);
                        let push = velocity.dot(&n);
                        if push > 0.0 {
                            velocity -= n * push;
                        }
                    }
                }
                for at in &contacts {
                    bumpers[bumper(&self.pose, *at)] = true;
                }
                let slide = velocity.norm();
                let dt = if slide > 1e-9 {
                    (CONTACT / slide).min(remaining)
                } else {
                    remaining
                };
                self.pose.x += velocity.x * dt;
                self.pose.y += velocity.y * dt;
                self.pose.theta += twist.omega * dt;
                remaining -= dt;
                continue;
            }
            let safe = gap - CONTACT / 2.0;
            if speed * remaining <= safe {
                self.drive(twist, remaining);
                return bumpers;
            }
            let dt = safe / speed;
            self.drive(twist, dt);
            remaining -= dt;
        }
        bumpers
    }

    fn drive(&mut self, twist: Command, dt: f64) {
        let [x, y, theta] = integrate(
            [self.pose.x, self.pose.y, self.pose.theta],
            Vector3::new(twist.vx, twist.vy, twist.omega),
            dt,
        );
        self.pose = Pose::new(x, y, theta);
    }

    /// Odometry integrates what the wheels report, slipping included.
    fn update_odometry(&mut self, driven: Command) {
        let drift = self.sensors.odometry.map_or(0.0, |o| o.drift);
        let noisy = |channel: u64| {
            1.0 + drift * gaussian_hash(self.seed, self.steps, ODOMETRY_CHANNEL + channel)
        };
        let measured = match &self.body {
            Body::Differential(d) if drift > 0.0 => {
                let [l, r] = d.wheel_speeds(driven.vx, driven.omega);
                let [v, w] = d.twist(l * noisy(0), r * noisy(1));
                Command::unicycle(v, w)
            }
            _ if drift > 0.0 => Command {
                vx: driven.vx * noisy(0),
                vy: driven.vy * noisy(1),
                omega: driven.omega * noisy(2),
            },
            _ => driven,
        };
        let [x, y, theta] = integrate(
            [self.odometry.x, self.odometry.y, self.odometry.theta],
            Vector3::new(measured.vx, measured.vy, measured.omega),
            self.dt,
        );
        self.odometry = Pose::new(x, y, theta);
    }
}
