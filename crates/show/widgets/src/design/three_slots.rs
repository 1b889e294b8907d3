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
use crate::widget::{LabWidget, Params, feedback_ui};
use crate::{link, theme};

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
struct Choice {
    body: usize,
    behaviours: usize,
    world: usize,
}

impl Choice {
    fn names(self) -> (&'static str, &'static str, &'static str) {
        (
            BODIES[self.body],
            BEHAVIOURS[self.behaviours],
            WORLDS[self.world],
        )
    }
}

struct ThreeSlots {
    choice: Choice,
    initial: Choice,
    run: Option<(Outcome, RunReport)>,
    problem: Option<String>,
    /// The matrix so far, in bodies × behaviours × worlds order.
    matrix: Vec<Outcome>,
    /// Which slot changed last: 0 body, 1 behaviours, 2 world.
    changed: Option<usize>,
    task: bool,
    feedback: Option<Feedback>,
}

fn index(list: &[&str], name: Option<&str>) -> usize {
    name.and_then(|n| list.iter().position(|x| *x == n))
        .unwrap_or(0)
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let task = p.choice("task") == Some("fix-the-car");
    let choice = if task {
        Choice {
            body: 1,
            behaviours: 0,
            world: 2,
        }
    } else {
        Choice {
            body: index(&BODIES, p.choice("body")),
            behaviours: index(&BEHAVIOURS, p.choice("behaviours")),
            world: index(&WORLDS, p.choice("world")),
        }
    };
    let mut w = ThreeSlots {
        choice,
        initial: choice,
        run: None,
        problem: None,
        matrix: Vec::new(),
        changed: None,
        task,
        feedback: None,
    };
    w.rerun();
    Ok(Box::new(w))
}

impl ThreeSlots {
    fn rerun(&mut self) {
        let (b, s, w) = self.choice.names();
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
        let before = self.choice;
        let rows: [(&str, &[&str], &mut usize); 3] = [
            ("body", &BODIES, &mut self.choice.body),
            ("behaviours", &BEHAVIOURS, &mut self.choice.behaviours),
            ("world", &WORLDS, &mut self.choice.world),
        ];
        for (label, options, slot) in rows {
            ui.horizontal_wrapped(|ui| {
                ui.label(RichText::new(format!("{label}:")).strong());
                for (i, o) in options.iter().enumerate() {
                    ui.selectable_value(slot, i, *o);
                }
            });
        }
        if self.choice != before {
            self.changed = [
                self.choice.body != before.body,
                self.choice.behaviours != before.behaviours,
                self.choice.world != before.world,
            ]
            .iter()
            .position(|c| *c);
            self.rerun();
        }
    }

    fn draw_run(&self, ui: &mut egui::Ui, width: f32) {
        let (b, s, w) = self.choice.names();
        let Ok(setup) = setup(b, s, w) else { return };
        let world = &setup.world;
        let height = (width * 0.55).min(260.0);
        let (rect, _) = ui.allocate_exact_size(vec2(width, height), Sense::hover());
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
    }

    /// The three analysis patterns; the one whose slot changed is lit.
    fn design_view(&self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            for (k, (pattern, slot, participants)) in PATTERNS.iter().enumerate() {
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
                        ui.vertical(|ui| {
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
        });
    }

    fn matrix_ui(&self, ui: &mut egui::Ui) {
        crate::widget::sideways(ui, |ui| self.matrix_grid(ui));
    }

    fn matrix_grid(&self, ui: &mut egui::Ui) {
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
                        ui.label(format!("{b}, {s}"));
                        for w in WORLDS {
                            match self
                                .matrix
                                .iter()
                                .find(|o| o.body == b && o.behaviours == s && o.world == w)
                            {
                                Some(o) if o.reached => {
                                    ui.label(
                                        RichText::new(format!(
                                            "{:.0} s",
                                            o.time.unwrap_or_default()
                                        ))
                                        .color(theme::good_color(ui)),
                                    );
                                }
                                Some(o) => {
                                    ui.label(RichText::new("fails").color(theme::error_color(ui)))
                                        .on_hover_text(&o.why);
                                }
                                None => {
                                    ui.label("…");
                                }
                            }
                        }
                        ui.end_row();
                    }
                }
            });
    }
}

impl LabWidget for ThreeSlots {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.slots(ui);
        if let Some(p) = &self.problem {
            crate::widget::error_box(ui, "This combination cannot run", p);
        }
        let width = ui.available_width();
        self.draw_run(ui, width);
        if let Some((o, _)) = &self.run {
            let text = if o.reached {
                format!(
                    "Reached the goal in {:.1} s ({} collisions).",
                    o.time.unwrap_or_default(),
                    o.collisions
                )
            } else {
                format!("Did not reach the goal: {}.", o.why)
            };
            ui.label(RichText::new(text).strong());
        }
        self.design_view(ui);
        ui.label(RichText::new("Every combination (hover a failure for why):").strong());
        self.matrix_ui(ui);
        if self.fill_matrix() {
            crate::widget::animate(ui);
        }
        if self.task {
            ui.separator();
            ui.label(RichText::new("Task: the car fails in the maze. Change exactly one slot, keep the world, so that the robot reaches the goal; then check.").strong());
            if ui.button("Check").clicked() {
                let (b, s, w) = self.choice.names();
                self.feedback = Some(kinolab_design::exercise::fix_the_car(b, s, w));
            }
            feedback_ui(ui, self.feedback.as_ref());
        }
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.choice, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(c) = link::decode::<Choice>(state)
            && c.body < BODIES.len()
            && c.behaviours < BEHAVIOURS.len()
            && c.world < WORLDS.len()
        {
            self.choice = c;
            self.rerun();
        }
        Ok(())
    }
}
