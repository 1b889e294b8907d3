//! The cart-table: a body on one foot, pushed. The ankle holds the zero
//! moment point at the capture point as far as the foot reaches; the side
//! view shows the body, the foot, the ZMP and the capture point, and a plot
//! follows x, ẋ and the ZMP through the run.

use egui::{Color32, Pos2, RichText, Sense, Stroke, vec2};
use egui_plot::{Line, Plot, PlotPoints};
use kinolab_common::Feedback;
use kinolab_common::display::fixed;
use kinolab_locomotion::balance::{CartTable, Recovery};
use serde::{Deserialize, Serialize};

use crate::draw::labels::Labels;
use crate::draw::plot::{REFERENCE, series_legend, series_lines};
use crate::draw::{PlaneView, canvas};
use crate::widget::{LabWidget, Params, feedback_ui};
use crate::{link, theme};

/// The plotted series, in palette order.
const NAMES: [&str; 3] = ["x (CoM)", "v (CoM speed)", "ZMP"];

/// The foot, m: heel and toe along x, the ankle at 0.
const HEEL: f64 = -0.05;
const TOE: f64 = 0.15;
/// Seconds a push is followed for, and the step.
const DURATION: f64 = 4.0;
const DT: f64 = 0.005;

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Setup {
    height: f64,
    push: f64,
}

struct ZmpCartTable {
    setup: Setup,
    initial: Setup,
    run: Option<Recovery>,
    /// Seconds into the run being shown.
    t: f64,
    playing: bool,
    task: bool,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let setup = Setup {
        height: p.number("height").unwrap_or(0.8),
        push: p.number("push").unwrap_or(0.2),
    };
    Ok(Box::new(ZmpCartTable {
        initial: setup.clone(),
        setup,
        run: None,
        t: 0.0,
        playing: false,
        task: p.choice("task") == Some("largest-push"),
        feedback: None,
    }))
}

impl ZmpCartTable {
    fn table(&self) -> Option<CartTable> {
        CartTable::new(self.setup.height, HEEL, TOE).ok()
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let before = self.setup.clone();
        ui.add(egui::Slider::new(&mut self.setup.height, 0.3..=1.5).text("CoM height z_c (m)"));
        ui.add(
            egui::Slider::new(&mut self.setup.push, 0.0..=2.0)
                .step_by(0.005)
                .text("push (m/s)"),
        );
        if self.setup != before {
            self.run = None;
            self.feedback = None;
        }
        ui.horizontal_wrapped(|ui| {
            if ui.button("Push").clicked() {
                self.run = self
                    .table()
                    .and_then(|t| t.push(0.0, self.setup.push, DURATION, DT).ok());
                self.t = 0.0;
                self.playing = true;
            }
            if ui.button("Reset").clicked() {
                self.setup = self.initial.clone();
                self.run = None;
                self.feedback = None;
            }
            if let Some(table) = self.table() {
                ui.label(format!("ω = √(g / z_c) = {} 1/s", fixed(table.omega(), 2)));
            }
        });
    }

    /// The sample shown now, if a push has been made.
    fn now(&self) -> Option<kinolab_locomotion::balance::BalanceSample> {
        let run = self.run.as_ref()?;
        let k = ((self.t / DT) as usize).min(run.samples.len().saturating_sub(1));
        run.samples.get(k).copied()
    }

