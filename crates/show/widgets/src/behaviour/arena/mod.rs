//! The behaviour arena: a robot with its behaviours and a coordinator in a
//! world. Every behaviour's output is an arrow, the coordinated command a
//! thicker one; the coordinator's own picture (layers and nodes, votes,
//! states) lights up as it decides; a timeline shows who had control, and
//! the run can be played, paused, stepped and scrubbed back. Runs are
//! deterministic, so a replay is the same run.

mod canvas;
mod diagram;
mod sets;
mod task;
mod timeline;

use kinolab_behaviours::coordinate::Trace;
use kinolab_behaviours::run::{Runner, Setup};
use kinolab_world::sensors::RayReading;
use kinolab_world::{Command, Pose, Vec2, World};
use serde::{Deserialize, Serialize};

use crate::link;
use crate::widget::{LabWidget, Params};
use task::LayerDesign;

/// Everything the learner can change, and what a link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Design {
    world: String,
    set: String,
    coordinator: String,
    seed: u64,
    /// Obstacles the learner dragged: index and new anchor.
    moved: Vec<(u32, [f64; 2])>,
    goal: Option<[f64; 2]>,
    /// The layer exercise's design, when there is one.
    layers: Option<LayerDesign>,
}

/// One step as the arena shows it.
#[derive(Debug, Clone, PartialEq)]
struct Record {
    t: f64,
    pose: Pose,
    rays: Vec<RayReading>,
    /// Each behaviour's output as a robot-frame vector (`None`: released).
    vectors: Vec<Option<Vec2>>,
    command: Command,
    in_control: Option<usize>,
    trace: Trace,
    /// Whether the robot bumped into something, or reached the goal, in
    /// this step.
    bump: bool,
    goal: bool,
}

struct Arena {
    design: Design,
    initial: Design,
    setup: Option<Setup>,
    problem: Option<String>,
    runner: Option<Runner>,
    records: Vec<Record>,
    /// How many records are shown: `records.len()` is the live end.
    cursor: usize,
    playing: bool,
    /// Steps per frame while playing.
    speed: usize,
    task: Option<task::TaskUi>,
}

/// The longest run the arena records, s.
const DURATION: f64 = 60.0;

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    Ok(Box::new(Arena::new(p)?))
}

impl Arena {
    fn new(p: &Params) -> Result<Self, String> {
        let world = p.choice("world").unwrap_or("scattered").to_owned();
        kinolab_world::catalogue::world(&world).map_err(|e| e.to_string())?;
        let task = (p.choice("task") == Some("layers")).then(task::TaskUi::new);
        let design = Design {
            world,
            set: p.choice("set").unwrap_or("goal-and-avoid").to_owned(),
            coordinator: p.choice("coordinator").unwrap_or("sum").to_owned(),
            seed: p.integer("seed").unwrap_or(1).max(0) as u64,
            moved: Vec::new(),
            goal: None,
            layers: task.as_ref().map(|_| LayerDesign::start()),
        };
        let mut arena = Arena {
            initial: design.clone(),
            design,
            setup: None,
            problem: None,
            runner: None,
            records: Vec::new(),
            cursor: 0,
            playing: true,
            speed: 1,
            task,
        };
        arena.rebuild();
        Ok(arena)
    }
}

impl Design {
    /// The world with the learner's moves.
    fn world(&self) -> Result<World, String> {
        let mut world = match &self.layers {
            Some(l) => kinolab_world::catalogue::scattered(l.world_seed(), 6),
            None => kinolab_world::catalogue::world(&self.world).map_err(|e| e.to_string())?,
        };
        for (i, at) in &self.moved {
            if let Some(o) = world.obstacles.get_mut(*i as usize) {
                let anchor = o.shape.anchor();
                let moved = o.shape.moved(Vec2::new(at[0], at[1]) - anchor);
                *o = kinolab_world::Obstacle::new(moved);
            }
        }
        if let Some(g) = self.goal {
            world.goal = Some(Vec2::new(g[0], g[1]));
        }
        Ok(world)
    }

    /// The run this design makes.
    fn setup(&self) -> Result<Setup, String> {
        let world = self.world()?;
        let (behaviours, coordinator) = match &self.layers {
            Some(l) => (
                kinolab_behaviours::exercise::layer_behaviours(),
                l.coordinator(),
            ),
            None => (
                sets::behaviours(&self.set),
                sets::coordinator(&self.set, &self.coordinator),
            ),
        };
        let mut setup = Setup::new(world, behaviours, coordinator);
        setup.duration = DURATION;
        setup.seed = self.seed;
        setup.stop_at_goal = setup.world.goal.is_some();
        setup.check().map_err(|e| e.to_string())?;
        Ok(setup)
    }
}

