//! The workbench's panels: the toolbar, the three degrees and the ICR in
//! words, the constraint rows, the selected wheel's numbers, the challenge,
//! and the robot file.

use egui::{RichText, vec2};
use kinolab_common::angle::snap;
use kinolab_common::display::{fixed, signed};
use kinolab_wheels::catalogue::{self, CATALOGUE};
use kinolab_wheels::challenge::check_disagreeing;
use kinolab_wheels::{Analysis, Chassis, Icr, Wheel, WheelKind};

use super::{GRID, Task, Workbench};
use crate::theme;
use crate::wheels::chassis::wheel_color;
use crate::widget::feedback_ui;

impl Workbench {
    /// A free spot for a new wheel: on the grid, away from the others.
    fn free_spot(&self) -> [f64; 2] {
        let taken = |x: f64, y: f64| {
            self.chassis.wheels().iter().any(|w| {
                let [wx, wy] = w.position();
                (wx - x).hypot(wy - y) < 0.12
            })
        };
        for ring in 1..8 {
            let r = ring as f64 * 0.15;
            for k in 0..8 {
                let a = k as f64 * std::f64::consts::FRAC_PI_4;
                let (x, y) = (snap(r * a.cos(), GRID), snap(r * a.sin(), GRID));
                if !taken(x, y) {
                    return [x, y];
                }
            }
        }
        [0.0, 0.0]
    }

    fn add_wheel(&mut self, kind: WheelKind) {
        let [x, y] = self.free_spot();
        let mut wheels = self.chassis.wheels().to_vec();
        wheels.push(Wheel::at(kind, x, y, 0.0, 0.08));
        if self.try_set(wheels) {
            self.selected = Some(self.chassis.wheels().len() - 1);
        }
    }

