//! Drive a robot on the floor: set wheel spins (forward kinematics) or a
//! chassis twist (inverse kinematics) and watch the trail, the ICR and each
//! wheel's velocity.

use std::collections::VecDeque;

use egui::{Key, RichText, Sense, Stroke, vec2};
use kinolab_lessons::WidgetSpec;
use kinolab_wheels::{Chassis, Icr, Vector3, WheelKind, integrate, twist_icr};

use super::chassis_view::{self as draw, View};
use super::wheel_workbench::robot_param;
use super::{LabWidget, known_params, shown};
use crate::theme;

#[derive(Clone, Copy, PartialEq, Eq)]
enum Mode {
    /// Spins in, twist out.
    Wheels,
    /// Twist in, spins (and steering) out.
    Twist,
}

struct Drive {
    start: Chassis,
    /// The robot as it is steered now.
    chassis: Chassis,
    mode: Mode,
    /// Commanded twist (twist mode).
    twist: [f64; 3],
    /// Commanded spins, rad/s (wheels mode); `None` for passive wheels.
    spins: Vec<Option<f64>>,
    pose: [f64; 3],
    trail: VecDeque<[f64; 2]>,
    running: bool,
}

pub(super) fn create(spec: &WidgetSpec) -> Result<Box<dyn LabWidget>, String> {
    known_params(spec, &["robot", "layout", "mode"])?;
    let chassis = robot_param(spec, "differential-drive")?;
    let mode = match spec.param("mode") {
        None | Some("twist") => Mode::Twist,
        Some("wheels") => Mode::Wheels,
        Some(other) => {
            return Err(format!(
                "Parameter `mode` must be wheels or twist, found `{other}`."
            ));
        }
    };
    Ok(Box::new(Drive::new(chassis, mode)))
}

/// Passive wheels (castors, balls) have no spin a learner can command.
fn driven(kind: WheelKind) -> bool {
    !matches!(kind, WheelKind::Castor { .. } | WheelKind::Spherical)
}

const TRAIL: usize = 1500;

impl Drive {
    fn new(chassis: Chassis, mode: Mode) -> Self {
        let mut drive = Self {
            start: chassis.clone(),
            spins: Vec::new(),
            chassis,
            mode,
            twist: [0.3, 0.0, 0.4],
            pose: [0.0, 0.0, 0.0],
            trail: VecDeque::new(),
            running: true,
        };
        drive.spins_from_twist();
        drive
    }

    /// Start the wheels mode from the spins that produce the current twist
    /// (or the nearest feasible one).
    fn spins_from_twist(&mut self) {
        let twist = self.feasible_twist(Vector3::from(self.twist));
        self.spins = match self.chassis.inverse(twist) {
            Ok(ik) => self
                .chassis
                .wheels()
                .iter()
                .zip(&ik.wheels)
                .map(|(w, c)| driven(w.kind).then_some(round2(c.spin)))
                .collect(),
            Err(_) => vec![None; self.chassis.wheels().len()],
        };
    }

    /// The requested twist projected onto what the wheels allow now (or, in
    /// twist mode, after steering): the robot never slides.
    fn feasible_twist(&self, want: Vector3<f64>) -> Vector3<f64> {
        let reach = self.chassis.analyze().reachable;
        let mut allowed = Vector3::zeros();
        for b in reach.basis() {
            allowed += b * b.dot(&want);
        }
        allowed
    }

