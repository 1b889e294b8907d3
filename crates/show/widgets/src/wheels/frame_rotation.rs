//! Inertial and robot frames: turn the robot by θ, set a motion in the
//! inertial frame, and see R(θ) turn it into robot-frame motion.

use egui::{Painter, Pos2, Rect, RichText, Sense, Stroke, Vec2, vec2};
use kinolab_common::display::{fixed, signed};
use kinolab_wheels::{Vector3, rotation};
use serde::{Deserialize, Serialize};

use crate::draw::labels::Labels;
use crate::draw::{axes, canvas};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params, range};

/// The widget's name in the schema.
const NAME: &str = "frame-rotation";

/// The heading and the inertial motion (ẋ_I, ẏ_I, θ̇): what the lesson
/// sets and a link carries, the schema's parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
struct Settings {
    theta_deg: f64,
    motion: [f64; 3],
}

/// The links of the first format.
#[derive(Deserialize)]
struct Legacy {
    theta_deg: f64,
    inertial: [f64; 3],
}

struct FrameRotation {
    setup: Settings,
    initial: Settings,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let setup: Settings = p.settings()?;
    Ok(Box::new(FrameRotation {
        setup,
        initial: setup,
    }))
}

/// A signed speed in words: "forward 0.50 m/s", "backward 0.20 m/s", "0.00 m/s".
fn along(value: f64, positive: &str, negative: &str, unit: &str) -> String {
    let text = fixed(value.abs(), 2);
    if fixed(value, 2) == "0.00" {
        format!("{text} {unit} {positive} or {negative}")
    } else if value > 0.0 {
        format!("{positive} {text} {unit}")
    } else {
        format!("{negative} {text} {unit}")
    }
}

impl FrameRotation {
    fn controls(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.setup;
        ui.add(
            egui::Slider::new(&mut s.theta_deg, range(NAME, "theta-deg"))
                .text("heading θ (°)")
                .fixed_decimals(0),
        );
        let motion = range(NAME, "motion");
        for (value, text) in s.motion.iter_mut().zip([
            "world x speed (m/s)",
            "world y speed (m/s)",
            "turn rate (rad/s)",
        ]) {
            ui.add(
                egui::Slider::new(value, motion.clone())
                    .text(text)
                    .fixed_decimals(2),
            );
        }
    }

    /// The world's axes at the left, the robot turned by θ in the middle,
    /// and the motion as an arrow.
    fn drawing(&self, ui: &egui::Ui, painter: &Painter, rect: Rect) {
        let ink = ui.visuals().text_color();
        let accent = theme::accent(ui);
        let scale = rect.height() * 0.36;
        let origin = rect.left_bottom() + vec2(40.0, -30.0);
        let mut labels = Labels::default();
        axes(
            painter,
            &mut labels,
            origin,
            [
                (origin + vec2(scale * 0.6, 0.0), "x"),
                (origin + vec2(0.0, -scale * 0.6), "y"),
            ],
            ink.gamma_multiply(0.6),
        );
        labels.add(origin, "world", ink).toward(vec2(1.0, 1.0));
        let p = rect.center() + vec2(-40.0, 10.0);
        let (s, c) = self.setup.theta_deg.to_radians().sin_cos();
        let x_r = vec2(c as f32, -s as f32) * scale * 0.7;
        let y_r = vec2(-s as f32, -c as f32) * scale * 0.7;
        robot_body(painter, p, x_r, y_r, accent);
        axes(
            painter,
            &mut labels,
            p,
            [(p + x_r, "x_R"), (p + y_r, "y_R")],
            accent,
        );
        let v = vec2(self.setup.motion[0] as f32, -self.setup.motion[1] as f32) * scale * 0.8;
        if v.length() > 1.0 {
            painter.arrow(p, v, Stroke::new(3.0, theme::good_color(ui)));
            labels.avoid_line(p, p + v);
        }
        labels.draw(painter, &egui::FontId::proportional(theme::LABEL_SIZE));
        painter.text(
            rect.right_top() + vec2(-10.0, 10.0),
            egui::Align2::RIGHT_TOP,
            format!("θ = {}°", fixed(self.setup.theta_deg, 0)),
            egui::FontId::proportional(theme::TITLE_SIZE),
            ink,
        );
    }

