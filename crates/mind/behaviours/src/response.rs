//! What a behaviour asks for, and how a body turns that into a command.

use kinolab_common::trig;
use kinolab_fields::descend::heading_command;
use kinolab_world::{Body, Command};

use crate::Vec2;

/// A behaviour's output, in the robot's own frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Response {
    /// A desired velocity (a motor schema): its direction is where to go,
    /// its length how fast, m/s.
    Vector(Vec2),
    /// Forward speed and turn rate, directly.
    Twist { v: f64, omega: f64 },
    /// Wheel speeds, rad/s: left, right.
    Wheels([f64; 2]),
}

/// How vectors become commands for a body.
#[derive(Debug, Clone, PartialEq)]
pub struct Drive {
    pub body: Body,
    /// k of the heading controller, 1/s.
    pub heading_gain: f64,
}

/// How far ahead a twist is looked when it must be read as a vector, s.
const LOOK_AHEAD: f64 = 1.0;

impl Drive {
    /// The command that carries out `response`.
    pub fn command(&self, response: &Response) -> Command {
        match *response {
            Response::Vector(v) => self.follow(v),
            Response::Twist { v, omega } => Command::unicycle(v, omega),
            Response::Wheels([l, r]) => match &self.body {
                kinolab_world::Body::Differential(d) => {
                    let [v, omega] = d.twist(l, r);
                    Command::unicycle(v, omega)
                }
                kinolab_world::Body::Point(_) => Command::STOP,
            },
        }
    }

    /// A unicycle steers towards the vector; a holonomic robot moves along
    /// it and turns to face it.
    pub fn follow(&self, v: Vec2) -> Command {
        let max = self.body.max_speed();
        if self.body.holonomic() {
            let speed = v.norm().min(max);
            let dir = v.try_normalize(1e-12).unwrap_or_else(Vec2::zeros);
            Command {
                vx: dir.x * speed,
                vy: dir.y * speed,
                omega: if speed > 0.0 {
                    self.heading_gain * trig::atan2(v.y, v.x)
                } else {
                    0.0
                },
            }
        } else {
            let (speed, omega) = heading_command(v, 0.0, self.heading_gain, max);
            Command::unicycle(speed, omega)
        }
    }

    /// Any response read as a vector, for blending: a twist becomes the
    /// chord to where it would take the robot in a second.
    pub fn as_vector(&self, response: &Response) -> Vec2 {
        if let Response::Vector(v) = response {
            return *v;
        }
        let c = self.command(response);
        let heading = c.omega * LOOK_AHEAD / 2.0;
        let speed = c.vx.hypot(c.vy);
        let along = trig::atan2(c.vy, c.vx);
        Vec2::new(trig::cos(heading + along), trig::sin(heading + along)) * speed
    }
}