    /// The twist to drive with this frame, and a note when the request
    /// could not be met as asked.
    fn current_twist(&mut self) -> (Vector3<f64>, Option<String>) {
        match self.mode {
            Mode::Twist => {
                let want = Vector3::from(self.twist);
                match self.chassis.inverse(want) {
                    Ok(ik) if ik.feasible => {
                        // Steer the wheels as inverse kinematics says.
                        for (i, c) in ik.wheels.iter().enumerate() {
                            let w = &self.chassis.wheels()[i];
                            if w.kind == WheelKind::Steered && (c.steer - w.beta).abs() > 1e-12 {
                                let mut wheels = self.chassis.wheels().to_vec();
                                wheels[i].beta = c.steer;
                                if let Ok(next) =
                                    Chassis::new(self.chassis.name().to_owned(), wheels)
                                {
                                    self.chassis = next;
                                }
                            }
                        }
                        (want, None)
                    }
                    Ok(ik) => {
                        let names: Vec<String> = ik
                            .violations
                            .iter()
                            .map(|v| match &v.group {
                                Some(g) => format!("the {g} linkage ({:+.2})", v.residual),
                                None => format!(
                                    "wheel {} would slide at {:+.2} m/s",
                                    v.wheel + 1,
                                    v.residual
                                ),
                            })
                            .collect();
                        (
                            Vector3::zeros(),
                            Some(format!(
                                "Not possible: {}. The robot waits; change the request.",
                                names.join(", ")
                            )),
                        )
                    }
                    Err(e) => (Vector3::zeros(), Some(e.to_string())),
                }
            }
            Mode::Wheels => match self.chassis.forward(&self.spins) {
                Ok(fk) => {
                    let note = if !fk.consistent {
                        Some(format!(
                            "The spins disagree (residual {:.3} m/s): real wheels would slip. The robot follows the best fit.",
                            fk.residual
                        ))
                    } else if !fk.determined {
                        Some("These spins do not pin the motion down; the robot takes the smallest motion that fits.".into())
                    } else {
                        None
                    };
                    (Vector3::from(fk.twist), note)
                }
                Err(e) => (Vector3::zeros(), Some(e.to_string())),
            },
        }
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            let before = self.mode;
            ui.selectable_value(&mut self.mode, Mode::Twist, "Set the twist (inverse)");
            ui.selectable_value(&mut self.mode, Mode::Wheels, "Set wheel spins (forward)");
            if before != self.mode && self.mode == Mode::Wheels {
                self.spins_from_twist();
            }
            ui.separator();
            if ui
                .button(if self.running { "Pause" } else { "Run" })
                .clicked()
            {
                self.running = !self.running;
            }
            if ui.button("Reset").clicked() {
                self.chassis = self.start.clone();
                self.pose = [0.0, 0.0, 0.0];
                self.trail.clear();
            }
            if ui.button("Stop").clicked() {
                self.twist = [0.0; 3];
                for s in self.spins.iter_mut().flatten() {
                    *s = 0.0;
                }
            }
        });
        match self.mode {
            Mode::Twist => {
                ui.vertical(|ui| {
                    for (k, (label, range)) in [
                        ("forward (m/s)", 1.0),
                        ("sideways (m/s)", 1.0),
                        ("turn (rad/s)", 2.0),
                    ]
                    .into_iter()
                    .enumerate()
                    {
                        ui.add(
                            egui::Slider::new(&mut self.twist[k], -range..=range)
                                .text(label)
                                .fixed_decimals(2),
                        );
                    }
                });
            }
            Mode::Wheels => {
                ui.vertical(|ui| {
                    for (i, s) in self.spins.iter_mut().enumerate() {
                        if let Some(s) = s {
                            ui.add(
                                egui::Slider::new(s, -20.0..=20.0)
                                    .text(format!("wheel {} (rad/s)", i + 1))
                                    .fixed_decimals(1),
                            );
                        }
                    }
                });
            }
        }
    }
}

fn round2(v: f64) -> f64 {
    (v * 100.0).round() / 100.0
}

impl LabWidget for Drive {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        let width = ui.available_width().min(900.0);
        let (response, painter) = ui.allocate_painter(vec2(width, 360.0), Sense::click());
        let rect = response.rect;
        let painter = painter.with_clip_rect(rect);
        painter.rect_filled(rect, 6.0, ui.visuals().extreme_bg_color);

        // Keyboard while the pointer is over the floor: arrows drive, Q/E slide.
        if response.hovered() && self.mode == Mode::Twist {
            ui.input(|i| {
                let step = 0.02;
                if i.key_down(Key::ArrowUp) {
                    self.twist[0] = (self.twist[0] + step).min(1.0);
                }
                if i.key_down(Key::ArrowDown) {
                    self.twist[0] = (self.twist[0] - step).max(-1.0);
                }
                if i.key_down(Key::ArrowLeft) {
                    self.twist[2] = (self.twist[2] + 2.0 * step).min(2.0);
                }
                if i.key_down(Key::ArrowRight) {
                    self.twist[2] = (self.twist[2] - 2.0 * step).max(-2.0);
                }
                if i.key_down(Key::Q) {
                    self.twist[1] = (self.twist[1] + step).min(1.0);
                }
                if i.key_down(Key::E) {
                    self.twist[1] = (self.twist[1] - step).max(-1.0);
                }
            });
        }

