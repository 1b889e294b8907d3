//! A robot system made of components, driving the simulated robot of the
//! behaviours unit: a laser and a base that touch the world, a mapper, a
//! planner, a motion component, an idle joystick, and a sequencer that is
//! the wiring master. The world is physics, not communication: only the
//! laser (sensing) and the base (driving) reach it.

mod base;
mod laser;
mod mapper;
mod motion;
mod planner;
mod sequencer;

use kinolab_world::{Pose, Vec2};
use serde::Deserialize;

pub use base::Base;
pub use laser::Laser;
pub use mapper::Mapper;
pub use motion::{Joystick, Motion};
pub use planner::Planner;
pub use sequencer::Sequencer;

use crate::FieldError;
use crate::component::Component;
use crate::kinds::params;
use crate::object::Object;

/// Build a robot component of `kind`.
pub fn build(kind: &str, value: &serde_json::Value) -> Result<Box<dyn Component>, FieldError> {
    Ok(match kind {
        "laser" => Box::new(Laser::new(params(value)?)?),
        "base" => Box::new(Base::new(params(value)?)?),
        "mapper" => Box::new(Mapper::new(params(value)?)?),
        "planner" => Box::new(Planner::default()),
        "motion" => Box::new(Motion::new(params(value)?)?),
        "joystick" => Box::new(Joystick),
        "sequencer" => Box::new(Sequencer::new(params(value)?)?),
        other => {
            return Err(FieldError::new(
                "kind",
                format!(
                    "no component kind `{other}`; the kinds are {}",
                    crate::kinds::KINDS.join(", ")
                ),
            ));
        }
    })
}

/// A period parameter with a default.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Periodic {
    #[serde(default = "kinolab_common::defaults::tenth")]
    pub period: f64,
}

impl Periodic {
    pub fn check(&self) -> Result<f64, FieldError> {
        kinolab_common::error::in_range("params.period", self.period, 0.01, 10.0)
    }
}

pub(crate) fn pose_object(p: Pose) -> Object {
    Object::new(
        "Pose",
        serde_json::json!({ "x": p.x, "y": p.y, "theta": p.theta }),
    )
}

pub(crate) fn pose_of(o: &Object) -> Option<Pose> {
    Some(Pose::new(o.field("x")?, o.field("y")?, o.field("theta")?))
}

pub(crate) fn point_of(o: &Object) -> Option<Vec2> {
    Some(Vec2::new(o.field("x")?, o.field("y")?))
}

pub(crate) fn path_object(points: &[[f64; 2]]) -> Object {
    Object::new("Path", serde_json::json!({ "points": points }))
}

pub(crate) fn path_of(o: &Object) -> Vec<[f64; 2]> {
    o.value
        .get("points")
        .and_then(serde_json::Value::as_array)
        .map(|pts| {
            pts.iter()
                .filter_map(|p| Some([p.get(0)?.as_f64()?, p.get(1)?.as_f64()?]))
                .collect()
        })
        .unwrap_or_default()
}
