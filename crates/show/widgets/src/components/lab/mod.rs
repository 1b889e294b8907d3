//! The component lab: a system of components on the runtime's clock. The
//! boxes show each component's services and ports and the wires between
//! them, with message tokens travelling along; the sequence diagram below
//! shows every message of the last moments; a port can be dragged onto a
//! service to wire it (a refusal says why) and cancelled; latency, jitter,
//! loss, period and prescale are sliders. The run is deterministic: every
//! change re-runs the system from the start with the learner's actions at
//! the times they made them, so scrubbing back and forth shows one history.

mod diagram;
mod sequence;

use kinolab_common::Feedback;
use kinolab_components::system::{System, example};
use kinolab_components::{Action, Runtime};
use kinolab_world::Pose;
use serde::{Deserialize, Serialize};

use crate::link;
use crate::widget::{LabWidget, Params, feedback_ui};

const SYSTEMS: [&str; 4] = ["out-of-order", "newest-vs-timed", "events", "robot"];
/// Playback speeds (simulated seconds per real second).
const SPEEDS: [f64; 5] = [0.05, 0.25, 1.0, 4.0, 16.0];

/// What the learner changed, and what a link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Setup {
    system: String,
    fixed: f64,
    jitter: f64,
    loss: f64,
    /// Push-timed period (s) and push-timed subscribers' prescale.
    period: f64,
    prescale: u32,
    /// The learner's wiring and cancels, at the times they made them.
    actions: Vec<(f64, Action)>,
}

struct ComponentLab {
    setup: Setup,
    initial: Setup,
    /// The wire-the-robot task.
    task: bool,
    rt: Option<Runtime>,
    problem: Option<String>,
    /// The robot's poses so far (time, pose), when the system has a world.
    track: Vec<(f64, Pose)>,
    until: f64,
    playing: bool,
    speed: usize,
    /// Seconds of history the sequence diagram shows.
    window: f64,
    selected: Option<String>,
    dragging: Option<String>,
    /// Each box's column, from the wiring at the start.
    columns: Vec<usize>,
    refusal: Option<String>,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let task = p.choice("task") == Some("wire-robot");
    let system = if task {
        "robot"
    } else {
        p.choice("system").unwrap_or("robot")
    };
    let base = example(system).map_err(|e| e.to_string())?;
    let setup = Setup {
        system: system.to_owned(),
        fixed: base.latency.fixed,
        jitter: base.latency.jitter,
        loss: base.latency.loss,
        period: 0.1,
        prescale: 3,
        actions: Vec::new(),
    };
    let small = system != "robot";
    let mut lab = ComponentLab {
        initial: setup.clone(),
        setup,
        task,
        rt: None,
        problem: None,
        track: Vec::new(),
        until: base.until,
        playing: false,
        speed: if small { 1 } else { 2 },
        window: if small { 1.0 } else { 2.0 },
        selected: None,
        dragging: None,
        columns: Vec::new(),
        refusal: None,
        feedback: None,
    };
    lab.rebuild(0.0);
    Ok(Box::new(lab))
}

impl Setup {
    /// The system file this set-up describes.
    fn system(&self, task: bool) -> Result<System, String> {
        let mut s = if task {
            kinolab_components::exercise::wire_task_system()
        } else {
            example(&self.system)
        }
        .map_err(|e| e.to_string())?;
        s.latency.fixed = self.fixed;
        s.latency.jitter = self.jitter;
        s.latency.loss = self.loss;
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
}

impl ComponentLab {
    /// Build the system afresh and run it to `t` with the learner's actions.
    fn rebuild(&mut self, t: f64) {
        self.track.clear();
        self.rt = match self.setup.system(self.task).and_then(|s| {
            self.until = s.until;
            s.build().map_err(|e| e.to_string())
        }) {
            Ok(mut rt) => {
                self.columns = diagram::columns(&rt.view());
                for (at, action) in &self.setup.actions {
                    rt.schedule(*at, action.clone());
                }
                self.problem = None;
                Some(rt)
            }
            Err(e) => {
                self.problem = Some(e);
                None
            }
        };
        self.advance_to(t);
    }

    /// Run forward to `t`, keeping the robot's track.
    fn advance_to(&mut self, t: f64) {
        let Some(rt) = self.rt.as_mut() else { return };
        let t = t.min(self.until);
        while rt.now() < t {
            let next = (rt.now() + 0.05).min(t);
            rt.run_until(next);
            if let Some(sim) = &rt.world {
                self.track.push((rt.now(), sim.pose));
            }
        }
    }

