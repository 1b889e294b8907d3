//! The component lab: a system of components on the runtime's clock. The
//! boxes show each component's services and ports and the wires between
//! them, with message tokens travelling along; the sequence diagram below
//! shows every message of the last moments; a port can be dragged onto a
//! service to wire it (a refusal says why) and cancelled; latency, jitter,
//! loss, period and prescale are sliders. The player plays the run a
//! twentieth of a second per tick, steps and scrubs it; the learner's
//! wiring and cancels are sprung on the run at the instant they are made
//! (see [`run`]), so scrubbing back and forth shows one history, a link
//! carries them, and "Save run" writes them as the system file's script.

mod diagram;
mod run;
mod sequence;

use egui::RichText;
use kinolab_common::Feedback;
use kinolab_common::display::tidy_report;
use kinolab_components::system::{EXAMPLES, System, example};
use kinolab_components::{Action, Latency, Runtime, Status};
use serde::{Deserialize, Serialize};

use self::run::LabRun;
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::player::{Player, Speed};
use crate::widget::{LabWidget, Params, SavedRun, control_grid, feedback_ui, range};

/// The widget's name in the schema.
const NAME: &str = "component-lab";
/// The file "Save run" writes (`kinolab components` reads it).
const FILE: &str = "lab.system.json";
/// The most changes a link may carry.
const MOST_CHANGES: usize = 200;

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    system: String,
    task: Option<Task>,
    /// Every connection's latency, jitter and loss (the system's own when `None`).
    latency: Option<f64>,
    jitter: Option<f64>,
    loss: Option<f64>,
    /// Push-timed period (s) and push-timed subscribers' prescale.
    period: f64,
    prescale: u32,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Task {
    WireRobot,
}

/// The links of the first format: the set-up with the learner's changes.
#[derive(Deserialize)]
struct Legacy {
    system: String,
    fixed: f64,
    jitter: f64,
    loss: f64,
    period: f64,
    prescale: u32,
    actions: Vec<(f64, Action)>,
}

impl Legacy {
    fn read(self, task: Option<Task>) -> (Settings, Moment<Action>) {
        let settings = Settings {
            system: self.system,
            task,
            latency: Some(self.fixed),
            jitter: Some(self.jitter),
            loss: Some(self.loss),
            period: self.period,
            prescale: self.prescale,
        };
        let moment = Moment {
            instant: 0.0,
            events: self.actions,
        };
        (settings, moment)
    }
}

impl Settings {
    /// The system as shipped, before the settings change it.
    fn base(&self) -> Result<System, String> {
        match self.task {
            Some(Task::WireRobot) => kinolab_components::exercise::wire_task_system(),
            None => example(&self.system),
        }
        .map_err(|e| e.to_string())
    }

    /// The system file these settings describe.
    fn system(&self) -> Result<System, String> {
        let mut s = self.base()?;
        let l = &mut s.latency;
        l.fixed = self.latency.unwrap_or(l.fixed);
        l.jitter = self.jitter.unwrap_or(l.jitter);
        l.loss = self.loss.unwrap_or(l.loss);
        for c in &mut s.components {
            let timed = c.params.get("pattern").and_then(|p| p.as_str()) == Some("push-timed");
            let has_period = c.kind == "base" || (c.kind == "publisher" && timed);
            if has_period && let Some(map) = c.params.as_object_mut() {
                map.insert("period".into(), serde_json::json!(self.period));
            }
            if c.kind == "subscriber"
                && timed
                && let Some(map) = c.params.as_object_mut()
            {
                map.insert("prescale".into(), serde_json::json!(self.prescale));
            }
        }
        Ok(s)
    }

    /// The robot system is watched at 1×, the small ones at ¼×.
    fn small(&self) -> bool {
        self.task.is_none() && self.system != "robot"
    }
}

/// How the lab is looked at: not part of the run, not in a link.
#[derive(Debug, Default)]
struct Look {
    /// Seconds of history the sequence diagram shows.
    window: f64,
    selected: Option<String>,
    dragging: Option<String>,
    /// Why the last drag wired nothing (dropped away from every service).
    missed: Option<String>,
    /// Each box's column, from the wiring at the start.
    columns: Vec<usize>,
    /// Where each port and service was drawn last.
    anchors: diagram::Anchors,
}

