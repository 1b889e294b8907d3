//! Subsumption (Brooks): layers from level 0 up. Each layer's behaviour
//! writes its message, if any, on its own wire; the motors read level 0's
//! wire. A higher layer acts on a lower wire only through a node:
//!
//! - **suppress**: the higher message replaces the lower one, and keeps
//!   replacing it for the hold time after the last higher message;
//! - **inhibit**: the wire carries nothing while the higher layer speaks
//!   and for the hold time after.
//!
//! Lower layers keep running all the while; remove the upper layers and
//! the lower ones still work.

use serde::{Deserialize, Serialize};

use super::{Decision, Responses, Trace};
use crate::{Drive, FieldError, Response};

/// A node's kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum NodeKind {
    Suppress,
    Inhibit,
}

/// A node on a lower layer's wire, driven by a higher layer.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Node {
    pub node: NodeKind,
    /// The higher layer whose messages drive the node.
    pub by: String,
    /// The lower layer whose output wire the node sits on.
    pub on: String,
    /// Seconds the node keeps acting after the last message.
    #[serde(default = "default_hold")]
    pub hold: f64,
}

fn default_hold() -> f64 {
    0.5
}

/// Layers (level 0 first, by behaviour name) and nodes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Subsumption {
    pub layers: Vec<String>,
    #[serde(default)]
    pub nodes: Vec<Node>,
}

/// Each node's remaining hold (in steps) and the message it holds.
#[derive(Debug, Clone, PartialEq)]
pub struct SubsumptionState {
    hold: Vec<(u64, Option<(Response, usize)>)>,
}

impl SubsumptionState {
    pub fn new(s: &Subsumption) -> Self {
        Self {
            hold: vec![(0, None); s.nodes.len()],
        }
    }
}

impl Subsumption {
    pub fn check(
        &self,
        known: &dyn Fn(String, &str) -> Result<(), FieldError>,
    ) -> Result<(), FieldError> {
        if self.layers.is_empty() {
            return Err(FieldError::new("layers", "needs at least one layer"));
        }
        for (i, name) in self.layers.iter().enumerate() {
            known(format!("layers[{i}]"), name)?;
            if self.layers[..i].contains(name) {
                return Err(FieldError::new(
                    format!("layers[{i}]"),
                    format!("`{name}` is a layer twice"),
                ));
            }
        }
        for (i, n) in self.nodes.iter().enumerate() {
            let level = |name: &str, field: &str| {
                self.layers.iter().position(|l| l == name).ok_or_else(|| {
                    FieldError::new(
                        format!("nodes[{i}].{field}"),
                        format!("`{name}` is not a layer"),
                    )
                })
            };
            let (by, on) = (level(&n.by, "by")?, level(&n.on, "on")?);
            if by <= on {
                return Err(FieldError::new(
                    format!("nodes[{i}].by"),
                    format!(
                        "a node is driven by a higher layer than its wire: `{}` is level {by}, `{}` level {on}",
                        n.by, n.on
                    ),
                ));
            }
            kinolab_common::error::in_range(format!("nodes[{i}].hold"), n.hold, 0.0, 60.0)?;
        }
        Ok(())
    }

    fn level(&self, name: &str) -> usize {
        self.layers.iter().position(|l| l == name).unwrap_or(0)
    }

    /// The message on every wire after the nodes act, and which nodes acted.
    pub fn wires(
        &self,
        state: &mut SubsumptionState,
        responses: &Responses<'_>,
        dt: f64,
    ) -> (Vec<Option<(Response, usize)>>, Vec<bool>) {
        // Each wire starts with its own layer's message, marked with the
        // behaviour it came from.
        let mut wires: Vec<Option<(Response, usize)>> = self
            .layers
            .iter()
            .map(|name| {
                let i = responses.index(name)?;
                responses.responses[i].map(|r| (r, i))
            })
            .collect();
        let mut acting = vec![false; self.nodes.len()];
        // Higher wires first, so a node reads its driving wire after the
        // nodes on that wire have acted.
        let higher_first = |&k: &usize| [-(self.level(&self.nodes[k].on) as f64), 0.0];
        let order = kinolab_common::order::sorted_by((0..self.nodes.len()).collect(), higher_first);
        for k in order {
            let node = &self.nodes[k];
            let (by, on) = (self.level(&node.by), self.level(&node.on));
            let hold_steps = (node.hold / dt).round() as u64;
            let (left, held) = &mut state.hold[k];
            if let Some(message) = wires[by] {
                *left = hold_steps;
                *held = Some(message);
            } else if *left > 0 {
                *left -= 1;
            } else {
                continue;
            }
            acting[k] = true;
            wires[on] = match node.node {
                NodeKind::Suppress => *held,
                NodeKind::Inhibit => None,
            };
        }
        (wires, acting)
    }

    pub fn decide(
        &self,
        state: &mut SubsumptionState,
        responses: &Responses<'_>,
        drive: &Drive,
        dt: f64,
    ) -> Decision {
        let (wires, acting) = self.wires(state, responses, dt);
        let motor = wires.first().copied().flatten();
        Decision {
            command: motor.map_or(kinolab_world::Command::STOP, |(r, _)| drive.command(&r)),
            in_control: motor.map(|(_, i)| i),
            trace: Trace::Subsumption { acting },
        }
    }
}
