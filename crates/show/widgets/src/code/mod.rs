//! The code panel: the learner writes the function a graded exercise asks
//! for, runs it on the worlds they can see, steps through what it saw and
//! answered at any instant, and submits it to be graded on worlds held
//! back. Hints unlock one by one after failed submissions. The code and
//! the hints travel in the widget's link (the code packed), so a reload or
//! a shared link brings them back.

mod editor;
mod stepper;

use std::rc::Rc;

use egui::RichText;
use kinolab_exercises::trace::Tracing;
use kinolab_exercises::{Check, Exercise, World};
use kinolab_script::ScriptError;
use serde::{Deserialize, Serialize};

use crate::link::{self, Moment};
use crate::player::{FRAME_BUDGET, Player, Speed};
use crate::theme;
use crate::widget::{LabWidget, Params, SavedRun};
use stepper::Stepping;

/// The widget's name in the schema.
const NAME: &str = "code";
/// The learner's script as "Save run" writes it.
const FILE: &str = "mine.rhai";
/// Steps of a run recorded between looks at the clock.
const STEPS_PER_LOOK: usize = 16;

/// What the lesson sets and a link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    exercise: String,
    /// The learner's code, packed; `None` while it is the starter.
    code: Option<String>,
    /// The world the stepper shows, counting from 1.
    world: usize,
    /// Hints unlocked.
    hints: usize,
}

struct Code {
    settings: Settings,
    initial: Settings,
    exercise: Exercise,
    worlds: Vec<World>,
    source: String,
    /// The code's syntax error, checked as it is typed.
    syntax: Option<ScriptError>,
    /// The last Run (visible worlds) or Submit (all of them).
    results: Option<Check>,
    submitted: bool,
    player: Option<Player<Stepping>>,
    /// The stepper still to be made for the world chosen (see [`Pending`]).
    to_step: Option<Pending>,
}

/// A stepper on its way. Recording a world's run can take longer than a
/// frame (a minute of an arena is thousands of calls of the learner's
/// code), so the run is recorded a piece per frame from the first frame
/// drawn (a widget made and then given a link records nothing twice), and
/// the stepper opens at `moment` once it is recorded.
struct Pending {
    moment: Moment<()>,
    speed: Option<Speed>,
    tracing: Option<Tracing>,
}

impl Pending {
    fn at(moment: Moment<()>, speed: Option<Speed>) -> Self {
        Self {
            moment,
            speed,
            tracing: None,
        }
    }
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    Ok(Box::new(Code::new(p.settings()?)?))
}

impl Code {
    fn new(settings: Settings) -> Result<Self, String> {
        let exercise = kinolab_exercises::find(&settings.exercise)
            .ok_or_else(|| format!("no exercise `{}`", settings.exercise))?;
        let source = match &settings.code {
            Some(packed) => kinolab_exercises::packed::unpack(packed)?,
            None => exercise.starter.to_owned(),
        };
        let worlds = (exercise.worlds)();
        if settings.world > worlds.len() {
            return Err(format!(
                "the exercise has {} worlds, not {}",
                worlds.len(),
                settings.world
            ));
        }
        let mut code = Code {
            initial: settings.clone(),
            settings,
            exercise,
            worlds,
            source,
            syntax: None,
            results: None,
            submitted: false,
            player: None,
            to_step: Some(Pending::at(Moment::default(), None)),
        };
        code.edited();
        Ok(code)
    }

    /// After any edit: the code in the settings, its syntax checked.
    fn edited(&mut self) {
        self.settings.code = (self.source != self.exercise.starter)
            .then(|| kinolab_exercises::packed::pack(&self.source));
        self.syntax = kinolab_script::Script::compile(&self.source, self.exercise.signature).err();
    }

    /// Run on the worlds shown, and step through the chosen one.
    fn run(&mut self) {
        self.results = Some(self.exercise.check(&self.source, false));
        self.submitted = false;
        let world = self.settings.world - 1;
        let shown = if self.worlds[world].visible { world } else { 0 };
        self.step_through(shown);
    }

    /// Grade on every world; a failure unlocks the next hint.
    fn submit(&mut self) {
        let check = self.exercise.check(&self.source, true);
        if !check.passed {
            self.settings.hints = (self.settings.hints + 1).min(self.exercise.hints.len());
        }
        let failing = check.worlds.iter().position(|w| !w.passed);
        self.results = Some(check);
        self.submitted = true;
        if let Some(i) = failing {
            self.step_through(i);
        }
    }

    /// Back to the starter code.
    fn reset(&mut self) {
        self.source = self.exercise.starter.to_owned();
        self.results = None;
        self.edited();
        self.step_through(0);
    }