struct ComponentLab {
    settings: Settings,
    initial: Settings,
    player: Option<Player<LabRun>>,
    problem: Option<String>,
    /// The system's own latency, which the sliders show until moved.
    own: Latency,
    look: Look,
    refusal: Option<String>,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    let mut lab = ComponentLab::new(settings);
    lab.rebuild(&Moment::default());
    Ok(Box::new(lab))
}

impl ComponentLab {
    fn new(settings: Settings) -> Self {
        let window = if settings.small() { 1.0 } else { 2.0 };
        Self {
            initial: settings.clone(),
            settings,
            player: None,
            problem: None,
            own: Latency::default(),
            look: Look {
                window,
                ..Look::default()
            },
            refusal: None,
            feedback: None,
        }
    }

    /// What a link carries of the run.
    fn moment(&self) -> Moment<Action> {
        self.player.as_ref().map(Player::moment).unwrap_or_default()
    }

    /// The run the settings make, with `moment`'s changes sprung at their
    /// times and landed at its instant (playing on if it was playing).
    fn rebuild(&mut self, moment: &Moment<Action>) {
        let (playing, speed) = match &self.player {
            Some(p) => (p.playing, p.speed),
            None if self.settings.small() => (false, Speed::Quarter),
            None => (false, Speed::One),
        };
        let start = self.settings.base().and_then(|base| {
            self.own = base.latency;
            LabRun::start(self.settings.system()?)
        });
        match start {
            Ok(run) => {
                self.look.columns = diagram::columns(&run.rt.view());
                let mut player = Player::new(run);
                player.speed = speed;
                player.replay(&moment.events, moment.instant);
                player.playing = playing;
                self.player = Some(player);
                self.problem = None;
            }
            Err(e) => {
                self.player = None;
                self.problem = Some(e);
            }
        }
        self.feedback = None;
    }

    /// The learner acts now (as the deployer): wire, cut, cancel. A wiring
    /// the runtime would refuse is not made, and the refusal says why.
    fn act(&mut self, action: Action) {
        self.refusal = None;
        let Some(player) = self.player.as_mut() else {
            return;
        };
        if let Action::Connect { port, service } = &action {
            let mut probe = player.state().rt.clone();
            if let Err(e) = probe.connect(port, service, "deployer", None) {
                self.refusal = Some(format!("Refused: {e}"));
                return;
            }
        }
        player.spring(action);
        self.feedback = None;
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let before = self.settings.clone();
        ui.horizontal_wrapped(|ui| {
            if self.settings.task.is_none() {
                egui::ComboBox::from_label("system")
                    .selected_text(&self.settings.system)
                    .show_ui(ui, |ui| {
                        for (id, _) in EXAMPLES {
                            crate::widget::choose(ui, &mut self.settings.system, id.to_owned(), id);
                        }
                    });
            }
            let changed = self.player.as_ref().is_some_and(|p| !p.events().is_empty());
            if changed
                && ui
                    .button("Clear my changes")
                    .on_hover_text("run again from 0 s without your wiring and cancels")
                    .clicked()
            {
                self.refusal = None;
                self.rebuild(&Moment::default());
            }
        });
        self.sliders(ui);
        if self.settings == before {
            return;
        }
        if self.settings.system == before.system {
            let moment = self.moment();
            self.rebuild(&moment);
        } else {
            // Another system: its own latency, and none of the changes.
            self.settings.latency = None;
            self.settings.jitter = None;
            self.settings.loss = None;
            self.look.selected = None;
            self.refusal = None;
            self.rebuild(&Moment::default());
        }
    }