    /// robot = R(θ) × inertial, number by number.
    fn equation(&self, ui: &mut egui::Ui, r: &kinolab_wheels::Matrix3<f64>, robot: &Vector3<f64>) {
        let mono = |s: String| RichText::new(s).monospace();
        ui.label("robot-frame motion = R(θ) × world motion:");
        crate::widget::sideways(ui, |ui| {
            egui::Grid::new(ui.scope_id().with("r"))
                .num_columns(7)
                .spacing(vec2(8.0, 2.0))
                .show(ui, |ui| {
                    for row in 0..3 {
                        ui.label(mono(signed(robot[row], 3)).color(theme::good_color(ui)));
                        ui.label(if row == 1 { "=" } else { " " });
                        for col in 0..3 {
                            ui.label(mono(signed(r[(row, col)], 3)));
                        }
                        ui.label(if row == 1 { "×" } else { " " });
                        ui.label(mono(signed(self.setup.motion[row], 3)));
                        ui.end_row();
                    }
                });
        });
    }
}

/// A body outline along the robot's x axis.
fn robot_body(painter: &Painter, p: Pos2, x_r: Vec2, y_r: Vec2, color: egui::Color32) {
    let body: Vec<Pos2> = [(0.45, 0.3), (0.45, -0.3), (-0.35, -0.3), (-0.35, 0.3)]
        .iter()
        .map(|(a, b)| p + x_r * *a + y_r * *b)
        .collect();
    painter.add(egui::Shape::convex_polygon(
        body,
        color.gamma_multiply(0.12),
        Stroke::new(1.0, color),
    ));
}

impl FrameRotation {
    /// The world motion seen from the robot: R(θ) times it.
    fn robot_motion(&self) -> Vector3<f64> {
        rotation(self.setup.theta_deg.to_radians()) * Vector3::from(self.setup.motion)
    }
}

/// The motion in the robot's frame, in words.
fn seen_text(robot: &Vector3<f64>) -> String {
    format!(
        "As the robot sees it: {}, {}, turning {} rad/s.",
        along(robot.x, "forward", "backward", "m/s"),
        along(robot.y, "to its left", "to its right", "m/s"),
        fixed(robot.z, 2),
    )
}

impl LabWidget for FrameRotation {
    /// The heading, the world motion, and that motion as the robot sees it.
    fn describe(&self) -> Option<String> {
        let [x, y, turn] = self.setup.motion;
        Some(format!(
            "Heading θ = {}°. In the world: {} m/s along x, {} m/s along y, turning {} rad/s. {}",
            fixed(self.setup.theta_deg, 0),
            fixed(x, 2),
            fixed(y, 2),
            fixed(turn, 2),
            seen_text(&self.robot_motion())
        ))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.vertical(|ui| self.controls(ui));
        let r = rotation(self.setup.theta_deg.to_radians());
        let robot = self.robot_motion();
        let size = vec2(ui.available_width().min(720.0), 260.0);
        let (response, painter) = canvas(ui, size, Sense::hover());
        self.drawing(ui, &painter, response.rect);
        self.equation(ui, &r, &robot);
        ui.label(
            RichText::new(format!(
                "{} The inverse of R(θ) is its transpose: applying it brings the motion back.",
                seen_text(&robot)
            ))
            .small(),
        );
        export::bar(
            ui,
            ui.scope_id().with("frame-rotation-exports"),
            &[Export::Png {
                file: "kinolab-frames.png",
                rect: response.rect,
            }],
        );
    }

    fn state(&self) -> Option<String> {
        link::write(NAME, &self.setup, &self.initial, &Moment::<()>::default())
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let setup = match link::read::<Settings, ()>(NAME, state) {
            Ok((setup, _)) => setup,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => Settings {
                    theta_deg: old.theta_deg,
                    motion: old.inertial,
                },
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &setup)?;
        self.setup = setup;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn widget(params: &[(&str, &str)]) -> FrameRotation {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let setup: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        FrameRotation {
            setup,
            initial: setup,
        }
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let old = link::encode(&(-45.0_f64, [0.5_f64, -0.25, 1.0])).unwrap_or_default();
        let mut w = widget(&[]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(
            w.setup,
            Settings {
                theta_deg: -45.0,
                motion: [0.5, -0.25, 1.0]
            }
        );
        let bad = link::encode(&(-45.0_f64, [5.0_f64, 0.0, 0.0])).unwrap_or_default();
        let mut w = widget(&[("theta-deg", "60")]);
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.setup.theta_deg, 60.0);
        // The new format carries the motion too.
        w.setup.motion = [0.0, 0.5, -0.5];
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.setup, w.setup);
    }

    #[test]
    fn motions_read_as_directions_not_signs() {
        assert_eq!(
            along(-1.0, "to its left", "to its right", "m/s"),
            "to its right 1.00 m/s"
        );
        assert_eq!(along(0.5, "forward", "backward", "m/s"), "forward 0.50 m/s");
        assert_eq!(
            along(-1e-9, "forward", "backward", "m/s"),
            "0.00 m/s forward or backward"
        );
    }
}
