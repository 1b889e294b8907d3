//! A trapezoidal speed profile: accelerate, cruise, brake, over a distance,
//! with the limits on sliders.

use egui::RichText;
use egui_plot::{Legend, Line, Plot, PlotPoints};
use kinolab_control::Profile;
use kinolab_lessons::WidgetSpec;

use super::{LabWidget, known_params, number_param};

struct SpeedProfile {
    distance: f64,
    max_speed: f64,
    max_accel: f64,
}

pub(super) fn create(spec: &WidgetSpec) -> Result<Box<dyn LabWidget>, String> {
    known_params(spec, &["distance", "max-speed", "max-accel"])?;
    Ok(Box::new(SpeedProfile {
        distance: number_param(spec, "distance", 1.0, 0.05..=5.0)?,
        max_speed: number_param(spec, "max-speed", 0.5, 0.05..=2.0)?,
        max_accel: number_param(spec, "max-accel", 1.0, 0.1..=5.0)?,
    }))
}

impl LabWidget for SpeedProfile {
    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.add(
                egui::Slider::new(&mut self.distance, 0.05..=5.0)
                    .text("distance (m)")
                    .fixed_decimals(2),
            );
            ui.add(
                egui::Slider::new(&mut self.max_speed, 0.05..=2.0)
                    .text("max speed (m/s)")
                    .fixed_decimals(2),
            );
            ui.add(
                egui::Slider::new(&mut self.max_accel, 0.1..=5.0)
                    .text("max accel (m/s²)")
                    .fixed_decimals(1),
            );
        });
        let p = Profile::new(self.distance, self.max_speed, self.max_accel);
        let total = p.duration();
        let n = 200;
        let times: Vec<f64> = (0..=n)
            .map(|i| total * f64::from(i) / f64::from(n))
            .collect();
        let speed: PlotPoints<'_> = times.iter().map(|&t| [t, p.speed(t)]).collect();
        let covered: PlotPoints<'_> = times.iter().map(|&t| [t, p.covered(t)]).collect();
        let width = ui.available_width().min(900.0);
        Plot::new(ui.scope_id().with("speed-profile"))
            .width(width)
            .height(200.0)
            .legend(Legend::default())
            .x_axis_label("t (s)")
            .include_y(0.0)
            .include_x(0.0)
            .allow_scroll(false)
            .show(ui, |plot| {
                plot.line(Line::new("speed v (m/s)", speed).width(2.0));
                plot.line(Line::new("distance s (m)", covered).width(2.0));
            });
        let shape = if p.cruise > 0.0 {
            format!(
                "Trapezoid: ramps of {:.2} s cover {:.2} m together, then {:.2} s at {:.2} m/s.",
                p.ramp,
                p.peak * p.ramp,
                p.cruise,
                p.peak
            )
        } else {
            format!(
                "Triangle: too short to reach {:.2} m/s; the speed peaks at √(d·a) = {:.2} m/s.",
                self.max_speed, p.peak
            )
        };
        ui.label(format!("{shape} Total {total:.2} s."));
        ui.label(RichText::new("The area under the speed curve is the distance.").small());
    }
}
