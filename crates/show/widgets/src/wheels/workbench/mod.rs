//! The wheel workbench: place wheels on a chassis seen from above and watch
//! the constraint rows, rank, the three degrees, DOF and the ICR follow.
//!
//! - this file: the state, the constructor, the layout and the link;
//! - [`canvas`]: the drawing, and dragging and turning wheels;
//! - [`panels`]: the degrees, the rows, the wheel editor, the challenge
//!   and the robot file.

mod canvas;
mod panels;

use egui::{RichText, vec2};
use kinolab_common::Feedback;
use kinolab_wheels::challenge::Goal;
use kinolab_wheels::{Chassis, Wheel, WheelKind};
use serde::{Deserialize, Serialize};

use crate::widget::{LabWidget, Params};
use crate::{link, theme};

/// Positions snap to this grid (metres) and angles to this step (degrees)
/// while dragging, so wheels can share an axle exactly.
const GRID: f64 = 0.05;
const ANGLE_STEP: f64 = 5.0;

enum Task {
    None,
    Goal(Goal),
    FindDisagreeing {
        chosen: Vec<usize>,
        feedback: Option<Feedback>,
    },
}

pub(super) struct Workbench {
    start: Chassis,
    chassis: Chassis,
    selected: Option<usize>,
    task: Task,
    /// Half the width of the drawing, metres.
    extent: f64,
    /// Unsnapped position of the wheel being dragged.
    drag: Option<[f64; 2]>,
    file_text: String,
    file_error: Option<String>,
    message: Option<String>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let chassis = kinolab_schema::robot_of(p)?;
    let count = |key: &str| p.integer(key).map(|v| v as usize);
    let task = if let Some(target) = count("goal-maneuverability") {
        Task::Goal(Goal::Maneuverability {
            target,
            max_steer_inputs: count("max-steer-inputs"),
        })
    } else if let Some(target) = count("goal-mobility") {
        Task::Goal(Goal::Mobility { target })
    } else if let Some(target) = count("goal-dof") {
        Task::Goal(Goal::Dof { target })
    } else if let Some([x, y]) = p.numbers("goal-icr") {
        Task::Goal(Goal::IcrAt {
            x: *x,
            y: *y,
            tolerance: 0.05,
        })
    } else if p.yes("find-disagreeing") {
        Task::FindDisagreeing {
            chosen: Vec::new(),
            feedback: None,
        }
    } else {
        Task::None
    };
    Ok(Box::new(Workbench::new(chassis, task)))
}

/// How far the drawing must reach to show every wheel, the point where
/// their zero-motion lines meet, and a goal ICR.
fn extent_for(chassis: &Chassis, task: &Task) -> f64 {
    let mut reach = chassis
        .wheels()
        .iter()
        .map(|w| w.l + w.radius)
        .fold(0.3, f64::max)
        * 1.5;
    if let kinolab_wheels::Icr::Point { x, y } = chassis.analyze().icr {
        reach = reach.max(x.hypot(y) * 1.15);
    }
    if let Task::Goal(Goal::IcrAt { x, y, .. }) = task {
        reach = reach.max(x.hypot(*y) * 1.15);
    }
    reach.min(4.0)
}

impl Workbench {
    fn new(chassis: Chassis, task: Task) -> Self {
        let extent = extent_for(&chassis, &task);
        let file_text = chassis.to_json();
        Self {
            start: chassis.clone(),
            chassis,
            selected: None,
            task,
            extent,
            drag: None,
            file_text,
            file_error: None,
            message: None,
        }
    }

    /// Replace the wheels if they make a valid chassis; say why not otherwise.
    fn try_set(&mut self, wheels: Vec<Wheel>) -> bool {
        match Chassis::new(self.chassis.name().to_owned(), wheels) {
            Ok(chassis) => {
                self.set(chassis);
                true
            }
            Err(e) => {
                self.message = Some(e.to_string());
                false
            }
        }
    }

    /// Take a changed chassis; a challenge's old verdict no longer holds.
    fn set(&mut self, chassis: Chassis) {
        self.chassis = chassis;
        self.file_text = self.chassis.to_json();
        self.message = None;
        if let Task::FindDisagreeing { feedback, .. } = &mut self.task {
            *feedback = None;
        }
    }

    fn load(&mut self, chassis: Chassis) {
        self.extent = extent_for(&chassis, &self.task);
        self.set(chassis);
        self.selected = None;
        if let Task::FindDisagreeing { chosen, .. } = &mut self.task {
            chosen.clear();
        }
    }

