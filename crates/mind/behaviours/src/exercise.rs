//! Graded exercises on behaviours, checked by running the learner's design.

use kinolab_common::Feedback;
use kinolab_world::catalogue::scattered;

use crate::FieldError;
use crate::coordinate::Coordinator;
use crate::coordinate::subsumption::{Node, Subsumption};
use crate::library::{Behaviour, Named};
use crate::run::{Setup, run};

/// "Order these layers and place one node so the robot reaches the goal
/// without a collision on three seeded worlds."
#[derive(Debug, Clone, PartialEq)]
pub struct LayerTask {
    /// The worlds: [`scattered`] rooms with these seeds.
    pub seeds: [u64; 3],
    pub obstacles: usize,
    /// Time allowed on each world, s.
    pub duration: f64,
}

impl Default for LayerTask {
    fn default() -> Self {
        Self {
            seeds: [11, 23, 37],
            obstacles: 6,
            duration: 60.0,
        }
    }
}

/// The behaviours the layer task offers, by name.
pub fn layer_behaviours() -> Vec<Named> {
    vec![
        Named::new(
            "go",
            Behaviour::GoToGoal {
                gain: 0.4,
                slow_within: 0.5,
            },
        ),
        Named::new(
            "avoid",
            Behaviour::Avoid {
                range: 0.7,
                gain: 0.4,
            },
        ),
        Named::new(
            "wander",
            Behaviour::Wander {
                gain: 0.3,
                turn_deg: 60.0,
                every: 2.0,
                seed: 5,
            },
        ),
    ]
}

impl LayerTask {
    /// The run set-up for one world with the learner's design.
    pub fn setup(&self, seed: u64, layers: &[String], node: Option<&Node>) -> Setup {
        let coordinator = Coordinator::Subsumption(Subsumption {
            layers: layers.to_vec(),
            nodes: node.into_iter().cloned().collect(),
        });
        let mut setup = Setup::new(
            scattered(seed, self.obstacles),
            layer_behaviours(),
            coordinator,
        );
        setup.duration = self.duration;
        setup.seed = seed;
        setup
    }

    /// Run the design on every world; met when all three reach the goal
    /// without touching anything.
    pub fn check(&self, layers: &[String], node: Option<&Node>) -> Result<Feedback, FieldError> {
        let mut times = Vec::new();
        for (k, seed) in self.seeds.iter().enumerate() {
            let report = run(&self.setup(*seed, layers, node))?;
            let m = &report.metrics;
            if m.collisions > 0 {
                let when = report
                    .events
                    .iter()
                    .find(|e| matches!(e.kind, kinolab_world::EventKind::Bump { .. }))
                    .map_or(0.0, |e| e.t);
                return Ok(Feedback::not_yet(format!(
                    "World {} hit something at {when:.1} s: the layer that keeps the robot safe must win when it speaks.",
                    k + 1
                )));
            }
            match m.time {
                Some(t) => times.push(t),
                None => {
                    return Ok(Feedback::not_yet(format!(
                        "World {} did not reach the goal in {} s: is the goal-seeking layer connected to the motors?",
                        k + 1,
                        self.duration
                    )));
                }
            }
        }
        let list: Vec<String> = times.iter().map(|t| format!("{t:.1} s")).collect();
        Ok(Feedback::met(format!(
            "All three worlds reached with no collision ({}).",
            list.join(", ")
        )))
    }
}