    pub(super) fn toolbar(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            let label = ui.label("Start from");
            let mut pick = None;
            let combo = egui::ComboBox::from_id_salt(ui.scope_id().with("robot"))
                .selected_text(self.chassis.name().to_owned())
                .width(210.0)
                .show_ui(ui, |ui| {
                    for entry in CATALOGUE {
                        if crate::widget::choice(ui, self.chassis.name() == entry.name, entry.name)
                            .on_hover_text(entry.summary)
                            .clicked()
                        {
                            pick = Some(entry.id);
                        }
                    }
                });
            combo.response.labelled_by(label.id);
            if let Some(id) = pick
                && let Ok(chassis) = catalogue::robot(id)
            {
                self.load(chassis);
            }
            if ui.button("Reset").clicked() {
                self.load(self.start.clone());
            }
            // The view never re-fits by itself (a wheel would jump from
            // under the pointer); this brings every wheel and the ICR in.
            if ui
                .button("Fit all")
                .on_hover_text("Zoom so that every wheel and the ICR are on the canvas")
                .clicked()
            {
                self.extent = super::extent_for(&self.chassis, &self.task);
            }
            ui.separator();
            ui.label("Add");
            for (label, kind) in [
                ("fixed", WheelKind::Fixed),
                ("steered", WheelKind::Steered),
                ("castor", WheelKind::Castor { offset: 0.04 }),
                ("Swedish", WheelKind::Swedish { gamma: 0.0 }),
                ("ball", WheelKind::Spherical),
            ] {
                if ui.small_button(label).clicked() {
                    self.add_wheel(kind);
                }
            }
            // Always there (greyed out until a wheel is selected), so
            // selecting a wheel never re-wraps the toolbar and moves the canvas.
            let remove = ui
                .add_enabled(
                    self.selected.is_some(),
                    egui::Button::new("Remove selected").small(),
                )
                .on_disabled_hover_text("Click a wheel first");
            if let Some(i) = self.selected
                && remove.clicked()
            {
                let mut wheels = self.chassis.wheels().to_vec();
                wheels.remove(i);
                if self.try_set(wheels) {
                    self.selected = None;
                }
            }
        });
    }

    /// The wheels, the degrees and the ICR in words.
    pub(super) fn description(&self) -> String {
        let a = self.chassis.analyze();
        let wheels = self.chassis.wheels();
        let mut kinds: Vec<String> = Vec::new();
        for w in wheels {
            let name = w.kind.name().to_owned();
            if !kinds.contains(&name) {
                kinds.push(name);
            }
        }
        format!(
            "{} wheel{} ({}). Mobility δm {}, steerability δs {}, maneuverability δM {}; {}. {}",
            wheels.len(),
            if wheels.len() == 1 { "" } else { "s" },
            kinds.join(", "),
            a.mobility,
            a.steerability,
            a.maneuverability,
            if a.holonomic {
                "holonomic"
            } else {
                "not holonomic"
            },
            icr_text(&a)
        )
    }

    pub(super) fn degrees_panel(&self, ui: &mut egui::Ui, a: &Analysis) {
        let strong = |ui: &mut egui::Ui, s: String| {
            ui.label(RichText::new(s).strong());
        };
        egui::Grid::new(ui.scope_id().with("degrees"))
            .num_columns(2)
            .spacing(vec2(14.0, 4.0))
            .show(ui, |ui| {
                ui.label("rank C1");
                strong(ui, a.rank_c1.to_string());
                ui.end_row();
                ui.label("mobility δm = 3 − rank C1");
                strong(ui, a.mobility.to_string());
                ui.end_row();
                ui.label(format!(
                    "steerability δs ({} input{})",
                    a.steering_inputs,
                    if a.steering_inputs == 1 { "" } else { "s" }
                ));
                strong(ui, a.steerability.to_string());
                ui.end_row();
                ui.label("maneuverability δM = δm + δs");
                strong(ui, a.maneuverability.to_string());
                ui.end_row();
                ui.label("DDOF (= δm)");
                strong(ui, a.mobility.to_string());
                ui.end_row();
                ui.label("DOF (Lie brackets)");
                strong(ui, a.dof.to_string());
                ui.end_row();
                ui.label("holonomic (DDOF = DOF)");
                strong(
                    ui,
                    if a.holonomic {
                        "yes".into()
                    } else {
                        "no".into()
                    },
                );
                ui.end_row();
            });
        let icr = icr_text(a);
        ui.label(RichText::new(icr).color(theme::accent(ui)));
    }

    pub(super) fn matrices(&self, ui: &mut egui::Ui) {
        let rows_for = self.chassis.c1_wheels();
        if rows_for.is_empty() {
            ui.label("No fixed or steered wheel: C1 and J1 have no rows, so nothing restricts the chassis.");
            return;
        }
        let mono = |s: String| RichText::new(s).monospace();
        crate::widget::sideways(ui, |ui| {
            egui::Grid::new(ui.scope_id().with("rows"))
                .num_columns(4)
                .striped(true)
                .spacing(vec2(12.0, 2.0))
                .show(ui, |ui| {
                    ui.label(RichText::new("wheel").strong());
                    ui.label(RichText::new("rolling row J1 (= r × spin)").strong());
                    ui.label(RichText::new("r").strong());
                    ui.label(RichText::new("sliding row C1 (= 0)").strong());
                    ui.end_row();
                    for &i in &rows_for {
                        let w = &self.chassis.wheels()[i];
                        let rows = w.rows();
                        let color = wheel_color(i);
                        let mut label =
                            RichText::new(format!("{} {}", i + 1, w.kind.name())).color(color);
                        if self.selected == Some(i) {
                            label = label.strong().background_color(color.gamma_multiply(0.15));
                        }
                        ui.label(label);
                        let v = |r: kinolab_wheels::Vector3<f64>| {
                            format!("[{} {} {}]", signed(r.x, 3), signed(r.y, 3), signed(r.z, 3))
                        };
                        ui.label(mono(v(rows.rolling)));
                        ui.label(mono(fixed(w.radius, 3)));
                        ui.label(mono(v(rows.sliding)));
                        ui.end_row();
                    }
                });
        });
    }

    pub(super) fn selected_editor(&mut self, ui: &mut egui::Ui) {
        let Some(i) = self.selected else {
            ui.label(RichText::new("Click a wheel to edit its numbers.").small());
            return;
        };
        let Some(w) = self.chassis.wheels().get(i).cloned() else {
            self.selected = None;
            return;
        };
        ui.label(
            RichText::new(format!("Wheel {} ({})", i + 1, w.kind.name()))
                .strong()
                .color(wheel_color(i)),
        );
        let mut edited = w.clone();
        let mut steered_to = None;
        egui::Grid::new(ui.scope_id().with("edit"))
            .num_columns(2)
            .show(ui, |ui| {
                metres_field(ui, "l (m)", &mut edited.l, 0.0..=3.0);
                if let Some(alpha) = degrees_field(ui, "α (°)", w.alpha, 180.0) {
                    edited.alpha = alpha;
                }
                steered_to = degrees_field(ui, "β (°)", w.beta, 180.0);
                metres_field(ui, "r (m)", &mut edited.radius, 0.01..=1.0);
                kind_fields(ui, &mut edited);
            });
        if let Some(beta) = steered_to {
            // Steering goes through the linkage, like the knob.
            self.steer(i, beta);
        } else if edited != w {
            let mut wheels = self.chassis.wheels().to_vec();
            wheels[i] = edited;
            self.try_set(wheels);
        }
    }

    pub(super) fn task_ui(&mut self, ui: &mut egui::Ui) {
        match &mut self.task {
            Task::None => {}
            Task::Goal(goal) => {
                ui.label(RichText::new(format!("Challenge: {}", goal.describe())).strong());
                feedback_ui(ui, Some(&goal.check(&self.chassis)));
            }
            Task::FindDisagreeing { chosen, feedback } => {
                ui.label(RichText::new("Challenge: this layout cannot move. Click the wheels that disagree with the others, then check.").strong());
                ui.horizontal(|ui| {
                    let mut names: Vec<usize> = chosen.iter().map(|i| i + 1).collect();
                    names.sort_unstable();
                    let names: Vec<String> = names.iter().map(usize::to_string).collect();
                    ui.label(if names.is_empty() {
                        "No wheel marked.".to_owned()
                    } else {
                        format!("Marked: {}", names.join(", "))
                    });
                    if ui.button("Check").clicked() {
                        *feedback = Some(check_disagreeing(&self.chassis, chosen));
                    }
                });
                feedback_ui(ui, feedback.as_ref());
            }
        }
    }

    pub(super) fn file_ui(&mut self, ui: &mut egui::Ui) {
        egui::CollapsingHeader::new("Robot file (save and load)")
            .id_salt(ui.scope_id().with("file"))
            .show(ui, |ui| {
                ui.label(RichText::new("The same JSON the command line reads: copy it to save the robot, paste one and load it.").small());
                ui.add(
                    egui::TextEdit::multiline(&mut self.file_text)
                        .code_editor()
                        .desired_rows(8)
                        .desired_width(f32::INFINITY),
                );
                ui.horizontal(|ui| {
                    if ui.button("Load this file").clicked() {
                        match Chassis::from_json(&self.file_text) {
                            Ok(c) => {
                                self.load(c);
                                self.file_error = None;
                            }
                            Err(e) => self.file_error = Some(e.to_string()),
                        }
                    }
                    if ui.button("Copy").clicked() {
                        ui.ctx().copy_text(self.file_text.clone());
                    }
                });
                if let Some(e) = &self.file_error {
                    ui.label(RichText::new(e).color(theme::error_color(ui)));
                }
            });
    }
}

