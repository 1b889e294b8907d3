//! A pick-and-place cell in a closed and an open world: the same parts,
//! a scripted robot and a sensing robot side by side.

use egui::{Painter, Rect, RichText, Sense, Stroke, vec2};
use kinolab_autonomy::{PickCell, PickTrial};
use serde::{Deserialize, Serialize};

use crate::draw::{PlaneView, marks};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params, range};

/// The widget's name in the schema.
const NAME: &str = "scripted-vs-sensing";

const PARTS: usize = 40;

/// What the lesson sets and a link carries: the schema's parameters, in
/// metres (the sliders show millimetres).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    gripper_tolerance: f64,
    placement_error: f64,
    sensor_error: f64,
    seed: u64,
}

/// The links of the first format: the widget's own struct, in mm.
#[derive(Deserialize)]
struct Legacy {
    placement_mm: f64,
    sensor_mm: f64,
    seed: u64,
}

struct ScriptedVsSensing {
    settings: Settings,
    initial: Settings,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(ScriptedVsSensing {
        initial: settings.clone(),
        settings,
    }))
}

/// A slider in millimetres over a setting in metres, its range the
/// schema's; the setting changes only when the slider is moved.
fn millimetres(ui: &mut egui::Ui, metres: &mut f64, param: &str, label: &str) {
    let label = ui.label(label);
    let r = range(NAME, param);
    let mut mm = *metres * 1000.0;
    let slider = egui::Slider::new(&mut mm, r.start() * 1000.0..=r.end() * 1000.0);
    if ui
        .add(slider.fixed_decimals(0))
        .labelled_by(label.id)
        .changed()
    {
        *metres = mm / 1000.0;
    }
}

impl ScriptedVsSensing {
    fn controls(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.settings;
        crate::widget::control_row(ui, |ui| {
            let label = "How far parts stray from their spot (mm):";
            millimetres(ui, &mut s.placement_error, "placement_error", label);
        });
        crate::widget::control_row(ui, |ui| {
            let label = "Sensing robot's measurement error (mm):";
            millimetres(ui, &mut s.sensor_error, "sensor_error", label);
            if ui.button("New batch of parts").clicked() {
                let last = *range(NAME, "seed").end() as u64;
                s.seed = if s.seed >= last { 0 } else { s.seed + 1 };
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
        let s = &self.settings;
        let extent_m = s.placement_error.max(s.sensor_error).max(0.02) * 1.15;
        let plot = Rect::from_min_max(area.min + vec2(0.0, 28.0), area.max - vec2(0.0, 6.0));
        let view = PlaneView::centred(plot, [0.0, 0.0], extent_m);
        let centre = view.to_screen([0.0, 0.0]);
        marks::plus(painter, centre, 6.0, Stroke::new(1.0, ink));
        if scripted {
            let reach = view.length(s.gripper_tolerance);
            painter.circle_stroke(centre, reach, Stroke::new(1.5, theme::accent(ui)));
        }
        if s.placement_error > 0.0 {
            let stray = view.length(s.placement_error);
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

impl ScriptedVsSensing {
    /// The cell the settings make and this batch's parts through it.
    fn batch(&self) -> Result<(PickCell, Vec<PickTrial>), String> {
        let s = &self.settings;
        let cell = PickCell::new(s.placement_error, s.gripper_tolerance, s.sensor_error)
            .map_err(|e| e.to_string())?;
        let trials = cell.run(PARTS, s.seed);
        Ok((cell, trials))
    }
}

/// How many parts of the batch each robot grasped.
fn batch_text(trials: &[PickTrial]) -> String {
    let scripted = trials.iter().filter(|t| t.scripted_grasped).count();
    let sensing = trials.iter().filter(|t| t.sensing_grasped).count();
    format!(
        "This batch: scripted robot grasps {scripted} of {PARTS}, sensing robot {sensing} of {PARTS}."
    )
}

/// Each robot's success rate over many batches.
fn long_run_text(cell: &PickCell) -> String {
    format!(
        "In the long run: scripted {:.0} %, sensing {:.0} %",
        cell.scripted_success() * 100.0,
        cell.sensing_success() * 100.0
    )
}

impl LabWidget for ScriptedVsSensing {
    /// The errors set, this batch's grasps and the long-run rates.
    fn describe(&self) -> Option<String> {
        let s = &self.settings;
        let set = format!(
            "Parts stray {:.0} mm from their spot; the sensing robot's measurement error is {:.0} mm; gripper tolerance {:.0} mm.",
            s.placement_error * 1000.0,
            s.sensor_error * 1000.0,
            s.gripper_tolerance * 1000.0
        );
        Some(match self.batch() {
            Ok((cell, trials)) => {
                format!("{set} {} {}.", batch_text(&trials), long_run_text(&cell))
            }
            Err(e) => format!("{set} {e}"),
        })
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        let s = &self.settings;
        let (cell, trials) = match self.batch() {
            Ok(batch) => batch,
            Err(e) => {
                ui.label(e);
                return;
            }
        };
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
        ui.label(RichText::new(batch_text(&trials)).strong());
        ui.label(format!(
            "{} (gripper tolerance {:.0} mm; green = grasped, red = missed).",
            long_run_text(&cell),
            s.gripper_tolerance * 1000.0
        ));
        export::bar(
            ui,
            ui.scope_id().with("pick-exports"),
            &[Export::Png {
                file: "kinolab-scripted-vs-sensing.png",
                rect: response.rect,
            }],
        );
    }

    fn state(&self) -> Option<String> {
        link::write(
            NAME,
            &self.settings,
            &self.initial,
            &Moment::<()>::default(),
        )
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if link::is_bare(state) {
            return Err("it is empty (cut short)".into());
        }
        let settings = match link::read::<Settings, ()>(NAME, state) {
            Ok((settings, _)) => settings,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => Settings {
                    placement_error: old.placement_mm / 1000.0,
                    sensor_error: old.sensor_mm / 1000.0,
                    seed: old.seed,
                    ..self.initial.clone()
                },
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
        self.settings = settings;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn widget(params: &[(&str, &str)]) -> ScriptedVsSensing {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        ScriptedVsSensing {
            initial: settings.clone(),
            settings,
        }
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let old = link::encode(&(25.0_f64, 4.0_f64, 7_u64)).unwrap_or_default();
        let mut w = widget(&[("gripper_tolerance", "0.02")]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(
            w.settings,
            Settings {
                gripper_tolerance: 0.02,
                placement_error: 0.025,
                sensor_error: 0.004,
                seed: 7,
            }
        );
        // Out of the schema's range: refused, the lesson's settings kept.
        let bad = link::encode(&(250.0_f64, 4.0_f64, 7_u64)).unwrap_or_default();
        let mut w = widget(&[("placement_error", "0.03")]);
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.settings.placement_error, 0.03);
    }

    #[test]
    fn the_settings_travel_in_the_link() {
        let mut w = widget(&[]);
        assert_eq!(w.state(), None);
        w.settings.sensor_error = 0.011;
        w.settings.seed = 3;
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
    }
}
