//! The scoreboard and the graded tasks.

use egui::RichText;
use kinolab_architectures::Architecture;
use kinolab_architectures::arena::Entrant;
use kinolab_architectures::exercise::{MISSIONS, pick_architecture, survive_the_person};
use kinolab_common::display::fixed;

use super::ArchitectureArena;
use super::canvas::NAMES;
use super::settings::Task;
use crate::widget::feedback_ui;

/// The scoreboard's rows.
const ROWS: [&str; 10] = [
    "doing",
    "reached at (s)",
    "path (m)",
    "closest (m)",
    "collisions",
    "replans",
    "model age, mean / max (s)",
    "cells expanded per plan",
    "behaviour evaluations per step",
    "time per step here (µs)",
];

/// Row `row` of robot `e`'s column; `spent`: microseconds its steps took.
fn cell(row: usize, e: &Entrant, spent: f64) -> String {
    let opt = |v: Option<f64>, d: usize| v.map_or("–".to_owned(), |v| fixed(v, d));
    let s = &e.scores;
    match row {
        0 => e.activity.clone(),
        1 => opt(s.time, 1),
        2 => fixed(s.path_length, 1),
        3 => fixed(s.min_clearance.max(0.0), 2),
        4 => s.collisions.to_string(),
        5 => s.replans.to_string(),
        6 => format!("{} / {}", opt(s.model_age_mean, 1), opt(s.model_age_max, 1)),
        7 => fixed(s.expanded_per_plan, 0),
        8 => fixed(s.evaluations_per_cycle, 1),
        _ => fixed(spent / s.cycles.max(1) as f64, 0),
    }
}

impl ArchitectureArena {
    pub(super) fn board(&mut self, ui: &mut egui::Ui) {
        let Some(player) = &mut self.player else {
            return;
        };
        let race = player.state();
        let arena = &race.arena;
        crate::widget::sideways(ui, |ui| {
            egui::Grid::new(ui.scope_id().with("scores"))
                .striped(true)
                .num_columns(4)
                .show(ui, |ui| {
                    ui.label("");
                    for (i, name) in NAMES.iter().enumerate() {
                        ui.label(
                            RichText::new(*name)
                                .strong()
                                .color(crate::theme::ARCHITECTURE_COLORS[i]),
                        );
                    }
                    ui.end_row();
                    for (row, label) in ROWS.iter().enumerate() {
                        ui.label(*label);
                        for (e, spent) in arena.entrants.iter().zip(race.spent) {
                            ui.label(cell(row, e, spent));
                        }
                        ui.end_row();
                    }
                });
        });
        ui.label(RichText::new("Shaded cells: the chosen robot's map (darker where a bumper felt something); dashes: its plan; faint cells: the search it is running. Model age: how old the sensing behind the plan was while the robot acted.").small());
    }

    pub(super) fn task_ui(&mut self, ui: &mut egui::Ui, task: Task) {
        ui.separator();
        match task {
            Task::SurviveThePerson => {
                ui.label(RichText::new("Task: set the planning cost so the hierarchical robot reaches the goal without touching the person, then check.").strong());
                if ui.button("Check").clicked() {
                    self.feedback = Some(
                        survive_the_person(self.settings.planning_cost)
                            .unwrap_or_else(|e| kinolab_common::Feedback::not_yet(e.to_string())),
                    );
                }
            }
            Task::PickArchitecture => {
                ui.label(RichText::new("Task: pick an architecture for each mission; the check runs each pick in the office.").strong());
                for (m, pick) in MISSIONS.iter().zip(self.settings.picks.0.iter_mut()) {
                    ui.horizontal_wrapped(|ui| {
                        ui.label(format!("{}:", m.name));
                        for kind in Architecture::ALL {
                            if crate::widget::choice(ui, *pick == kind, kind.name()).clicked() {
                                *pick = kind;
                                self.feedback = None;
                            }
                        }
                    });
                }
                if ui.button("Check by running").clicked() {
                    let picks = self.settings.picks.0;
                    self.feedback = Some(
                        pick_architecture(picks)
                            .unwrap_or_else(|e| kinolab_common::Feedback::not_yet(e.to_string())),
                    );
                }
            }
        }
        feedback_ui(ui, self.feedback.as_ref());
    }
}