    /// Record more of the stepper's run, for at most `budget` of wall
    /// time; open the stepper once the run is recorded.
    fn record(&mut self, budget: std::time::Duration) {
        let Some(pending) = &mut self.to_step else {
            return;
        };
        let started = web_time::Instant::now();
        let world = &self.worlds[self.settings.world - 1];
        let tracing = pending
            .tracing
            .get_or_insert_with(|| self.exercise.tracing(&self.source, world));
        while !tracing.advance(STEPS_PER_LOOK) {
            if started.elapsed() > budget {
                return;
            }
        }
        let Some(Pending {
            moment,
            speed,
            tracing: Some(tracing),
        }) = self.to_step.take()
        else {
            return;
        };
        let mut player = Player::new(Stepping::new(Rc::new(tracing.finish())));
        if let Some(speed) = speed {
            player.speed = speed;
        }
        player.replay(&moment.events, moment.instant);
        self.player = Some(player);
    }

    /// Record world `i` with the current code and show it in the stepper
    /// (from the next frames on, see [`Pending`]).
    fn step_through(&mut self, i: usize) {
        if i >= self.worlds.len() {
            return;
        }
        self.settings.world = i + 1;
        let speed = self.player.take().map(|p| p.speed);
        self.to_step = Some(Pending::at(Moment::default(), speed));
    }

    /// The stepper while its run is still being recorded.
    fn recording_ui(&self, ui: &mut egui::Ui) {
        let Some(pending) = &self.to_step else {
            return;
        };
        let done = pending.tracing.as_ref().map_or(0.0, Tracing::progress);
        ui.horizontal(|ui| {
            ui.spinner();
            ui.label(format!("Recording the run: {:.0} %", done * 100.0));
            ui.add(egui::ProgressBar::new(done as f32).desired_width(240.0));
        });
        crate::widget::animate(ui);
    }

    fn header(&self, ui: &mut egui::Ui) {
        ui.label(
            RichText::new(self.exercise.title)
                .strong()
                .size(theme::BODY_SIZE),
        );
        crate::widget::message_ui(ui, self.exercise.task, ui.visuals().text_color());
        let signature = self.exercise.signature.text();
        let returns = self.exercise.hook.returns();
        ui.label(
            RichText::new(format!("You write {signature}, answering {returns}."))
                .size(theme::LABEL_SIZE)
                .weak(),
        );
    }

    fn buttons(&mut self, ui: &mut egui::Ui) {
        crate::widget::control_row(ui, |ui| {
            let runnable = self.syntax.is_none();
            if ui
                .add_enabled(runnable, egui::Button::new("Run"))
                .on_hover_text("Run your code on the worlds shown, and step through it")
                .clicked()
            {
                self.run();
            }
            if ui
                .add_enabled(runnable, egui::Button::new("Submit"))
                .on_hover_text("Grade your code on every world, those held back too")
                .clicked()
            {
                self.submit();
            }
            if ui
                .button("Reset")
                .on_hover_text("Start again from the starter code")
                .clicked()
            {
                self.reset();
            }
        });
    }

    /// Each world's verdict, with a button to step through it.
    fn results(&mut self, ui: &mut egui::Ui) {
        let Some(check) = &self.results else {
            let visible = self.worlds.iter().filter(|w| w.visible).count();
            let held = self.worlds.len() - visible;
            ui.label(format!(
                "Run tries your code on the {visible} worlds shown; Submit also on {held} held back."
            ));
            return;
        };
        let (good, bad) = (theme::good_color(ui), theme::error_color(ui));
        let verdict = match (check.passed, self.submitted) {
            (true, true) => ("Passed on every world, those held back too.", good),
            (true, false) => ("Passed on the worlds shown: now Submit.", good),
            (false, _) => ("Not yet:", bad),
        };
        ui.label(RichText::new(verdict.0).color(verdict.1).strong());
        let mut open = None;
        for w in &check.worlds {
            ui.horizontal_wrapped(|ui| {
                let (mark, color) = if w.passed {
                    ("passed", good)
                } else {
                    ("failed", bad)
                };
                ui.label(RichText::new(mark).color(color));
                let held = if w.visible { "" } else { " (held back)" };
                ui.label(format!("{}{held}", w.name));
                if let Some(reason) = &w.reason {
                    ui.label(RichText::new(reason).color(bad));
                }
                if ui.small_button("Step through").clicked() {
                    open = self.worlds.iter().position(|x| x.name == w.name);
                }
            });
        }
        if let Some(i) = open {
            self.step_through(i);
        }
    }

    fn hints(&self, ui: &mut egui::Ui) {
        let shown = self.settings.hints.min(self.exercise.hints.len());
        if shown == 0 {
            return;
        }
        ui.label(RichText::new("Hints").strong());
        for hint in &self.exercise.hints[..shown] {
            let text = format!("· {hint}");
            crate::widget::message_ui(ui, &text, ui.visuals().text_color());
        }
    }

    /// "Save run": the code, for `kinolab script check`.
    fn exports(&self, ui: &mut egui::Ui) {
        let command = format!(
            "kinolab script check {FILE} --exercise {}",
            self.exercise.id
        );
        let make = || Ok(self.source.clone());
        crate::export::bar(
            ui,
            ui.scope_id().with("code-exports"),
            &[crate::export::Export::Run {
                file: FILE,
                command: &command,
                make: &make,
            }],
        );
    }
}

