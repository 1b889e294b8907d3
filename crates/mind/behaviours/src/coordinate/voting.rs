//! Voting (after DAMN): a fixed set of candidate arcs; each active
//! behaviour gives every arc a vote in [−1, 1]; votes are weighted and
//! summed, and the arc with the highest total wins.

use kinolab_common::trig;
use std::collections::BTreeMap;

use kinolab_common::angle::wrap;
use kinolab_world::Command;
use kinolab_world::sensors::Percepts;
use serde::{Deserialize, Serialize};

use super::{Decision, Responses, Trace};
use crate::library::Behaviour;
use crate::{Drive, FieldError, Response};

/// The candidates and the weights.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Voting {
    /// How many arcs, spread evenly from hard right to hard left.
    #[serde(default = "default_arcs")]
    pub arcs: usize,
    /// The tightest curvature, 1/m.
    #[serde(default = "default_curvature")]
    pub max_curvature: f64,
    /// Forward speed on every arc, m/s.
    #[serde(default = "default_speed")]
    pub speed: f64,
    /// Each behaviour's weight (1 when not given).
    #[serde(default)]
    pub weights: BTreeMap<String, f64>,
}

fn default_arcs() -> usize {
    21
}
fn default_curvature() -> f64 {
    2.0
}
fn default_speed() -> f64 {
    0.4
}

impl Default for Voting {
    fn default() -> Self {
        Self {
            arcs: default_arcs(),
            max_curvature: default_curvature(),
            speed: default_speed(),
            weights: BTreeMap::new(),
        }
    }
}

/// How far along an arc its direction is judged, m.
const LOOK_AHEAD: f64 = 1.0;

impl Voting {
    pub fn check(
        &self,
        known: &dyn Fn(String, &str) -> Result<(), FieldError>,
    ) -> Result<(), FieldError> {
        if !(3..=101).contains(&self.arcs) {
            return Err(FieldError::new(
                "arcs",
                format!("must be from 3 to 101, got {}", self.arcs),
            ));
        }
        kinolab_common::error::positive("max_curvature", self.max_curvature)?;
        kinolab_common::error::positive("speed", self.speed)?;
        for (name, w) in &self.weights {
            known(format!("weights.{name}"), name)?;
            kinolab_common::error::non_negative(format!("weights.{name}"), *w)?;
        }
        Ok(())
    }

    /// The candidates' curvatures, hard right (negative) to hard left.
    pub fn curvatures(&self) -> Vec<f64> {
        let n = self.arcs.max(2);
        (0..n)
            .map(|i| self.max_curvature * (2.0 * i as f64 / (n - 1) as f64 - 1.0))
            .collect()
    }

    /// One behaviour's votes. `avoid` judges each arc by the free space
    /// along it; every other behaviour votes by how well the arc's
    /// direction agrees with the way it wants to go.
    pub fn votes(
        &self,
        behaviour: &Behaviour,
        response: &Response,
        percepts: &Percepts,
        drive: &Drive,
    ) -> Vec<f64> {
        let chords: Vec<f64> = self
            .curvatures()
            .iter()
            .map(|k| k * LOOK_AHEAD / 2.0)
            .collect();
        if let Behaviour::Avoid { range, .. } = behaviour {
            return chords
                .iter()
                .map(|&a| {
                    let free = percepts
                        .nearest_within(a, 12f64.to_radians())
                        .unwrap_or(*range);
                    (2.0 * free / range - 1.0).clamp(-1.0, 1.0)
                })
                .collect();
        }
        let want = drive.as_vector(response);
        if want.norm() < 1e-12 {
            return vec![0.0; chords.len()];
        }
        let heading = trig::atan2(want.y, want.x);
        chords
            .iter()
            .map(|a| trig::cos(wrap(a - heading)))
            .collect()
    }

    pub fn decide(
        &self,
        responses: &Responses<'_>,
        percepts: &Percepts,
        drive: &Drive,
    ) -> Decision {
        let curvatures = self.curvatures();
        let mut totals = vec![0.0; curvatures.len()];
        let mut weighted: Vec<(usize, Vec<f64>)> = Vec::new();
        for (i, response) in responses.responses.iter().enumerate() {
            let (Some(r), Some(b)) = (response, responses.behaviours.get(i)) else {
                continue;
            };
            let w = self.weights.get(responses.name(i)).copied().unwrap_or(1.0);
            let votes: Vec<f64> = self
                .votes(&b.behaviour, r, percepts, drive)
                .into_iter()
                .map(|v| v * w)
                .collect();
            for (t, v) in totals.iter_mut().zip(&votes) {
                *t += v;
            }
            weighted.push((i, votes));
        }
        // Highest total wins; ties go to the straighter arc.
        let winner = (!weighted.is_empty())
            .then(|| {
                (0..totals.len()).max_by(|&a, &b| {
                    totals[a]
                        .total_cmp(&totals[b])
                        .then(curvatures[b].abs().total_cmp(&curvatures[a].abs()))
                })
            })
            .flatten();
        let in_control = winner.and_then(|k| {
            weighted
                .iter()
                .max_by(|a, b| a.1[k].total_cmp(&b.1[k]))
                .map(|(i, _)| *i)
        });
        Decision {
            command: winner.map_or(Command::STOP, |k| {
                Command::unicycle(self.speed, curvatures[k] * self.speed)
            }),
            in_control,
            trace: Trace::Voting {
                curvatures,
                totals,
                winner,
            },
        }
    }
}
