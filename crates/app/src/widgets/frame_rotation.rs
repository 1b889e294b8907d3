//! Inertial and robot frames: turn the robot by θ, set a motion in the
//! inertial frame, and see R(θ) turn it into robot-frame motion.

use egui::{RichText, Sense, Stroke, vec2};
use kinolab_lessons::WidgetSpec;
use kinolab_wheels::{Vector3, rotation};

use super::{LabWidget, known_params, number_param, shown};
use crate::theme;

struct FrameRotation {
    theta_deg: f64,
    /// Inertial motion (ẋ_I, ẏ_I, θ̇).
    inertial: [f64; 3],
}

pub(super) fn create(spec: &WidgetSpec) -> Result<Box<dyn LabWidget>, String> {
    known_params(spec, &["theta-deg"])?;
    let theta_deg = number_param(spec, "theta-deg", 30.0, -180.0..=180.0)?;
    Ok(Box::new(FrameRotation {
        theta_deg,
        inertial: [1.0, 0.0, 0.0],
    }))
}

fn fmt(v: f64) -> String {
    format!("{:+.3}", shown(v, 5e-4))
}

impl LabWidget for FrameRotation {
    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.vertical(|ui| {
            ui.add(
                egui::Slider::new(&mut self.theta_deg, -180.0..=180.0)
                    .text("heading θ (°)")
                    .fixed_decimals(0),
            );
            ui.add(
                egui::Slider::new(&mut self.inertial[0], -1.0..=1.0)
                    .text("along X_I (m/s)")
                    .fixed_decimals(2),
            );
            ui.add(
                egui::Slider::new(&mut self.inertial[1], -1.0..=1.0)
                    .text("along Y_I (m/s)")
                    .fixed_decimals(2),
            );
            ui.add(
                egui::Slider::new(&mut self.inertial[2], -1.0..=1.0)
                    .text("turn (rad/s)")
                    .fixed_decimals(2),
            );
        });
        let theta = self.theta_deg.to_radians();
        let r = rotation(theta);
        let robot = r * Vector3::from(self.inertial);

        let size = vec2(ui.available_width().min(720.0), 260.0);
        let (response, painter) = ui.allocate_painter(size, Sense::hover());
        let rect = response.rect;
        painter.rect_filled(rect, 6.0, ui.visuals().extreme_bg_color);
        let text = ui.visuals().text_color();
        let accent = theme::accent(ui);
        let good = theme::good_color(ui);
        let scale = rect.height() * 0.36;
        // Inertial frame at the left, robot in the middle.
        let origin = rect.left_bottom() + vec2(40.0, -30.0);
        let inertial_stroke = Stroke::new(1.5, text.gamma_multiply(0.6));
        painter.arrow(origin, vec2(scale * 0.6, 0.0), inertial_stroke);
        painter.arrow(origin, vec2(0.0, -scale * 0.6), inertial_stroke);
        let font = egui::FontId::proportional(13.0);
        painter.text(
            origin + vec2(scale * 0.65, 0.0),
            egui::Align2::LEFT_CENTER,
            "X_I",
            font.clone(),
            text,
        );
        painter.text(
            origin + vec2(0.0, -scale * 0.65),
            egui::Align2::CENTER_BOTTOM,
            "Y_I",
            font.clone(),
            text,
        );
        let p = rect.center() + vec2(-40.0, 10.0);
        let (s, c) = theta.sin_cos();
        let x_r = vec2(c as f32, -s as f32) * scale * 0.7;
        let y_r = vec2(-s as f32, -c as f32) * scale * 0.7;
        // A body outline along the robot's x axis.
        let body: Vec<egui::Pos2> = [(0.45, 0.3), (0.45, -0.3), (-0.35, -0.3), (-0.35, 0.3)]
            .iter()
            .map(|(a, b)| p + x_r * *a + y_r * *b)
            .collect();
        painter.add(egui::Shape::convex_polygon(
            body,
            accent.gamma_multiply(0.12),
            Stroke::new(1.0, accent),
        ));
        painter.arrow(p, x_r, Stroke::new(2.0, accent));
        painter.arrow(p, y_r, Stroke::new(2.0, accent));
        painter.text(
            p + x_r * 1.1,
            egui::Align2::CENTER_CENTER,
            "X_R",
            font.clone(),
            accent,
        );
        painter.text(
            p + y_r * 1.1,
            egui::Align2::CENTER_CENTER,
            "Y_R",
            font.clone(),
            accent,
        );
        // The motion, drawn in the world.
        let v = vec2(self.inertial[0] as f32, -self.inertial[1] as f32) * scale * 0.8;
        if v.length() > 1.0 {
            painter.arrow(p, v, Stroke::new(3.0, good));
        }
        painter.text(
            rect.right_top() + vec2(-10.0, 10.0),
            egui::Align2::RIGHT_TOP,
            format!("θ = {:.0}°", self.theta_deg),
            font,
            text,
        );

        let mono = |s: String| RichText::new(s).monospace();
        ui.horizontal(|ui| {
            ui.label("robot-frame motion = R(θ) × inertial motion:");
        });
        egui::Grid::new(ui.scope_id().with("r"))
            .num_columns(7)
            .spacing(vec2(8.0, 2.0))
            .show(ui, |ui| {
                for row in 0..3 {
                    ui.label(mono(fmt(robot[row])).color(good));
                    ui.label(if row == 1 { "=" } else { " " });
                    for col in 0..3 {
                        ui.label(mono(fmt(r[(row, col)])));
                    }
                    ui.label(if row == 1 { "×" } else { " " });
                    ui.label(mono(fmt(self.inertial[row])));
                    ui.end_row();
                }
            });
        ui.label(RichText::new(format!(
            "Forward {:.2} m/s, to the left {:.2} m/s, turning {:.2} rad/s, as the robot sees it. The inverse of R(θ) is its transpose: applying it brings the motion back.",
            shown(robot.x, 5e-3),
            shown(robot.y, 5e-3),
            shown(robot.z, 5e-3)
        )).small());
    }
}
