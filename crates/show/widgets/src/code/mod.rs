//! The code panel: the learner writes the function a graded exercise asks
//! for, runs it on the worlds they can see, steps through what it saw and
//! answered at any instant, and submits it to be graded on worlds held
//! back (of which they learn only how many passed). Hints unlock one by
//! one after failed submissions. The code and the hints travel in the
//! widget's link (the code packed), so a reload or a shared link brings
//! them back, but the code never runs until the learner presses Run: a
//! link cannot make a reader's page run anything.
//!
//! The code runs off the page's thread (see [`runner`]): while it runs the
//! panel stays responsive and the learner may stop it; a run that ends the
//! runner is reported, and remembered with the code.

mod editor;
pub mod runner;
mod stepper;

use std::rc::Rc;

use egui::RichText;
use kinolab_exercises::job::{Job, Task};
use kinolab_exercises::{Check, Exercise, World};
use kinolab_script::ScriptError;
use serde::{Deserialize, Serialize};

use crate::link::{self, Moment};
use crate::player::{Player, Speed};
use crate::theme;
use crate::widget::{LabWidget, Params, SavedRun};
use runner::{Ran, Runner};
use stepper::Stepping;

/// The widget's name in the schema.
const NAME: &str = "code";
/// The learner's script as "Save run" writes it.
const FILE: &str = "mine.rhai";

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
    /// Why the last run ended what ran it, if it did: kept with the code,
    /// so the lesson reopens with a notice rather than a surprise.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    ended: Option<String>,
}

