//! The playground's plots, and taking runs away: CSV (copy or save) and
//! the plots as a PNG.

use std::sync::{Arc, Mutex};

use egui::RichText;
use egui_plot::{Plot, PlotPoints};
use kinolab_common::angle::wrap;
use kinolab_control::{Sample, Trajectory};

use super::Playground;
use crate::draw::plot::{REFERENCE, series_legend, series_lines};
use crate::export::{png_of, request_save};

/// Where a requested screen capture lands when it arrives.
type CaptureSlot = Arc<Mutex<Option<Arc<egui::ColorImage>>>>;

/// A capture of the plots on its way: the area to crop, and the slot.
pub(super) type Capture = (egui::Rect, CaptureSlot);

/// The CSV columns.
const CSV_HEADER: &str = "run,t,x,y,theta_deg,v,omega,rho,alpha_deg,beta_deg,wheel_speed";

fn csv_rows(out: &mut String, name: &str, t: &Trajectory) {
    use std::fmt::Write as _;
    for s in &t.samples {
        let _ = writeln!(
            out,
            "{name},{:.4},{:.6},{:.6},{:.4},{:.6},{:.6},{:.6},{:.4},{:.4},{:.4}",
            s.t,
            s.pose.x,
            s.pose.y,
            wrap(s.pose.theta).to_degrees(),
            s.v,
            s.omega,
            s.polar.rho,
            s.polar.alpha.to_degrees(),
            s.polar.beta.to_degrees(),
            s.wheel_speed
        );
    }
}

/// The runs as one CSV text.
fn csv(runs: &[(&str, &Trajectory)]) -> String {
    let mut out = format!("{CSV_HEADER}\n");
    for (name, t) in runs {
        csv_rows(&mut out, name, t);
    }
    out
}

impl Playground {
    /// ρ, α, β and v, ω against time on linked axes, with the cursor.
    pub(super) fn plots(&mut self, ui: &mut egui::Ui, t: &Trajectory, width: f32) {
        let series = |f: &dyn Fn(&Sample) -> f64| -> PlotPoints<'static> {
            t.samples.iter().map(|s| [s.t, f(s)]).collect()
        };
        let base = ui.scope_id();
        let link = base.with("plots-link");
        let cursor = self.cursor;
        let top = ui.cursor().min;
        let plot = |id: &str, y_label: &str| {
            Plot::new(base.with(id))
                .width(width)
                .height(170.0)
                .link_axis(link, [true, false])
                .y_axis_label(y_label.to_owned())
                .allow_scroll(false)
        };
        let polar = ["ρ (m)", "α (rad)", "β (rad)"];
        plot("polar-plot", "ρ (m), α β (rad)").show(ui, |plot| {
            let values = [
                series(&|s| s.polar.rho),
                series(&|s| s.polar.alpha),
                series(&|s| s.polar.beta),
            ];
            series_lines(plot, polar.into_iter().zip(values).collect(), Some(cursor));
        });
        series_legend(ui, &polar, &[("now", REFERENCE)]);
        let command = ["v (m/s)", "ω (rad/s)"];
        plot("command-plot", "v (m/s), ω (rad/s)")
            .x_axis_label("t (s)")
            .show(ui, |plot| {
                let values = [series(&|s| s.v), series(&|s| s.omega)];
                series_lines(
                    plot,
                    command.into_iter().zip(values).collect(),
                    Some(cursor),
                );
            });
        series_legend(ui, &command, &[("now", REFERENCE)]);
        let area = egui::Rect::from_min_max(top, egui::pos2(top.x + width, ui.cursor().min.y));
        if ui.button("Save plots as PNG").clicked() {
            self.request_capture(ui, area);
        }
    }

    fn request_capture(&mut self, ui: &egui::Ui, area: egui::Rect) {
        let slot: CaptureSlot = Arc::default();
        let fill = slot.clone();
        let ctx = ui.ctx().clone();
        ui.ctx()
            .send_viewport_cmd(egui::ViewportCommand::Screenshot(
                egui::ScreenshotCallback::new(move |image| {
                    if let Ok(mut s) = fill.lock() {
                        *s = Some(image);
                    }
                    ctx.request_repaint();
                }),
            ));
        self.capture = Some((area, slot));
        self.status = Some("Capturing the plots…".into());
    }

    /// Finish a requested capture once the image has arrived.
    pub(super) fn finish_capture(&mut self, ui: &egui::Ui) {
        let Some((rect, slot)) = &self.capture else {
            return;
        };
        let Some(image) = slot.lock().ok().and_then(|mut s| s.take()) else {
            return;
        };
        let name = "kinolab-controller-plots.png";
        self.status = Some(match png_of(&image, *rect, ui.ctx().pixels_per_point()) {
            Ok(png) => {
                request_save(ui.ctx(), name, "image/png", png);
                format!("Saved {name}.")
            }
            Err(e) => format!("Could not save the plots: {e}."),
        });
        self.capture = None;
    }

    pub(super) fn exports(&mut self, ui: &mut egui::Ui, runs: &[(&str, &Trajectory)]) {
        ui.horizontal_wrapped(|ui| {
            if ui.button("Copy CSV").clicked() {
                ui.ctx().copy_text(csv(runs));
                self.status = Some("Copied the run as CSV.".into());
            }
            if ui.button("Save CSV").clicked() {
                request_save(
                    ui.ctx(),
                    "kinolab-run.csv",
                    "text/csv",
                    csv(runs).into_bytes(),
                );
                self.status = Some("Saved kinolab-run.csv.".into());
            }
            // Kept even when empty, so the layout does not jump.
            ui.label(RichText::new(self.status.clone().unwrap_or_default()).small());
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kinolab_control::{Pose, Run};

    #[test]
    fn csv_has_one_row_per_sample() {
        let Ok(run) = Run::polar(
            Pose::new(-1.0, 0.5, 0.0),
            Pose::default(),
            kinolab_control::TEXTBOOK_GAINS,
        ) else {
            panic!("the textbook run is valid")
        };
        let Ok(t) = run.simulate() else {
            panic!("it simulates")
        };
        let text = csv(&[("closed", &t)]);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 1 + t.samples.len());
        // v at t = 0 is k_ρ ρ = 3 · √1.25 = 3.354102.
        assert!(
            lines[1].starts_with("closed,0.0000,-1.000000,0.500000,0.0000,3.354102,"),
            "{}",
            lines[1]
        );
        assert_eq!(lines[1].split(',').count(), CSV_HEADER.split(',').count());
    }
}
