//! The controller playground: the polar go-to-pose controller on a
//! differential drive. Drag start and goal, set gains, see the path, the
//! robot, and ρ, α, β, v, ω over time, played by the one player; many
//! starts at once; open loop against closed loop under the same slip; the
//! stability region.
//!
//! - this file: the state, the constructor, the tabs and the link;
//! - [`settings`]: what the learner sets, the run files and the runs;
//! - [`playback`]: the runs on screen as the player plays them;
//! - [`floor`]: the floor with its draggable poses;
//! - [`tabs`]: one run, many starts, open against closed loop;
//! - [`gains`]: the gain sliders, the gain plane and the conditions;
//! - [`export`]: plots, and what the export bar offers;
//! - [`exercise`]: the graded tasks.

mod exercise;
mod export;
mod floor;
mod gains;
mod playback;
mod settings;
mod tabs;

use kinolab_common::Feedback;
use kinolab_control::exercise::Task;
use kinolab_control::{Plan, Trajectory};

use crate::draw::PlaneView;
use crate::link::{self, Moment};
use crate::player::Player;
use crate::widget::{LabWidget, Params, SavedRun};
use playback::Shown;
use settings::{Legacy, Settings, View};

/// The widget's name in the schema.
const NAME: &str = "controller-playground";

const TABS: [(View, &str); 4] = [
    (View::Run, "One run"),
    (View::Many, "Many starts"),
    (View::OpenVsClosed, "Open vs closed loop"),
    (View::Gains, "Gain region"),
];

/// The most samples the player runs on in one frame.
const MOST_PER_FRAME: usize = 100;

/// What the learner is asked to do, and how it went.
struct Exercise {
    task: Task,
    marks: Vec<bool>,
    feedback: Option<Feedback>,
}

/// The open-vs-closed comparison: the plan, then open and closed runs.
type Comparison = (Plan, Trajectory, Trajectory);

struct Playground {
    set: Settings,
    initial: Settings,
    /// The settings the runs below were computed for.
    computed: Option<Settings>,
    run: Option<Result<Trajectory, String>>,
    many: Option<Result<Vec<Trajectory>, String>>,
    compare: Option<Result<Comparison, String>>,
    /// The player of the runs on screen (one run, or open and closed).
    player: Option<Player<Shown>>,
    /// The instant and whether it plays, for the next player made.
    resume: Option<(f64, bool)>,
    /// The view kept while the learner drags on the floor, so it does not
    /// slide away under the pointer.
    frozen: Option<PlaneView>,
    exercise: Option<Exercise>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let set: Settings = p.settings()?;
    Ok(Box::new(Playground::new(set)?))
}

impl Playground {
    fn new(set: Settings) -> Result<Self, String> {
        let mut playground = Playground {
            exercise: exercise::from_settings(&set)?,
            initial: set.clone(),
            set,
            computed: None,
            run: None,
            many: None,
            compare: None,
            player: None,
            resume: None,
            frozen: None,
        };
        // The marks live in the exercise from here on.
        playground.set.marked = None;
        playground.refresh();
        Ok(playground)
    }

    /// What the runs depend on (not the tab, nor the marks).
    fn key(&self) -> Settings {
        Settings {
            view: View::Run,
            marked: None,
            ..self.set.clone()
        }
    }

    /// Recompute what the visible tab shows, once per change; a changed
    /// run keeps the instant shown.
    fn refresh(&mut self) {
        let key = self.key();
        if self.computed.as_ref() != Some(&key) {
            if let Some(p) = &self.player
                && self.resume.is_none()
            {
                self.resume = Some((p.time(), p.playing));
            }
            self.computed = Some(key);
            self.run = None;
            self.many = None;
            self.compare = None;
            self.player = None;
            if let Some(ex) = &mut self.exercise {
                ex.feedback = None;
            }
        }
        match self.set.view {
            View::Run if self.run.is_none() => self.run = Some(self.set.run()),
            View::Many if self.many.is_none() => self.many = Some(self.set.many()),
            View::OpenVsClosed if self.compare.is_none() => {
                self.compare = Some(self.set.compare());
            }
            _ => {}
        }
        if self.player.is_none() {
            self.make_player();
        }
    }

    /// A player for the runs the tab shows.
    fn make_player(&mut self) {
        let runs = match self.set.view {
            View::Run => self
                .run
                .as_ref()
                .and_then(|r| r.as_ref().ok())
                .map(|t| vec![t.clone()]),
            View::OpenVsClosed => self
                .compare
                .as_ref()
                .and_then(|c| c.as_ref().ok())
                .map(|(_, open, closed)| vec![open.clone(), closed.clone()]),
            View::Many | View::Gains => None,
        };
        if let Some(runs) = runs {
            let mut player = Player::new(Shown::new(runs));
            if let Some((t, playing)) = self.resume.take() {
                player.seek_time(t);
                player.playing = playing;
            }
            self.player = Some(player);
        }
    }

    /// Show `view`, its runs from the start, playing.
    fn show(&mut self, view: View) {
        if self.set.view != view {
            self.set.view = view;
            self.player = None;
            self.resume = Some((0.0, true));
        }
    }

    /// The runs again from the start, playing (after a drag).
    fn replay_from_start(&mut self) {
        self.resume = Some((0.0, true));
    }

