//! One Denavit–Hartenberg link, built motion by motion: frame i−1, the
//! frames after each of the four elementary motions, frame i, and the 4×4
//! matrix. With a target row, a dashed frame shows where frame i must land
//! and the core checks the learner's row by comparing transforms.

use egui::{RichText, Sense, Stroke, vec2};
use kinolab_lessons::WidgetSpec;
use kinolab_mechanism::Pose;
use kinolab_mechanism::dh::{Convention, link, steps};
use kinolab_mechanism::exercise::{Task, Verdict};

use super::scene3d::{AXIS_COLOURS, Camera, ViewKind, draw_frame, draw_grid};
use super::{LabWidget, known_params, number_list, shown};
use crate::theme;

struct DhLink {
    convention: Convention,
    /// a (m), α (°), d (m), θ (°).
    row: [f64; 4],
    initial: [f64; 4],
    camera: Camera,
    task: Option<Task>,
    verdict: Option<Verdict>,
}

fn row_param(key: &str, text: &str) -> Result<[f64; 4], String> {
    let v = number_list(key, text)?;
    let row: [f64; 4] = v.try_into().map_err(|_| {
        format!("Parameter `{key}` takes four numbers: a (m), α (°), d (m), θ (°).")
    })?;
    if row[0].abs() > 2.0 || row[2].abs() > 2.0 {
        return Err(format!("Parameter `{key}`: a and d must be within ±2 m."));
    }
    Ok(row)
}

pub(super) fn create(spec: &WidgetSpec) -> Result<Box<dyn LabWidget>, String> {
    known_params(spec, &["convention", "row", "target"])?;
    let convention = match spec.param("convention") {
        None | Some("standard") => Convention::StandardDh,
        Some("modified") => Convention::ModifiedDh,
        Some(other) => {
            return Err(format!(
                "Parameter `convention` must be standard or modified, found `{other}`."
            ));
        }
    };
    let row = match spec.param("row") {
        Some(t) => row_param("row", t)?,
        None => [0.0; 4],
    };
    let task = match spec.param("target") {
        Some(t) => {
            let [a, alpha, d, theta] = row_param("target", t)?;
            Some(Task::DhRow {
                convention,
                target: [a, alpha.to_radians(), d, theta.to_radians()],
            })
        }
        None => None,
    };
    Ok(Box::new(DhLink {
        convention,
        row,
        initial: row,
        camera: Camera::new(ViewKind::Orbit, [0.3, 0.0, 0.2], 0.8),
        task,
        verdict: None,
    }))
}

impl DhLink {
    fn radians(&self) -> [f64; 4] {
        [
            self.row[0],
            self.row[1].to_radians(),
            self.row[2],
            self.row[3].to_radians(),
        ]
    }
}

const NAMES_STANDARD: [&str; 4] = ["Rz(θ)", "Tz(d)", "Tx(a)", "Rx(α)"];
const NAMES_MODIFIED: [&str; 4] = ["Rx(α)", "Tx(a)", "Rz(θ)", "Tz(d)"];