    fn now(&self) -> f64 {
        self.rt.as_ref().map_or(0.0, Runtime::now)
    }

    /// Go to time `t`: forward by running on, backward by re-running.
    fn seek(&mut self, t: f64) {
        if t + 1e-9 < self.now() {
            self.rebuild(t);
        } else {
            self.advance_to(t);
        }
    }

    /// The learner acts now (as the deployer): wire, cut, cancel.
    fn act(&mut self, action: Action) {
        let t = self.now();
        self.refusal = None;
        if let (Action::Connect { port, service }, Some(rt)) = (&action, self.rt.as_mut())
            && let Err(e) = rt.connect(port, service, "you", None)
        {
            self.refusal = Some(format!("Refused: {e}"));
            return;
        }
        if !matches!(action, Action::Connect { .. })
            && let Some(rt) = self.rt.as_mut()
        {
            rt.act(&action, "you");
        }
        self.setup.actions.push((t, action));
        self.feedback = None;
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let before = self.setup.clone();
        ui.horizontal_wrapped(|ui| {
            if !self.task {
                egui::ComboBox::from_label("system")
                    .selected_text(&self.setup.system)
                    .show_ui(ui, |ui| {
                        for s in SYSTEMS {
                            ui.selectable_value(&mut self.setup.system, s.to_owned(), s);
                        }
                    });
            }
            let label = if self.playing { "Pause" } else { "Play" };
            if ui.button(label).clicked() {
                self.playing = !self.playing;
            }
            if ui
                .button("Step")
                .on_hover_text("run to the next thing that happens")
                .clicked()
            {
                self.playing = false;
                if let Some(next) = self.rt.as_ref().and_then(Runtime::next_due) {
                    self.seek(next);
                }
            }
            if ui
                .button("Restart")
                .on_hover_text(
                    "run again from 0 s, with your wiring and cancels at the times you made them",
                )
                .clicked()
            {
                self.rebuild(0.0);
            }
            if !self.setup.actions.is_empty() && ui.button("Clear my changes").clicked() {
                self.setup.actions.clear();
                self.refusal = None;
                self.feedback = None;
                self.rebuild(0.0);
            }
            egui::ComboBox::from_label("speed")
                .selected_text(format!("{}×", SPEEDS[self.speed]))
                .show_ui(ui, |ui| {
                    for (i, s) in SPEEDS.iter().enumerate() {
                        ui.selectable_value(&mut self.speed, i, format!("{s}×"));
                    }
                });
        });
        let mut t = self.now();
        let scrub = ui.add(egui::Slider::new(&mut t, 0.0..=self.until).text("time (s)"));
        if scrub.changed() {
            self.playing = false;
            self.seek(t);
        }
        crate::widget::control_row(ui, |ui| {
            ui.add(
                egui::Slider::new(&mut self.setup.fixed, 0.0..=0.5)
                    .text("latency (s)")
                    .max_decimals(3),
            );
            ui.add(
                egui::Slider::new(&mut self.setup.jitter, 0.0..=0.5)
                    .text("jitter (s)")
                    .max_decimals(3),
            );
            ui.add(egui::Slider::new(&mut self.setup.loss, 0.0..=0.5).text("loss"));
        });
        crate::widget::control_row(ui, |ui| {
            if matches!(self.setup.system.as_str(), "newest-vs-timed" | "robot") {
                ui.add(
                    egui::Slider::new(&mut self.setup.period, 0.02..=1.0)
                        .text("push-timed period (s)"),
                );
            }
            if self.setup.system == "newest-vs-timed" {
                ui.add(egui::Slider::new(&mut self.setup.prescale, 1..=10).text("prescale"));
            }
            ui.add(
                egui::Slider::new(&mut self.window, 0.1..=10.0)
                    .logarithmic(true)
                    .text("diagram window (s)"),
            );
        });
        if self.setup != before {
            if self.setup.system != before.system {
                self.setup.actions.clear();
                self.selected = None;
                if let Ok(s) = example(&self.setup.system) {
                    self.setup.fixed = s.latency.fixed;
                    self.setup.jitter = s.latency.jitter;
                    self.setup.loss = s.latency.loss;
                }
                self.rebuild(0.0);
            } else {
                let t = self.now();
                self.rebuild(t);
            }
            self.feedback = None;
        }
    }

