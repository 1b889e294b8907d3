//! A pick-and-place cell in a closed and an open world: the same parts,
//! a scripted robot and a sensing robot side by side.

use egui::{Painter, Rect, RichText, Sense, Stroke, vec2};
use kinolab_autonomy::{PickCell, PickTrial};
use serde::{Deserialize, Serialize};

use crate::draw::{PlaneView, marks};
use crate::widget::{LabWidget, Params};
use crate::{link, theme};

const PARTS: usize = 40;

/// What the learner sets (millimetres in the UI; the core takes metres),
/// and what a link carries.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
struct Setup {
    placement_mm: f64,
    sensor_mm: f64,
    seed: u64,
}

struct ScriptedVsSensing {
    setup: Setup,
    initial: Setup,
    tolerance_mm: f64,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let setup = Setup {
        placement_mm: 15.0,
        sensor_mm: 2.0,
        seed: 1,
    };
    Ok(Box::new(ScriptedVsSensing {
        setup,
        initial: setup,
        tolerance_mm: p.number("gripper_tolerance").unwrap_or(0.01) * 1000.0,
    }))
}

impl ScriptedVsSensing {
    fn controls(&mut self, ui: &mut egui::Ui) {
        crate::widget::control_row(ui, |ui| {
            let label = ui.label("How far parts stray from their spot (mm):");
            ui.add(egui::Slider::new(&mut self.setup.placement_mm, 0.0..=50.0).fixed_decimals(0))
                .labelled_by(label.id);
        });
        crate::widget::control_row(ui, |ui| {
            let label = ui.label("Sensing robot's measurement error (mm):");
            ui.add(egui::Slider::new(&mut self.setup.sensor_mm, 0.0..=30.0).fixed_decimals(0))
                .labelled_by(label.id);
            if ui.button("New batch of parts").clicked() {
                self.setup.seed = self.setup.seed.wrapping_add(1);
            }
        });
    }

    /// One robot's panel: the nominal spot, the stray disc, each part
    /// green (grasped) or red (missed).
    fn panel(
        &self,
        ui: &egui::Ui,
        painter: &Painter,
        area: Rect,
        scripted: bool,
        trials: &[PickTrial],
    ) {
        let ink = ui.visuals().text_color();
        painter.rect_filled(area, 6.0, ui.visuals().extreme_bg_color);
        let title = if scripted {
            "Scripted robot: goes to the spot"
        } else {
            "Sensing robot: goes where it sees the part"
        };
        painter.text(
            area.center_top() + vec2(0.0, 6.0),
            egui::Align2::CENTER_TOP,
            title,
            egui::FontId::proportional(theme::LABEL_SIZE),
            ink,
        );
        // Both panels share one scale: the larger of the stray disc and 20 mm fits.
        let extent_m = self.setup.placement_mm.max(self.setup.sensor_mm).max(20.0) * 1.15 / 1000.0;
        let plot = Rect::from_min_max(area.min + vec2(0.0, 28.0), area.max - vec2(0.0, 6.0));
        let view = PlaneView::centred(plot, [0.0, 0.0], extent_m);
        let centre = view.to_screen([0.0, 0.0]);
        marks::plus(painter, centre, 6.0, Stroke::new(1.0, ink));
        if scripted {
            let reach = view.length(self.tolerance_mm / 1000.0);
            painter.circle_stroke(centre, reach, Stroke::new(1.5, theme::accent(ui)));
        }
        if self.setup.placement_mm > 0.0 {
            let stray = view.length(self.setup.placement_mm / 1000.0);
            painter.circle_stroke(centre, stray, Stroke::new(1.0, ink.gamma_multiply(0.3)));
        }
        for t in trials {
            let ok = if scripted {
                t.scripted_grasped
            } else {
                t.sensing_grasped
            };
            let color = if ok {
                theme::good_color(ui)
            } else {
                theme::error_color(ui)
            };
            painter.circle_filled(view.to_screen(t.part), 4.0, color);
        }
    }
}

impl LabWidget for ScriptedVsSensing {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        let s = self.setup;
        let cell = match PickCell::new(
            s.placement_mm / 1000.0,
            self.tolerance_mm / 1000.0,
            s.sensor_mm / 1000.0,
        ) {
            Ok(cell) => cell,
            Err(e) => {
                ui.label(e.to_string());
                return;
            }
        };
        let trials = cell.run(PARTS, s.seed);
        let width = ui.available_width().min(720.0);
        let (response, painter) = ui.allocate_painter(vec2(width, 220.0), Sense::hover());
        let half = response.rect.width() / 2.0;
        for (i, scripted) in [true, false].into_iter().enumerate() {
            let area = Rect::from_min_size(
                response.rect.min + vec2(i as f32 * half, 0.0),
                vec2(half - 6.0, response.rect.height()),
            );
            self.panel(ui, &painter, area, scripted, &trials);
        }
        let scripted = trials.iter().filter(|t| t.scripted_grasped).count();
        let sensing = trials.iter().filter(|t| t.sensing_grasped).count();
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

    fn state(&self) -> Option<String> {
        link::changed(&self.setup, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(s) = link::decode::<Setup>(state) {
            self.setup = Setup {
                placement_mm: clamp_finite(s.placement_mm, 0.0, 50.0),
                sensor_mm: clamp_finite(s.sensor_mm, 0.0, 30.0),
                seed: s.seed,
            };
        }
        Ok(())
    }
}

/// `x` within `[lo, hi]`; `lo` for NaN.
fn clamp_finite(x: f64, lo: f64, hi: f64) -> f64 {
    if x.is_nan() { lo } else { x.clamp(lo, hi) }
}
