//! A trapezoidal speed profile: accelerate, cruise, brake, over a distance,
//! with the limits on sliders.

use egui::RichText;
use egui_plot::{Plot, PlotPoints};
use kinolab_common::display::fixed;
use kinolab_control::Profile;
use serde::{Deserialize, Serialize};

use crate::draw::plot::{series_legend, series_lines};
use crate::link;
use crate::widget::{LabWidget, Params, number};

/// The plotted series, in palette order.
const NAMES: [&str; 2] = ["speed v (m/s)", "distance s (m)"];

/// The limits on the sliders, and what a link carries.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
struct SpeedProfile {
    distance: f64,
    max_speed: f64,
    max_accel: f64,
}

struct Widget {
    now: SpeedProfile,
    initial: SpeedProfile,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let now = SpeedProfile {
        distance: number(p, "distance"),
        max_speed: number(p, "max-speed"),
        max_accel: number(p, "max-accel"),
    };
    Ok(Box::new(Widget { now, initial: now }))
}

impl LabWidget for Widget {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.now.ui(ui);
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.now, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(s) = link::decode::<SpeedProfile>(state)
            && [s.distance, s.max_speed, s.max_accel]
                .iter()
                .all(|v| v.is_finite())
        {
            self.now = SpeedProfile {
                distance: s.distance.clamp(0.05, 5.0),
                max_speed: s.max_speed.clamp(0.05, 2.0),
                max_accel: s.max_accel.clamp(0.1, 5.0),
            };
        }
        Ok(())
    }
}

impl SpeedProfile {
    fn ui(&mut self, ui: &mut egui::Ui) {
        crate::widget::control_row(ui, |ui| {
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
        let width = ui.available_width();
        Plot::new(ui.scope_id().with("speed-profile"))
            .width(width)
            .height(200.0)
            .x_axis_label("t (s)")
            .include_y(0.0)
            .include_x(0.0)
            .allow_scroll(false)
            .show(ui, |plot| {
                series_lines(
                    plot,
                    NAMES.into_iter().zip([speed, covered]).collect(),
                    None,
                );
            });
        series_legend(ui, &NAMES, &[]);
        let shape = if p.cruise > 0.0 {
            format!(
                "Trapezoid: ramps of {} s cover {} m together, then {} s at {} m/s.",
                fixed(p.ramp, 2),
                fixed(p.peak * p.ramp, 2),
                fixed(p.cruise, 2),
                fixed(p.peak, 2)
            )
        } else {
            format!(
                "Triangle: too short to reach {} m/s; the speed peaks at √(d·a) = {} m/s.",
                fixed(self.max_speed, 2),
                fixed(p.peak, 2)
            )
        };
        ui.label(format!("{shape} Total {} s.", fixed(total, 2)));
        ui.label(RichText::new("The area under the speed curve is the distance.").small());
    }
}