impl Code {
    /// The exercise, whether the code compiles and ran and how that went,
    /// and the call shown in the world stepped through.
    fn description(&self) -> String {
        let title = self.exercise.title;
        let verdict = match (&self.syntax, &self.results) {
            (Some(e), _) => format!("Your code does not compile: {}.", editor::error_line(e)),
            (None, None) => "Your code has not been run yet.".to_owned(),
            (None, Some(check)) => check_text(check, self.submitted),
        };
        let world = self
            .settings
            .world
            .checked_sub(1)
            .and_then(|i| self.worlds.get(i))
            .map_or("", |w| w.name.as_str());
        let call = self.player.as_ref().and_then(|p| {
            let shown = p.peek();
            let k = shown.tick()?;
            Some(format!(
                " At {} s your function answered {}.",
                kinolab_common::display::fixed(p.time(), 2),
                k.returned
            ))
        });
        format!(
            "{title}. {verdict} Stepping through world “{world}”.{}",
            call.unwrap_or_default()
        )
    }
}

/// How a check went: passed, or the first world that failed and why.
fn check_text(check: &Check, submitted: bool) -> String {
    if check.passed {
        return if submitted {
            "Passed on every world, those held back too.".to_owned()
        } else {
            "Passed on the worlds shown.".to_owned()
        };
    }
    if let Some(e) = &check.error {
        return format!("It stopped with an error: {}.", editor::error_line(e));
    }
    match check.worlds.iter().find(|w| !w.passed) {
        Some(w) => format!(
            "Not yet: it failed on {}{}.",
            w.name,
            w.reason
                .as_deref()
                .map_or(String::new(), |r| format!(" ({r})"))
        ),
        None => "Not yet.".to_owned(),
    }
}

impl LabWidget for Code {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.record(FRAME_BUDGET);
        self.header(ui);
        ui.add_space(4.0);
        if editor::editor(ui, &mut self.source, self.syntax.as_ref()) {
            self.edited();
        }
        self.buttons(ui);
        self.results(ui);
        self.hints(ui);
        ui.separator();
        let name = self.worlds[self.settings.world - 1].name.clone();
        ui.label(RichText::new(format!("Stepping through: {name}")).strong());
        if let Some(player) = &mut self.player {
            stepper::show(ui, player);
        }
        self.recording_ui(ui);
        self.exports(ui);
    }

    fn state(&self) -> Option<String> {
        let moment = match (&self.player, &self.to_step) {
            (_, Some(pending)) => pending.moment.clone(),
            (Some(player), None) => player.moment(),
            (None, None) => Moment::default(),
        };
        link::write(NAME, &self.settings, &self.initial, &moment)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment): (Settings, Moment<()>) = link::read(NAME, state)?;
        let mut restored = Code::new(settings)?;
        restored.initial = self.initial.clone();
        restored.to_step = Some(Pending::at(moment, None));
        *self = restored;
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        self.record(std::time::Duration::MAX);
        if let Some(p) = &mut self.player {
            p.seek_time(t);
        }
    }

    fn saved_run(&mut self) -> Option<SavedRun> {
        let check = self.exercise.check(&self.source, true);
        let worlds = kinolab_common::display::tidy_report(&check.worlds).ok()?;
        let shows = vec![
            ("/passed".to_owned(), serde_json::Value::Bool(check.passed)),
            ("/worlds".to_owned(), worlds),
        ];
        Some(SavedRun {
            file: FILE.into(),
            text: self.source.clone(),
            args: vec![
                "script".into(),
                "check".into(),
                FILE.into(),
                "--exercise".into(),
                self.exercise.id.into(),
            ],
            shows,
        })
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn a_long_run_is_recorded_over_frames_and_opens_at_the_links_instant() {
        let mut code = Code::new(Settings {
            exercise: "sequencer-replan".into(),
            code: None,
            world: 2,
            hints: 0,
        })
        .unwrap();
        let moment = Moment {
            instant: 12.0,
            events: Vec::new(),
        };
        code.to_step = Some(Pending::at(moment.clone(), Some(Speed::Four)));
        let mut frames = 0;
        let mut progress = 0.0;
        while code.player.is_none() {
            // The least a frame does: a few steps of the run.
            code.record(std::time::Duration::ZERO);
            frames += 1;
            assert!(frames < 100_000, "the recording never ends");
            if let Some(Pending {
                tracing: Some(t), ..
            }) = &code.to_step
            {
                assert!(t.progress() >= progress);
                progress = t.progress();
            }
            assert!(
                code.state().is_some(),
                "the link keeps its instant meanwhile"
            );
        }
        assert!(frames > 20, "a minute of an arena took {frames} frames");
        let at_once = code.exercise.trace(&code.source, &code.worlds[1]);
        let player = code.player.as_mut().unwrap();
        assert_eq!(player.speed, Speed::Four);
        assert!((player.time() - 12.0).abs() < 0.1, "{}", player.time());
        assert_eq!(player.state().trace().ticks, at_once.ticks);
    }
}