    /// Steer wheel `i` to `beta`: through its linkage for a steered wheel,
    /// directly otherwise.
    fn steer(&mut self, i: usize, beta: f64) {
        if self.chassis.wheels()[i].kind == WheelKind::Steered {
            match self.chassis.steer(i, beta) {
                Ok(c) => self.set(c),
                Err(e) => self.message = Some(e.to_string()),
            }
        } else {
            let mut wheels = self.chassis.wheels().to_vec();
            wheels[i].beta = beta;
            self.try_set(wheels);
        }
    }
}

impl LabWidget for Workbench {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.toolbar(ui);
        let analysis = self.chassis.analyze();
        let wide = ui.available_width() > 760.0;
        let canvas_size = if wide {
            vec2(ui.available_width() * 0.56, 400.0)
        } else {
            vec2(ui.available_width(), 340.0)
        };
        if wide {
            ui.horizontal_top(|ui| {
                self.canvas(ui, &analysis, canvas_size);
                ui.vertical(|ui| {
                    self.degrees_panel(ui, &analysis);
                    ui.separator();
                    self.selected_editor(ui);
                });
            });
        } else {
            self.canvas(ui, &analysis, canvas_size);
            self.degrees_panel(ui, &analysis);
            self.selected_editor(ui);
        }
        // One line kept for messages, so the layout does not jump.
        let message = self.message.clone().unwrap_or_default();
        ui.label(RichText::new(message).color(theme::error_color(ui)));
        self.task_ui(ui);
        self.matrices(ui);
        self.file_ui(ui);
    }

    fn state(&self) -> Option<String> {
        (self.chassis != self.start)
            .then(|| link::encode(&LinkLayout::of(&self.chassis)))
            .flatten()
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(c) = link::decode::<LinkLayout>(state).and_then(LinkLayout::chassis) {
            self.load(c);
        }
        Ok(())
    }
}

/// A layout as a link carries it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct LinkLayout {
    name: String,
    wheels: Vec<LinkWheel>,
}

/// One wheel: its kind (0 fixed, 1 steered, 2 castor with `extra` its
/// offset, 3 Swedish with `extra` its roller angle, 4 ball), placement and
/// steering group.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct LinkWheel {
    kind: u8,
    alpha: f64,
    beta: f64,
    l: f64,
    radius: f64,
    extra: f64,
    group: Option<String>,
}

impl LinkLayout {
    fn of(chassis: &Chassis) -> Self {
        let wheels = chassis
            .wheels()
            .iter()
            .map(|w| {
                let (kind, extra) = match w.kind {
                    WheelKind::Fixed => (0, 0.0),
                    WheelKind::Steered => (1, 0.0),
                    WheelKind::Castor { offset } => (2, offset),
                    WheelKind::Swedish { gamma } => (3, gamma),
                    WheelKind::Spherical => (4, 0.0),
                };
                LinkWheel {
                    kind,
                    alpha: w.alpha,
                    beta: w.beta,
                    l: w.l,
                    radius: w.radius,
                    extra,
                    group: w.steer_group.clone(),
                }
            })
            .collect();
        Self {
            name: chassis.name().to_owned(),
            wheels,
        }
    }

    /// The chassis, if the link describes a valid one.
    fn chassis(self) -> Option<Chassis> {
        let wheels = self
            .wheels
            .into_iter()
            .map(|w| {
                let kind = match w.kind {
                    0 => WheelKind::Fixed,
                    1 => WheelKind::Steered,
                    2 => WheelKind::Castor { offset: w.extra },
                    3 => WheelKind::Swedish { gamma: w.extra },
                    4 => WheelKind::Spherical,
                    _ => return None,
                };
                Some(Wheel {
                    kind,
                    alpha: w.alpha,
                    beta: w.beta,
                    l: w.l,
                    radius: w.radius,
                    steer_group: w.group,
                })
            })
            .collect::<Option<Vec<_>>>()?;
        Chassis::new(self.name, wheels).ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_catalogue_layout_survives_a_link() {
        for entry in kinolab_wheels::catalogue::CATALOGUE {
            let Ok(chassis) = kinolab_wheels::catalogue::robot(entry.id) else {
                panic!("{}", entry.id)
            };
            let text = link::encode(&LinkLayout::of(&chassis)).unwrap_or_default();
            let back = link::decode::<LinkLayout>(&text).and_then(LinkLayout::chassis);
            assert_eq!(back.as_ref(), Some(&chassis), "{}", entry.id);
        }
        assert!(
            link::decode::<LinkLayout>("a_broken")
                .and_then(LinkLayout::chassis)
                .is_none()
        );
    }
}