/// A length in metres, edited in place.
fn metres_field(
    ui: &mut egui::Ui,
    label: &str,
    value: &mut f64,
    range: std::ops::RangeInclusive<f64>,
) {
    ui.label(label);
    ui.add(
        egui::DragValue::new(value)
            .speed(0.005)
            .range(range)
            .clamp_existing_to_range(false)
            .max_decimals(3),
    );
    ui.end_row();
}

/// An angle shown in degrees: the new value in radians when the learner
/// changed it this frame (so an untouched angle is never rounded by the
/// trip through degrees).
fn degrees_field(ui: &mut egui::Ui, label: &str, radians: f64, limit: f64) -> Option<f64> {
    ui.label(label);
    let mut degrees = radians.to_degrees();
    let changed = ui
        .add(
            egui::DragValue::new(&mut degrees)
                .speed(0.5)
                .range(-limit..=limit)
                .clamp_existing_to_range(false)
                .max_decimals(2),
        )
        .changed();
    ui.end_row();
    changed.then(|| degrees.to_radians())
}

/// The castor offset, the Swedish roller angle, or a steered wheel's group.
fn kind_fields(ui: &mut egui::Ui, edited: &mut Wheel) {
    match &mut edited.kind {
        WheelKind::Castor { offset } => metres_field(ui, "d (m)", offset, 0.005..=0.5),
        WheelKind::Swedish { gamma } => {
            if let Some(g) = degrees_field(ui, "γ (°)", *gamma, 80.0) {
                *gamma = g;
            }
        }
        WheelKind::Steered => {
            ui.label("steering group");
            let mut group = edited.steer_group.clone().unwrap_or_default();
            let edit = egui::TextEdit::singleline(&mut group)
                .desired_width(90.0)
                .hint_text("own input");
            if ui.add(edit).changed() {
                edited.steer_group = (!group.trim().is_empty()).then(|| group.trim().to_owned());
            }
            ui.end_row();
        }
        _ => {}
    }
}

/// Where the instantaneous centre of rotation is, as a sentence.
fn icr_text(a: &Analysis) -> String {
    let pair = |p: [f64; 2]| format!("({}, {})", fixed(p[0], 2), fixed(p[1], 2));
    match a.icr {
        Icr::Anywhere => "ICR: anywhere (no standard wheel objects).".to_owned(),
        Icr::Line { point, direction } => format!(
            "ICR: on the line through {} along {}.",
            pair(point),
            pair(direction)
        ),
        Icr::Point { x, y } => format!("ICR: at {} in the robot frame.", pair([x, y])),
        Icr::Infinity { direction } => format!(
            "ICR: at infinity. The robot can only translate, along {}.",
            pair(direction)
        ),
        Icr::None => {
            "ICR: none. The zero-motion lines share no point: the robot cannot move.".to_owned()
        }
    }
}
