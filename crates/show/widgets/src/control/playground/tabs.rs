//! The playground's tabs that show runs: one run with its plots, many
//! starts at once, and open loop against closed loop.

use egui::{RichText, Stroke, vec2};
use kinolab_common::display::fixed;
use kinolab_control::{Pose, Sample, Trajectory};

use super::Playground;
use super::floor::Grabs;
use super::settings::pose;
use crate::control::field;
use crate::draw::labels::Labels;
use crate::theme;
use crate::widget::sentence;

impl Playground {
    pub(super) fn run_tab(&mut self, ui: &mut egui::Ui) {
        let width = ui.available_width().min(900.0);
        let top = ui.cursor().min;
        let keep = [pose(self.set.start), pose(self.set.goal)];
        let (painter, view) = self.floor(ui, vec2(width, 320.0), Grabs::StartAndGoal, &keep);
        let Some(run) = self.run.clone() else {
            self.draw_ends(ui, &painter, &view, true, None);
            return;
        };
        let t = match run {
            Ok(t) => t,
            Err(e) => {
                self.draw_ends(ui, &painter, &view, true, None);
                ui.label(RichText::new(e).color(theme::error_color(ui)));
                return;
            }
        };
        let accent = theme::accent(ui);
        field::path(&painter, &view, &t.samples, Stroke::new(2.0, accent));
        // Ghosts every second, then the robot at the instant shown.
        let ghost = ui.visuals().text_color().gamma_multiply(0.15);
        for s in t
            .samples
            .iter()
            .filter(|s| s.t > 0.0 && (s.t.fract() < 1e-9 || 1.0 - s.t.fract() < 1e-9))
        {
            field::robot(&painter, &view, &s.pose, ghost);
        }
        let now = field::at_time(&t.samples, self.time()).map(|s| s.pose);
        if let Some(pose) = &now {
            field::robot(&painter, &view, pose, accent);
        }
        // Start and goal over the run, their names clear of the robot.
        self.draw_ends(ui, &painter, &view, true, now.as_ref());
        ui.label(
            RichText::new("Drag the dots to move start and goal, the rings to turn them.").small(),
        );
        self.player_ui(ui, t.samples.len());
        let text = RichText::new(summary(&t));
        ui.label(if t.diverged.is_some() {
            text.color(theme::error_color(ui))
        } else {
            text
        });
        let plots = self.plots(ui, &t, width);
        self.exports(
            ui,
            egui::Rect::from_min_max(top, plots.max),
            &[("closed", &t)],
        );
    }

    /// The player of the runs on screen: its buttons, the time, the scrub
    /// bar (`samples` long), and playing on.
    pub(super) fn player_ui(&mut self, ui: &mut egui::Ui, samples: usize) {
        let Some(player) = &mut self.player else {
            return;
        };
        player.controls(ui);
        player.timeline(
            ui,
            "Time in the run",
            samples.saturating_sub(1),
            &mut |_, _, _, _| {},
        );
        player.run(ui, super::MOST_PER_FRAME);
    }

    pub(super) fn many_tab(&mut self, ui: &mut egui::Ui) {
        crate::widget::control_row(ui, |ui| {
            let count = crate::widget::range(super::NAME, "starts");
            ui.add(
                egui::Slider::new(
                    &mut self.set.starts,
                    *count.start() as usize..=*count.end() as usize,
                )
                .text("starts on a 1 m circle"),
            );
            ui.add(
                egui::Slider::new(
                    &mut self.set.start_heading,
                    crate::widget::range(super::NAME, "start-heading"),
                )
                .text("start heading (°)")
                .step_by(5.0),
            );
        });
        let width = ui.available_width().min(900.0);
        // The 1 m circle of starts and a little room.
        let [gx, gy, _] = self.set.goal;
        let ring: Vec<Pose> = [[-0.6, -0.6], [0.6, 0.6]]
            .iter()
            .map(|[dx, dy]| Pose::new(gx + dx, gy + dy, 0.0))
            .collect();
        let (painter, view) = self.floor(ui, vec2(width, 380.0), Grabs::Goal, &ring);
        let area = painter.clip_rect();
        let (accent, bad) = (theme::accent(ui), theme::error_color(ui));
        let runs = match self.many.clone() {
            Some(Ok(runs)) => runs,
            Some(Err(e)) => {
                ui.label(RichText::new(e).color(bad));
                return;
            }
            None => return,
        };
        for t in &runs {
            let color = if t.backward { bad } else { accent };
            field::path(
                &painter,
                &view,
                &t.samples,
                Stroke::new(1.3, color.gamma_multiply(0.8)),
            );
            if let Some(s) = t.samples.first() {
                let mut marks = Labels::default();
                let faint = color.gamma_multiply(0.6);
                field::pose(&painter, &mut marks, &view, &s.pose, faint, "", false);
            }
        }
        self.draw_ends(ui, &painter, &view, false, None);
        let reached = runs.iter().filter(|t| t.reached).count();
        let slowest = runs
            .iter()
            .filter_map(|t| t.time_to_goal)
            .fold(0.0, f64::max);
        ui.label(format!(
            "{reached} of {} starts reach the goal within {} s (slowest {} s). Blue drove forward, red rear first.",
            runs.len(),
            kinolab_control::batch::PREVIEW_DURATION,
            fixed(slowest, 1)
        ));
        self.many_exports(ui, area);
    }

