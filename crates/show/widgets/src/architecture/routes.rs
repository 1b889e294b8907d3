//! Sensing routes: sensors on the left, the functions they can feed on the
//! right. Click a sensor, then a function, to draw (or remove) a wire; the
//! core names each sensor's route and the paradigm the wiring amounts to.

use egui::{Color32, Rect, RichText, Sense, Stroke, pos2, vec2};
use kinolab_architectures::Architecture;
use kinolab_architectures::exercise::wire_hybrid;
use kinolab_architectures::routes::{FUNCTIONS, MODEL, Route, SENSORS, Wiring};
use kinolab_common::Feedback;

use crate::widget::{LabWidget, Params, feedback_ui};
use crate::{link, theme};

struct SensingRoutes {
    wiring: Wiring,
    initial: Wiring,
    /// The sensor picked, waiting for a function.
    picked: Option<usize>,
    task: bool,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let wiring = match p.choice("preset") {
        Some("hierarchical") => Wiring::preset(Architecture::Hierarchical),
        Some("reactive") => Wiring::preset(Architecture::Reactive),
        Some("hybrid") => Wiring::preset(Architecture::Hybrid),
        _ => Wiring::default(),
    };
    Ok(Box::new(SensingRoutes {
        wiring,
        initial: wiring,
        picked: None,
        task: p.choice("task") == Some("wire-hybrid"),
        feedback: None,
    }))
}

fn route_color(ui: &egui::Ui, r: Route) -> Color32 {
    match r {
        Route::Unused => ui.visuals().weak_text_color(),
        Route::Global => theme::ARCHITECTURE_COLORS[0],
        Route::Local => theme::ARCHITECTURE_COLORS[1],
        Route::Hybrid => theme::ARCHITECTURE_COLORS[2],
    }
}

impl SensingRoutes {
    /// The two columns of boxes and the wires between them.
    fn diagram(&mut self, ui: &mut egui::Ui) {
        let width = ui.available_width();
        let row = 34.0;
        let (rect, _) = ui.allocate_exact_size(
            vec2(width, row * SENSORS.len() as f32 + 8.0),
            Sense::hover(),
        );
        let box_w = (width * 0.34).min(170.0);
        let left = |i: usize| {
            Rect::from_min_size(
                pos2(rect.left(), rect.top() + 4.0 + row * i as f32),
                vec2(box_w, row - 8.0),
            )
        };
        let right_row = row * SENSORS.len() as f32 / FUNCTIONS.len() as f32;
        let right = |j: usize| {
            Rect::from_min_size(
                pos2(
                    rect.right() - box_w,
                    rect.top() + 4.0 + right_row * j as f32 + (right_row - row) / 2.0,
                ),
                vec2(box_w, row - 8.0),
            )
        };
        let report = self.wiring.report();
        let painter = ui.painter_at(rect);
        for (s, feeds) in self.wiring.feeds.iter().enumerate() {
            for (f, on) in feeds.iter().enumerate() {
                if *on {
                    let c = route_color(ui, report.routes[s]);
                    painter.line_segment(
                        [left(s).right_center(), right(f).left_center()],
                        Stroke::new(2.5, c),
                    );
                }
            }
        }
        let ink = ui.visuals().text_color();
        for (s, name) in SENSORS.iter().enumerate() {
            let r = left(s);
            let picked = self.picked == Some(s);
            let response = ui.interact(r, ui.scope_id().with(("sensor", s)), Sense::click());
            if response.clicked() {
                self.picked = if picked { None } else { Some(s) };
            }
            let stroke = Stroke::new(
                if picked { 3.0 } else { 1.0 },
                if picked { theme::accent(ui) } else { ink },
            );
            painter.rect(
                r,
                4.0,
                ui.visuals().extreme_bg_color,
                stroke,
                egui::StrokeKind::Inside,
            );
            painter.text(
                r.left_center() + vec2(8.0, 0.0),
                egui::Align2::LEFT_CENTER,
                *name,
                egui::FontId::proportional(theme::TITLE_SIZE),
                ink,
            );
            let route = report.routes[s];
            painter.text(
                r.right_center() - vec2(6.0, 0.0),
                egui::Align2::RIGHT_CENTER,
                route.name(),
                egui::FontId::proportional(theme::SMALL_SIZE),
                route_color(ui, route),
            );
        }
        for (f, name) in FUNCTIONS.iter().enumerate() {
            let r = right(f);
            let response = ui.interact(r, ui.scope_id().with(("function", f)), Sense::click());
            if response.clicked()
                && let Some(s) = self.picked
            {
                self.wiring.feeds[s][f] = !self.wiring.feeds[s][f];
                self.feedback = None;
            }
            let fill = if f == MODEL {
                theme::accent(ui).gamma_multiply(0.15)
            } else {
                ui.visuals().extreme_bg_color
            };
            painter.rect(
                r,
                4.0,
                fill,
                Stroke::new(1.0, ink),
                egui::StrokeKind::Inside,
            );
            let label = if f == MODEL {
                "world model → planner"
            } else {
                name
            };
            painter.text(
                r.left_center() + vec2(8.0, 0.0),
                egui::Align2::LEFT_CENTER,
                label,
                egui::FontId::proportional(theme::TITLE_SIZE),
                ink,
            );
        }
    }
}

impl LabWidget for SensingRoutes {
    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label("Start from:");
            for (name, kind) in [
                ("hierarchical", Architecture::Hierarchical),
                ("reactive", Architecture::Reactive),
                ("hybrid", Architecture::Hybrid),
            ] {
                if ui.button(name).clicked() {
                    self.wiring = Wiring::preset(kind);
                    self.feedback = None;
                }
            }
            if ui.button("Clear").clicked() {
                self.wiring = Wiring::default();
                self.feedback = None;
            }
        });
        ui.horizontal_wrapped(|ui| {
            ui.label(
                RichText::new("Click a sensor, then a function, to add or remove a wire. Routes:")
                    .small(),
            );
            for route in [Route::Local, Route::Global, Route::Hybrid] {
                ui.label(
                    RichText::new(route.name())
                        .small()
                        .color(route_color(ui, route)),
                );
            }
        });
        self.diagram(ui);
        let report = self.wiring.report();
        let verdict = match report.paradigm {
            None => "Nothing is wired yet.".to_owned(),
            Some(Architecture::Reactive) => "Reactive: every sensor goes straight to behaviours (local routes); there is no world model.".to_owned(),
            Some(Architecture::Hierarchical) => "Hierarchical: every sensor is fused into the world model (global routes); nothing reaches a behaviour directly.".to_owned(),
            Some(Architecture::Hybrid) => "Hybrid: behaviours read sensors directly and a cartographer also fuses sensors into a world model for the planner.".to_owned(),
        };
        ui.label(RichText::new(verdict).strong());
        if self.task {
            ui.separator();
            ui.label(RichText::new("Task: wire a hybrid robot that uses every sensor.").strong());
            if ui.button("Check").clicked() {
                self.feedback = Some(wire_hybrid(&self.wiring));
            }
            feedback_ui(ui, self.feedback.as_ref());
        }
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.wiring, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(w) = link::decode::<Wiring>(state) {
            self.wiring = w;
        }
        Ok(())
    }
}
