//! A run: a world, a robot with sensors, behaviours and a coordinator,
//! stepped for a duration from a seed. The same file and seed always give
//! the same run, so a link, a test and a graded exercise see one result.

use kinolab_common::error::{from_json, in_range, positive};
use kinolab_common::trajectory::Sample as Motion;
use kinolab_world::sensors::{LightSensors, Percepts, Rays};
use kinolab_world::{Body, Event, EventKind, Sensors, Sim, World};
use serde::{Deserialize, Serialize};

use crate::coordinate::{Coordinator, Decision, Memory, Responses, decide};
use crate::{Drive, FieldError, Named, Response};

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a behaviour run file (an object with `world`, `behaviours` and `coordinator`)"
)]
struct RunFile {
    /// An example world's id, or a world file's contents.
    world: serde_json::Value,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    robot: Option<serde_json::Value>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    sensors: Option<Sensors>,
    behaviours: Vec<Named>,
    coordinator: Coordinator,
    #[serde(default = "kinolab_common::defaults::whole::<DURATION_S>")]
    duration: f64,
    #[serde(default = "kinolab_common::defaults::reciprocal::<STEPS_PER_S>")]
    dt: f64,
    #[serde(default)]
    seed: u64,
    #[serde(default = "default_heading_gain")]
    heading_gain: f64,
    #[serde(default = "yes")]
    stop_at_goal: bool,
    #[serde(default = "kinolab_common::defaults::one")]
    output_every: usize,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    script: Vec<Change>,
}

/// A change made to a run while it goes, as a learner makes it in the lab
/// (a light dragged, a vehicle rewired): at `at` seconds, before the first
/// step that starts then or later.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "do", rename_all = "snake_case", deny_unknown_fields)]
pub enum Change {
    /// Light `light` (its index in the world's `lights`) moves to (`x`, `y`).
    MoveLight {
        at: f64,
        light: usize,
        x: f64,
        y: f64,
    },
    /// The behaviour called `behaviour.name` becomes `behaviour` (its
    /// state starts afresh).
    ReplaceBehaviour { at: f64, behaviour: Box<Named> },
}

impl Change {
    /// When it happens, s.
    pub fn at(&self) -> f64 {
        match self {
            Change::MoveLight { at, .. } | Change::ReplaceBehaviour { at, .. } => *at,
        }
    }
}

fn default_heading_gain() -> f64 {
    3.0
}
fn yes() -> bool {
    true
}

/// The longest run, s, and the most steps one may take.
pub const MAX_DURATION: f64 = 3600.0;
pub const MAX_STEPS: f64 = 200_000.0;

/// Everything a run needs.
#[derive(Debug, Clone, PartialEq)]
pub struct Setup {
    pub world: World,
    pub body: Body,
    pub sensors: Sensors,
    pub behaviours: Vec<Named>,
    pub coordinator: Coordinator,
    pub duration: f64,
    pub dt: f64,
    pub seed: u64,
    /// k of the heading controller that steers towards vectors, 1/s.
    pub heading_gain: f64,
    pub stop_at_goal: bool,
    /// Keep one sample in this many steps.
    pub output_every: usize,
    /// Changes made while it runs, in time order.
    pub script: Vec<Change>,
}

/// The sensors a robot carries unless a run says otherwise: 16 rays over
/// 240°, 2 m long, and two light sensors.
pub fn default_sensors() -> Sensors {
    Sensors {
        rays: Some(Rays {
            count: 16,
            fov_deg: 240.0,
            max_range: 2.0,
            noise: 0.0,
        }),
        lights: Some(LightSensors::default()),
        ..Sensors::default()
    }
}

/// A run's length when its file does not say, s.
const DURATION_S: u32 = 30;
/// Steps a second when the file does not give `dt`.
const STEPS_PER_S: u32 = 20;

impl Setup {
    /// A run of `behaviours` under `coordinator` in `world` with the
    /// default robot and sensors, 30 s at 20 steps a second, seed 0.
    pub fn new(world: World, behaviours: Vec<Named>, coordinator: Coordinator) -> Self {
        Self {
            world,
            body: Body::default(),
            sensors: default_sensors(),
            behaviours,
            coordinator,
            duration: kinolab_common::defaults::whole::<DURATION_S>(),
            dt: kinolab_common::defaults::reciprocal::<STEPS_PER_S>(),
            seed: 0,
            heading_gain: default_heading_gain(),
            stop_at_goal: true,
            output_every: 1,
            script: Vec::new(),
        }
    }