    fn sliders(&mut self, ui: &mut egui::Ui) {
        let own = self.own;
        let s = &mut self.settings;
        // In a grid, so a row of sliders wraps instead of widening the page.
        let period = s.task.is_some() || matches!(s.system.as_str(), "newest-vs-timed" | "robot");
        let prescale = s.task.is_none() && s.system == "newest-vs-timed";
        let mut shown = vec!["latency", "jitter", "loss"];
        shown.extend(period.then_some("period"));
        shown.extend(prescale.then_some("prescale"));
        shown.push("window");
        let window = &mut self.look.window;
        control_grid(
            ui,
            "component-lab-sliders",
            shown.len(),
            270.0,
            |ui, i| match shown.get(i).copied() {
                Some("latency") => own_or(ui, &mut s.latency, own.fixed, "latency", "latency (s)"),
                Some("jitter") => own_or(ui, &mut s.jitter, own.jitter, "jitter", "jitter (s)"),
                Some("loss") => own_or(ui, &mut s.loss, own.loss, "loss", "loss"),
                Some("period") => {
                    let slider = egui::Slider::new(&mut s.period, range(NAME, "period"));
                    ui.add(slider.text("push-timed period (s)"));
                }
                Some("prescale") => {
                    let r = range(NAME, "prescale");
                    let (lo, hi) = (*r.start() as u32, *r.end() as u32);
                    ui.add(egui::Slider::new(&mut s.prescale, lo..=hi).text("prescale"));
                }
                _ => {
                    let slider = egui::Slider::new(window, 0.1..=10.0).logarithmic(true);
                    ui.add(slider.text("diagram window (s)"));
                }
            },
        );
    }

    /// The player, the diagram at the instant shown, its timeline, the
    /// port panel, the statuses and the sequence diagram; the area to
    /// save as a picture.
    fn run_ui(&mut self, ui: &mut egui::Ui) -> Option<egui::Rect> {
        let player = self.player.as_mut()?;
        player.controls(ui);
        let (wired, diagram) = diagram::show(ui, player.state(), &mut self.look);
        let marks: Vec<usize> = player
            .events()
            .into_iter()
            .map(|(t, _)| run::tick_of(t))
            .collect();
        let expected = run::tick_of(player.state().system.until);
        let ink = ui.visuals().text_color();
        player.timeline(
            ui,
            "Simulated time",
            expected,
            &mut |painter, rect, x, _| {
                for k in &marks {
                    let at = x(*k);
                    painter.line_segment(
                        [egui::pos2(at, rect.top()), egui::pos2(at, rect.bottom())],
                        egui::Stroke::new(2.0, ink.gamma_multiply(0.6)),
                    );
                }
            },
        );
        player.run(ui, 40);
        for r in [&self.refusal, &self.look.missed].into_iter().flatten() {
            crate::widget::message_ui(ui, r, crate::theme::error_color(ui));
        }
        let rt = &player.state().rt;
        let picked = pick_and_wire(ui, rt, &mut self.look.selected);
        let acted = port_panel(ui, rt, self.look.selected.as_deref());
        statuses(ui, rt);
        let sequence = sequence::show(ui, rt, self.look.window);
        if let Some(action) = wired.or(picked).or(acted) {
            self.act(action);
        }
        Some(diagram.union(sequence))
    }

    fn exports(&mut self, ui: &mut egui::Ui, shown: egui::Rect) {
        let Some(player) = self.player.as_mut() else {
            return;
        };
        let command = format!("kinolab components {FILE} --until {}", player.time());
        let run = player.state();
        let csv = || trace_csv(run.rt.trace());
        let file = || run.file();
        export::bar(
            ui,
            ui.scope_id().with("component-lab-exports"),
            &[
                Export::Png {
                    file: "kinolab-components.png",
                    rect: shown,
                },
                Export::Csv {
                    file: "kinolab-components-trace.csv",
                    make: &csv,
                },
                Export::Run {
                    file: FILE,
                    command: &command,
                    make: &file,
                },
            ],
        );
    }

    fn task_ui(&mut self, ui: &mut egui::Ui) {
        ui.separator();
        ui.label(egui::RichText::new("Task: wire it so the map reaches the planner and the planner drives the base, then check (the core runs it for 40 s).").strong());
        if ui.button("Check").clicked() {
            let pairs: Vec<(String, String)> = self
                .player
                .as_ref()
                .map(Player::events)
                .unwrap_or_default()
                .into_iter()
                .filter_map(|(_, a)| match a {
                    Action::Connect { port, service } => Some((port, service)),
                    _ => None,
                })
                .collect();
            self.feedback = Some(kinolab_components::exercise::wire_robot(&pairs));
        }
        feedback_ui(ui, self.feedback.as_ref());
    }
}