    /// The selected port: where it is wired, what it saw, why it is quiet,
    /// and the buttons that act on it.
    fn port_panel(&mut self, ui: &mut egui::Ui) {
        let Some(name) = self.selected.clone() else {
            ui.label("Click a port (a circle on a box's left edge) to see it; drag it onto a service (a square on a box's right edge) to wire it.");
            return;
        };
        let Some(rt) = self.rt.as_ref() else { return };
        let (component, port) = name.split_once('.').unwrap_or_default();
        let Some(view) = rt
            .component(component)
            .and_then(|c| c.ports.into_iter().find(|p| p.name == port))
        else {
            return;
        };
        let why = rt.why_nothing(&name);
        ui.horizontal_wrapped(|ui| {
            ui.strong(&name);
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
            ui.label(
                egui::RichText::new(format!("Why nothing? {}", why.message))
                    .color(crate::theme::error_color(ui)),
            );
        }
        ui.horizontal_wrapped(|ui| {
            if view.blocking {
                if ui
                    .button("Cancel")
                    .on_hover_text(
                        "switch the port to non-blocking: waiting calls return \"cancelled\"",
                    )
                    .clicked()
                {
                    self.act(Action::Cancel { port: name.clone() });
                }
            } else if ui.button("Block again").clicked() {
                self.act(Action::Block { port: name.clone() });
            }
            if view.connected_to.is_some() && ui.button("Disconnect").clicked() {
                self.act(Action::Disconnect { port: name.clone() });
            }
        });
    }

    /// Each component's state and what it says of itself.
    fn statuses(&self, ui: &mut egui::Ui) {
        let Some(rt) = self.rt.as_ref() else { return };
        // A line each, wrapping: a status can be long and the column narrow.
        for c in rt.view() {
            ui.horizontal_wrapped(|ui| {
                ui.label(
                    egui::RichText::new(&c.name)
                        .strong()
                        .size(crate::theme::LABEL_SIZE),
                );
                let state = match &c.waiting_on {
                    Some(p) => format!("blocked on {p}"),
                    None => c.state.name().to_owned(),
                };
                ui.label(
                    egui::RichText::new(format!("{state}: {}", c.status))
                        .size(crate::theme::LABEL_SIZE),
                );
            });
        }
    }

    fn task_ui(&mut self, ui: &mut egui::Ui) {
        ui.separator();
        ui.label(egui::RichText::new("Task: wire it so the map reaches the planner and the planner drives the base, then check (the core runs it for 40 s).").strong());
        if ui.button("Check").clicked() {
            let pairs: Vec<(String, String)> = self
                .setup
                .actions
                .iter()
                .filter_map(|(_, a)| match a {
                    Action::Connect { port, service } => Some((port.clone(), service.clone())),
                    _ => None,
                })
                .collect();
            self.feedback = Some(kinolab_components::exercise::wire_robot(&pairs));
        }
        feedback_ui(ui, self.feedback.as_ref());
    }
}

impl LabWidget for ComponentLab {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        if let Some(p) = &self.problem {
            crate::widget::error_box(ui, "This system cannot run", p);
            return;
        }
        if let Some(action) = diagram::show(ui, self) {
            self.act(action);
        }
        if let Some(r) = &self.refusal {
            ui.label(egui::RichText::new(r).color(crate::theme::error_color(ui)));
        }
        self.port_panel(ui);
        self.statuses(ui);
        sequence::show(ui, self);
        if self.task {
            self.task_ui(ui);
        }
        if self.playing {
            let dt = crate::widget::frame_dt(ui);
            let t = self.now() + dt * SPEEDS[self.speed];
            self.advance_to(t);
            if self.now() >= self.until {
                self.playing = false;
            }
            crate::widget::animate(ui);
        }
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.setup, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(s) = link::decode::<Setup>(state)
            && SYSTEMS.contains(&s.system.as_str())
            && (0.0..=0.5).contains(&s.fixed)
            && (0.0..=0.5).contains(&s.jitter)
            && (0.0..=0.5).contains(&s.loss)
            && (0.02..=1.0).contains(&s.period)
            && (1..=10).contains(&s.prescale)
            && s.actions.len() <= 200
        {
            self.setup = s;
            self.rebuild(0.0);
        }
        Ok(())
    }
}