    /// Read a run file. Errors name the JSON path of the bad field.
    pub fn from_json(text: &str) -> Result<Self, FieldError> {
        let file: RunFile = from_json(text)?;
        let world = match &file.world {
            serde_json::Value::String(id) => kinolab_world::catalogue::world(id)?,
            other => World::from_value(other.clone()).map_err(|e| e.within("world"))?,
        };
        let body = match file.robot {
            Some(v) => Body::from_value(v).map_err(|e| e.within("robot"))?,
            None => Body::default(),
        };
        let setup = Setup {
            world,
            body,
            sensors: file.sensors.unwrap_or_else(default_sensors),
            behaviours: file.behaviours,
            coordinator: file.coordinator,
            duration: file.duration,
            dt: file.dt,
            seed: file.seed,
            heading_gain: file.heading_gain,
            stop_at_goal: file.stop_at_goal,
            output_every: file.output_every,
            script: file.script,
        };
        setup.check()?;
        Ok(setup)
    }

    /// The run file for this set-up.
    pub fn to_json(&self) -> String {
        let world: serde_json::Value =
            serde_json::from_str(&self.world.to_json()).unwrap_or_default();
        let file = RunFile {
            world,
            robot: Some(self.body.to_value()),
            sensors: Some(self.sensors),
            behaviours: self.behaviours.clone(),
            coordinator: self.coordinator.clone(),
            duration: self.duration,
            dt: self.dt,
            seed: self.seed,
            heading_gain: self.heading_gain,
            stop_at_goal: self.stop_at_goal,
            output_every: self.output_every,
            script: self.script.clone(),
        };
        serde_json::to_string_pretty(&file).unwrap_or_default()
    }

    /// Check every number and name; errors name the field.
    pub fn check(&self) -> Result<(), FieldError> {
        in_range("duration", self.duration, 0.0, MAX_DURATION)?;
        in_range("dt", self.dt, 1e-3, 0.5)?;
        if self.duration / self.dt > MAX_STEPS {
            return Err(FieldError::new(
                "dt",
                format!(
                    "{} s at {} s a step is more than {MAX_STEPS} steps",
                    self.duration, self.dt
                ),
            ));
        }
        positive("heading_gain", self.heading_gain)?;
        if self.output_every == 0 {
            return Err(FieldError::new("output_every", "must be at least 1"));
        }
        self.sensors.check().map_err(|e| e.within("sensors"))?;
        let mut names = Vec::new();
        for (i, b) in self.behaviours.iter().enumerate() {
            b.check()
                .map_err(|e| e.within(&format!("behaviours[{i}]")))?;
            if names.contains(&b.name) {
                return Err(FieldError::new(
                    format!("behaviours[{i}].name"),
                    format!("`{}` is used twice", b.name),
                ));
            }
            if matches!(b.behaviour, crate::Behaviour::Braitenberg(_)) && self.body.holonomic() {
                return Err(FieldError::new(
                    format!("behaviours[{i}]"),
                    "a Braitenberg vehicle needs a differential robot",
                ));
            }
            names.push(b.name.clone());
        }
        self.coordinator
            .check(&names)
            .map_err(|e| e.within("coordinator"))?;
        let mut last = 0.0;
        for (i, change) in self.script.iter().enumerate() {
            self.check_change(change, last)
                .map_err(|e| e.within(&format!("script[{i}]")))?;
            last = change.at();
        }
        Ok(())
    }

    /// One change of the script, which may not come before `after`.
    fn check_change(&self, change: &Change, after: f64) -> Result<(), FieldError> {
        in_range("at", change.at(), after, self.duration)?;
        match change {
            Change::MoveLight { light, x, y, .. } => {
                if *light >= self.world.lights.len() {
                    return Err(FieldError::new(
                        "light",
                        format!("the world has {} lights", self.world.lights.len()),
                    ));
                }
                kinolab_common::error::finite("x", *x)?;
                kinolab_common::error::finite("y", *y).map(|_| ())
            }
            Change::ReplaceBehaviour { behaviour, .. } => {
                if !self.behaviours.iter().any(|b| b.name == behaviour.name) {
                    return Err(FieldError::new(
                        "behaviour.name",
                        format!("no behaviour is called `{}`", behaviour.name),
                    ));
                }
                behaviour.check().map_err(|e| e.within("behaviour"))?;
                if matches!(behaviour.behaviour, crate::Behaviour::Braitenberg(_))
                    && self.body.holonomic()
                {
                    return Err(FieldError::new(
                        "behaviour",
                        "a Braitenberg vehicle needs a differential robot",
                    ));
                }
                Ok(())
            }
        }
    }
}

