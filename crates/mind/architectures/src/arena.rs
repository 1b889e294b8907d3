//! The arena: robots of different architectures, each in its own copy of
//! one world, on one simulated clock with the same seed and surprises.

use kinolab_world::{Body, Event, EventKind, FieldError, Sensors, Sim, Vec2, World};
use serde::Serialize;

use crate::map::Cartographer;
use crate::paradigm::{Architecture, Controller, Settings};
use crate::surprise::Surprise;

/// The longest arena run, s.
pub const MAX_DURATION: f64 = 600.0;

/// Everything an arena needs.
#[derive(Debug, Clone, PartialEq)]
pub struct ArenaSetup {
    pub world: World,
    pub surprises: Vec<Surprise>,
    /// Simulated planning time per expanded cell, s.
    pub planning_cost: f64,
    pub cell: f64,
    pub duration: f64,
    pub dt: f64,
    pub seed: u64,
    /// A learner's sequencer for the hybrid robot (`next(state)`).
    pub sequencer: Option<String>,
}

impl ArenaSetup {
    /// `world` with no surprises: 2 ms a cell, 10 cm cells, 120 s at 20 Hz.
    pub fn new(world: World) -> Self {
        Self {
            world,
            surprises: Vec::new(),
            planning_cost: 0.002,
            cell: 0.1,
            duration: 120.0,
            dt: 0.05,
            seed: 0,
            sequencer: None,
        }
    }

    /// The learner's sequencer, compiled; a syntax error names its line.
    pub fn sequencer_script(&self) -> Result<Option<kinolab_script::Script>, FieldError> {
        self.sequencer
            .as_deref()
            .map(|source| {
                kinolab_script::Script::compile(source, crate::paradigm::scripted::SIGNATURE)
                    .map_err(|e| FieldError::new("sequencer", e.to_string()))
            })
            .transpose()
    }

    pub fn check(&self) -> Result<(), FieldError> {
        use kinolab_common::error::in_range;
        in_range("planning_cost", self.planning_cost, 0.0, 1.0)?;
        in_range("cell", self.cell, 0.02, 2.0)?;
        in_range("duration", self.duration, 0.0, MAX_DURATION)?;
        in_range("dt", self.dt, 0.01, 0.2)?;
        if self.world.goal.is_none() {
            return Err(FieldError::new("goal", "an arena world needs a goal"));
        }
        for (i, s) in self.surprises.iter().enumerate() {
            s.check(&format!("perturb[{i}]"), &self.world)?;
        }
        self.sequencer_script().map(|_| ())
    }
}

/// The sensors every robot in the arena carries: the behaviour runs'
/// default, 16 rays over 240°, 2 m long, and two light sensors; bumpers
/// and the goal come with every body.
pub fn arena_sensors() -> Sensors {
    kinolab_behaviours::run::default_sensors()
}

/// How a robot is doing.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scores {
    pub reached: bool,
    /// When it reached the goal, s.
    pub time: Option<f64>,
    pub path_length: f64,
    /// The smallest gap between the robot and anything, m.
    pub min_clearance: f64,
    /// Times it touched something (or something touched it).
    pub collisions: usize,
    /// Plans made after the first.
    pub replans: usize,
    /// How old the sensing behind its plan was while it acted, s: mean and
    /// largest (`None` when it acts on no model).
    pub model_age_mean: Option<f64>,
    pub model_age_max: Option<f64>,
    /// Planning layer: searches run and cells expanded per search.
    pub plans: usize,
    pub expanded_per_plan: f64,
    /// Reactive layer: behaviour evaluations per control cycle.
    pub evaluations_per_cycle: f64,
    pub cycles: u64,
}

/// One robot in the arena.
#[derive(Debug, Clone)]
pub struct Entrant {
    pub architecture: Architecture,
    pub sim: Sim,
    pub controller: Controller,
    pub scores: Scores,
    /// What it is doing now.
    pub activity: String,
    /// The twist it drove in the last step.
    pub driven: kinolab_world::Command,
    age: (f64, usize),
}

impl Entrant {
    pub fn finished(&self, duration: f64) -> bool {
        self.sim.goal_reached
            || self.sim.time >= duration - 1e-9
            || self.controller.failed().is_some()
    }

    /// Sense, decide and move one step; the events of the step.
    fn step(&mut self) -> Vec<Event> {
        // Localisation is not this unit's subject: the robots know their
        // pose (wheel odometry would drift whenever a wheel slips against
        // something, and the maps with it).
        let mut percepts = self.sim.sense();
        percepts.odometry = self.sim.pose;
        let before = self.sim.position();
        let act = self.controller.act(&percepts, self.sim.dt);
        let step = self.sim.advance(act.command);
        let s = &mut self.scores;
        s.cycles += 1;
        s.path_length += (self.sim.position() - before).norm();
        s.min_clearance = s.min_clearance.min(step.clearance);
        if let Some(age) = act.model_age {
            self.age = (self.age.0 + age, self.age.1 + 1);
            s.model_age_mean = Some(self.age.0 / self.age.1 as f64);
            s.model_age_max = Some(s.model_age_max.unwrap_or(0.0).max(age));
        }
        if let Some(work) = self.controller.planner_work() {
            s.plans = work.searches;
            s.replans = work.searches.saturating_sub(1);
            s.expanded_per_plan = work.expanded as f64 / work.searches.max(1) as f64;
        }
        s.evaluations_per_cycle = self.controller.evaluations() as f64 / s.cycles as f64;
        for e in &step.events {
            match e.kind {
                EventKind::Bump { .. } => s.collisions += 1,
                EventKind::GoalReached => {
                    s.reached = true;
                    s.time = Some(e.t);
                }
                EventKind::Appeared { .. } => {}
            }
        }
        self.activity = act.activity;
        self.driven = step.driven;
        step.events
    }
}