impl Arena {
    /// Start the run afresh from the design.
    fn rebuild(&mut self) {
        self.records.clear();
        self.cursor = 0;
        match self
            .design
            .setup()
            .and_then(|s| Runner::new(&s).map(|r| (s, r)).map_err(|e| e.to_string()))
        {
            Ok((setup, runner)) => {
                self.setup = Some(setup);
                self.runner = Some(runner);
                self.problem = None;
            }
            Err(e) => {
                self.setup = None;
                self.runner = None;
                self.problem = Some(e);
            }
        }
    }

    /// One more step of the run, recorded.
    fn step(&mut self) -> bool {
        let Some(runner) = &mut self.runner else {
            return false;
        };
        if runner.done() {
            return false;
        }
        let frame = runner.step();
        let vectors = frame
            .responses
            .iter()
            .map(|r| r.as_ref().map(|r| runner.drive.as_vector(r)))
            .collect();
        let bump = frame
            .events
            .iter()
            .any(|e| matches!(e.kind, kinolab_world::EventKind::Bump { .. }));
        let goal = frame
            .events
            .iter()
            .any(|e| e.kind == kinolab_world::EventKind::GoalReached);
        self.records.push(Record {
            bump,
            goal,
            t: runner.sim.time,
            pose: frame.pose,
            rays: frame.percepts.rays,
            vectors,
            command: frame.driven,
            in_control: frame.decision.in_control,
            trace: frame.decision.trace,
        });
        self.cursor = self.records.len();
        true
    }

    /// Continue from the record shown: replay the run to there (runs are
    /// deterministic) and drop what came after.
    fn resume_from_cursor(&mut self) {
        if self.cursor == self.records.len() {
            return;
        }
        let keep = self.cursor;
        self.rebuild();
        for _ in 0..keep {
            self.step();
        }
    }

    /// The pose shown now.
    fn shown_pose(&self) -> Option<Pose> {
        match self.cursor {
            0 => self.setup.as_ref().map(|s| s.world.start),
            k => self.records.get(k - 1).map(|r| r.pose),
        }
    }

    fn shown_time(&self) -> f64 {
        self.cursor
            .checked_sub(1)
            .and_then(|k| self.records.get(k))
            .map_or(0.0, |r| r.t)
    }

    fn names(&self) -> Vec<String> {
        self.setup
            .as_ref()
            .map(|s| s.behaviours.iter().map(|b| b.name.clone()).collect())
            .unwrap_or_default()
    }
}

impl LabWidget for Arena {
    fn ui(&mut self, ui: &mut egui::Ui) {
        if self.playing && self.cursor == self.records.len() {
            for _ in 0..self.speed {
                if !self.step() {
                    self.playing = false;
                    break;
                }
            }
        }
        self.controls(ui);
        if let Some(problem) = &self.problem {
            crate::widget::error_box(ui, "This set-up cannot run", problem);
            self.task_ui(ui);
            return;
        }
        let wide = ui.available_width() >= 760.0;
        if wide {
            let canvas_width = ui.available_width() * 0.64;
            ui.horizontal_top(|ui| {
                self.canvas(ui, canvas_width);
                ui.vertical(|ui| self.diagram(ui));
            });
        } else {
            self.canvas(ui, ui.available_width());
            self.diagram(ui);
        }
        self.timeline(ui);
        self.task_ui(ui);
        if self.playing {
            crate::widget::animate(ui);
        }
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.design, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(design) = link::decode::<Design>(state)
            && design.setup().is_ok()
        {
            self.design = design;
            self.rebuild();
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn arena(params: &[(&str, &str)]) -> Arena {
        let p = kinolab_schema::validate(&spec("behaviour-arena", params)).unwrap();
        Arena::new(&p).unwrap()
    }

    #[test]
    fn every_set_runs_under_every_coordinator() {
        for set in ["goal-and-avoid", "explore", "light"] {
            for c in sets::COORDINATORS {
                let world = if set == "light" {
                    "lights"
                } else {
                    "scattered"
                };
                let mut a = arena(&[("world", world), ("set", set), ("coordinator", c)]);
                assert!(a.problem.is_none(), "{set}/{c}: {:?}", a.problem);
                for _ in 0..100 {
                    a.step();
                }
                assert!(!a.records.is_empty());
            }
        }
    }

    #[test]
    fn scrubbing_back_and_resuming_replays_the_same_run() {
        let mut a = arena(&[("coordinator", "voting")]);
        for _ in 0..200 {
            a.step();
        }
        let original = a.records.clone();
        a.cursor = 80;
        a.resume_from_cursor();
        assert_eq!(a.records.len(), 80);
        for _ in 0..120 {
            a.step();
        }
        assert_eq!(a.records, original);
    }
}