/// Everything one step produced, for drawing and for the report.
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    pub percepts: Percepts,
    /// Each behaviour's response (`None`: its releaser was off).
    pub responses: Vec<Option<Response>>,
    pub decision: Decision,
    /// The command the body actually drove (after its limits).
    pub driven: kinolab_world::Command,
    pub events: Vec<Event>,
    /// The pose after the step.
    pub pose: kinolab_world::Pose,
    pub clearance: f64,
    /// What each learner's script (behaviour or coordinator) returned and
    /// printed this step.
    pub calls: Vec<crate::script::ScriptCall>,
}

/// A run in progress.
#[derive(Debug, Clone)]
pub struct Runner {
    pub sim: Sim,
    pub behaviours: Vec<Named>,
    pub coordinator: Coordinator,
    pub drive: Drive,
    memory: Memory,
    pub duration: f64,
    pub stop_at_goal: bool,
    /// The error that stopped a learner's script, and with it the run.
    pub error: Option<kinolab_script::ScriptError>,
    /// The set-up's changes still to come.
    script: std::collections::VecDeque<Change>,
}

impl Runner {
    pub fn new(setup: &Setup) -> Result<Self, FieldError> {
        setup.check()?;
        let sim = Sim::new(
            setup.world.clone(),
            setup.body.clone(),
            setup.sensors,
            setup.dt,
            setup.seed,
        )?;
        let mut behaviours = setup.behaviours.clone();
        behaviours.iter_mut().for_each(Named::reset);
        Ok(Self {
            sim,
            behaviours,
            memory: Memory::new(&setup.coordinator),
            coordinator: setup.coordinator.clone(),
            drive: Drive {
                body: setup.body.clone(),
                heading_gain: setup.heading_gain,
            },
            duration: setup.duration,
            stop_at_goal: setup.stop_at_goal,
            error: None,
            script: setup.script.iter().cloned().collect(),
        })
    }
    /// Make `change` now (whatever its time says).
    pub fn apply(&mut self, change: &Change) {
        match change {
            Change::MoveLight { light, x, y, .. } => {
                if let Some(l) = self.sim.world.lights.get_mut(*light) {
                    l.x = *x;
                    l.y = *y;
                }
            }
            Change::ReplaceBehaviour { behaviour, .. } => {
                if let Some(b) = self
                    .behaviours
                    .iter_mut()
                    .find(|b| b.name == behaviour.name)
                {
                    *b = (**behaviour).clone();
                    b.reset();
                }
            }
        }
    }

    /// Make the script's changes that are due before the next step.
    fn apply_due(&mut self) {
        let now = self.sim.time + self.sim.dt / 2.0;
        while self.script.front().is_some_and(|c| c.at() <= now) {
            if let Some(change) = self.script.pop_front() {
                self.apply(&change);
            }
        }
    }

    /// Whether the run is over: out of time, at the goal when it should
    /// stop there, or stopped by a learner's script.
    pub fn done(&self) -> bool {
        self.sim.time >= self.duration - 1e-9
            || (self.stop_at_goal && self.sim.goal_reached)
            || self.error.is_some()
    }

    /// What the learner's scripts did this step; the first error stops the run.
    fn script_calls(&mut self) -> Vec<crate::script::ScriptCall> {
        let coordinator = self.memory.script();
        let failed = self
            .behaviours
            .iter()
            .find_map(|b| b.failed.clone())
            .or_else(|| coordinator.and_then(|c| c.failed.clone()));
        let calls = self
            .behaviours
            .iter()
            .filter_map(|b| b.call.clone())
            .chain(coordinator.and_then(|c| c.call.clone()))
            .collect();
        if self.error.is_none() {
            self.error = failed;
        }
        calls
    }

    /// Sense, let every behaviour respond, coordinate, and move.
    pub fn step(&mut self) -> Frame {
        self.apply_due();
        let percepts = self.sim.sense();
        let responses: Vec<Option<Response>> = self
            .behaviours
            .iter_mut()
            .map(|b| b.respond(&percepts))
            .collect();
        let decision = decide(
            &self.coordinator,
            &mut self.memory,
            &Responses {
                behaviours: &self.behaviours,
                responses: &responses,
            },
            &percepts,
            &self.drive,
            self.sim.dt,
        );
        let calls = self.script_calls();
        let command = match self.error {
            Some(_) => kinolab_world::Command::unicycle(0.0, 0.0),
            None => decision.command,
        };
        let step = self.sim.advance(command);
        Frame {
            percepts,
            responses,
            decision,
            driven: step.driven,
            events: step.events,
            pose: self.sim.pose,
            clearance: step.clearance,
            calls,
        }
    }

