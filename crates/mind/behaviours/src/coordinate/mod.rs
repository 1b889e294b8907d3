//! Coordination functions: how the behaviours' responses become one
//! command. Every behaviour runs every step (a lower layer keeps running
//! while it is overruled); the coordinator decides what reaches the wheels.

pub mod scripted;
pub mod sequencer;
pub mod subsumption;
pub mod voting;

use std::collections::BTreeMap;

use kinolab_world::Command;
use kinolab_world::sensors::Percepts;
use serde::{Deserialize, Serialize};

use crate::{Drive, FieldError, Named, Response, Vec2};
pub use scripted::ScriptState;
pub use sequencer::{Sequencer, SequencerState};
pub use subsumption::{Subsumption, SubsumptionState};
pub use voting::Voting;

/// A coordination function and its settings, as run files write it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Coordinator {
    /// Cooperative: the active behaviours' vectors, each times its gain
    /// (1 when not given), added up.
    Sum {
        #[serde(default)]
        gains: BTreeMap<String, f64>,
    },
    /// Competitive: layers with suppress and inhibit nodes.
    Subsumption(Subsumption),
    /// Competitive: weighted votes over candidate arcs.
    Voting(Voting),
    /// Sequential: a finite-state machine choosing the active set.
    Sequencer(Sequencer),
    /// A learner's: `coordinate(outputs, p)` (see [`crate::script`]).
    Script { source: String },
}

impl Coordinator {
    pub fn name(&self) -> &'static str {
        match self {
            Coordinator::Sum { .. } => "vector summation",
            Coordinator::Subsumption(_) => "subsumption",
            Coordinator::Voting(_) => "voting",
            Coordinator::Sequencer(_) => "sequencer",
            Coordinator::Script { .. } => "your coordinator",
        }
    }

    /// Check against the behaviours' names; errors name the field.
    pub fn check(&self, names: &[String]) -> Result<(), FieldError> {
        let known = |field: String, name: &str| {
            if names.iter().any(|n| n == name) {
                Ok(())
            } else {
                Err(FieldError::new(
                    field,
                    format!("no behaviour is called `{name}`"),
                ))
            }
        };
        match self {
            Coordinator::Sum { gains } => {
                for (name, g) in gains {
                    known(format!("gains.{name}"), name)?;
                    kinolab_common::error::non_negative(format!("gains.{name}"), *g)?;
                }
                Ok(())
            }
            Coordinator::Subsumption(s) => s.check(&known),
            Coordinator::Voting(v) => v.check(&known),
            Coordinator::Sequencer(s) => s.check(&known),
            Coordinator::Script { source } => {
                kinolab_script::Script::compile(source, crate::script::COORDINATE)
                    .map(|_| ())
                    .map_err(|e| FieldError::new("source", e.to_string()))
            }
        }
    }
}

/// What a coordinator remembers between steps.
#[derive(Debug, Clone, PartialEq)]
pub enum Memory {
    Stateless,
    Subsumption(SubsumptionState),
    Sequencer(SequencerState),
    Script(Box<ScriptState>),
}

impl Memory {
    pub fn new(c: &Coordinator) -> Self {
        match c {
            Coordinator::Subsumption(s) => Memory::Subsumption(SubsumptionState::new(s)),
            Coordinator::Sequencer(s) => Memory::Sequencer(SequencerState::new(s)),
            Coordinator::Script { source } => Memory::Script(Box::new(ScriptState::new(source))),
            _ => Memory::Stateless,
        }
    }

    /// A learner's coordinator that stopped on an error, and what its
    /// last call returned and printed.
    pub fn script(&self) -> Option<&ScriptState> {
        match self {
            Memory::Script(state) => Some(state),
            _ => None,
        }
    }
}

