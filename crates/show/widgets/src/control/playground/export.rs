//! The playground's plots, and what its export bar offers: the floor and
//! plots as a PNG, the runs as CSV, and the run's file for `kinolab
//! simulate` (or `kinolab batch` for many starts).

use egui_plot::{Plot, PlotPoints};
use kinolab_common::angle::wrap;
use kinolab_control::{Sample, Trajectory};

use super::Playground;
use super::settings::pretty;
use crate::draw::plot::{REFERENCE, series_legend, series_lines};
use crate::export::{self, Export};

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
    /// ρ, α, β and v, ω against time on linked axes, with the instant
    /// shown; the area they took.
    pub(super) fn plots(&self, ui: &mut egui::Ui, t: &Trajectory, width: f32) -> egui::Rect {
        let series = |f: &dyn Fn(&Sample) -> f64| -> PlotPoints<'static> {
            t.samples.iter().map(|s| [s.t, f(s)]).collect()
        };
        let base = ui.scope_id();
        let link = base.with("plots-link");
        let now = self.time();
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
            series_lines(plot, polar.into_iter().zip(values).collect(), Some(now));
        });
        series_legend(ui, &polar, &[("now", REFERENCE)]);
        let command = ["v (m/s)", "ω (rad/s)"];
        plot("command-plot", "v (m/s), ω (rad/s)")
            .x_axis_label("t (s)")
            .show(ui, |plot| {
                let values = [series(&|s| s.v), series(&|s| s.omega)];
                series_lines(plot, command.into_iter().zip(values).collect(), Some(now));
            });
        series_legend(ui, &command, &[("now", REFERENCE)]);
        egui::Rect::from_min_max(top, egui::pos2(top.x + width, ui.cursor().min.y))
    }

    /// The bar under runs: `area` as a PNG, `runs` as CSV, and the run on
    /// screen as its run file.
    pub(super) fn exports(
        &self,
        ui: &mut egui::Ui,
        area: egui::Rect,
        runs: &[(&str, &Trajectory)],
    ) {
        let table = || csv(runs);
        let shown = self.shown_run();
        let (file, command) = match shown {
            Some((name, _, _)) => (name, format!("kinolab simulate {name}")),
            None => ("playground.run.json", String::new()),
        };
        let make = || match &shown {
            Some((_, text, _)) => pretty(text),
            None => Err("these settings make no run".into()),
        };
        export::bar(
            ui,
            ui.scope_id().with("playground-exports"),
            &[
                Export::Png {
                    file: "kinolab-controller.png",
                    rect: area,
                },
                Export::Csv {
                    file: "kinolab-run.csv",
                    make: &table,
                },
                Export::Run {
                    file,
                    command: &command,
                    make: &make,
                },
            ],
        );
    }

    /// The bar under many starts: the floor as a PNG, and the runs' file
    /// with the `kinolab batch` command that repeats them.
    pub(super) fn many_exports(&self, ui: &mut egui::Ui, area: egui::Rect) {
        let file = "many-starts.run.json";
        let command = format!("kinolab {}", self.set.many_args(file).join(" "));
        let make = || pretty(&self.set.many_file());
        export::bar(
            ui,
            ui.scope_id().with("playground-many-exports"),
            &[
                Export::Png {
                    file: "kinolab-many-starts.png",
                    rect: area,
                },
                Export::Run {
                    file,
                    command: &command,
                    make: &make,
                },
            ],
        );
    }
}

/// The bar under a picture with nothing else to take away.
pub(super) fn picture_export(ui: &mut egui::Ui, area: egui::Rect, file: &str) {
    export::bar(
        ui,
        ui.scope_id().with("playground-picture-exports"),
        &[Export::Png { file, rect: area }],
    );
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
