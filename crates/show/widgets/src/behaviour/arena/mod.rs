//! The behaviour arena: a robot with its behaviours and a coordinator in a
//! world. Every behaviour's output is an arrow, the coordinated command a
//! thicker one; the coordinator's own picture (layers and nodes, votes,
//! states) lights up as it decides; the player's timeline shows who had
//! control and the bumps, and the run can be played, paused, stepped and
//! scrubbed. Runs are deterministic, so what is shown at any instant is
//! the state the run had there, and "Save run" writes the run file
//! `kinolab run` reproduces it from.

mod canvas;
mod diagram;
mod sets;
mod task;
mod timeline;

use kinolab_behaviours::coordinate::Trace;
use kinolab_behaviours::coordinate::subsumption::NodeKind;
use kinolab_behaviours::run::{Runner, Setup};
use kinolab_world::sensors::RayReading;
use kinolab_world::{Command, Pose, Vec2, World};
use serde::{Deserialize, Serialize};

use crate::behaviour::world_view::colors;
use crate::link::{self, Moment};
use crate::player::{Player, Simulation};
use crate::widget::{LabWidget, Params, SavedRun};
use sets::{CoordinatorKind, Set};
use task::LayerDesign;

/// The widget's name in the schema.
const NAME: &str = "behaviour-arena";

/// What the lesson sets and a link carries: the schema's parameters,
/// among them the obstacles and goal the learner dragged and the layer
/// exercise's design.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    world: String,
    set: Set,
    coordinator: CoordinatorKind,
    /// What the top layer's node does in the subsumption stack.
    #[serde(rename = "top-node")]
    top_node: NodeKind,
    seed: u64,
    task: Option<Task>,
    /// Obstacles moved: number, x, y.
    moved: Vec<[f64; 3]>,
    goal: Option<[f64; 2]>,
    layers: Option<String>,
    node: Option<String>,
    hold: f64,
    #[serde(rename = "task-world")]
    task_world: usize,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Task {
    Layers,
}

/// The links of the first format: the design as the arena kept it.
#[derive(Deserialize)]
struct Legacy {
    world: String,
    set: String,
    coordinator: String,
    seed: u64,
    moved: Vec<(u32, [f64; 2])>,
    goal: Option<[f64; 2]>,
    layers: Option<task::LegacyLayers>,
}

impl Legacy {
    /// The old design as settings (not yet checked against the schema).
    fn settings(self, initial: &Settings) -> Result<Settings, String> {
        let word = |text: String| serde_json::Value::String(text);
        let mut s = Settings {
            world: self.world,
            set: serde_json::from_value(word(self.set)).map_err(|e| e.to_string())?,
            coordinator: serde_json::from_value(word(self.coordinator))
                .map_err(|e| e.to_string())?,
            seed: self.seed,
            moved: self
                .moved
                .iter()
                .map(|(i, at)| [f64::from(*i), at[0], at[1]])
                .collect(),
            goal: self.goal,
            ..initial.clone()
        };
        if let Some(layers) = self.layers {
            layers.design().write(&mut s);
        }
        Ok(s)
    }
}

/// The longest run the arena records, s.
const DURATION: f64 = 60.0;

impl Settings {
    /// The layer exercise's design, when there is the exercise.
    fn layer_design(&self) -> Result<Option<LayerDesign>, String> {
        match self.task {
            Some(Task::Layers) => LayerDesign::read(self).map(Some),
            None => Ok(None),
        }
    }

    /// The world with the learner's moves.
    fn world(&self) -> Result<World, String> {
        let mut world = match self.layer_design()? {
            Some(l) => kinolab_world::catalogue::scattered(l.world_seed(), 6),
            None => kinolab_world::catalogue::world(&self.world).map_err(|e| e.to_string())?,
        };
        for [i, x, y] in &self.moved {
            let o = world
                .obstacles
                .get_mut(*i as usize)
                .filter(|o| o.is_static() && o.appear_at <= 0.0)
                .ok_or_else(|| format!("this world has no obstacle {i} to move"))?;
            let moved = o.shape.moved(Vec2::new(*x, *y) - o.shape.anchor());
            *o = kinolab_world::Obstacle::new(moved);
        }
        if let Some(g) = self.goal {
            world.goal = Some(Vec2::new(g[0], g[1]));
        }
        Ok(world)
    }