/// A slider for a setting that is the system's own (`own`) until moved.
fn own_or(ui: &mut egui::Ui, value: &mut Option<f64>, own: f64, param: &str, text: &str) {
    let mut v = value.unwrap_or(own);
    let slider = egui::Slider::new(&mut v, range(NAME, param))
        .text(text)
        .max_decimals(3);
    if ui.add(slider).changed() {
        *value = Some(v);
    }
}

/// The trace as a table: a row per message, wiring, state change and note.
fn trace_csv(trace: &[kinolab_components::Record]) -> String {
    use std::fmt::Write as _;
    let mut out = String::from(
        "seq,sent (s),delivered (s),from,to,pattern,kind,port,service,status,summary\n",
    );
    for r in trace {
        let delivered = r.delivered.map(|d| d.to_string()).unwrap_or_default();
        let _ = writeln!(
            out,
            "{},{},{delivered},{},{},{},{},{},{},{},{}",
            r.seq,
            r.sent,
            export::csv_field(&r.from),
            export::csv_field(&r.to),
            r.pattern,
            r.kind,
            export::csv_field(&r.port),
            export::csv_field(&r.service),
            r.status.name(),
            export::csv_field(&r.summary),
        );
    }
    out
}

/// The keyboard's way to do what a press and a drag do on the diagram:
/// choose a port from a list, then the service to wire it to. A wiring
/// the runtime refuses is refused here as it is after a drag.
fn pick_and_wire(ui: &mut egui::Ui, rt: &Runtime, selected: &mut Option<String>) -> Option<Action> {
    // The lists are read only while open: the runtime's view is rebuilt
    // for each call, and the lab draws many frames a second.
    let named = |c: &str, x: &str| format!("{c}.{x}");
    let mut action = None;
    ui.horizontal_wrapped(|ui| {
        let shown = selected.as_deref().unwrap_or("choose one").to_owned();
        egui::ComboBox::from_label("port")
            .selected_text(shown)
            .show_ui(ui, |ui| {
                for c in &rt.view() {
                    for p in &c.ports {
                        let name = named(&c.name, &p.name);
                        crate::widget::choose(ui, selected, Some(name.clone()), name);
                    }
                }
            });
        let Some(port) = selected.clone() else {
            return;
        };
        egui::ComboBox::from_label("wire it to")
            .selected_text("a service")
            .show_ui(ui, |ui| {
                for c in &rt.view() {
                    for s in &c.services {
                        let service = named(&c.name, &s.name);
                        if ui.selectable_label(false, &service).clicked() {
                            let port = port.clone();
                            action = Some(Action::Connect { port, service });
                        }
                    }
                }
            });
    });
    action
}

/// The selected port: where it is wired, what it saw, why it is quiet,
/// and the buttons that act on it.
fn port_panel(ui: &mut egui::Ui, rt: &Runtime, selected: Option<&str>) -> Option<Action> {
    let Some(name) = selected else {
        ui.label("Click a port (a circle on a box's left edge) to see it, or choose it above; drag it onto a service (a square on a box's right edge), or choose the service above, to wire it.");
        return None;
    };
    let (component, port) = name.split_once('.')?;
    let view = rt
        .component(component)
        .and_then(|c| c.ports.into_iter().find(|p| p.name == port))?;
    let why = rt.why_nothing(name);
    ui.horizontal_wrapped(|ui| {
        ui.strong(name);
        ui.label(format!(
            "{} {}{}",
            view.pattern,
            view.signature,
            if view.wireable { ", wireable" } else { "" }
        ));
        match &view.connected_to {
            Some(s) => ui.label(format!("→ {s}")),
            None => ui.label("not connected"),
        };
    });
    let s = view.stats;
    ui.label(format!(
        "sent {}, received {}, lost {}, skipped {}, held back by prescale {}, cancelled {}",
        s.sent, s.received, s.lost, s.skipped, s.withheld, s.cancelled
    ));
    if why.reason != "received" {
        let text = format!("Why nothing? {}", why.message);
        crate::widget::message_ui(ui, &text, crate::theme::error_color(ui));
    }
    let port = name.to_owned();
    ui.horizontal_wrapped(|ui| {
        let mut action = None;
        if view.blocking {
            if ui
                .button("Cancel")
                .on_hover_text(
                    "switch the port to non-blocking: waiting calls return \"cancelled\"",
                )
                .clicked()
            {
                action = Some(Action::Cancel { port: port.clone() });
            }
        } else if ui.button("Block again").clicked() {
            action = Some(Action::Block { port: port.clone() });
        }
        if view.connected_to.is_some() && ui.button("Disconnect").clicked() {
            action = Some(Action::Disconnect { port });
        }
        action
    })
    .inner
}

