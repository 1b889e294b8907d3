//! A pick-and-place cell in a closed and an open world: the same parts,
//! a scripted robot and a sensing robot side by side.

use egui::{RichText, Sense, Stroke, pos2, vec2};
use kinolab_autonomy::PickCell;
use kinolab_lessons::WidgetSpec;

use super::{LabWidget, known_params, number_param};
use crate::theme;

const PARTS: usize = 40;

struct ScriptedVsSensing {
    /// All lengths in millimetres in the UI; the core takes metres.
    placement_mm: f64,
    sensor_mm: f64,
    tolerance_mm: f64,
    seed: u64,
}

pub(super) fn create(spec: &WidgetSpec) -> Result<Box<dyn LabWidget>, String> {
    known_params(spec, &["gripper_tolerance"])?;
    let tolerance = number_param(spec, "gripper_tolerance", 0.01, 0.001..=0.05)?;
    Ok(Box::new(ScriptedVsSensing {
        placement_mm: 15.0,
        sensor_mm: 2.0,
        tolerance_mm: tolerance * 1000.0,
        seed: 1,
    }))
}

impl LabWidget for ScriptedVsSensing {
    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            let label = ui.label("How far parts stray from their spot (mm):");
            ui.add(egui::Slider::new(&mut self.placement_mm, 0.0..=50.0).fixed_decimals(0))
                .labelled_by(label.id);
        });
        ui.horizontal_wrapped(|ui| {
            let label = ui.label("Sensing robot's measurement error (mm):");
            ui.add(egui::Slider::new(&mut self.sensor_mm, 0.0..=30.0).fixed_decimals(0))
                .labelled_by(label.id);
            if ui.button("New batch of parts").clicked() {
                self.seed = self.seed.wrapping_add(1);
            }
        });
        let cell = match PickCell::new(
            self.placement_mm / 1000.0,
            self.tolerance_mm / 1000.0,
            self.sensor_mm / 1000.0,
        ) {
            Ok(cell) => cell,
            Err(e) => {
                ui.label(e.to_string());
                return;
            }
        };
        let trials = cell.run(PARTS, self.seed);
        let scripted = trials.iter().filter(|t| t.scripted_grasped).count();
        let sensing = trials.iter().filter(|t| t.sensing_grasped).count();

        let width = ui.available_width().min(720.0);
        let (response, painter) = ui.allocate_painter(vec2(width, 220.0), Sense::hover());
        let half = response.rect.width() / 2.0;
        let good = theme::good_color(ui);
        let bad = theme::warn_color(ui);
        let text = ui.visuals().text_color();
        // Both panels share one scale: the larger of the stray disc and 20 mm fits.
        let extent_mm = self.placement_mm.max(self.sensor_mm).max(20.0) as f32 * 1.15;
        for (panel, title) in [
            (0, "Scripted robot: goes to the spot"),
            (1, "Sensing robot: goes where it sees the part"),
        ] {
            let area = egui::Rect::from_min_size(
                response.rect.min + vec2(panel as f32 * half, 0.0),
                vec2(half - 6.0, response.rect.height()),
            );
            painter.rect_filled(area, 6.0, ui.visuals().extreme_bg_color);
            painter.text(
                area.center_top() + vec2(0.0, 6.0),
                egui::Align2::CENTER_TOP,
                title,
                egui::FontId::proportional(12.5),
                text,
            );
            let centre = area.center() + vec2(0.0, 10.0);
            let scale = (area.height() - 40.0) / 2.0 / extent_mm;
            // The nominal spot and the gripper's reach around where it goes.
            painter.line_segment(
                [centre - vec2(6.0, 0.0), centre + vec2(6.0, 0.0)],
                Stroke::new(1.0, text),
            );
            painter.line_segment(
                [centre - vec2(0.0, 6.0), centre + vec2(0.0, 6.0)],
                Stroke::new(1.0, text),
            );
            if panel == 0 {
                painter.circle_stroke(
                    centre,
                    self.tolerance_mm as f32 * scale,
                    Stroke::new(1.5, theme::accent(ui)),
                );
            }
            if self.placement_mm > 0.0 {
                painter.circle_stroke(
                    centre,
                    self.placement_mm as f32 * scale,
                    Stroke::new(1.0, text.gamma_multiply(0.3)),
                );
            }
            for t in &trials {
                let ok = if panel == 0 {
                    t.scripted_grasped
                } else {
                    t.sensing_grasped
                };
                let at = centre + vec2(t.part[0] as f32, -t.part[1] as f32) * 1000.0 * scale;
                painter.circle_filled(pos2(at.x, at.y), 4.0, if ok { good } else { bad });
            }
        }
        ui.label(
            RichText::new(format!(
                "This batch: scripted robot grasps {scripted} of {PARTS}, sensing robot {sensing} of {PARTS}."
            ))
            .strong(),
        );
        ui.label(format!(
            "In the long run: scripted {:.0} %, sensing {:.0} % (gripper tolerance {:.0} mm; green = grasped, red = missed).",
            cell.scripted_success() * 100.0,
            cell.sensing_success() * 100.0,
            self.tolerance_mm
        ));
    }
}