    fn side_view(&self, ui: &mut egui::Ui) {
        let width = ui.available_width();
        let height = 280.0;
        let (response, painter) = canvas(ui, vec2(width, height), Sense::hover());
        let rect = response.rect;
        let z = self.setup.height;
        let view = PlaneView::fit(rect.shrink(12.0), [-0.35, -0.08], [0.65, z + 0.12]);
        let ink = ui.visuals().text_color();
        let ground = [view.to_screen([-0.35, 0.0]), view.to_screen([0.65, 0.0])];
        painter.line_segment(ground, Stroke::new(1.5, ink.gamma_multiply(0.5)));
        let foot =
            egui::Rect::from_two_pos(view.to_screen([HEEL, 0.03]), view.to_screen([TOE, 0.0]));
        painter.rect_filled(foot, 2.0, ink.gamma_multiply(0.6));
        let s = self.now();
        let (x, zmp, wanted) = s.map_or((0.0, 0.0, 0.0), |s| (s.x, s.zmp, s.wanted));
        let fallen = s.is_some_and(|s| !s.inside);
        let body = view.to_screen([x, z]);
        let ankle = view.to_screen([0.0, 0.03]);
        painter.line_segment([ankle, body], Stroke::new(3.0, ink));
        let color = if fallen {
            theme::error_color(ui)
        } else {
            theme::accent(ui)
        };
        painter.circle(body, 14.0, color, Stroke::new(1.5, ink));
        // Marks on the ground, their names below it, clear of each other.
        let mut labels = Labels::default();
        let mut mark = |at: f64, color: Color32, text: &str| {
            let p = view.to_screen([at, 0.0]);
            painter.circle_filled(p, 5.0, color);
            labels.reserve(egui::Rect::from_center_size(p, vec2(10.0, 10.0)));
            labels
                .add(p, text, color)
                .toward(vec2(0.0, 1.0))
                .beyond(4.0);
        };
        mark(zmp, theme::good_color(ui), "ZMP");
        if s.is_some() {
            let at = wanted.clamp(-0.35, 0.65);
            mark(at, theme::error_color(ui), "capture point");
        }
        let com_ground: Pos2 = view.to_screen([x, 0.0]);
        painter.line_segment(
            [body, com_ground],
            Stroke::new(1.0, ink.gamma_multiply(0.3)),
        );
        labels.avoid_line(body, com_ground);
        labels.draw(&painter, &egui::FontId::proportional(theme::LABEL_SIZE));
    }

    fn plot(&self, ui: &mut egui::Ui) {
        let Some(run) = &self.run else { return };
        let series = |f: &dyn Fn(&kinolab_locomotion::balance::BalanceSample) -> f64| -> PlotPoints<'static> {
            run.samples.iter().map(|s| [s.t, f(s)]).collect()
        };
        Plot::new(ui.scope_id().with("zmp-plot"))
            .height(170.0)
            .x_axis_label("t (s)")
            .y_axis_label("m, m/s")
            .allow_scroll(false)
            .show(ui, |plot| {
                let values = [series(&|s| s.x), series(&|s| s.xd), series(&|s| s.zmp)];
                series_lines(plot, NAMES.into_iter().zip(values).collect(), Some(self.t));
                plot.line(Line::new("toe", series(&|_| TOE)).color(REFERENCE));
            });
        series_legend(ui, &NAMES, &[("toe and now", REFERENCE)]);
    }

    fn verdict(&self) -> String {
        match &self.run {
            None => "Press Push to give the body the chosen speed.".to_owned(),
            Some(r) => match r.left_foot_at {
                Some(t) => format!(
                    "From t = {} s the ZMP this motion needs lies past the toe. The real ZMP stays on the foot, at the toe, and the body falls forwards.",
                    fixed(t, 2)
                ),
                None if r.recovered => "Caught: the capture point stayed on the foot, and the body came to rest over it.".to_owned(),
                None => "Still settling.".to_owned(),
            },
        }
    }
}

impl LabWidget for ZmpCartTable {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        self.side_view(ui);
        ui.label(RichText::new(self.verdict()).strong());
        self.plot(ui);
        if self.playing {
            self.t += crate::widget::frame_dt(ui);
            if self.t >= DURATION {
                self.t = DURATION;
                self.playing = false;
            }
            crate::widget::animate(ui);
        }
        if self.task {
            ui.separator();
            ui.label(RichText::new("Task: find the largest push the ankle can still catch (to within 5 %), then check.").strong());
            if ui.button("Check").clicked()
                && let Some(table) = self.table()
            {
                self.feedback = Some(
                    kinolab_locomotion::exercise::largest_push(&table, self.setup.push)
                        .unwrap_or_else(|e| Feedback::not_yet(e.to_string())),
                );
            }
            feedback_ui(ui, self.feedback.as_ref());
        }
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.setup, &self.initial)
    }

    fn restore(&mut self, state: &str) {
        if let Some(s) = link::decode::<Setup>(state)
            && (0.3..=1.5).contains(&s.height)
            && (0.0..=2.0).contains(&s.push)
        {
            self.setup = s;
        }
    }
}