    /// The instant shown, s.
    fn time(&self) -> f64 {
        self.player.as_ref().map_or(0.0, Player::time)
    }

    fn tab_bar(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            for (view, label) in TABS {
                if crate::widget::choice(ui, self.set.view == view, label).clicked() {
                    self.show(view);
                }
            }
        });
    }

    /// The settings as the learner has them, with the marks of the task.
    fn settings(&self) -> Settings {
        let mut s = self.set.clone();
        if let Some(ex) = &self.exercise
            && matches!(ex.task, Task::SpotUnstable { .. })
        {
            let marked: Vec<f64> = (1..=ex.marks.len())
                .zip(&ex.marks)
                .filter(|(_, m)| **m)
                .map(|(n, _)| n as f64)
                .collect();
            s.marked = (!marked.is_empty()).then_some(marked);
        }
        s
    }

    /// The run on screen as the command line reproduces it: its file's
    /// name, the file, and the samples shown (to the instant).
    fn shown_run(&self) -> Option<(&'static str, serde_json::Value, &Trajectory)> {
        match self.set.view {
            View::Run => {
                let t = self.run.as_ref()?.as_ref().ok()?;
                Some(("playground.run.json", self.set.run_file(), t))
            }
            View::OpenVsClosed => {
                let (_, open, _) = self.compare.as_ref()?.as_ref().ok()?;
                let (file, _) = self.set.open_file().ok()?;
                Some(("open-loop.run.json", file, open))
            }
            View::Many | View::Gains => None,
        }
    }
}

impl Playground {
    /// The gains and the tab shown; in one run, where the robot is at the
    /// instant shown; elsewhere, what the gains promise.
    fn description(&self) -> String {
        use kinolab_common::display::fixed;
        let [k_rho, k_alpha, k_beta] = self.set.gains;
        let tab = TABS
            .iter()
            .find(|(v, _)| *v == self.set.view)
            .map_or("", |(_, label)| label);
        let gains = format!(
            "Gains k_ρ = {}, k_α = {}, k_β = {} ({tab}).",
            fixed(k_rho, 2),
            fixed(k_alpha, 2),
            fixed(k_beta, 2)
        );
        let run = self.run.as_ref().and_then(|r| r.as_ref().ok());
        let now = run.and_then(|t| crate::control::field::at_time(&t.samples, self.time()));
        let more = match (self.set.view, now) {
            (View::Run, Some(s)) => {
                let goal = settings::pose(self.set.goal);
                let off = kinolab_common::angle::wrap(goal.theta - s.pose.theta);
                format!(
                    "At t = {} s the robot is {} m from the goal, its heading {}° off.",
                    fixed(s.t, 2),
                    fixed(s.polar.rho, 3),
                    fixed(off.to_degrees().abs(), 1)
                )
            }
            // The verdict's own sentence is on the page beside the gains.
            _ => match self.set.gains().map(|g| g.stability()) {
                Ok(s) if s.strongly_stable => "These gains are strongly stable.",
                Ok(s) if s.locally_stable => "These gains are locally but not strongly stable.",
                Ok(_) => "These gains are not stable.",
                Err(_) => "These gains cannot be used.",
            }
            .to_owned(),
        };
        format!("{gains} {more}")
    }
}

impl LabWidget for Playground {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.tab_bar(ui);
        self.gain_sliders(ui);
        self.stability_line(ui);
        self.effects(ui);
        let before = self.set.clone();
        self.refresh();
        match self.set.view {
            View::Run => self.run_tab(ui),
            View::Many => self.many_tab(ui),
            View::OpenVsClosed => self.compare_tab(ui),
            View::Gains => self.gains_tab(ui),
        }
        self.exercise_ui(ui);
        if self.set != before {
            crate::widget::animate(ui);
        }
    }

    fn state(&self) -> Option<String> {
        let moment = self.player.as_ref().map(Player::moment).unwrap_or_default();
        link::write(NAME, &self.settings(), &self.initial, &moment)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment) = match link::read::<Settings, ()>(NAME, state) {
            Ok(read) => read,
            Err(why) => match link::decode::<Legacy>(state).and_then(|l| l.settings(&self.initial))
            {
                Some(old) => (old, Moment::default()),
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
        let initial = self.initial.clone();
        // A task to reach the goal keeps the lesson's start and goal.
        let exercise = exercise::from_settings(&Settings {
            start: initial.start,
            goal: initial.goal,
            ..settings.clone()
        })?;
        *self = Playground::new(settings)?;
        (self.initial, self.exercise) = (initial, exercise);
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
        let k = self.player.as_ref()?.cursor();
        let (name, file, t) = self.shown_run()?;
        let spec = settings::spec(&file).ok()?;
        let report = kinolab_control::report::simulation(&spec, t);
        let shown = report
            .samples
            .get(..=k.min(report.samples.len().checked_sub(1)?))?;
        Some(SavedRun {
            file: name.into(),
            text: settings::pretty(&file).ok()?,
            args: vec!["simulate".into(), name.into()],
            shows: vec![(
                "/samples".into(),
                kinolab_common::display::tidy_report(&shown).ok()?,
            )],
        })
    }
}

#[cfg(test)]
mod tests;
