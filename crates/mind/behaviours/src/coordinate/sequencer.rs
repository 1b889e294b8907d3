//! A finite-state sequencer: each state names the behaviours active in it
//! (blended by vector summation), and transitions fire on perceptual
//! events.

use std::collections::BTreeMap;

use kinolab_world::sensors::Percepts;
use serde::{Deserialize, Serialize};

use super::{Decision, Responses, Trace, blend};
use crate::{Drive, FieldError};

/// A perceptual event.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "event", rename_all = "snake_case", deny_unknown_fields)]
pub enum Trigger {
    /// A bumper is pressed.
    Bump,
    /// The goal is within `distance`, m.
    GoalWithin { distance: f64 },
    /// Either light sensor reads more than `level`.
    LightAbove { level: f64 },
    /// Both light sensors read less than `level`.
    LightBelow { level: f64 },
    /// A range ray reads less than `distance` within 30° of ahead.
    ObstacleAhead { distance: f64 },
    /// Nothing within `distance` within 30° of ahead.
    ClearAhead { distance: f64 },
    /// `seconds` after entering the state.
    After { seconds: f64 },
}

impl Trigger {
    fn fires(&self, p: &Percepts, in_state: f64) -> bool {
        let ahead = || p.nearest_within(0.0, 30f64.to_radians());
        match *self {
            Trigger::Bump => p.bumped(),
            Trigger::GoalWithin { distance } => p.goal.is_some_and(|g| g.distance <= distance),
            Trigger::LightAbove { level } => p.light[0].max(p.light[1]) > level,
            Trigger::LightBelow { level } => p.light[0].max(p.light[1]) < level,
            Trigger::ObstacleAhead { distance } => ahead().is_some_and(|d| d < distance),
            Trigger::ClearAhead { distance } => ahead().is_none_or(|d| d >= distance),
            Trigger::After { seconds } => in_state >= seconds,
        }
    }

    fn check(&self) -> Result<(), FieldError> {
        use kinolab_common::error::non_negative;
        match *self {
            Trigger::Bump => Ok(()),
            Trigger::GoalWithin { distance }
            | Trigger::ObstacleAhead { distance }
            | Trigger::ClearAhead { distance } => non_negative("distance", distance).map(|_| ()),
            Trigger::LightAbove { level } | Trigger::LightBelow { level } => {
                non_negative("level", level).map(|_| ())
            }
            Trigger::After { seconds } => non_negative("seconds", seconds).map(|_| ()),
        }
    }
}

/// A state: its name and the behaviours active in it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct State {
    pub name: String,
    pub behaviours: Vec<String>,
}

/// A transition from one state to another when `when` fires.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Transition {
    pub from: String,
    pub to: String,
    pub when: Trigger,
}

/// The machine: its states, the first one, and the transitions (the first
/// one that fires wins).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sequencer {
    pub start: String,
    pub states: Vec<State>,
    #[serde(default)]
    pub transitions: Vec<Transition>,
}

/// The current state and how long the machine has been in it.
#[derive(Debug, Clone, PartialEq)]
pub struct SequencerState {
    pub current: usize,
    pub since: f64,
}

impl SequencerState {
    pub fn new(s: &Sequencer) -> Self {
        Self {
            current: s.state_index(&s.start).unwrap_or(0),
            since: 0.0,
        }
    }
}

impl Sequencer {
    pub fn state_index(&self, name: &str) -> Option<usize> {
        self.states.iter().position(|s| s.name == name)
    }

    pub fn check(
        &self,
        known: &dyn Fn(String, &str) -> Result<(), FieldError>,
    ) -> Result<(), FieldError> {
        if self.states.is_empty() {
            return Err(FieldError::new("states", "needs at least one state"));
        }
        for (i, s) in self.states.iter().enumerate() {
            if self.states[..i].iter().any(|t| t.name == s.name) {
                return Err(FieldError::new(
                    format!("states[{i}].name"),
                    format!("`{}` is used twice", s.name),
                ));
            }
            for (j, b) in s.behaviours.iter().enumerate() {
                known(format!("states[{i}].behaviours[{j}]"), b)?;
            }
        }
        let state = |field: String, name: &str| {
            self.state_index(name)
                .map(|_| ())
                .ok_or_else(|| FieldError::new(field, format!("no state is called `{name}`")))
        };
        state("start".into(), &self.start)?;
        for (i, t) in self.transitions.iter().enumerate() {
            state(format!("transitions[{i}].from"), &t.from)?;
            state(format!("transitions[{i}].to"), &t.to)?;
            t.when
                .check()
                .map_err(|e| e.within(&format!("transitions[{i}].when")))?;
        }
        Ok(())
    }

    pub fn decide(
        &self,
        st: &mut SequencerState,
        responses: &Responses<'_>,
        percepts: &Percepts,
        drive: &Drive,
        dt: f64,
    ) -> Decision {
        let current = &self.states[st.current.min(self.states.len() - 1)].name;
        let next = self
            .transitions
            .iter()
            .find(|t| &t.from == current && t.when.fires(percepts, st.since))
            .and_then(|t| self.state_index(&t.to));
        match next {
            Some(n) => {
                *st = SequencerState {
                    current: n,
                    since: 0.0,
                }
            }
            None => st.since += dt,
        }
        let state = &self.states[st.current.min(self.states.len() - 1)];
        let active: Vec<usize> = state
            .behaviours
            .iter()
            .filter_map(|b| responses.index(b))
            .collect();
        let (command, in_control, _) = blend(&BTreeMap::new(), responses, drive, Some(&active));
        Decision {
            command,
            in_control,
            trace: Trace::Sequencer {
                state: state.name.clone(),
            },
        }
    }
}
