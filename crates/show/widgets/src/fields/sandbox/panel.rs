//! The sandbox's side panel: presets, the list of primitives and the
//! selected one's editor, view switches, what the core found, the remedies
//! and the basin map.

use egui::{RichText, ScrollArea};
use kinolab_common::display::fixed;
use kinolab_fields::catalogue::PRESETS;
use kinolab_fields::descend::{Descent, Outcome};
use kinolab_fields::minima::Equilibrium as EquilibriumPoint;
use kinolab_fields::minima::Kind as Equilibrium;

use super::Sandbox;
use super::analysis::REMEDIES;
use super::piece::{Kind, Piece};

/// How close to a saddle (m) a stopped descent counts as stopped on it.
const SADDLE_NEAR: f64 = 0.05;

impl Sandbox {
    pub(super) fn panel(&mut self, ui: &mut egui::Ui) {
        ui.set_min_width(240.0);
        self.preset_ui(ui);
        if let Some(problem) = &self.problem {
            ui.colored_label(crate::theme::error_color(ui), problem);
        }
        ui.separator();
        self.pieces_ui(ui);
        ui.separator();
        ui.horizontal_wrapped(|ui| {
            ui.checkbox(&mut self.settings.streamlines, "streamlines");
            ui.checkbox(&mut self.settings.shading, "shading");
            ui.checkbox(&mut self.settings.unicycle, "unicycle");
        });
        self.findings_ui(ui);
        if self.settings.remedies {
            self.remedies_ui(ui);
        }
        self.basins_ui(ui);
        self.exercise_ui(ui);
    }

    fn preset_ui(&mut self, ui: &mut egui::Ui) {
        if self.task.is_some() {
            return;
        }
        let current = PRESETS.iter().find(|p| p.id == self.settings.preset);
        let mut chosen = None;
        // Labelled, so a screen reader names it too.
        egui::ComboBox::new(ui.scope_id().with("preset"), "field")
            .selected_text(current.map_or("Choose a field", |p| p.title))
            .width(230.0_f32.min(ui.available_width() - 60.0))
            .show_ui(ui, |ui| {
                for p in &PRESETS {
                    if crate::widget::choice(ui, current.is_some_and(|c| c.id == p.id), p.title)
                        .clicked()
                    {
                        chosen = Some(p);
                    }
                }
            });
        if let Some(p) = current {
            ui.label(RichText::new(p.shows).small());
        }
        if let Some(p) = chosen {
            self.load(p);
        }
    }

    /// How piece `i` may be edited (see [`super::exercise::Task::edit`]).
    pub(super) fn edit_mode(&self, i: usize) -> Option<bool> {
        match &self.task {
            Some(t) => t.edit(i, self.is_added(i)),
            None => self.settings.editable.then_some(false),
        }
    }

    fn pieces_ui(&mut self, ui: &mut egui::Ui) {
        ui.label(RichText::new(format!("Fields ({})", self.design.pieces.len())).strong());
        ScrollArea::vertical()
            .max_height(120.0)
            .id_salt("pieces")
            .show(ui, |ui| {
                for i in 0..self.design.pieces.len() {
                    let title = format!("{}. {}", i + 1, self.design.pieces[i].title());
                    if crate::widget::choice(ui, self.selected == Some(i), title).clicked() {
                        self.selected = Some(i);
                    }
                }
            });
        if let Some(i) = self.selected.filter(|&i| i < self.design.pieces.len()) {
            if let Some(locked) = self.edit_mode(i) {
                ui.push_id(i, |ui| {
                    if self.design.pieces[i].editor(ui, locked) {
                        self.changed();
                    }
                });
                if !locked && ui.button("Remove this field").clicked() {
                    self.design.pieces.remove(i);
                    self.selected = None;
                    self.changed();
                }
            } else {
                ui.label(RichText::new("This field is part of the exercise.").small());
            }
        }
        let added = self.design.pieces.len().saturating_sub(self.preset_pieces);
        let may_add = match &self.task {
            Some(t) => t.may_add(added),
            None => self.settings.editable,
        };
        if may_add && self.design.pieces.len() < 16 {
            ui.horizontal_wrapped(|ui| {
                ui.label("Add:");
                for k in Kind::ALL {
                    if ui.small_button(k.name()).clicked() {
                        let centre = [
                            (self.area.x_min + self.area.x_max) / 2.0,
                            (self.area.y_min + self.area.y_max) / 2.0,
                        ];
                        self.design.pieces.push(Piece::new(k, centre));
                        self.selected = Some(self.design.pieces.len() - 1);
                        self.changed();
                    }
                }
            });
        }
    }

    /// How many traps and saddles the field has.
    fn census(&self) -> (usize, usize) {
        let eq = &self.analysis.equilibria;
        let traps = eq
            .iter()
            .filter(|e| e.kind == Equilibrium::Stable && !self.is_goal([e.x, e.y]))
            .count();
        let saddles = eq.iter().filter(|e| e.kind == Equilibrium::Saddle).count();
        (traps, saddles)
    }

