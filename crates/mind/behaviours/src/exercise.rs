//! Graded exercises on behaviours, checked by running the learner's design.

use kinolab_common::Feedback;
use kinolab_world::catalogue::scattered;

use crate::FieldError;
use crate::coordinate::Coordinator;
use crate::coordinate::subsumption::{Node, NodeKind, Subsumption};
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

/// The layer task's layers as a lesson writes them: each of its
/// behaviours once, level 0 first, separated by commas (`avoid, wander, go`).
pub fn layers_from_text(text: &str) -> Result<Vec<String>, String> {
    let names: Vec<String> = text.split(',').map(|n| n.trim().to_owned()).collect();
    let known: Vec<String> = layer_behaviours().into_iter().map(|b| b.name).collect();
    let mut given = names.clone();
    given.sort();
    let mut all = known.clone();
    all.sort();
    if given != all {
        return Err(format!(
            "must name each of {} once, level 0 first, separated by commas",
            known.join(", ")
        ));
    }
    Ok(names)
}

/// Layers as [`layers_from_text`] reads them.
pub fn layers_text(layers: &[String]) -> String {
    layers.join(", ")
}

/// A node of the layer task as a lesson writes it: the layer that drives
/// it, `suppresses` or `inhibits`, and the layer whose wire it sits on
/// (`avoid suppresses go`); it holds for `hold` seconds.
pub fn node_from_text(text: &str, hold: f64) -> Result<Node, String> {
    let known: Vec<String> = layer_behaviours().into_iter().map(|b| b.name).collect();
    let words: Vec<&str> = text.split_whitespace().collect();
    let wrong = || {
        format!(
            "must be `BY suppresses ON` or `BY inhibits ON`, BY and ON each one of {}",
            known.join(", ")
        )
    };
    let [by, verb, on] = words.as_slice() else {
        return Err(wrong());
    };
    let node = match *verb {
        "suppresses" => NodeKind::Suppress,
        "inhibits" => NodeKind::Inhibit,
        _ => return Err(wrong()),
    };
    if !known.iter().any(|k| k == by) || !known.iter().any(|k| k == on) {
        return Err(wrong());
    }
    Ok(Node {
        node,
        by: (*by).to_owned(),
        on: (*on).to_owned(),
        hold,
    })
}

/// A node as [`node_from_text`] reads it (without its hold).
pub fn node_text(node: &Node) -> String {
    let verb = match node.node {
        NodeKind::Suppress => "suppresses",
        NodeKind::Inhibit => "inhibits",
    };
    format!("{} {verb} {}", node.by, node.on)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn layers_and_nodes_read_back_as_written() {
        let layers = layers_from_text(" avoid,wander , go").unwrap_or_default();
        assert_eq!(layers, ["avoid", "wander", "go"]);
        assert_eq!(layers_text(&layers), "avoid, wander, go");
        assert!(layers_from_text("avoid, go").is_err());
        assert!(layers_from_text("avoid, go, go").is_err());
        let node = node_from_text("avoid suppresses go", 0.75);
        assert_eq!(
            node.as_ref().map(node_text).as_deref(),
            Ok("avoid suppresses go")
        );
        assert_eq!(
            node.map(|n| (n.node, n.hold)),
            Ok((NodeKind::Suppress, 0.75))
        );
        assert!(node_from_text("avoid eats go", 0.5).is_err());
        assert!(node_from_text("avoid inhibits", 0.5).is_err());
        assert!(node_from_text("sonar inhibits go", 0.5).is_err());
    }
}
