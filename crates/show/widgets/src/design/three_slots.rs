//! Three slots: a body, a behaviour set and a world, each chosen on its
//! own. The chosen combination runs and is drawn; the matrix of every
//! combination fills in a cell per frame; the design view lights the
//! analysis pattern whose slot changed.

use egui::{RichText, Sense, Stroke, vec2};
use kinolab_behaviours::run::RunReport;
use kinolab_common::Feedback;
use kinolab_design::slots::{BEHAVIOURS, BODIES, Outcome, PATTERNS, WORLDS, outcome, setup};
use kinolab_world::Pose;
use serde::{Deserialize, Serialize};

use crate::behaviour::world_view::{draw_robot, draw_trail, draw_world};
use crate::draw::PlaneView;
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params, feedback_ui};

/// The widget's name in the schema.
const NAME: &str = "three-slots";

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    body: String,
    behaviours: String,
    world: String,
    task: Option<Task>,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Task {
    FixTheCar,
}

/// The links of the first format: each slot by its place in the core's list.
#[derive(Deserialize)]
struct Legacy {
    body: usize,
    behaviours: usize,
    world: usize,
}

/// `list`'s entry called `name`, as the core names it.
fn named(list: &[&'static str], name: &str) -> Option<&'static str> {
    list.iter().copied().find(|x| *x == name)
}

impl Settings {
    /// The three slots as the core names them.
    fn names(&self) -> Option<(&'static str, &'static str, &'static str)> {
        Some((
            named(&BODIES, &self.body)?,
            named(&BEHAVIOURS, &self.behaviours)?,
            named(&WORLDS, &self.world)?,
        ))
    }
}

struct ThreeSlots {
    settings: Settings,
    initial: Settings,
    run: Option<(Outcome, RunReport)>,
    problem: Option<String>,
    /// The matrix so far, in bodies × behaviours × worlds order.
    matrix: Vec<Outcome>,
    /// Which slot changed last: 0 body, 1 behaviours, 2 world.
    changed: Option<usize>,
    feedback: Option<Feedback>,
    /// The failure whose reason shows under the matrix (a tap or a click
    /// picks it: hovering cannot work on a touch screen).
    why: Option<usize>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let mut settings: Settings = p.settings()?;
    if settings.task == Some(Task::FixTheCar) {
        // The task starts from the car failing in the maze.
        settings.body = "car".into();
        settings.behaviours = "go-and-avoid".into();
        settings.world = "maze".into();
    }
    Ok(Box::new(ThreeSlots::new(settings)))
}

impl ThreeSlots {
    fn new(settings: Settings) -> Self {
        let mut w = ThreeSlots {
            initial: settings.clone(),
            settings,
            run: None,
            problem: None,
            matrix: Vec::new(),
            changed: None,
            feedback: None,
            why: None,
        };
        w.rerun();
        w
    }

    fn rerun(&mut self) {
        let Some((b, s, w)) = self.settings.names() else {
            self.problem = Some("no such slot".into());
            return;
        };
        match outcome(b, s, w) {
            Ok(r) => {
                self.run = Some(r);
                self.problem = None;
            }
            Err(e) => self.problem = Some(e.to_string()),
        }
        self.feedback = None;
    }

    /// One more cell of the matrix (a frame's work).
    fn fill_matrix(&mut self) -> bool {
        let n = self.matrix.len();
        let total = BODIES.len() * BEHAVIOURS.len() * WORLDS.len();
        if n >= total {
            return false;
        }
        let (b, rest) = (
            n / (BEHAVIOURS.len() * WORLDS.len()),
            n % (BEHAVIOURS.len() * WORLDS.len()),
        );
        let (s, w) = (rest / WORLDS.len(), rest % WORLDS.len());
        if let Ok((o, _)) = outcome(BODIES[b], BEHAVIOURS[s], WORLDS[w]) {
            self.matrix.push(o);
        }
        true
    }

    fn slots(&mut self, ui: &mut egui::Ui) {
        let before = self.settings.clone();
        let s = &mut self.settings;
        let rows: [(&str, &[&str], &mut String); 3] = [
            ("body", &BODIES, &mut s.body),
            ("behaviours", &BEHAVIOURS, &mut s.behaviours),
            ("world", &WORLDS, &mut s.world),
        ];
        for (label, options, slot) in rows {
            ui.horizontal_wrapped(|ui| {
                ui.label(RichText::new(format!("{label}:")).strong());
                for o in options {
                    crate::widget::choose(ui, slot, (*o).to_owned(), *o);
                }
            });
        }
        if self.settings != before {
            let now = &self.settings;
            self.changed = [
                now.body != before.body,
                now.behaviours != before.behaviours,
                now.world != before.world,
            ]
            .iter()
            .position(|c| *c);
            self.rerun();
        }
    }

    /// The chosen combination's run; where it was drawn.
    fn draw_run(&self, ui: &mut egui::Ui, width: f32) -> egui::Rect {
        let height = (width * 0.55).min(260.0);
        let (rect, _) = ui.allocate_exact_size(vec2(width, height), Sense::hover());
        let Some((b, s, w)) = self.settings.names() else {
            return rect;
        };
        let Ok(setup) = setup(b, s, w) else {
            return rect;
        };
        let world = &setup.world;
        let bounds = world.bounds;
        let view = PlaneView::fit(
            rect.shrink(6.0),
            [bounds.x_min, bounds.y_min],
            [bounds.x_max, bounds.y_max],
        );
        let painter = ui.painter_at(rect);
        draw_world(ui, &painter, &view, world, 0.0);
        if let Some((_, report)) = &self.run {
            let accent = theme::accent(ui);
            draw_trail(
                &painter,
                &view,
                report.samples.iter().map(|p| [p.motion.x, p.motion.y]),
                accent,
            );
            if let Some(last) = report.samples.last() {
                let pose = Pose::new(last.motion.x, last.motion.y, last.motion.theta());
                draw_robot(
                    &painter,
                    &view,
                    &pose,
                    setup.body.radius(),
                    accent,
                    ui.visuals().text_color(),
                );
            }
        }
        rect
    }

    /// The three analysis patterns side by side (one under the other on a
    /// phone); the one whose slot changed is lit.
    fn design_view(&self, ui: &mut egui::Ui) {
        crate::widget::panels(ui, PATTERNS.len(), |ui, k, width| {
            let Some((pattern, slot, participants)) = PATTERNS.get(k) else {
                return;
            };
            let lit = self.changed == Some(k);
            let stroke = if lit {
                Stroke::new(2.5, theme::error_color(ui))
            } else {
                Stroke::new(1.0, ui.visuals().weak_text_color())
            };
            egui::Frame::new()
                .stroke(stroke)
                .corner_radius(6.0)
                .inner_margin(6.0)
                .show(ui, |ui| {
                    ui.set_width(width - 14.0);
                    ui.label(RichText::new(format!("{pattern} ({slot})")).strong());
                    for p in *participants {
                        ui.label(RichText::new(*p).size(theme::LABEL_SIZE));
                    }
                    if lit {
                        ui.label(
                            RichText::new("changed")
                                .color(theme::error_color(ui))
                                .size(theme::LABEL_SIZE),
                        );
                    }
                });
        });
    }

    /// The matrix as a table: a row per combination run so far.
    fn matrix_csv(&self) -> String {
        use std::fmt::Write as _;
        let mut out = String::from("body,behaviours,world,reached,time (s),collisions,why\n");
        for o in &self.matrix {
            let time = o.time.map(|t| t.to_string()).unwrap_or_default();
            let _ = writeln!(
                out,
                "{},{},{},{},{time},{},{}",
                o.body,
                o.behaviours,
                o.world,
                if o.reached { "yes" } else { "no" },
                o.collisions,
                export::csv_field(&o.why)
            );
        }
        out
    }

    fn exports(&self, ui: &mut egui::Ui, run: egui::Rect) {
        let csv = || self.matrix_csv();
        export::bar(
            ui,
            ui.scope_id().with("three-slots-exports"),
            &[
                Export::Png {
                    file: "kinolab-three-slots.png",
                    rect: run,
                },
                Export::Csv {
                    file: "kinolab-every-combination.csv",
                    make: &csv,
                },
            ],
        );
    }

    fn task_ui(&mut self, ui: &mut egui::Ui) {
        ui.separator();
        ui.label(RichText::new("Task: the car fails in the maze. Change exactly one slot, keep the world, so that the robot reaches the goal; then check.").strong());
        if ui.button("Check").clicked()
            && let Some((b, s, w)) = self.settings.names()
        {
            self.feedback = Some(kinolab_design::exercise::fix_the_car(b, s, w));
        }
        feedback_ui(ui, self.feedback.as_ref());
    }

    fn matrix_ui(&mut self, ui: &mut egui::Ui) {
        let narrow = crate::widget::narrow(ui);
        crate::widget::sideways(ui, |ui| self.matrix_grid(ui, narrow));
        let picked = self.why.and_then(|i| self.matrix.get(i));
        if let Some(o) = picked {
            ui.label(format!(
                "{}, {} in the {}: {}.",
                o.body, o.behaviours, o.world, o.why
            ));
        }
    }

    /// The matrix; a failure is a button that shows why under it. On a
    /// narrow column a row's name takes two lines.
    fn matrix_grid(&mut self, ui: &mut egui::Ui, narrow: bool) {
        egui::Grid::new(ui.scope_id().with("matrix"))
            .striped(true)
            .show(ui, |ui| {
                ui.label("");
                for w in WORLDS {
                    ui.label(RichText::new(w).strong());
                }
                ui.end_row();
                for b in BODIES {
                    for s in BEHAVIOURS {
                        ui.label(if narrow {
                            format!("{b},\n{s}")
                        } else {
                            format!("{b}, {s}")
                        });
                        for w in WORLDS {
                            self.matrix_cell(ui, b, s, w);
                        }
                        ui.end_row();
                    }
                }
            });
    }

    fn matrix_cell(&mut self, ui: &mut egui::Ui, b: &str, s: &str, w: &str) {
        let found = self
            .matrix
            .iter()
            .position(|o| o.body == b && o.behaviours == s && o.world == w);
        match found.and_then(|i| Some((i, self.matrix.get(i)?))) {
            Some((_, o)) if o.reached => {
                ui.label(
                    RichText::new(format!("{:.0} s", o.time.unwrap_or_default()))
                        .color(theme::good_color(ui)),
                );
            }
            Some((i, o)) => {
                let picked = self.why == Some(i);
                let text = RichText::new("fails").color(theme::error_color(ui));
                if crate::widget::choice(ui, picked, text)
                    .on_hover_text(&o.why)
                    .clicked()
                {
                    self.why = (!picked).then_some(i);
                }
            }
            None => {
                ui.label("…");
            }
        }
    }
}

/// How a combination's run went, in a sentence.
fn outcome_text(o: &Outcome) -> String {
    if o.reached {
        format!(
            "Reached the goal in {:.1} s ({} collisions).",
            o.time.unwrap_or_default(),
            o.collisions
        )
    } else {
        format!("Did not reach the goal: {}.", o.why)
    }
}

impl LabWidget for ThreeSlots {
    /// The three slots as chosen, and how the run went.
    fn describe(&self) -> Option<String> {
        let s = &self.settings;
        let how = match (&self.problem, &self.run) {
            (Some(p), _) => format!("This combination cannot run: {p}."),
            (None, Some((o, _))) => outcome_text(o),
            (None, None) => "It has not run.".to_owned(),
        };
        Some(format!(
            "Body {}, behaviours {}, world {}. {how}",
            s.body, s.behaviours, s.world
        ))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.slots(ui);
        if let Some(p) = &self.problem {
            crate::widget::error_box(ui, "This combination cannot run", p);
        }
        let width = ui.available_width();
        let run = self.draw_run(ui, width);
        if let Some((o, _)) = &self.run {
            ui.label(RichText::new(outcome_text(o)).strong());
        }
        self.design_view(ui);
        ui.label(RichText::new("Every combination (tap a failure for why):").strong());
        self.matrix_ui(ui);
        if self.fill_matrix() {
            crate::widget::animate(ui);
        }
        self.exports(ui, run);
        if self.settings.task == Some(Task::FixTheCar) {
            self.task_ui(ui);
        }
    }

    fn state(&self) -> Option<String> {
        link::write(
            NAME,
            &self.settings,
            &self.initial,
            &Moment::<()>::default(),
        )
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let settings = match link::read::<Settings, ()>(NAME, state) {
            Ok((settings, _)) => settings,
            Err(why) => {
                let Some(old) = link::decode::<Legacy>(state) else {
                    return Err(why);
                };
                let name = |list: &[&str], i: usize| list.get(i).map(|s| (*s).to_owned());
                let (Some(body), Some(behaviours), Some(world)) = (
                    name(&BODIES, old.body),
                    name(&BEHAVIOURS, old.behaviours),
                    name(&WORLDS, old.world),
                ) else {
                    return Err("it names a slot this lab does not have".into());
                };
                Settings {
                    body,
                    behaviours,
                    world,
                    ..self.initial.clone()
                }
            }
        };
        // The old format's slots pass through the schema's choices too.
        link::check(NAME, &settings)?;
        // A link is written only when something changed: one holding the
        // lesson's own settings is not one of this widget's.
        if settings == self.initial {
            return Err("it holds nothing this widget would change".into());
        }
        self.settings = settings;
        self.changed = None;
        self.rerun();
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn widget(params: &[(&str, &str)]) -> ThreeSlots {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        ThreeSlots::new(settings)
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let old = link::encode(&(2_usize, 1_usize, 3_usize)).unwrap_or_default();
        let mut w = widget(&[]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(
            (
                w.settings.body.as_str(),
                w.settings.behaviours.as_str(),
                w.settings.world.as_str()
            ),
            ("omni", "wander-when-stuck", "beach")
        );
        // A slot the lab does not have: refused, the lesson's settings kept.
        let bad = link::encode(&(0_usize, 0_usize, 9_usize)).unwrap_or_default();
        let mut w = widget(&[("world", "office")]);
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.settings.world, "office");
    }

    #[test]
    fn the_slots_travel_in_the_link_and_the_matrix_is_a_table() {
        let mut w = widget(&[]);
        w.settings.world = "maze".into();
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
        while again.fill_matrix() {}
        let csv = again.matrix_csv();
        let rows = BODIES.len() * BEHAVIOURS.len() * WORLDS.len();
        assert_eq!(csv.lines().count(), rows + 1);
        assert!(csv.starts_with("body,behaviours,world,reached"), "{csv}");
    }
}
