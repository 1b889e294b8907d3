//! One architecture's run through an arena, as `kinolab arena` prints it.

use kinolab_common::trajectory::Sample as Motion;
use kinolab_world::{Event, FieldError};
use serde::Serialize;

use crate::arena::{Arena, ArenaSetup, Scores};
use crate::paradigm::Architecture;
use crate::surprise::Surprise;

/// One kept sample of the trajectory.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sample {
    #[serde(flatten)]
    pub motion: Motion,
    /// What the robot was doing in the step that ended here.
    pub activity: String,
}

/// What `kinolab arena` prints.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ArenaReport {
    pub architecture: Architecture,
    pub surprises: Vec<Surprise>,
    pub planning_cost_ms: f64,
    pub samples: Vec<Sample>,
    pub events: Vec<Event>,
    pub metrics: Scores,
    /// The error that stopped a learner's sequencer, when one did.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<kinolab_script::ScriptError>,
}

/// Run one `architecture` through `setup` to the end, keeping one sample
/// in `every` steps (and the last).
pub fn run(
    setup: &ArenaSetup,
    architecture: Architecture,
    every: usize,
) -> Result<ArenaReport, FieldError> {
    let mut recording = Recording::new(setup, architecture, every)?;
    while recording.step() {}
    Ok(recording.finish())
}

/// One architecture's run being recorded into its [`ArenaReport`] a step
/// at a time, so a host can spread a long run over several frames and
/// look at the arena after each step.
#[derive(Debug)]
pub struct Recording {
    pub arena: Arena,
    every: usize,
    steps: usize,
    report: ArenaReport,
}

impl Recording {
    pub fn new(
        setup: &ArenaSetup,
        architecture: Architecture,
        every: usize,
    ) -> Result<Self, FieldError> {
        if every == 0 {
            return Err(FieldError::new("every", "must be at least 1"));
        }
        let arena = Arena::new(setup, &[architecture])?;
        let report = ArenaReport {
            architecture,
            surprises: setup.surprises.clone(),
            planning_cost_ms: setup.planning_cost * 1e3,
            samples: vec![sample(&arena)],
            events: Vec::new(),
            metrics: arena.entrants[0].scores.clone(),
            error: None,
        };
        Ok(Self {
            arena,
            every,
            steps: 0,
            report,
        })
    }

    /// Run one step and record it; whether it ran (false once the run is over).
    pub fn step(&mut self) -> bool {
        if self.arena.done() {
            return false;
        }
        let events = self.arena.step().into_iter().map(|(_, e)| e);
        self.report.events.extend(events);
        self.steps += 1;
        if self.steps.is_multiple_of(self.every) || self.arena.done() {
            self.report.samples.push(sample(&self.arena));
        }
        true
    }

    /// The report of the run so far (the whole run once
    /// [`Recording::step`] has said it is over).
    pub fn finish(mut self) -> ArenaReport {
        let e = &self.arena.entrants[0];
        self.report.metrics = e.scores.clone();
        self.report.error = e.controller.failed().cloned();
        self.report
    }
}

/// The first entrant's motion and activity now.
fn sample(arena: &Arena) -> Sample {
    let e = &arena.entrants[0];
    let p = e.sim.pose;
    Sample {
        motion: Motion::new(e.sim.time, [p.x, p.y, p.theta], e.driven.vx, e.driven.omega),
        activity: e.activity.clone(),
    }
}

/// A run as the command line and the JS API ask for it.
#[derive(Debug, Clone, PartialEq, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Request {
    pub architecture: String,
    /// Surprises as written on the command line (`door:5,1,5,2@6`, …).
    #[serde(default)]
    pub perturb: Vec<String>,
    /// Simulated planning time per expanded cell, ms.
    #[serde(default = "kinolab_common::defaults::whole::<2>")]
    pub planning_cost_ms: f64,
    #[serde(default = "kinolab_common::defaults::whole::<120>")]
    pub duration: f64,
    #[serde(default)]
    pub seed: u64,
    /// Keep one sample in this many steps.
    #[serde(default = "kinolab_common::defaults::one")]
    pub every: usize,
    /// A learner's sequencer for the hybrid robot: the script's code
    /// (`next(state)`).
    #[serde(default)]
    pub sequencer: Option<String>,
}

impl Request {
    /// Run the request in `world`. Errors name the field (`perturb[i]`,
    /// `planning_cost`, …).
    pub fn run(&self, world: kinolab_world::World) -> Result<ArenaReport, FieldError> {
        let mut setup = ArenaSetup::new(world);
        let kind = Architecture::parse("architecture", &self.architecture)?;
        setup.surprises = self
            .perturb
            .iter()
            .enumerate()
            .map(|(i, spec)| Surprise::parse(&format!("perturb[{i}]"), spec))
            .collect::<Result<_, _>>()?;
        setup.planning_cost =
            kinolab_common::error::in_range("planning_cost", self.planning_cost_ms, 0.0, 1000.0)?
                / 1e3;
        setup.duration = self.duration;
        setup.seed = self.seed;
        setup.sequencer.clone_from(&self.sequencer);
        run(&setup, kind, self.every)
    }
}
