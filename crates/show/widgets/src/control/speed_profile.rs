//! A trapezoidal speed profile: accelerate, cruise, brake, over a distance,
//! with the limits on sliders; the plot saved as PNG or CSV.

use egui::RichText;
use egui_plot::{Plot, PlotPoints};
use kinolab_common::display::fixed;
use kinolab_control::Profile;
use serde::{Deserialize, Serialize};

use crate::draw::plot::{series_legend, series_lines};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::widget::{LabWidget, Params, range};

/// The widget's name in the schema.
const NAME: &str = "speed-profile";

/// The plotted series, in palette order.
const NAMES: [&str; 2] = ["speed v (m/s)", "distance s (m)"];

/// Samples along the profile.
const SAMPLES: u32 = 200;

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
struct Settings {
    distance: f64,
    max_speed: f64,
    max_accel: f64,
}

/// The links of the first format: the three sliders.
#[derive(Deserialize)]
struct Legacy {
    distance: f64,
    max_speed: f64,
    max_accel: f64,
}

struct Widget {
    settings: Settings,
    initial: Settings,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(Widget {
        settings,
        initial: settings,
    }))
}

impl Settings {
    fn profile(&self) -> Profile {
        Profile::new(self.distance, self.max_speed, self.max_accel)
    }

    /// Speed and distance against time, sampled evenly.
    fn series(&self) -> Vec<(&'static str, Vec<[f64; 2]>)> {
        let p = self.profile();
        let total = p.duration();
        let times: Vec<f64> = (0..=SAMPLES)
            .map(|i| total * f64::from(i) / f64::from(SAMPLES))
            .collect();
        let speed = times.iter().map(|&t| [t, p.speed(t)]).collect();
        let covered = times.iter().map(|&t| [t, p.covered(t)]).collect();
        NAMES.into_iter().zip([speed, covered]).collect()
    }
}

impl Widget {
    fn sliders(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.settings;
        crate::widget::control_row(ui, |ui| {
            ui.add(
                egui::Slider::new(&mut s.distance, range(NAME, "distance"))
                    .text("distance (m)")
                    .fixed_decimals(2),
            );
            ui.add(
                egui::Slider::new(&mut s.max_speed, range(NAME, "max-speed"))
                    .text("max speed (m/s)")
                    .fixed_decimals(2),
            );
            ui.add(
                egui::Slider::new(&mut s.max_accel, range(NAME, "max-accel"))
                    .text("max accel (m/s²)")
                    .fixed_decimals(1),
            );
        });
    }

    /// The plot; the area it took on screen.
    fn plot(&self, ui: &mut egui::Ui) -> egui::Rect {
        let series = self.settings.series();
        let width = ui.available_width();
        let top = ui.cursor().min;
        Plot::new(ui.scope_id().with("speed-profile"))
            .width(width)
            .height(200.0)
            .x_axis_label("t (s)")
            .include_y(0.0)
            .include_x(0.0)
            .allow_scroll(false)
            .show(ui, |plot| {
                let lines = series
                    .into_iter()
                    .map(|(name, points)| (name, PlotPoints::from(points)))
                    .collect();
                series_lines(plot, lines, None);
            });
        series_legend(ui, &NAMES, &[]);
        egui::Rect::from_min_max(top, egui::pos2(top.x + width, ui.cursor().min.y))
    }

    fn exports(&self, ui: &mut egui::Ui, plot: egui::Rect) {
        let csv = || export::series_csv("t (s)", &self.settings.series());
        export::bar(
            ui,
            ui.scope_id().with("speed-profile-exports"),
            &[
                Export::Png {
                    file: "kinolab-speed-profile.png",
                    rect: plot,
                },
                Export::Csv {
                    file: "kinolab-speed-profile.csv",
                    make: &csv,
                },
            ],
        );
    }

    fn words(&self, ui: &mut egui::Ui) {
        ui.label(self.settings.shape_text());
        ui.label(RichText::new("The area under the speed curve is the distance.").small());
    }
}

impl Settings {
    /// The profile's shape, its peak speed and how long it takes.
    fn shape_text(&self) -> String {
        let p = self.profile();
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
        format!("{shape} Total {} s.", fixed(p.duration(), 2))
    }
}

impl LabWidget for Widget {
    /// The move asked for, then the profile's shape, peak and duration.
    fn describe(&self) -> Option<String> {
        let s = &self.settings;
        Some(format!(
            "{} m with at most {} m/s and {} m/s². {}",
            fixed(s.distance, 2),
            fixed(s.max_speed, 2),
            fixed(s.max_accel, 1),
            s.shape_text()
        ))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.sliders(ui);
        let plot = self.plot(ui);
        self.words(ui);
        self.exports(ui, plot);
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
        let settings = match link::read::<Settings, ()>(NAME, state) {
            Ok((settings, _)) => settings,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => Settings {
                    distance: old.distance,
                    max_speed: old.max_speed,
                    max_accel: old.max_accel,
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

    fn widget(params: &[(&str, &str)]) -> Widget {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        Widget {
            settings,
            initial: settings,
        }
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let old = link::encode(&(2.0_f64, 0.8_f64, 1.5_f64)).unwrap_or_default();
        let mut w = widget(&[]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(
            w.settings,
            Settings {
                distance: 2.0,
                max_speed: 0.8,
                max_accel: 1.5
            }
        );
        let bad = link::encode(&(2.0_f64, 9.0_f64, 1.5_f64)).unwrap_or_default();
        let mut w = widget(&[("distance", "3")]);
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.settings.distance, 3.0);
    }

    #[test]
    fn the_description_holds_the_peak_and_the_duration() {
        let mut w = widget(&[("distance", "2"), ("max-speed", "0.5"), ("max-accel", "1")]);
        let says = |w: &Widget| {
            let p = w.settings.profile();
            let words = w.describe().unwrap_or_default();
            for part in [
                format!("{} m/s", fixed(p.peak, 2)),
                format!("Total {} s", fixed(p.duration(), 2)),
            ] {
                assert!(words.contains(&part), "{part} missing from: {words}");
            }
            words
        };
        let trapezoid = says(&w);
        assert!(trapezoid.contains("Trapezoid"), "{trapezoid}");
        // Too short to cruise: a triangle, and the words change with it.
        w.settings.distance = 0.1;
        let triangle = says(&w);
        assert!(triangle.contains("Triangle"), "{triangle}");
        assert_ne!(triangle, trapezoid);
    }

    #[test]
    fn settings_round_trip_and_the_csv_has_a_row_per_sample() {
        let mut w = widget(&[]);
        assert_eq!(w.state(), None);
        w.settings.max_speed = 0.25;
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
        let csv = export::series_csv("t (s)", &w.settings.series());
        assert_eq!(csv.lines().count(), 1 + SAMPLES as usize + 1);
    }
}
