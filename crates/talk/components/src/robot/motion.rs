//! The motion component follows the newest path on its wireable `source`
//! port (the joystick's or the planner's: it cannot tell, and need not),
//! and sends velocity commands to the base. The joystick, untouched,
//! publishes an empty path: stand still.

use kinolab_architectures::follow::Follower;
use kinolab_common::angle::wrap;
use kinolab_common::trig;
use kinolab_world::Vec2;
use serde::Deserialize;

use crate::FieldError;
use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, PortSpec, ServiceSpec, Signature};
use crate::runtime::Ctx;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MotionParams {
    #[serde(default = "kinolab_common::defaults::tenth")]
    pub period: f64,
    /// Top speed, m/s.
    #[serde(default = "speed")]
    pub speed: f64,
}

fn speed() -> f64 {
    0.5
}

/// Within this distance (m) a waypoint counts as passed.
const REACH: f64 = 0.25;

#[derive(Debug, Clone)]
pub struct Motion {
    period: f64,
    speed: f64,
    follower: Follower,
    path: Vec<[f64; 2]>,
    last: [f64; 2],
}

impl Motion {
    pub fn new(p: MotionParams) -> Result<Self, FieldError> {
        Ok(Self {
            period: kinolab_common::error::in_range("params.period", p.period, 0.01, 10.0)?,
            speed: kinolab_common::error::in_range("params.speed", p.speed, 0.0, 5.0)?,
            follower: Follower::new(Vec::new()),
            path: Vec::new(),
            last: [0.0; 2],
        })
    }

    /// Turn towards the target and go, slower while the heading is off and
    /// near the end.
    fn steer(&mut self, cx: &Ctx<'_>) -> [f64; 2] {
        let Some(pose) = cx.newest("pose").and_then(super::pose_of) else {
            return [0.0; 2];
        };
        let at = Vec2::new(pose.x, pose.y);
        let Some(target) = self.follower.target(at, REACH) else {
            return [0.0; 2];
        };
        let to = target - at;
        let d = to.norm();
        if d < 0.05 {
            return [0.0; 2];
        }
        let error = wrap(trig::atan2(to.y, to.x) - pose.theta);
        let v = self.speed * trig::cos(error).max(0.0) * (d / 0.5).min(1.0);
        [v, (2.0 * error).clamp(-2.0, 2.0)]
    }
}

impl Component for Motion {
    fn interface(&self) -> Interface {
        Interface {
            services: Vec::new(),
            ports: vec![
                PortSpec::new("source", Pattern::PushNewest, Signature::one("Path"), true),
                PortSpec::new("pose", Pattern::PushTimed, Signature::one("Pose"), false),
                PortSpec::new("velocity", Pattern::Send, Signature::one("Twist"), false),
            ],
            master: false,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        cx.subscribe("source", 1);
        cx.subscribe("pose", 1);
        cx.after(self.period, 0);
    }

    fn update(&mut self, port: &str, object: &Object, _cx: &mut Ctx<'_>) {
        if port == "source" {
            let path = super::path_of(object);
            if path != self.path {
                self.path = path.clone();
                self.follower = Follower::new(path);
            }
        }
    }

    fn timer(&mut self, _tag: u32, cx: &mut Ctx<'_>) {
        let [v, omega] = self.steer(cx);
        self.last = [v, omega];
        let twist = Object::new("Twist", serde_json::json!({ "v": v, "omega": omega }));
        let _ = cx.send("velocity", twist);
        cx.after(self.period, 0);
    }

    fn status(&self) -> String {
        format!(
            "{} waypoints ahead, v {:.2} m/s, ω {:.2} rad/s",
            self.follower.ahead().len(),
            self.last[0],
            self.last[1]
        )
    }
}

/// A joystick nobody touches: it publishes an empty path (stand still).
#[derive(Debug, Clone, Default)]
pub struct Joystick;

impl Component for Joystick {
    fn interface(&self) -> Interface {
        Interface {
            services: vec![ServiceSpec::new(
                "route",
                Pattern::PushNewest,
                Signature::one("Path"),
            )],
            ports: Vec::new(),
            master: false,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        cx.publish("route", super::path_object(&[]));
    }

    fn status(&self) -> String {
        "idle".to_owned()
    }
}