    /// The field's pieces, traps and saddles, and the point robot's
    /// descent, in words.
    pub(super) fn description(&self) -> String {
        let (traps, saddles) = self.census();
        let mut text = format!(
            "A field of {} piece{}: {traps} trap{} and {saddles} saddle{}.",
            self.design.pieces.len(),
            if self.design.pieces.len() == 1 {
                ""
            } else {
                "s"
            },
            if traps == 1 { "" } else { "s" },
            if saddles == 1 { "" } else { "s" },
        );
        if let Some(d) = &self.descent {
            text += &format!(
                " Point robot: {}.",
                outcome_text(d, &self.analysis.equilibria)
            );
        }
        text
    }

    fn findings_ui(&self, ui: &mut egui::Ui) {
        let eq = &self.analysis.equilibria;
        let (traps, saddles) = self.census();
        ui.label(format!(
            "Traps (stable, not the goal): {traps} · saddles: {saddles}"
        ));
        for e in eq
            .iter()
            .filter(|e| e.kind == Equilibrium::Stable && !self.is_goal([e.x, e.y]))
        {
            ui.label(
                RichText::new(format!("  trap at ({}, {})", fixed(e.x, 3), fixed(e.y, 3))).small(),
            );
        }
        if let Some(d) = &self.descent {
            ui.label(format!(
                "Point robot: {}",
                outcome_text(d, &self.analysis.equilibria)
            ));
        }
        if self.settings.unicycle
            && let Some(t) = &self.analysis.trail
        {
            let text = match t.outcome {
                Outcome::Reached => format!(
                    "reaches the goal in {} s",
                    fixed(t.poses.len() as f64 * 0.02, 1)
                ),
                Outcome::Trapped => "stops short of the goal".to_owned(),
                Outcome::MaxSteps => "still driving after 60 s".to_owned(),
            };
            ui.label(format!("Unicycle: {text}"));
        }
    }

    fn is_goal(&self, p: [f64; 2]) -> bool {
        self.design
            .goal
            .is_some_and(|g| (g[0] - p[0]).hypot(g[1] - p[1]) < 1e-6)
    }

    fn remedies_ui(&mut self, ui: &mut egui::Ui) {
        ui.separator();
        ui.label(RichText::new("Remedies from the start (tick to draw the path)").strong());
        let names = REMEDIES.iter().map(|r| r.name()).chain(["wavefront"]);
        for (k, name) in names.enumerate() {
            let run = self
                .analysis
                .remedies
                .get(k)
                .and_then(|r| r.descent.as_ref());
            let text = run.map_or_else(|| "…".to_owned(), |d| outcome_text(d, &[]));
            if ui
                .checkbox(&mut self.design.drawn[k], format!("{name}: {text}"))
                .changed()
            {
                self.design.write(&mut self.settings);
            }
        }
    }

    fn basins_ui(&mut self, ui: &mut egui::Ui) {
        match &self.analysis.basins {
            None => {
                if ui.button("Map the basins").clicked() {
                    self.analysis.map_basins(&self.area);
                }
            }
            Some(map) if !map.done() => {
                let f = map.cells.len() as f32 / map.starts.len() as f32;
                ui.add(egui::ProgressBar::new(f).text("mapping the basins…"));
            }
            Some(_) => {
                ui.horizontal(|ui| {
                    ui.label(RichText::new("Basins: green reaches the goal, red and purple are trapped, grey stalls.").small());
                    if ui.small_button("clear").clicked() {
                        self.analysis.basins = None;
                    }
                });
            }
        }
    }
}

/// How the point robot's descent ended; a stop on a saddle says so (it is
/// not a trap: the smallest nudge sideways frees the robot).
fn outcome_text(d: &Descent, equilibria: &[EquilibriumPoint]) -> String {
    let on_saddle = equilibria.iter().any(|e| {
        e.kind == Equilibrium::Saddle && (e.x - d.end[0]).hypot(e.y - d.end[1]) < SADDLE_NEAR
    });
    match d.outcome {
        Outcome::Reached => format!("reaches the goal in {} steps", d.steps()),
        Outcome::Trapped if on_saddle => format!(
            "stopped on a saddle at ({}, {}) after {} steps: balanced, not trapped (a nudge sideways frees it)",
            fixed(d.end[0], 2),
            fixed(d.end[1], 2),
            d.steps()
        ),
        Outcome::Trapped => format!(
            "stuck at ({}, {}) after {} steps",
            fixed(d.end[0], 2),
            fixed(d.end[1], 2),
            d.steps()
        ),
        Outcome::MaxSteps => format!("still going after {} steps", d.steps()),
    }
}
