//! The reactive robot: behaviours coupling sensing straight to acting,
//! with no map and no plan. It answers at once and remembers nothing.

use kinolab_world::sensors::Percepts;

use super::{Act, Settings};
use crate::skills::Skills;

#[derive(Debug, Clone)]
pub struct Reactive {
    pub skills: Skills,
}

impl Reactive {
    pub fn new(settings: &Settings) -> Self {
        Self {
            skills: Skills::avoid_and_go(&settings.body),
        }
    }

    pub fn act(&mut self, p: &Percepts, dt: f64) -> Act {
        let step = self.skills.act(p, dt);
        Act {
            command: step.command,
            activity: step.in_control.unwrap_or_else(|| "idle".into()),
            model_age: None,
        }
    }
}