/// Robots on one clock.
#[derive(Debug, Clone)]
pub struct Arena {
    pub entrants: Vec<Entrant>,
    pub duration: f64,
    /// Goal moves still to come: when, and where to.
    goal_moves: Vec<(f64, Vec2)>,
}

impl Arena {
    /// One robot of each kind in `kinds`, each in a copy of the set-up's
    /// world with the surprises in it.
    pub fn new(setup: &ArenaSetup, kinds: &[Architecture]) -> Result<Self, FieldError> {
        setup.check()?;
        let missing: Vec<usize> = setup
            .surprises
            .iter()
            .flat_map(|s| match s {
                Surprise::WrongMap { missing } => missing.clone(),
                _ => Vec::new(),
            })
            .collect();
        let body = Body::default();
        let clearance = setup.world.robot_radius.max(body.radius());
        let map = Cartographer::from_world(&setup.world, setup.cell, clearance, |k| {
            !missing.contains(&k)
        })?;
        let mut world = setup.world.clone();
        let mut sensors = arena_sensors();
        for s in &setup.surprises {
            s.apply(&mut world, &mut sensors);
        }
        let goal_moves = setup
            .surprises
            .iter()
            .filter_map(|s| match s {
                Surprise::Goal { to, at } => Some((*at, Vec2::new(to[0], to[1]))),
                _ => None,
            })
            .collect();
        let settings = Settings {
            body: body.clone(),
            planning_cost: setup.planning_cost,
            sequencer: setup.sequencer_script()?,
        };
        let entrants = kinds
            .iter()
            .map(|&kind| {
                let sim = Sim::new(world.clone(), body.clone(), sensors, setup.dt, setup.seed)?;
                Ok(Entrant {
                    architecture: kind,
                    scores: Scores {
                        reached: false,
                        time: None,
                        path_length: 0.0,
                        min_clearance: sim.clearance(),
                        collisions: 0,
                        replans: 0,
                        model_age_mean: None,
                        model_age_max: None,
                        plans: 0,
                        expanded_per_plan: 0.0,
                        evaluations_per_cycle: 0.0,
                        cycles: 0,
                    },
                    sim,
                    controller: Controller::new(kind, &settings, map.clone())?,
                    activity: "waiting".into(),
                    driven: kinolab_world::Command::STOP,
                    age: (0.0, 0),
                })
            })
            .collect::<Result<Vec<_>, FieldError>>()?;
        Ok(Self {
            entrants,
            duration: setup.duration,
            goal_moves,
        })
    }

    /// The clock: the time of the robot furthest along.
    pub fn time(&self) -> f64 {
        self.entrants.iter().map(|e| e.sim.time).fold(0.0, f64::max)
    }

    pub fn done(&self) -> bool {
        self.entrants.iter().all(|e| e.finished(self.duration))
    }

    /// Move every robot that is still going one step; each event with the
    /// robot's index.
    pub fn step(&mut self) -> Vec<(usize, Event)> {
        let mut events = Vec::new();
        for i in 0..self.entrants.len() {
            events.extend(self.step_one(i).into_iter().map(|e| (i, e)));
        }
        events
    }

    /// Move robot `i` one step (if it is still going); its events.
    pub fn step_one(&mut self, i: usize) -> Vec<Event> {
        let duration = self.duration;
        let Some(e) = self.entrants.get_mut(i).filter(|e| !e.finished(duration)) else {
            return Vec::new();
        };
        for (at, to) in &self.goal_moves {
            if *at <= e.sim.time + 1e-9 && e.sim.world.goal != Some(*to) {
                e.sim.world.goal = Some(*to);
            }
        }
        e.step()
    }

    /// Spring a surprise on every robot now (a door closes now, a person
    /// starts walking now, the goal moves now).
    pub fn spring(&mut self, surprise: &Surprise) -> Result<(), FieldError> {
        let now = self.time();
        let surprise = surprise.clone().at(now);
        for e in &mut self.entrants {
            surprise.check("surprise", &e.sim.world)?;
            let mut world = e.sim.world.clone();
            let mut sensors = e.sim.sensors;
            surprise.apply(&mut world, &mut sensors);
            e.sim.world = world;
            e.sim.sensors = sensors;
        }
        if let Surprise::Goal { to, at } = surprise {
            self.goal_moves.push((at, Vec2::new(to[0], to[1])));
        }
        Ok(())
    }
}
