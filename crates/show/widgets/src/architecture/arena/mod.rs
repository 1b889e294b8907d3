//! The architecture arena: a hierarchical, a reactive and a hybrid robot
//! with the same body and sensors, each in its own copy of one world, on
//! one clock, which the player plays, steps and scrubs both ways.
//! Surprises can be scripted into the set-up or sprung while it runs (in
//! any world: the core places them from its geometry); one robot's
//! beliefs (its map, its plan, the search in progress) are drawn over what
//! is really there; a scoreboard computed by the core says how each is
//! doing, next to the time its controller took here.

mod board;
mod canvas;
mod race;
mod settings;

use kinolab_architectures::run::Sample;
use kinolab_architectures::{Architecture, Arena, ArenaSetup};
use kinolab_common::Feedback;

use self::race::{Race, Spring, sample};
use self::settings::{Legacy, Settings, WorldId};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::player::{Player, Speed};
use crate::widget::{LabWidget, Params, SavedRun};

/// The widget's name in the schema.
const NAME: &str = "architecture-arena";

struct ArchitectureArena {
    settings: Settings,
    initial: Settings,
    /// The set-up the settings make, and the player that runs it.
    setup: Option<ArenaSetup>,
    player: Option<Player<Race>>,
    /// Every robot's sample at the start (the ticks hold the rest).
    first: Vec<Sample>,
    /// Why the set-up cannot run.
    problem: Option<String>,
    /// Why a surprise could not be sprung.
    notice: Option<String>,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    Ok(Box::new(ArchitectureArena::new(p.settings()?)))
}

impl ArchitectureArena {
    fn new(settings: Settings) -> Self {
        let mut widget = ArchitectureArena {
            initial: settings.clone(),
            settings,
            setup: None,
            player: None,
            first: Vec::new(),
            problem: None,
            notice: None,
            feedback: None,
        };
        widget.rebuild();
        widget
    }

    /// Start again from the settings, paused at the start.
    fn rebuild(&mut self) {
        self.feedback = None;
        self.notice = None;
        let made = self.settings.setup().and_then(|setup| {
            let arena = Arena::new(&setup, &Architecture::ALL).map_err(|e| e.to_string())?;
            Ok((setup, arena))
        });
        match made {
            Ok((setup, arena)) => {
                self.first = arena.entrants.iter().map(sample).collect();
                let office = self.settings.world == WorldId::Office;
                let mut player = Player::new(Race::new(arena, office, setup.dt));
                player.speed = Speed::Four;
                self.player = Some(player);
                self.setup = Some(setup);
                self.problem = None;
            }
            Err(e) => {
                self.player = None;
                self.setup = None;
                self.first.clear();
                self.problem = Some(e);
            }
        }
    }

    /// Spring `kind` at the instant shown, or say why it has no place.
    fn spring(&mut self, kind: Spring) {
        let Some(player) = &mut self.player else {
            return;
        };
        match player.state().place(kind) {
            Ok(_) => {
                player.spring(kind);
                self.notice = None;
            }
            Err(e) => self.notice = Some(format!("{}: {e}.", kind.label())),
        }
    }

    /// `kinolab arena`'s arguments for the robot in focus, with every
    /// surprise in the run up to the instant shown.
    fn run_args(&mut self) -> Option<Vec<String>> {
        let file = self.file_name();
        let setup = self.setup.as_ref()?;
        let race = self.player.as_mut()?.state();
        let mut args = vec![
            "arena".to_owned(),
            file,
            "--architecture".to_owned(),
            self.settings.focus.name().to_owned(),
        ];
        for s in setup.surprises.iter().chain(&race.sprung) {
            args.push("--perturb".to_owned());
            args.push(s.spec());
        }
        args.extend([
            "--planning-cost".to_owned(),
            self.settings.planning_cost.to_string(),
            "--duration".to_owned(),
            setup.duration.to_string(),
        ]);
        Some(args)
    }

    fn file_name(&self) -> String {
        format!("{}.world.json", self.settings.world.id())
    }