    /// The run these settings make, exactly as its run file reads.
    fn setup(&self) -> Result<Setup, String> {
        let world = self.world()?;
        let (behaviours, coordinator) = match self.layer_design()? {
            Some(l) => (
                kinolab_behaviours::exercise::layer_behaviours(),
                l.coordinator(),
            ),
            None => (
                sets::behaviours(self.set),
                sets::coordinator(self.set, self.coordinator, self.top_node),
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

/// What the last step showed beyond the pose: the rays, each behaviour's
/// output as a robot-frame vector (`None`: released), the command and the
/// coordinator's trace.
#[derive(Debug, Clone, PartialEq)]
struct Shown {
    rays: Vec<RayReading>,
    vectors: Vec<Option<Vec2>>,
    command: Command,
    in_control: Option<usize>,
    trace: Trace,
}

/// One step as the player keeps it: small, for the timeline, the trail
/// and the samples `kinolab run` prints.
#[derive(Debug, Clone, PartialEq)]
struct Tick {
    pose: Pose,
    v: f64,
    omega: f64,
    in_control: Option<usize>,
    events: Vec<kinolab_world::Event>,
}

impl Tick {
    fn bump(&self) -> bool {
        self.events
            .iter()
            .any(|e| matches!(e.kind, kinolab_world::EventKind::Bump { .. }))
    }

    fn goal(&self) -> bool {
        self.events
            .iter()
            .any(|e| e.kind == kinolab_world::EventKind::GoalReached)
    }
}

/// The run in progress and what its last step showed.
#[derive(Debug, Clone)]
struct Run {
    runner: Runner,
    last: Option<Shown>,
}

impl Simulation for Run {
    type Tick = Tick;
    type Event = ();

    fn step(&mut self) -> Option<Tick> {
        if self.runner.done() {
            return None;
        }
        let frame = self.runner.step();
        let vectors = frame
            .responses
            .iter()
            .map(|r| r.as_ref().map(|r| self.runner.drive.as_vector(r)))
            .collect();
        self.last = Some(Shown {
            rays: frame.percepts.rays,
            vectors,
            command: frame.driven,
            in_control: frame.decision.in_control,
            trace: frame.decision.trace,
        });
        Some(Tick {
            pose: frame.pose,
            v: frame.driven.vx,
            omega: frame.driven.omega,
            in_control: frame.decision.in_control,
            events: frame.events,
        })
    }

    fn time(&self) -> f64 {
        self.runner.sim.time
    }

    fn dt(&self) -> f64 {
        self.runner.sim.dt
    }

    fn spring(&mut self, (): &()) {}
}

struct Arena {
    settings: Settings,
    initial: Settings,
    setup: Option<Setup>,
    problem: Option<String>,
    player: Option<Player<Run>>,
    task: Option<task::TaskUi>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    Ok(Box::new(Arena::new(p.settings()?)?))
}

impl Arena {
    fn new(settings: Settings) -> Result<Self, String> {
        kinolab_world::catalogue::world(&settings.world).map_err(|e| e.to_string())?;
        let task = settings.task.map(|_| task::TaskUi::new());
        let mut arena = Arena {
            initial: settings.clone(),
            settings,
            setup: None,
            problem: None,
            player: None,
            task,
        };
        arena.rebuild();
        Ok(arena)
    }

    /// Start the run afresh from the settings, paused (or playing on, as
    /// it was).
    fn rebuild(&mut self) {
        let playing = self.player.as_ref().is_some_and(|p| p.playing);
        let speed = self.player.as_ref().map(|p| p.speed);
        match self
            .settings
            .setup()
            .and_then(|s| Runner::new(&s).map(|r| (s, r)).map_err(|e| e.to_string()))
        {
            Ok((setup, runner)) => {
                let mut player = Player::new(Run { runner, last: None });
                player.playing = playing;
                if let Some(speed) = speed {
                    player.speed = speed;
                }
                self.setup = Some(setup);
                self.player = Some(player);
                self.problem = None;
            }
            Err(e) => {
                self.setup = None;
                self.player = None;
                self.problem = Some(e);
            }
        }
    }

    /// Take `settings` and start again, playing; when they cannot run,
    /// keep what was there.
    fn change(&mut self, settings: Settings) {
        let before = std::mem::replace(&mut self.settings, settings);
        self.rebuild();
        if self.problem.is_some() {
            self.settings = before;
            self.rebuild();
        }
        self.play();
    }

    fn play(&mut self) {
        if let Some(player) = &mut self.player {
            player.playing = true;
        }
    }

    /// The run at the instant shown.
    fn shown(&mut self) -> Option<&Run> {
        Some(self.player.as_mut()?.state())
    }

    /// Each behaviour's colour (see [`colors`]).
    fn colors(&self) -> Vec<egui::Color32> {
        self.setup
            .as_ref()
            .map(|s| colors(&s.behaviours))
            .unwrap_or_default()
    }

    /// Who drives at the instant shown, and how the run has gone so far.
    fn description(&self) -> Option<String> {
        let player = self.player.as_ref()?;
        let shown = player.ticks_shown();
        let names = self.names();
        let driver = shown
            .last()
            .and_then(|t| t.in_control)
            .and_then(|i| names.get(i))
            .map_or("no behaviour".to_owned(), Clone::clone);
        let touches = shown.iter().filter(|t| t.bump()).count();
        let goal = shown.iter().any(Tick::goal);
        Some(format!(
            "{} coordination, {} s into the run: {driver} has control; {touches} touch{} so far{}.",
            self.settings.coordinator.name(),
            kinolab_common::display::fixed(player.time(), 1),
            if touches == 1 { "" } else { "es" },
            if goal { ", goal reached" } else { "" }
        ))
    }

    fn names(&self) -> Vec<String> {
        self.setup
            .as_ref()
            .map(|s| s.behaviours.iter().map(|b| b.name.clone()).collect())
            .unwrap_or_default()
    }
}

impl LabWidget for Arena {
    fn describe(&self) -> Option<String> {
        self.description()
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        if let Some(problem) = &self.problem {
            crate::widget::error_box(ui, "This set-up cannot run", problem);
            self.task_ui(ui);
            return;
        }
        let wide = ui.available_width() >= 760.0;
        let view = if wide {
            let canvas_width = ui.available_width() * 0.64;
            ui.horizontal_top(|ui| {
                let view = self.canvas(ui, canvas_width);
                ui.vertical(|ui| self.diagram(ui));
                view
            })
            .inner
        } else {
            let view = self.canvas(ui, ui.available_width());
            self.diagram(ui);
            view
        };
        self.timeline(ui);
        self.exports(ui, view);
        self.task_ui(ui);
    }

    fn state(&self) -> Option<String> {
        let moment = self.player.as_ref().map(Player::moment).unwrap_or_default();
        link::write(NAME, &self.settings, &self.initial, &moment)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment) = match link::read::<Settings, ()>(NAME, state) {
            Ok(read) => read,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => (old.settings(&self.initial)?, Moment::default()),
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
        settings.setup()?;
        self.settings = settings;
        self.rebuild();
        if let Some(player) = &mut self.player {
            player.replay(&moment.events, moment.instant);
        }
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        if let Some(player) = &mut self.player {
            player.seek_time(t);
        }
    }

    fn saved_run(&mut self) -> Option<SavedRun> {
        let setup = self.setup.as_ref()?;
        let player = self.player.as_ref()?;
        Some(SavedRun {
            file: "arena.run.json".into(),
            text: setup.to_json(),
            args: vec!["run".into(), "arena.run.json".into()],
            shows: timeline::shows(setup, player)?,
        })
    }
}

#[cfg(test)]
mod tests;
