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
    if every == 0 {
        return Err(FieldError::new("every", "must be at least 1"));
    }
    let mut arena = Arena::new(setup, &[architecture])?;
    let sample = |arena: &Arena| {
        let e = &arena.entrants[0];
        let p = e.sim.pose;
        Sample {
            motion: Motion::new(e.sim.time, [p.x, p.y, p.theta], e.driven.vx, e.driven.omega),
            activity: e.activity.clone(),
        }
    };
    let mut samples = vec![sample(&arena)];
    let mut events = Vec::new();
    let mut k = 0;
    while !arena.done() {
        events.extend(arena.step().into_iter().map(|(_, e)| e));
        k += 1;
        if k % every == 0 || arena.done() {
            samples.push(sample(&arena));
        }
    }
    Ok(ArenaReport {
        architecture,
        surprises: setup.surprises.clone(),
        planning_cost_ms: setup.planning_cost * 1e3,
        samples,
        events,
        metrics: arena.entrants[0].scores.clone(),
        error: arena.entrants[0].controller.failed().cloned(),
    })
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