    /// The robot in focus's samples from the start to the instant shown,
    /// as `kinolab arena` prints them.
    fn samples(&self) -> Vec<Sample> {
        let focus = self.settings.focus_index();
        let Some(player) = &self.player else {
            return Vec::new();
        };
        let ticks = player.ticks_shown().iter().filter_map(|f| {
            f.robots
                .get(focus)
                .filter(|(_, moved)| *moved)
                .map(|(s, _)| s.clone())
        });
        self.first
            .get(focus)
            .cloned()
            .into_iter()
            .chain(ticks)
            .collect()
    }

    fn exports(&mut self, ui: &mut egui::Ui, view: Option<egui::Rect>) {
        let command = self
            .run_args()
            .map_or_else(String::new, |a| format!("kinolab {}", a.join(" ")));
        let file = self.file_name();
        let world = || {
            self.setup
                .as_ref()
                .map(|s| s.world.to_json())
                .ok_or_else(|| "this set-up cannot run".to_owned())
        };
        let mut offers = Vec::new();
        if let Some(rect) = view {
            offers.push(Export::Png {
                file: "kinolab-architecture-arena.png",
                rect,
            });
        }
        offers.push(Export::Run {
            file: &file,
            command: &command,
            make: &world,
        });
        export::bar(ui, ui.scope_id().with("arena-exports"), &offers);
    }
}

impl ArchitectureArena {
    /// The instant shown: where each robot is (or when it reached the
    /// goal) and the surprises so far.
    fn description(&self) -> String {
        let Some(player) = &self.player else {
            let why = self.problem.as_deref().unwrap_or_default();
            return format!("This set-up cannot run: {why}");
        };
        let race = player.peek();
        let robots: Vec<String> = race
            .arena
            .entrants
            .iter()
            .zip(canvas::NAMES)
            .map(|(e, name)| robot_words(e, name))
            .collect();
        let sprung = race.sprung.len();
        format!(
            "The {} world, {} s into the run ({} robot in focus): {}. Scripted surprise: {}; {sprung} sprung while it ran.",
            self.settings.world.id(),
            kinolab_common::display::fixed(player.time(), 1),
            self.settings.focus.name(),
            robots.join("; "),
            self.settings.scripted().id(),
        )
    }
}

/// One robot at the instant shown, in words.
fn robot_words(e: &kinolab_architectures::arena::Entrant, name: &str) -> String {
    use kinolab_common::display::fixed;
    let s = &e.scores;
    let bumps = match s.collisions {
        0 => String::new(),
        1 => ", 1 collision".to_owned(),
        n => format!(", {n} collisions"),
    };
    if let Some(t) = s.time {
        return format!("{name} reached the goal at {} s{bumps}", fixed(t, 1));
    }
    let p = e.sim.pose;
    let goal = e.sim.world.goal.map_or(String::new(), |g| {
        format!(
            ", {} m from the goal",
            fixed((g.x - p.x).hypot(g.y - p.y), 1)
        )
    });
    format!("{name} is {}{goal}{bumps}", e.activity)
}

impl LabWidget for ArchitectureArena {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        if let Some(problem) = &self.problem {
            crate::widget::error_box(ui, "This set-up cannot run", problem);
        }
        if let Some(player) = &mut self.player {
            player.controls(ui);
        }
        self.springs(ui);
        let view = self.canvas(ui);
        self.timeline(ui);
        self.board(ui);
        self.exports(ui, view);
        if let Some(task) = self.settings.task {
            self.task_ui(ui, task);
        }
    }

    fn state(&self) -> Option<String> {
        let moment = self.player.as_ref().map(Player::moment).unwrap_or_default();
        link::write(NAME, &self.settings, &self.initial, &moment)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if link::is_bare(state) {
            return Err("it is empty (cut short)".into());
        }
        let (settings, moment) = match link::read::<Settings, Spring>(NAME, state) {
            Ok(read) => read,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => (old.settings(&self.initial)?, Moment::default()),
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
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
        let args = self.run_args()?;
        let text = self.setup.as_ref()?.world.to_json();
        let samples = kinolab_common::display::tidy_report(&self.samples()).ok()?;
        Some(SavedRun {
            file: self.file_name(),
            text,
            args,
            shows: vec![("/samples".into(), samples)],
        })
    }
}

#[cfg(test)]
mod tests;
