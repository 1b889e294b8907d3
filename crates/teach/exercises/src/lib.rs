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
pub mod arm;
pub mod behaviours;
pub mod control;
pub mod fields;
pub mod job;
pub mod legs;
pub mod packed;
pub mod trace;

use std::collections::BTreeMap;

use kinolab_script::{ErrorKind, ScriptError, Signature};
use serde::{Deserialize, Serialize};

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
    /// An arm's joint controller: listed as a `control` hook, like the
    /// wheeled robot's, with the arm's own signature.
    #[serde(rename = "control")]
    Arm,
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
            Hook::Arm => "[tau1, tau2]",
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
    Arm(arm::Trial),
    Arena(architecture::Trial),
}

/// How one world went.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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
        arm::EXERCISES.as_slice(),
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
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Check {
    pub exercise: String,
    pub passed: bool,
    /// Each world's outcome: every world run, or only the visible ones
    /// once [`Check::for_learner`] has hidden the rest.
    pub worlds: Vec<Outcome>,
    /// The held-back worlds as a learner sees them: how many passed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub held_back: Option<Tally>,
    /// The code did not compile (nothing ran), or stopped a run: the
    /// first such error.
    pub error: Option<ScriptError>,
}

/// Worlds passed, of how many.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Tally {
    pub passed: usize,
    pub of: usize,
}

impl Exercise {
    /// Run `source` on every world (`held_back` too, or only the visible).
    /// Once the code has run out of time in one world, the worlds after it
    /// are not run: they fail for the same reason.
    pub fn check(&self, source: &str, held_back: bool) -> Check {
        self.check_knowing(source, held_back, None)
    }

    /// [`Exercise::check`], with world `i`'s outcome already known (from
    /// its trace: the recorded run is the graded run).
    pub fn check_knowing(
        &self,
        source: &str,
        held_back: bool,
        known: Option<(usize, Outcome)>,
    ) -> Check {
        if let Err(e) = kinolab_script::Script::compile(source, self.signature) {
            return Check {
                exercise: self.id.into(),
                passed: false,
                worlds: Vec::new(),
                held_back: None,
                error: Some(e),
            };
        }
        let mut slow: Option<String> = None;
        let mut known = known;
        let worlds: Vec<Outcome> = (self.worlds)()
            .iter()
            .enumerate()
            .filter(|(_, w)| held_back || w.visible)
            .map(|(i, w)| match &slow {
                Some(first) => Outcome::new(w).judged(Some(format!(
                    "not run: your code ran out of time in “{first}”"
                ))),
                None => {
                    let out = match known.take_if(|(k, _)| *k == i) {
                        Some((_, out)) => out,
                        None => self.run(source, w),
                    };
                    if out
                        .error
                        .as_ref()
                        .is_some_and(|e| e.kind == ErrorKind::TooSlow)
                    {
                        slow = Some(w.name.clone());
                    }
                    out
                }
            })
            .collect();
        Check {
            exercise: self.id.into(),
            passed: worlds.iter().all(|w| w.passed),
            error: worlds.iter().find_map(|w| w.error.clone()),
            worlds,
            held_back: None,
        }
    }

    /// Run `source` on one of this exercise's worlds.
    pub fn run(&self, source: &str, world: &World) -> Outcome {
        match &world.trial {
            Trial::Control(t) => control::run(source, world, t),
            Trial::Behaviours(t) => behaviours::run(self.hook, source, world, t),
            Trial::Field(t) => fields::run(source, world, t),
            Trial::Legs(t) => legs::run(source, world, t),
            Trial::Arm(t) => arm::run(source, world, t),
            Trial::Arena(t) => architecture::run(source, world, t),
        }
    }
}

impl Check {
    /// The check as a learner may see it: the visible worlds in full, and
    /// of the held-back worlds only how many passed. An error that stopped
    /// a held-back world keeps its kind, line and time, not its words
    /// (they may quote the world: a point, a percept the code threw).
    pub fn for_learner(mut self) -> Check {
        let hidden: Vec<Outcome> = self.worlds.iter().filter(|w| !w.visible).cloned().collect();
        if hidden.is_empty() {
            return self;
        }
        self.worlds.retain(|w| w.visible);
        self.held_back = Some(Tally {
            passed: hidden.iter().filter(|w| w.passed).count(),
            of: hidden.len(),
        });
        let shown = self.worlds.iter().find_map(|w| w.error.clone());
        self.error = shown.or_else(|| hidden.iter().find_map(|w| w.error.as_ref().map(withheld)));
        self
    }
}

/// An error from a held-back world, told without the world's details.
fn withheld(e: &ScriptError) -> ScriptError {
    let what = match e.kind {
        ErrorKind::Endless => "a call ran too long: is there a loop that never ends?",
        ErrorKind::TooSlow => {
            "the run took too long in all: does each call do far more work than it needs?"
        }
        ErrorKind::TooDeep => {
            "functions called functions too deep: does one call itself without end?"
        }
        ErrorKind::TooLarge => "a string, list or map grew too large",
        ErrorKind::Shape => "your function answered something of the wrong shape",
        ErrorKind::NotFinite => "your function answered NaN or an infinity",
        ErrorKind::Syntax | ErrorKind::Missing | ErrorKind::Runtime => {
            "your code stopped with an error"
        }
    };
    let t = e.t.map_or(String::new(), |t| {
        format!(" at t = {} s", kinolab_common::display::fixed(t, 2))
    });
    ScriptError {
        message: format!("in a world held back{t}, {what}"),
        ..e.clone()
    }
}
