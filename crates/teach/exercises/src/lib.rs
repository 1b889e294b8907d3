//! Graded code exercises: the learner writes one function (a control law,
//! a behaviour, a coordinator, a field, a sequencer, a leg sequencer); the
//! lab runs it in the existing simulations on worlds the learner can see
//! while working and on worlds held back until they submit, and says for
//! each world whether it passed, or why not ("touched the wall at 4.2 s",
//! "not at the goal after 20 s", "arrived facing 40° off").
//!
//! Each unit's exercises live in their own module: [`control`] (motion
//! control), [`behaviours`], [`fields`] (potential fields), [`legs`]
//! (legged locomotion) and [`architecture`].

pub mod architecture;
pub mod behaviours;
pub mod control;
pub mod fields;
pub mod legs;
pub mod packed;
pub mod trace;

use std::collections::BTreeMap;

use kinolab_script::{ScriptError, Signature};
use serde::Serialize;

/// Where the learner's code goes in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Hook {
    Control,
    Behaviour,
    Coordinator,
    Field,
    Sequencer,
    Legs,
}

impl Hook {
    /// What the learner's function answers.
    pub fn returns(self) -> &'static str {
        match self {
            Hook::Control => "[v, omega]",
            Hook::Behaviour => "[v, omega], #{x, y} or ()",
            Hook::Coordinator => "a behaviour's name, [v, omega], #{x, y} or ()",
            Hook::Field => "[fx, fy]",
            Hook::Sequencer => "#{ replan, target }",
            Hook::Legs => "#{ stance, at: [x, y, z] }",
        }
    }
}

/// One exercise: what to write, where it belongs, how it is graded.
#[derive(Debug, Clone, Copy)]
pub struct Exercise {
    pub id: &'static str,
    /// The unit's and the lesson's addresses.
    pub unit: &'static str,
    pub lesson: &'static str,
    pub hook: Hook,
    pub signature: Signature,
    pub title: &'static str,
    /// What the learner must achieve, in a few sentences.
    pub task: &'static str,
    /// The code the editor starts with.
    pub starter: &'static str,
    /// Hints, given one more after each failed submission.
    pub hints: &'static [&'static str],
    /// Every world the exercise grades on.
    pub worlds: fn() -> Vec<World>,
}

/// A world of an exercise: its name, whether the learner sees it before
/// submitting, and what to run.
#[derive(Debug, Clone)]
pub struct World {
    pub name: String,
    pub visible: bool,
    pub trial: Trial,
}

/// What a world runs.
#[derive(Debug, Clone)]
pub enum Trial {
    Control(control::Trial),
    Behaviours(behaviours::Trial),
    Field(fields::Trial),
    Legs(legs::Trial),
    Arena(architecture::Trial),
}

/// How one world went.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Outcome {
    pub name: String,
    pub visible: bool,
    pub passed: bool,
    /// Why not, in words (`None` when passed).
    pub reason: Option<String>,
    /// When it ended (or failed), s or for a walk the phase.
    pub time: Option<f64>,
    /// The run's numbers, by name.
    pub metrics: BTreeMap<String, f64>,
    /// The script's error, when it stopped the run.
    pub error: Option<ScriptError>,
}

impl Outcome {
    pub(crate) fn new(world: &World) -> Self {
        Self {
            name: world.name.clone(),
            visible: world.visible,
            passed: false,
            reason: None,
            time: None,
            metrics: BTreeMap::new(),
            error: None,
        }
    }

    /// Passed unless `reason`, or unless the learner's code stopped the
    /// run: then that is the reason, whatever followed from it.
    pub(crate) fn judged(mut self, reason: Option<String>) -> Self {
        self.reason = match &self.error {
            Some(e) => Some(format!("your code stopped: {e}")),
            None => reason,
        };
        self.passed = self.reason.is_none();
        self
    }

    pub(crate) fn metric(mut self, name: &str, value: f64) -> Self {
        self.metrics.insert(name.to_owned(), value);
        self
    }
}

/// Every exercise, unit by unit.
pub fn all() -> Vec<Exercise> {
    [
        control::EXERCISES.as_slice(),
        behaviours::EXERCISES.as_slice(),
        fields::EXERCISES.as_slice(),
        legs::EXERCISES.as_slice(),
        architecture::EXERCISES.as_slice(),
    ]
    .concat()
}

/// The exercise called `id`.
pub fn find(id: &str) -> Option<Exercise> {
    all().into_iter().find(|e| e.id == id)
}

/// A learner's submission graded: every world (or only the visible ones).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Check {
    pub exercise: String,
    pub passed: bool,
    pub worlds: Vec<Outcome>,
    /// The code did not compile (nothing ran), or stopped a run: the
    /// first such error.
    pub error: Option<ScriptError>,
}

impl Exercise {
    /// Run `source` on every world (`held_back` too, or only the visible).
    pub fn check(&self, source: &str, held_back: bool) -> Check {
        if let Err(e) = kinolab_script::Script::compile(source, self.signature) {
            return Check {
                exercise: self.id.into(),
                passed: false,
                worlds: Vec::new(),
                error: Some(e),
            };
        }
        let worlds: Vec<Outcome> = (self.worlds)()
            .iter()
            .filter(|w| held_back || w.visible)
            .map(|w| self.run(source, w))
            .collect();
        Check {
            exercise: self.id.into(),
            passed: worlds.iter().all(|w| w.passed),
            error: worlds.iter().find_map(|w| w.error.clone()),
            worlds,
        }
    }

    /// Run `source` on one of this exercise's worlds.
    pub fn run(&self, source: &str, world: &World) -> Outcome {
        match &world.trial {
            Trial::Control(t) => control::run(source, world, t),
            Trial::Behaviours(t) => behaviours::run(self.hook, source, world, t),
            Trial::Field(t) => fields::run(source, world, t),
            Trial::Legs(t) => legs::run(source, world, t),
            Trial::Arena(t) => architecture::run(source, world, t),
        }
    }
}
