//! The playground's graded tasks: reach the goal within a time with your
//! gains, or spot the unstable gain sets. The control crate checks both.

use egui::RichText;
use kinolab_common::Feedback;
use kinolab_common::display::fixed;
use kinolab_control::Gains;
use kinolab_control::exercise::Task;

use super::settings::{Settings, TaskKind, View, pose};
use super::{Exercise, Playground};
use crate::widget::feedback_ui;

/// The task the settings set up, if any, with the marks they carry.
pub(super) fn from_settings(set: &Settings) -> Result<Option<Exercise>, String> {
    let task = match set.task {
        Some(TaskKind::ReachWithin) => Task::ReachWithin {
            start: pose(set.start),
            goal: pose(set.goal),
            time_limit: set.time_limit,
            forward_only: set.forward_only,
        },
        Some(TaskKind::SpotUnstable) => {
            let sets = set
                .sets
                .iter()
                .map(|g| Gains::new(g[0], g[1], g[2]).map_err(|e| format!("parameter `sets`: {e}")))
                .collect::<Result<Vec<_>, _>>()?;
            Task::SpotUnstable { sets }
        }
        None => return Ok(None),
    };
    let marks = match &task {
        Task::SpotUnstable { sets } => {
            let marked = set.marked.clone().unwrap_or_default();
            (1..=sets.len())
                .map(|n| marked.contains(&(n as f64)))
                .collect()
        }
        Task::ReachWithin { .. } => Vec::new(),
    };
    Ok(Some(Exercise {
        task,
        marks,
        feedback: None,
    }))
}

impl Playground {
    pub(super) fn exercise_ui(&mut self, ui: &mut egui::Ui) {
        let gains = self.set.gains();
        let Some(ex) = &mut self.exercise else { return };
        let mut load = None;
        egui::Frame::group(ui.style()).show(ui, |ui| {
            ui.label(RichText::new(format!("Exercise: {}", ex.task.describe())).strong());
            match &ex.task {
                Task::SpotUnstable { sets } => {
                    for (i, (g, mark)) in sets.iter().zip(ex.marks.iter_mut()).enumerate() {
                        ui.horizontal(|ui| {
                            let text = format!("set {}: (k_ρ, k_α, k_β) = ({}, {}, {})", i + 1, g.k_rho, g.k_alpha, g.k_beta);
                            if ui.checkbox(mark, text).changed() {
                                ex.feedback = None;
                            }
                            if ui.small_button("try it").clicked() {
                                load = Some(*g);
                            }
                        });
                    }
                }
                Task::ReachWithin { start, goal, .. } => {
                    ui.label(RichText::new(format!(
                        "From ({}, {}) heading {}° to ({}, {}) heading {}°, with the gains on the sliders.",
                        start.x, start.y, fixed(start.theta.to_degrees(), 0), goal.x, goal.y, fixed(goal.theta.to_degrees(), 0)
                    )).small());
                }
            }
            if ui.button("Check").clicked() {
                ex.feedback = Some(match &ex.task {
                    Task::ReachWithin { .. } => match &gains {
                        Ok(g) => Feedback::from(ex.task.check_gains(*g)),
                        Err(e) => Feedback::from_error(e),
                    },
                    Task::SpotUnstable { .. } => Feedback::from(ex.task.check_marks(&ex.marks)),
                });
            }
            feedback_ui(ui, ex.feedback.as_ref());
        });
        if let Some(g) = load {
            self.set.gains = [g.k_rho, g.k_alpha, g.k_beta];
            if self.set.view == View::OpenVsClosed {
                self.show(View::Run);
            }
        }
    }
}