/// Each component's state and what it says of itself.
fn statuses(ui: &mut egui::Ui, rt: &Runtime) {
    // A line each, wrapping: a status can be long and the column narrow.
    for c in rt.view() {
        ui.horizontal_wrapped(|ui| {
            ui.label(
                RichText::new(&c.name)
                    .strong()
                    .size(crate::theme::LABEL_SIZE),
            );
            let state = match &c.waiting_on {
                Some(p) => format!("blocked on {p}"),
                None => c.state.name().to_owned(),
            };
            ui.label(
                RichText::new(format!("{state}: {}", c.status)).size(crate::theme::LABEL_SIZE),
            );
        });
    }
}

impl ComponentLab {
    /// The system at the instant shown: the patterns its messages use,
    /// and how many were sent, delivered and lost so far.
    fn description(&self) -> String {
        let name = match self.settings.task {
            Some(Task::WireRobot) => "robot to wire",
            None => self.settings.system.as_str(),
        };
        let Some(player) = &self.player else {
            let why = self.problem.as_deref().unwrap_or_default();
            return format!("The {name} system cannot run: {why}");
        };
        let run = player.peek();
        let messages: Vec<_> = run
            .rt
            .trace()
            .iter()
            .filter(|r| !matches!(r.pattern, "wiring" | "state" | "note"))
            .collect();
        let mut patterns: Vec<&str> = messages.iter().map(|r| r.pattern).collect();
        patterns.sort_unstable();
        patterns.dedup();
        let count = |s: Status| messages.iter().filter(|r| r.status == s).count();
        format!(
            "The {name} system at {} s: {} message{} sent ({}), {} delivered, {} lost.",
            kinolab_common::display::fixed(player.time(), 2),
            messages.len(),
            if messages.len() == 1 { "" } else { "s" },
            if patterns.is_empty() {
                "none yet".to_owned()
            } else {
                patterns.join(", ")
            },
            count(Status::Delivered),
            count(Status::Lost)
        )
    }
}

impl LabWidget for ComponentLab {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        if let Some(p) = &self.problem {
            crate::widget::error_box(ui, "This system cannot run", p);
            return;
        }
        if let Some(shown) = self.run_ui(ui) {
            self.exports(ui, shown);
        }
        if self.settings.task.is_some() {
            self.task_ui(ui);
        }
    }

    fn state(&self) -> Option<String> {
        link::write(NAME, &self.settings, &self.initial, &self.moment())
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment) = match link::read::<Settings, Action>(NAME, state) {
            Ok(read) => read,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => old.read(self.initial.task),
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
        if moment.events.len() > MOST_CHANGES {
            return Err(format!("it holds more than {MOST_CHANGES} changes"));
        }
        // A link is written only when something changed: one holding the
        // lesson's own settings and nothing else is not one of this widget's.
        if settings == self.initial && moment == Moment::default() {
            return Err("it holds nothing this widget would change".into());
        }
        self.settings = settings;
        self.look.selected = None;
        self.refusal = None;
        self.rebuild(&moment);
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        if let Some(player) = &mut self.player {
            player.seek_time(t);
        }
    }

    fn saved_run(&mut self) -> Option<SavedRun> {
        let player = self.player.as_mut()?;
        let until = player.time().to_string();
        let run = player.state();
        let mut shows = vec![
            ("/trace".to_owned(), tidy_report(&run.rt.trace()).ok()?),
            ("/components".to_owned(), tidy_report(&run.rt.view()).ok()?),
        ];
        if let Some(sim) = &run.rt.world {
            let pose = [sim.pose.x, sim.pose.y, sim.pose.theta];
            shows.push(("/robot".to_owned(), tidy_report(&pose).ok()?));
        }
        Some(SavedRun {
            file: FILE.into(),
            text: run.file().ok()?,
            args: vec!["components".into(), FILE.into(), "--until".into(), until],
            shows,
        })
    }
}

#[cfg(test)]
mod tests;
