//! The sandbox's graded tasks; the fields crate checks each one.

use egui::{DragValue, RichText};
use kinolab_common::Feedback;
use kinolab_fields::exercise::{check_escape, check_stand_off, check_vector};
use kinolab_fields::{Field, Vec2};

use super::piece::Kind;
use super::{Design, Sandbox, Settings, TaskName};
use crate::widget::feedback_ui;

pub(super) enum TaskKind {
    /// Work out F at `at`; `answer` is what the learner typed.
    VectorAt { at: [f64; 2], answer: [f64; 2] },
    /// Add one primitive so the robot escapes.
    Escape,
    /// Set the wall's range and gain so the robot stops `clearance` away.
    StandOff { wall: usize, clearance: f64 },
}

pub(super) struct Task {
    pub kind: TaskKind,
    pub feedback: Option<Feedback>,
}

/// The task a lesson set up, if any.
pub(super) fn from_settings(s: &Settings, design: &Design) -> Result<Option<Task>, String> {
    let kind = match s.task {
        Some(TaskName::VectorAt) => TaskKind::VectorAt {
            at: s.at.ok_or("`task: vector-at` needs `at: x, y`")?,
            answer: [0.0, 0.0],
        },
        Some(TaskName::Escape) => TaskKind::Escape,
        Some(TaskName::StandOff) => TaskKind::StandOff {
            wall: design
                .pieces
                .iter()
                .position(|q| q.kind == Kind::Perpendicular)
                .ok_or("`task: stand-off` needs a preset with a wall")?,
            clearance: s.clearance,
        },
        None => return Ok(None),
    };
    Ok(Some(Task {
        kind,
        feedback: None,
    }))
}

impl Task {
    /// The point the task asks about, if any.
    pub fn point(&self) -> Option<[f64; 2]> {
        match self.kind {
            TaskKind::VectorAt { at, .. } => Some(at),
            _ => None,
        }
    }

    pub fn hides_readout(&self) -> bool {
        matches!(self.kind, TaskKind::VectorAt { .. })
    }

    /// How piece `i` may be edited: `None` not at all, `Some(true)` range
    /// and gain only, `Some(false)` freely.
    pub fn edit(&self, i: usize, added: bool) -> Option<bool> {
        match self.kind {
            TaskKind::VectorAt { .. } => None,
            TaskKind::Escape => added.then_some(false),
            TaskKind::StandOff { wall, .. } => (i == wall).then_some(true),
        }
    }

    /// Whether the learner may add a piece when `added` are already added.
    pub fn may_add(&self, added: usize) -> bool {
        matches!(self.kind, TaskKind::Escape) && added == 0
    }
}

impl Sandbox {
    /// The exercise box under the panel.
    pub(super) fn exercise_ui(&mut self, ui: &mut egui::Ui) {
        let (Some(field), Some(task)) = (self.field.clone(), self.task.as_mut()) else {
            return;
        };
        let base = self.preset_pieces;
        let start = Vec2::new(self.design.start[0], self.design.start[1]);
        egui::Frame::group(ui.style()).show(ui, |ui| {
            let title = match &task.kind {
                TaskKind::VectorAt { at, .. } => format!("Exercise: what vector does the robot feel at P = ({}, {})?", at[0], at[1]),
                TaskKind::Escape => "Exercise: add one field so the robot reaches the goal.".to_owned(),
                TaskKind::StandOff { clearance, .. } => {
                    format!("Exercise: choose the wall's range and gain so the robot stops at least {clearance} m from it.")
                }
            };
            ui.label(RichText::new(title).strong());
            if let TaskKind::VectorAt { answer, .. } = &mut task.kind {
                ui.horizontal(|ui| {
                    ui.label("F =");
                    ui.add(DragValue::new(&mut answer[0]).speed(0.01).max_decimals(3).prefix("x "));
                    ui.add(DragValue::new(&mut answer[1]).speed(0.01).max_decimals(3).prefix("y "));
                });
            }
            if ui.button("Check").clicked() {
                task.feedback = Some(check(&task.kind, &field, base, start));
            }
            feedback_ui(ui, task.feedback.as_ref());
        });
    }
}

fn check(kind: &TaskKind, field: &Field, base: usize, start: Vec2) -> Feedback {
    match kind {
        TaskKind::VectorAt { at, answer } => check_vector(field, Vec2::new(at[0], at[1]), *answer),
        TaskKind::Escape => {
            let mut preset = field.clone();
            let added = preset
                .primitives
                .split_off(base.min(preset.primitives.len()));
            Feedback::from(check_escape(&preset, &added, start))
        }
        TaskKind::StandOff { wall, clearance } => {
            Feedback::from(check_stand_off(field, *wall, start, *clearance))
        }
    }
}