impl LabWidget for DhLink {
    fn ui(&mut self, ui: &mut egui::Ui) {
        let mut changed = false;
        ui.horizontal_wrapped(|ui| {
            ui.label(match self.convention {
                Convention::StandardDh => {
                    "standard DH: frame i = frame i−1 · Rz(θ) · Tz(d) · Tx(a) · Rx(α)"
                }
                Convention::ModifiedDh => {
                    "modified DH: frame i = frame i−1 · Rx(α) · Tx(a) · Rz(θ) · Tz(d)"
                }
            });
            self.camera.buttons(ui);
        });
        egui::Grid::new(ui.scope_id().with("dh"))
            .num_columns(2)
            .show(ui, |ui| {
                for (k, (label, range, unit)) in [
                    ("a", -1.0..=1.0, " m"),
                    ("α", -180.0..=180.0, "°"),
                    ("d", -1.0..=1.0, " m"),
                    ("θ", -180.0..=180.0, "°"),
                ]
                .into_iter()
                .enumerate()
                {
                    ui.label(label);
                    let angle = k % 2 == 1;
                    let slider = egui::Slider::new(&mut self.row[k], range)
                        .suffix(unit)
                        .fixed_decimals(if angle { 0 } else { 2 })
                        .step_by(if angle { 1.0 } else { 0.01 });
                    changed |= ui.add(slider).changed();
                    ui.end_row();
                }
            });
        if changed {
            self.verdict = None;
        }
        let [a, alpha, d, theta] = self.radians();
        let parts = steps(self.convention, a, alpha, d, theta);
        let names = match self.convention {
            Convention::StandardDh => NAMES_STANDARD,
            Convention::ModifiedDh => NAMES_MODIFIED,
        };

        let size = vec2(ui.available_width().min(720.0), 300.0);
        let (response, painter) = ui.allocate_painter(size, Sense::click_and_drag());
        let rect = response.rect;
        self.camera.handle(ui, &response, true);
        painter.rect_filled(rect, 6.0, ui.visuals().extreme_bg_color);
        let text = ui.visuals().text_color();
        draw_grid(&painter, &self.camera, rect, text.gamma_multiply(0.08));
        let font = egui::FontId::proportional(12.0);
        draw_frame(
            &painter,
            &self.camera,
            rect,
            &Pose::identity(),
            0.25,
            1.0,
            2.5,
        );
        let (o, _) = self
            .camera
            .project(rect, &Pose::identity().translation.vector);
        painter.text(
            o + vec2(-6.0, 6.0),
            egui::Align2::RIGHT_TOP,
            "i−1",
            font.clone(),
            text,
        );
        // The path through the intermediate frames.
        let mut at = Pose::identity();
        for (k, step) in parts.iter().enumerate() {
            let before = at.translation.vector;
            at *= step;
            let (p0, _) = self.camera.project(rect, &before);
            let (p1, _) = self.camera.project(rect, &at.translation.vector);
            painter.line_segment([p0, p1], Stroke::new(1.5, text.gamma_multiply(0.5)));
            if k < 3 {
                draw_frame(&painter, &self.camera, rect, &at, 0.12, 0.35, 1.0);
                // Staggered: a motion that only turns leaves the origin
                // where it was, and the labels would overlap.
                painter.text(
                    p1 + vec2(4.0, -4.0 - 14.0 * k as f32),
                    egui::Align2::LEFT_BOTTOM,
                    format!("after {}", names[k]),
                    font.clone(),
                    text.gamma_multiply(0.5),
                );
            }
        }
        if let Some(Task::DhRow { convention, target }) = &self.task {
            let goal = link(*convention, target[0], target[1], target[2], target[3]);
            let (g, _) = self.camera.project(rect, &goal.translation.vector);
            for (k, colour) in AXIS_COLOURS.iter().enumerate() {
                let mut axis = kinolab_mechanism::Vector3::zeros();
                axis[k] = 0.25;
                let (tip, _) = self
                    .camera
                    .project(rect, &(goal.rotation * axis + goal.translation.vector));
                let dashes = egui::Shape::dashed_line(
                    &[g, tip],
                    Stroke::new(2.0, colour.gamma_multiply(0.7)),
                    5.0,
                    4.0,
                );
                painter.extend(dashes);
            }
            painter.text(
                g + vec2(6.0, 6.0),
                egui::Align2::LEFT_TOP,
                "target",
                font.clone(),
                text.gamma_multiply(0.7),
            );
        }
        let frame_i = link(self.convention, a, alpha, d, theta);
        draw_frame(&painter, &self.camera, rect, &frame_i, 0.25, 1.0, 3.0);
        let (pi, _) = self.camera.project(rect, &frame_i.translation.vector);
        painter.text(
            pi + vec2(6.0, 6.0),
            egui::Align2::LEFT_TOP,
            "i",
            font.clone(),
            text,
        );
        painter.text(
            rect.left_bottom() + vec2(8.0, -8.0),
            egui::Align2::LEFT_BOTTOM,
            "x red, y green, z blue · drag to turn the view",
            font,
            text.gamma_multiply(0.6),
        );

        ui.label("The link's transform, frame i seen from frame i−1:");
        let h = frame_i.to_homogeneous();
        egui::Grid::new(ui.scope_id().with("m"))
            .spacing(vec2(10.0, 2.0))
            .show(ui, |ui| {
                for r in 0..4 {
                    for c in 0..4 {
                        ui.label(
                            RichText::new(format!("{:+.3}", shown(h[(r, c)], 5e-4))).monospace(),
                        );
                    }
                    ui.end_row();
                }
            });
        let radians = self.radians();
        if let Some(task) = &self.task {
            let verdict = &mut self.verdict;
            ui.group(|ui| {
                ui.label(RichText::new(format!("Exercise: {}", task.describe())).strong());
                if ui.button("Check").clicked() {
                    let r = task.check_row(radians);
                    *verdict = Some(r.unwrap_or_else(|e| Verdict {
                        met: false,
                        message: e.to_string(),
                    }));
                }
                if let Some(v) = verdict.as_ref() {
                    let colour = if v.met {
                        theme::good_color(ui)
                    } else {
                        theme::warn_color(ui)
                    };
                    ui.label(RichText::new(&v.message).color(colour));
                }
            });
        }
    }

    fn state(&self) -> Option<String> {
        (self.row != self.initial).then(|| self.row.map(|v| format!("{v:.2}")).join(","))
    }

    fn restore(&mut self, state: &str) {
        if let Ok(row) = row_param("row", state) {
            self.row = row;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(params: &[(&str, &str)]) -> WidgetSpec {
        super::super::test_spec("dh-link", params)
    }

    #[test]
    fn rows_parse_and_round_trip_through_links() {
        let Ok(mut w) = create(&spec(&[
            ("row", "0.5, 90, 0.2, 30"),
            ("convention", "modified"),
        ])) else {
            panic!()
        };
        assert_eq!(w.state(), None);
        w.restore("0.10,-90.00,0.00,45.00");
        assert_eq!(w.state().as_deref(), Some("0.10,-90.00,0.00,45.00"));
        assert!(create(&spec(&[("row", "1, 2, 3")])).is_err());
        assert!(create(&spec(&[("convention", "craig")])).is_err());
    }
}