    pub(super) fn compare_tab(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            let label = ui.label("Plan:");
            let width = ui.available_width().min(360.0);
            ui.add(
                egui::TextEdit::singleline(&mut self.set.plan)
                    .desired_width(width)
                    .font(egui::TextStyle::Monospace),
            )
            .labelled_by(label.id);
        });
        ui.label(RichText::new("Segments: line METRES, arc RADIUS DEGREES, turn DEGREES, separated by semicolons. Raise the slip under real-world effects.").small());
        let (plan, open, closed) = match self.compare.clone() {
            Some(Ok(c)) => c,
            Some(Err(e)) => {
                ui.label(RichText::new(e).color(theme::error_color(ui)));
                return;
            }
            None => return,
        };
        // The plan as drawn on paper: the nominal pose at each sample time.
        let nominal: Vec<Sample> = open
            .samples
            .iter()
            .map(|s| Sample {
                pose: plan.nominal(s.t),
                ..*s
            })
            .collect();
        let mut keep: Vec<Pose> = nominal.iter().step_by(20).map(|s| s.pose).collect();
        keep.push(pose(self.set.start));
        let runs = [("Open loop", &open), ("Closed loop", &closed)];
        let top = ui.cursor().min;
        crate::widget::panels(ui, runs.len(), |ui, i, width| {
            let (title, t) = runs[i];
            ui.label(RichText::new(title).strong());
            self.compare_floor(ui, width.min(450.0), &keep, &nominal, &plan.end(), t);
        });
        let area = egui::Rect::from_min_max(
            top,
            egui::pos2(top.x + ui.available_width(), ui.cursor().min.y),
        );
        ui.label(RichText::new("Grey: the plan as drawn on paper. Both robots meet the same slip and pushes (same seed).").small());
        self.player_ui(ui, open.samples.len().max(closed.samples.len()));
        self.exports(ui, area, &[("open", &open), ("closed", &closed)]);
    }

    /// One side of the comparison: the plan in grey, the run, the robot.
    fn compare_floor(
        &mut self,
        ui: &mut egui::Ui,
        width: f32,
        keep: &[Pose],
        nominal: &[Sample],
        end: &Pose,
        t: &Trajectory,
    ) {
        let (painter, view) = self.floor(ui, vec2(width, 280.0), Grabs::Start, keep);
        let accent = theme::accent(ui);
        field::path(
            &painter,
            &view,
            nominal,
            Stroke::new(1.5, ui.visuals().text_color().gamma_multiply(0.3)),
        );
        let mut labels = Labels::default();
        let good = theme::good_color(ui);
        field::pose(&painter, &mut labels, &view, end, good, "goal", false);
        let ink = ui.visuals().text_color().gamma_multiply(0.7);
        field::pose(
            &painter,
            &mut labels,
            &view,
            &pose(self.set.start),
            ink,
            "start",
            true,
        );
        labels.draw(&painter, &egui::FontId::proportional(theme::TITLE_SIZE));
        field::path(&painter, &view, &t.samples, Stroke::new(2.0, accent));
        if let Some(s) = field::at_time(&t.samples, self.time()) {
            field::robot(&painter, &view, &s.pose, accent);
        }
        ui.label(format!(
            "Ends {} cm and {}° from the goal.",
            fixed(t.final_position_error * 100.0, 1),
            fixed(t.final_heading_error.to_degrees().abs(), 1)
        ));
    }
}

/// A run in one sentence.
pub(super) fn summary(t: &Trajectory) -> String {
    if let Some(d) = &t.diverged {
        return format!(
            "{}. The plots show the run up to that moment.",
            sentence(&d.reason)
        );
    }
    let reached = match t.time_to_goal {
        Some(s) => format!(
            "Reached (within 1 mm and 0.1°, and stayed) after {} s",
            fixed(s, 2)
        ),
        None => format!(
            "Not reached: ends {} mm and {}° off",
            fixed(t.final_position_error * 1000.0, 1),
            fixed(t.final_heading_error.to_degrees().abs(), 1)
        ),
    };
    format!(
        "{reached}, driving {}. Path {} m; fastest wheel {} rad/s.",
        if t.backward { "rear first" } else { "forward" },
        fixed(t.path_length, 2),
        fixed(t.peak_wheel_speed, 1)
    )
}