/// What the coordinator shows about its decision.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Trace {
    /// The blended vector (robot frame).
    Sum { total: [f64; 2] },
    /// Which nodes acted this step, in file order; which wire fed the motor.
    Subsumption { acting: Vec<bool> },
    /// Each candidate's curvature and total vote; the winner's index.
    Voting {
        curvatures: Vec<f64>,
        totals: Vec<f64>,
        winner: Option<usize>,
    },
    /// The current state's name.
    Sequencer { state: String },
    /// What a learner's coordinator chose: a behaviour by name, or its own
    /// command (`None`).
    Script { chose: Option<String> },
}

/// One step's decision.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Decision {
    pub command: Command,
    /// The behaviour whose response reached the wheels (or weighed most).
    pub in_control: Option<usize>,
    pub trace: Trace,
}

/// The behaviours and their responses this step, index for index.
#[derive(Debug)]
pub struct Responses<'a> {
    pub behaviours: &'a [Named],
    pub responses: &'a [Option<Response>],
}

impl Responses<'_> {
    pub fn index(&self, name: &str) -> Option<usize> {
        self.behaviours.iter().position(|b| b.name == name)
    }

    pub fn name(&self, i: usize) -> &str {
        self.behaviours.get(i).map_or("", |b| b.name.as_str())
    }

    pub fn get(&self, name: &str) -> Option<Response> {
        self.index(name).and_then(|i| self.responses[i])
    }
}

/// Decide this step's command.
pub fn decide(
    coordinator: &Coordinator,
    memory: &mut Memory,
    responses: &Responses<'_>,
    percepts: &Percepts,
    drive: &Drive,
    dt: f64,
) -> Decision {
    match (coordinator, &mut *memory) {
        (Coordinator::Sum { gains }, _) => sum(gains, responses, drive),
        (Coordinator::Subsumption(s), Memory::Subsumption(st)) => {
            s.decide(st, responses, drive, dt)
        }
        (Coordinator::Voting(v), _) => v.decide(responses, percepts, drive),
        (Coordinator::Sequencer(s), Memory::Sequencer(st)) => {
            s.decide(st, responses, percepts, drive, dt)
        }
        (Coordinator::Script { .. }, Memory::Script(st)) => st.decide(responses, percepts, drive),
        // A memory that does not match its coordinator: start it afresh.
        (c, _) => {
            *memory = Memory::new(c);
            match memory {
                Memory::Stateless => sum(&BTreeMap::new(), responses, drive),
                _ => decide(c, memory, responses, percepts, drive, dt),
            }
        }
    }
}

/// Vector summation over the active behaviours in `only` (all when `None`).
pub fn blend(
    gains: &BTreeMap<String, f64>,
    responses: &Responses<'_>,
    drive: &Drive,
    only: Option<&[usize]>,
) -> (Command, Option<usize>, Vec2) {
    let active: Vec<(usize, f64, &Response)> = responses
        .responses
        .iter()
        .enumerate()
        .filter(|(i, _)| only.is_none_or(|set| set.contains(i)))
        .filter_map(|(i, r)| {
            let gain = gains.get(responses.name(i)).copied().unwrap_or(1.0);
            r.as_ref().map(|r| (i, gain, r))
        })
        .collect();
    // One behaviour alone at gain 1 drives exactly as it asks.
    if let [(i, gain, r)] = active.as_slice()
        && (*gain - 1.0).abs() < 1e-12
    {
        return (drive.command(r), Some(*i), drive.as_vector(r));
    }
    let mut total = Vec2::zeros();
    let mut strongest: Option<(usize, f64)> = None;
    for (i, gain, r) in &active {
        let v = drive.as_vector(r) * *gain;
        total += v;
        if strongest.is_none_or(|(_, s)| v.norm() > s) {
            strongest = Some((*i, v.norm()));
        }
    }
    (drive.follow(total), strongest.map(|(i, _)| i), total)
}

fn sum(gains: &BTreeMap<String, f64>, responses: &Responses<'_>, drive: &Drive) -> Decision {
    let (command, in_control, total) = blend(gains, responses, drive, None);
    Decision {
        command,
        in_control,
        trace: Trace::Sum {
            total: [total.x, total.y],
        },
    }
}