        let (twist, note) = self.current_twist();
        if self.running {
            let dt = f64::from(ui.input(|i| i.stable_dt)).clamp(0.0, 0.05);
            self.pose = integrate(self.pose, twist, dt);
            let last = self.trail.back().copied();
            let here = [self.pose[0], self.pose[1]];
            if last.is_none_or(|l| (l[0] - here[0]).hypot(l[1] - here[1]) > 0.01) {
                self.trail.push_back(here);
                if self.trail.len() > TRAIL {
                    self.trail.pop_front();
                }
            }
            if twist.norm() > 0.0 {
                ui.ctx().request_repaint();
            }
        }

        let extent = self
            .chassis
            .wheels()
            .iter()
            .map(|w| w.l + w.radius)
            .fold(0.3, f64::max)
            * 3.2;
        let view = View {
            centre: rect.center(),
            scale: (rect.height() / 2.0) / extent as f32,
            look_at: [self.pose[0], self.pose[1]],
            pose: self.pose,
        };
        let text = ui.visuals().text_color();
        draw::draw_grid(&painter, &view, rect, 0.25, text.gamma_multiply(0.08));
        let trail: Vec<egui::Pos2> = self.trail.iter().map(|p| view.world(*p)).collect();
        if trail.len() > 1 {
            painter.add(egui::Shape::line(
                trail,
                Stroke::new(2.0, theme::accent(ui).gamma_multiply(0.6)),
            ));
        }
        draw::draw_frame(&painter, &view, text.gamma_multiply(0.5), extent * 0.2);
        let arrow_scale = 0.5;
        for (i, w) in self.chassis.wheels().iter().enumerate() {
            let color = draw::wheel_color(i);
            draw::draw_wheel(&painter, &view, w, color, false);
            // Velocity of the contact point, drawn in the world.
            let [ux, uy] = {
                let c = draw::contact_point(w);
                [twist.x - twist.z * c[1], twist.y + twist.z * c[0]]
            };
            let from = view.robot(draw::contact_point(w));
            let d = view.robot_dir([ux * arrow_scale, uy * arrow_scale]);
            let to = view.world([
                view.robot_to_world(draw::contact_point(w))[0] + d[0],
                view.robot_to_world(draw::contact_point(w))[1] + d[1],
            ]);
            if (to - from).length() > 2.0 {
                painter.arrow(from, to - from, Stroke::new(2.0, color));
            }
        }
        draw::draw_icr(&painter, &view, &twist_icr(&twist), theme::accent(ui), rect);

        let c = |x: f64| shown(x, 5e-3);
        let icr_text = match twist_icr(&twist) {
            Icr::Point { x, y } => {
                format!("ICR at ({:.2}, {:.2}) m in the robot frame", c(x), c(y))
            }
            Icr::Infinity { .. } => "ICR at infinity: driving straight".to_owned(),
            _ => "standing still".to_owned(),
        };
        ui.label(format!(
            "Twist (forward, sideways, turn) = ({:.2} m/s, {:.2} m/s, {:.2} rad/s). {icr_text}. Pose x = {:.2} m, y = {:.2} m, θ = {:.0}°.",
            c(twist.x), c(twist.y), c(twist.z), c(self.pose[0]), c(self.pose[1]), c(self.pose[2].to_degrees())
        ));
        if self.mode == Mode::Twist
            && let Ok(ik) = self.chassis.inverse(twist)
        {
            let spins: Vec<String> = ik
                .wheels
                .iter()
                .enumerate()
                .map(|(i, c)| {
                    let w = &self.chassis.wheels()[i];
                    match w.kind {
                        WheelKind::Steered => format!(
                            "{}: {:.1} rad/s at β {:.0}°",
                            i + 1,
                            c.spin,
                            c.steer.to_degrees()
                        ),
                        WheelKind::Castor { .. } => format!(
                            "{}: {:.1} rad/s, swings {:.0}°/s",
                            i + 1,
                            c.spin,
                            c.steer_rate.to_degrees()
                        ),
                        _ => format!("{}: {:.1} rad/s", i + 1, c.spin),
                    }
                })
                .collect();
            ui.label(RichText::new(format!("Wheel spins. {}", spins.join("; "))).small());
        }
        if let Some(note) = note {
            ui.label(RichText::new(note).color(theme::warn_color(ui)));
        }
        ui.label(
            RichText::new(
                "Hover the floor and use the arrow keys to drive (Q and E slide sideways).",
            )
            .small(),
        );
    }
}