    /// The name of behaviour `i`.
    pub fn name(&self, i: usize) -> &str {
        self.behaviours.get(i).map_or("", |b| b.name.as_str())
    }
}

/// One kept sample of the trajectory.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sample {
    #[serde(flatten)]
    pub motion: Motion,
    /// The behaviour in control during the step that ended here.
    pub control: Option<String>,
}

/// A stretch of time during which one behaviour had control.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Stretch {
    pub from: f64,
    pub to: f64,
    pub behaviour: Option<String>,
}

/// How the run went.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Metrics {
    pub reached: bool,
    /// When the goal was reached, s.
    pub time: Option<f64>,
    pub path_length: f64,
    /// The smallest gap between the robot and anything, m.
    pub min_clearance: f64,
    /// Times the robot touched something.
    pub collisions: usize,
}

/// What `kinolab run` prints.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunReport {
    pub samples: Vec<Sample>,
    pub control: Vec<Stretch>,
    pub events: Vec<Event>,
    pub metrics: Metrics,
    /// The error that stopped a learner's script (`kind`, `message`,
    /// `line`, `column`, `t`), when one did.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<kinolab_script::ScriptError>,
}

/// Run `setup` to the end.
pub fn run(setup: &Setup) -> Result<RunReport, FieldError> {
    let mut recording = Recording::new(setup)?;
    while recording.step().is_some() {}
    Ok(recording.finish())
}

/// A run being recorded into its [`RunReport`] a step at a time, so a
/// host can spread a long run over several frames and look at each
/// step's [`Frame`] on the way.
#[derive(Debug)]
pub struct Recording {
    pub runner: Runner,
    output_every: usize,
    steps: usize,
    report: RunReport,
}

impl Recording {
    pub fn new(setup: &Setup) -> Result<Self, FieldError> {
        let runner = Runner::new(setup)?;
        let start = runner.sim.pose;
        let report = RunReport {
            samples: vec![Sample {
                motion: Motion::new(0.0, [start.x, start.y, start.theta], 0.0, 0.0),
                control: None,
            }],
            control: Vec::new(),
            events: Vec::new(),
            metrics: Metrics {
                reached: false,
                time: None,
                path_length: 0.0,
                min_clearance: runner.sim.clearance(),
                collisions: 0,
            },
            error: None,
        };
        Ok(Self {
            runner,
            output_every: setup.output_every,
            steps: 0,
            report,
        })
    }

    /// Run one step and record it; `None` once the run is over.
    pub fn step(&mut self) -> Option<Frame> {
        let runner = &mut self.runner;
        if runner.done() {
            return None;
        }
        let before = runner.sim.position();
        let t0 = runner.sim.time;
        let frame = runner.step();
        self.steps += 1;
        let who = frame.decision.in_control.map(|i| runner.name(i).to_owned());
        let report = &mut self.report;
        match report.control.last_mut() {
            Some(last) if last.behaviour == who => last.to = runner.sim.time,
            _ => report.control.push(Stretch {
                from: t0,
                to: runner.sim.time,
                behaviour: who.clone(),
            }),
        }
        let metrics = &mut report.metrics;
        metrics.path_length += (runner.sim.position() - before).norm();
        metrics.min_clearance = metrics.min_clearance.min(frame.clearance);
        for e in &frame.events {
            match e.kind {
                EventKind::Bump { .. } => metrics.collisions += 1,
                EventKind::GoalReached => {
                    metrics.reached = true;
                    metrics.time = Some(e.t);
                }
                EventKind::Appeared { .. } => {}
            }
        }
        report.events.extend(frame.events.iter().cloned());
        if self.steps.is_multiple_of(self.output_every) || runner.done() {
            let p = frame.pose;
            report.samples.push(Sample {
                motion: Motion::new(
                    runner.sim.time,
                    [p.x, p.y, p.theta],
                    frame.driven.vx,
                    frame.driven.omega,
                ),
                control: who,
            });
        }
        Some(frame)
    }

    /// The report of the run so far (the whole run once
    /// [`Recording::step`] has said it is over).
    pub fn finish(mut self) -> RunReport {
        self.report.error = self.runner.error;
        self.report
    }
}
