//! The architecture arena: a hierarchical, a reactive and a hybrid robot
//! with the same body and sensors, each in its own copy of one world, on
//! one clock. Surprises can be scripted into the set-up or sprung while it
//! runs; one robot's beliefs (its map, its plan, the search in progress)
//! are drawn over what is really there; a scoreboard computed by the core
//! says how each is doing, next to the time its controller took here.

mod board;
mod canvas;

use kinolab_architectures::exercise::office;
use kinolab_architectures::surprise::OFFICE;
use kinolab_architectures::{Architecture, Arena, ArenaSetup, Surprise};
use kinolab_common::Feedback;
use kinolab_world::Pose;
use serde::{Deserialize, Serialize};

use crate::link;
use crate::widget::{LabWidget, Params};

/// The worlds the arena offers (each needs a start and a goal).
const WORLDS: [&str; 4] = ["office", "two-rooms", "u-trap", "crossing"];

/// Everything the learner can change, and what a link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Design {
    world: String,
    surprise: String,
    planning_cost_ms: f64,
    /// The pick-an-architecture task's choice per mission.
    picks: [u8; 3],
}

/// Where every robot was after one step.
#[derive(Debug, Clone, PartialEq)]
struct Frame {
    t: f64,
    poses: Vec<Pose>,
}

/// The graded tasks.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Task {
    SurviveThePerson,
    PickArchitecture,
}

struct ArchitectureArena {
    design: Design,
    initial: Design,
    task: Option<Task>,
    arena: Option<Arena>,
    problem: Option<String>,
    frames: Vec<Frame>,
    /// How many frames are shown (scrubbing moves it back).
    cursor: usize,
    playing: bool,
    speed: usize,
    /// Whose beliefs are drawn.
    focus: usize,
    /// Microseconds each robot's steps (sensing, controller, motion) took
    /// here, summed.
    spent: [f64; 3],
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let task = match p.choice("task") {
        Some("survive-the-person") => Some(Task::SurviveThePerson),
        Some("pick-architecture") => Some(Task::PickArchitecture),
        _ => None,
    };
    let surprise = match task {
        Some(Task::SurviveThePerson) => "person",
        _ => p.choice("surprise").unwrap_or("none"),
    };
    let design = Design {
        world: p.choice("world").unwrap_or("office").to_owned(),
        surprise: surprise.to_owned(),
        planning_cost_ms: p.number("planning_cost").unwrap_or(2.0),
        picks: [1, 1, 1],
    };
    let mut widget = ArchitectureArena {
        initial: design.clone(),
        design,
        task,
        arena: None,
        problem: None,
        frames: Vec::new(),
        cursor: 0,
        playing: false,
        speed: 4,
        focus: 0,
        spent: [0.0; 3],
        feedback: None,
    };
    widget.rebuild();
    Ok(Box::new(widget))
}

/// The surprise called `id` in `world`: the office has its own; elsewhere
/// only the kinds that need no place (noise, a wrong map of obstacle 0).
fn surprise(id: &str, world: &str) -> Option<Surprise> {
    let spec = match (world, id) {
        (_, "none") => return None,
        ("office", _) => OFFICE.iter().find(|(name, _)| *name == id)?.1,
        (_, "noise") => "noise:0.15",
        (_, "wrong-map") => "wrong-map:0",
        _ => return None,
    };
    Surprise::parse("surprise", spec).ok()
}

impl ArchitectureArena {
    fn setup(&self) -> Result<ArenaSetup, String> {
        let mut setup = if self.design.world == "office" {
            office(None).map_err(|e| e.to_string())?
        } else {
            let world =
                kinolab_world::catalogue::world(&self.design.world).map_err(|e| e.to_string())?;
            ArenaSetup::new(world)
        };
        setup
            .surprises
            .extend(surprise(&self.design.surprise, &self.design.world));
        setup.planning_cost = self.design.planning_cost_ms / 1e3;
        Ok(setup)
    }

    /// Start again from the design.
    fn rebuild(&mut self) {
        self.frames.clear();
        self.cursor = 0;
        self.spent = [0.0; 3];
        self.feedback = None;
        match self
            .setup()
            .and_then(|s| Arena::new(&s, &Architecture::ALL).map_err(|e| e.to_string()))
        {
            Ok(arena) => {
                self.frames.push(Frame {
                    t: 0.0,
                    poses: arena.entrants.iter().map(|e| e.sim.pose).collect(),
                });
                self.cursor = 1;
                self.arena = Some(arena);
                self.problem = None;
            }
            Err(e) => {
                self.arena = None;
                self.problem = Some(e);
            }
        }
    }

    /// One step of every robot, timed.
    fn step(&mut self) {
        let Some(arena) = self.arena.as_mut() else {
            return;
        };
        if arena.done() {
            self.playing = false;
            return;
        }
        for (i, spent) in self.spent.iter_mut().enumerate() {
            let start = web_time::Instant::now();
            arena.step_one(i);
            *spent += start.elapsed().as_secs_f64() * 1e6;
        }
        self.frames.push(Frame {
            t: arena.time(),
            poses: arena.entrants.iter().map(|e| e.sim.pose).collect(),
        });
        self.cursor = self.frames.len();
    }

    /// Spring a surprise on the running robots.
    fn spring(&mut self, id: &str) {
        if let (Some(arena), Some(s)) = (self.arena.as_mut(), surprise(id, &self.design.world)) {
            self.problem = arena.spring(&s).err().map(|e| e.to_string());
        }
    }
}

impl LabWidget for ArchitectureArena {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        if let Some(problem) = &self.problem {
            crate::widget::error_box(ui, "This set-up cannot run", problem);
        }
        self.canvas(ui);
        self.scrubber(ui);
        self.board(ui);
        if let Some(task) = self.task {
            self.task_ui(ui, task);
        }
        if self.playing {
            for _ in 0..self.speed {
                self.step();
            }
            crate::widget::animate(ui);
        }
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.design, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(d) = link::decode::<Design>(state)
            && WORLDS.contains(&d.world.as_str())
            && (0.0..=20.0).contains(&d.planning_cost_ms)
            && d.picks.iter().all(|p| *p < 3)
        {
            self.design = d;
            self.rebuild();
        }
        Ok(())
    }
}