struct Code {
    settings: Settings,
    initial: Settings,
    exercise: Exercise,
    worlds: Vec<World>,
    source: String,
    /// The code's syntax error, checked as it is typed.
    syntax: Option<ScriptError>,
    /// The last Run (visible worlds) or Submit (all of them, the held-back
    /// ones only counted).
    results: Option<Check>,
    submitted: bool,
    player: Option<Player<Stepping>>,
    /// Where the stepper should open once a run is recorded (a link's
    /// instant, or the one the learner was at).
    moment: Moment<()>,
    speed: Option<Speed>,
    runner: Box<dyn Runner>,
    /// The job under way, if any.
    busy: Option<Task>,
    /// A job that was refused, or stopped.
    problem: Option<String>,
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
        let shown = settings.world.checked_sub(1).and_then(|i| worlds.get(i));
        if !shown.is_some_and(|w| w.visible) {
            return Err(format!(
                "world {} is not one of the exercise's {} visible worlds",
                settings.world,
                worlds.iter().filter(|w| w.visible).count()
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
            moment: Moment::default(),
            speed: None,
            runner: runner::runner(),
            busy: None,
            problem: None,
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

    /// Hand `task` to the runner; the answer arrives in a later frame.
    fn start(&mut self, task: Task) {
        if let Some(player) = self.player.take() {
            self.speed = Some(player.speed);
        }
        self.problem = None;
        self.runner.start(Job {
            exercise: self.exercise.id.into(),
            source: self.source.clone(),
            task,
        });
        self.busy = Some(task);
    }

    /// Run on the worlds shown, and step through the chosen one.
    fn run(&mut self) {
        self.submitted = false;
        self.start(Task::Run {
            world: self.settings.world - 1,
        });
    }

    /// Grade on every world.
    fn submit(&mut self) {
        self.submitted = true;
        self.start(Task::Submit {
            world: self.settings.world - 1,
        });
    }

    /// Record visible world `i` and show it in the stepper.
    fn step_through(&mut self, i: usize) {
        if self.worlds.get(i).is_some_and(|w| w.visible) {
            self.settings.world = i + 1;
            self.moment = Moment::default();
            self.start(Task::Trace { world: i });
        }
    }

    /// Back to the starter code.
    fn reset(&mut self) {
        self.stop();
        self.source = self.exercise.starter.to_owned();
        self.results = None;
        self.player = None;
        self.settings.ended = None;
        self.edited();
    }

    /// Stop the job under way.
    fn stop(&mut self) {
        if self.busy.take().is_some() {
            self.runner.stop();
            self.problem = Some("Stopped. Your code is as you left it.".into());
        }
    }

    /// Take the runner's answer, if it has one.
    fn collect(&mut self) {
        let Some(task) = self.busy else { return };
        let Some(ran) = self.runner.poll() else {
            return;
        };
        self.busy = None;
        match ran {
            Ran::Answered(answer) => {
                self.settings.ended = None;
                if let Some(check) = answer.check {
                    if matches!(task, Task::Submit { .. }) && !check.passed {
                        let more = self.settings.hints + 1;
                        self.settings.hints = more.min(self.exercise.hints.len());
                    }
                    self.results = Some(check);
                }
                if let Some((world, trace)) = answer.trace {
                    self.settings.world = world + 1;
                    self.open(trace);
                }
            }
            Ran::Refused(why) => self.problem = Some(format!("The run was refused: {why}.")),
            Ran::Crashed(why) => {
                self.problem = Some(format!(
                    "Your code stopped what runs it: {why}. The page is fine and your code is kept; the next Run starts afresh."
                ));
                self.settings.ended = Some(note(&why));
            }
        }
    }

    /// Open the stepper on `trace`, at the moment kept for it.
    fn open(&mut self, trace: kinolab_exercises::trace::Trace) {
        let mut player = Player::new(Stepping::new(Rc::new(trace)));
        if let Some(speed) = self.speed {
            player.speed = speed;
        }
        let moment = std::mem::take(&mut self.moment);
        player.replay(&moment.events, moment.instant);
        self.player = Some(player);
    }

    /// While a job runs: what it is, a spinner, and the way to stop it.
    fn busy_ui(&mut self, ui: &mut egui::Ui) {
        let Some(task) = self.busy else { return };
        let doing = match task {
            Task::Run { .. } => "Running your code on the worlds shown…",
            Task::Submit { .. } => "Grading your code on every world…",
            Task::Trace { .. } => "Recording the run…",
        };
        ui.horizontal(|ui| {
            ui.spinner();
            ui.label(doing);
        });
        // Look for the answer again soon; nothing moves once it is in.
        ui.ctx()
            .request_repaint_after(std::time::Duration::from_millis(50));
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
            let runnable = self.syntax.is_none() && self.busy.is_none();
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
                .add_enabled(self.busy.is_some(), egui::Button::new("Stop"))
                .on_hover_text("Stop the run under way")
                .clicked()
            {
                self.stop();
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

    /// A notice kept from the last run, and a job refused or stopped.
    fn notices(&self, ui: &mut egui::Ui) {
        let bad = theme::error_color(ui);
        if let (Some(why), None) = (&self.settings.ended, &self.problem) {
            let text = format!(
                "Your last run did not finish: {why}. Your code is as you left it; look at what it does before you run it again."
            );
            crate::widget::message_ui(ui, &text, bad);
        }
        if let Some(problem) = &self.problem {
            crate::widget::message_ui(ui, problem, bad);
        }
    }

    /// Each visible world's verdict, with a button to step through it, and
    /// after a submission how many held-back worlds passed.
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
        for w in check.worlds.iter().filter(|w| w.visible) {
            ui.horizontal_wrapped(|ui| {
                let (mark, color) = if w.passed {
                    ("passed", good)
                } else {
                    ("failed", bad)
                };
                ui.label(RichText::new(mark).color(color));
                ui.label(&w.name);
                if let Some(reason) = &w.reason {
                    ui.label(RichText::new(reason).color(bad));
                }
                let idle = self.busy.is_none();
                if ui
                    .add_enabled(idle, egui::Button::new("Step through").small())
                    .clicked()
                {
                    open = self.worlds.iter().position(|x| x.name == w.name);
                }
            });
        }
        if let Some(tally) = check.held_back {
            let color = if tally.passed == tally.of { good } else { bad };
            ui.label(
                RichText::new(format!(
                    "Held back: {} of {} passed.",
                    tally.passed, tally.of
                ))
                .color(color),
            );
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
            _ if self.busy.is_some() => "Your code is running.".to_owned(),
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

/// `why` as a note a link can carry: one line of at most 200 characters.
fn note(why: &str) -> String {
    why.chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .take(200)
        .collect()
}

/// How a check went: passed, or the first world that failed and why, and
/// how many held-back worlds passed.
fn check_text(check: &Check, submitted: bool) -> String {
    let tally = check.held_back.map_or(String::new(), |t| {
        format!(" Held back: {} of {} passed.", t.passed, t.of)
    });
    if check.passed {
        let all = if submitted {
            "Passed on every world, those held back too."
        } else {
            "Passed on the worlds shown."
        };
        return format!("{all}{tally}");
    }
    if let Some(e) = &check.error {
        return format!(
            "It stopped with an error: {}.{tally}",
            editor::error_line(e)
        );
    }
    match check.worlds.iter().find(|w| !w.passed) {
        Some(w) => format!(
            "Not yet: it failed on {}{}.{tally}",
            w.name,
            w.reason
                .as_deref()
                .map_or(String::new(), |r| format!(" ({r})"))
        ),
        None => format!("Not yet.{tally}"),
    }
}

impl LabWidget for Code {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.collect();
        self.header(ui);
        ui.add_space(4.0);
        if editor::editor(ui, &mut self.source, self.syntax.as_ref()) {
            self.edited();
        }
        self.buttons(ui);
        self.busy_ui(ui);
        self.notices(ui);
        self.results(ui);
        self.hints(ui);
        ui.separator();
        let name = self.worlds[self.settings.world - 1].name.clone();
        ui.label(RichText::new(format!("Stepping through: {name}")).strong());
        match &mut self.player {
            Some(player) => stepper::show(ui, player),
            None if self.busy.is_none() => {
                ui.label(
                    RichText::new("Press Run to try your code and step through it here.").weak(),
                );
            }
            None => {}
        }
        self.exports(ui);
    }

    fn state(&self) -> Option<String> {
        let moment = match &self.player {
            Some(player) => player.moment(),
            None => self.moment.clone(),
        };
        link::write(NAME, &self.settings, &self.initial, &moment)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment): (Settings, Moment<()>) = link::read(NAME, state)?;
        let mut restored = Code::new(settings)?;
        restored.initial = self.initial.clone();
        restored.moment = moment;
        *self = restored;
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        if let Some(p) = &mut self.player {
            p.seek_time(t);
        }
    }

    fn saved_run(&mut self) -> Option<SavedRun> {
        let check = self.exercise.check(&self.source, true).for_learner();
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

    fn panel(exercise: &str, code: Option<&str>, world: usize) -> Code {
        Code::new(Settings {
            exercise: exercise.into(),
            code: code.map(kinolab_exercises::packed::pack),
            world,
            hints: 0,
            ended: None,
        })
        .unwrap()
    }

    #[test]
    fn code_from_a_link_never_runs_until_run_is_pressed() {
        // A script that would never stop, carried in a link.
        let endless = "fn control(rho, alpha, beta) { loop { } }";
        let mut code = panel("control-park", Some(endless), 1);
        code.initial = panel("control-park", None, 1).settings;
        let state = code.state().unwrap();
        code.restore(&state).unwrap();
        assert!(code.busy.is_none() && code.results.is_none() && code.player.is_none());
        assert_eq!(code.source, endless);
        // Run: the sandbox stops it, with the line.
        code.run();
        code.collect();
        let check = code.results.as_ref().unwrap();
        assert!(!check.passed);
        assert_eq!(check.error.as_ref().unwrap().line, Some(1));
    }

    #[test]
    fn a_run_opens_the_stepper_at_the_links_instant() {
        let mut code = panel("sequencer-replan", None, 2);
        code.moment = Moment {
            instant: 12.0,
            events: Vec::new(),
        };
        code.speed = Some(Speed::Four);
        code.run();
        code.collect();
        let at_once = code.exercise.trace(&code.source, &code.worlds[1]);
        let player = code.player.as_mut().unwrap();
        assert_eq!(player.speed, Speed::Four);
        assert!((player.time() - 12.0).abs() < 0.1, "{}", player.time());
        assert_eq!(player.state().trace().ticks, at_once.ticks);
    }

    #[test]
    fn a_submission_counts_the_held_back_worlds_and_never_shows_them() {
        let mut code = panel("field-pull", None, 1);
        code.submit();
        code.collect();
        let check = code.results.as_ref().unwrap();
        assert!(check.worlds.iter().all(|w| w.visible));
        assert_eq!(check.held_back.unwrap().of, 3);
        assert_eq!(code.settings.hints, 1, "a failed submission unlocks a hint");
        // A held-back world cannot be stepped through.
        let held = code.worlds.iter().position(|w| !w.visible).unwrap();
        code.step_through(held);
        assert!(code.busy.is_none());
        assert!(
            Code::new(Settings {
                world: held + 1,
                ..code.settings.clone()
            })
            .is_err()
        );
    }

    /// A runner that crashes whatever it is given.
    struct Crashing;

    impl Runner for Crashing {
        fn start(&mut self, _: Job) {}
        fn poll(&mut self) -> Option<Ran> {
            Some(Ran::Crashed(
                "RangeError: Maximum call stack size exceeded".into(),
            ))
        }
        fn stop(&mut self) {}
    }

    #[test]
    fn a_run_that_ends_its_runner_is_remembered_with_the_code() {
        let mut code = panel(
            "control-park",
            Some("fn control(rho, alpha, beta) { [0.0, 0.0] }"),
            1,
        );
        code.runner = Box::new(Crashing);
        code.run();
        code.collect();
        assert!(code.busy.is_none());
        assert!(
            code.problem
                .as_ref()
                .unwrap()
                .contains("Maximum call stack")
        );
        // The link and the progress keep it: the lesson reopens with a
        // notice and the code, and nothing runs.
        let state = code.state().unwrap();
        let mut reopened = panel("control-park", None, 1);
        reopened.restore(&state).unwrap();
        assert!(
            reopened
                .settings
                .ended
                .as_ref()
                .unwrap()
                .contains("Maximum call stack")
        );
        assert_eq!(reopened.source, code.source);
        assert!(reopened.busy.is_none() && reopened.results.is_none());
    }
}
