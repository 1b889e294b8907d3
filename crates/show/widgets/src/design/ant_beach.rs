//! Simon's ant on the beach: the pebbles, the path the one rule makes at
//! the chosen body size, the core's numbers, and tortuosity against size
//! for this beach.

use egui::{RichText, Sense, Stroke, vec2};
use egui_plot::{Line, Plot, PlotPoints, Points};
use kinolab_common::Feedback;
use kinolab_design::ant::{self, Beach, DEFAULT_PEBBLES, Walk};
use serde::{Deserialize, Serialize};

use crate::draw::PlaneView;
use crate::draw::labels::Labels;
use crate::widget::{LabWidget, Params, feedback_ui, number};
use crate::{link, theme};

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Setup {
    size: f64,
    seed: u64,
}

struct AntBeach {
    setup: Setup,
    initial: Setup,
    beach: Option<Beach>,
    walk: Option<Walk>,
    /// (size, tortuosity) for this beach.
    curve: Vec<[f64; 2]>,
    task: bool,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let setup = Setup {
        size: number(p, "size").clamp(1.0, ant::MAX_SIZE),
        seed: number(p, "seed").clamp(0.0, 9999.0) as u64,
    };
    let mut w = AntBeach {
        initial: setup.clone(),
        setup,
        beach: None,
        walk: None,
        curve: Vec::new(),
        task: p.choice("task") == Some("nearly-straight"),
        feedback: None,
    };
    w.new_beach();
    Ok(Box::new(w))
}

impl AntBeach {
    fn new_beach(&mut self) {
        self.beach = Beach::new(self.setup.seed, DEFAULT_PEBBLES).ok();
        self.curve = self.beach.as_ref().map_or_else(Vec::new, |b| {
            ant::sizes()
                .filter_map(|s| ant::walk(b, s).ok().map(|w| [s, w.tortuosity]))
                .collect()
        });
        self.rewalk();
    }

    fn rewalk(&mut self) {
        self.walk = self
            .beach
            .as_ref()
            .and_then(|b| ant::walk(b, self.setup.size).ok());
        self.feedback = None;
    }

    fn draw(&self, ui: &mut egui::Ui) {
        let width = ui.available_width();
        let (rect, _) = ui.allocate_exact_size(vec2(width, width * 0.6 * 0.9), Sense::hover());
        let view = PlaneView::fit(
            rect.shrink(4.0),
            [0.0, -ant::HALF_WIDTH],
            [ant::LENGTH, ant::HALF_WIDTH],
        );
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 6.0, theme::sand_color(ui));
        let body = ant::ANT * self.setup.size;
        if let Some(beach) = &self.beach {
            for p in &beach.pebbles {
                painter.circle_filled(
                    view.to_screen([p.x, p.y]),
                    view.length(p.r).max(0.8),
                    theme::pebble_color(p.r > 0.25 * body),
                );
            }
        }
        if let Some(w) = &self.walk {
            let pts: Vec<egui::Pos2> = w.path.iter().map(|&p| view.to_screen(p)).collect();
            painter.add(egui::Shape::line(pts, Stroke::new(2.0, theme::accent(ui))));
            if let Some(&last) = w.path.last() {
                let r = view.length(body / 2.0).max(3.0);
                painter.circle_stroke(
                    view.to_screen(last),
                    r,
                    Stroke::new(1.5, theme::robot_color(ui)),
                );
            }
        }
        let mut labels = Labels::default();
        for (p, label) in [(ant::START, "start"), (ant::GOAL, "goal")] {
            let at = view.to_screen(p);
            labels
                .add(at, label, ui.visuals().text_color())
                .toward(vec2(0.0, -1.0));
        }
        labels.draw(&painter, &egui::FontId::proportional(theme::SMALL_SIZE));
    }

    fn plot(&self, ui: &mut egui::Ui) {
        let curve: PlotPoints<'static> = self.curve.iter().map(|[s, t]| [s.log10(), *t]).collect();
        let here: PlotPoints<'static> = self
            .walk
            .iter()
            .map(|w| [w.size.log10(), w.tortuosity])
            .collect();
        Plot::new(ui.scope_id().with("tortuosity"))
            .height(150.0)
            .x_axis_label("body size (log10 of ant lengths)")
            .y_axis_label("tortuosity")
            .include_y(1.0)
            .allow_scroll(false)
            .show(ui, |plot| {
                plot.line(Line::new("this beach", curve).width(2.0));
                plot.points(Points::new("this body", here).radius(5.0));
            });
    }
}

impl LabWidget for AntBeach {
    fn ui(&mut self, ui: &mut egui::Ui) {
        let before = self.setup.clone();
        crate::widget::control_row(ui, |ui| {
            ui.add(
                egui::Slider::new(&mut self.setup.size, 1.0..=ant::MAX_SIZE)
                    .logarithmic(true)
                    .text("body size (ant lengths)"),
            );
            if ui.button("New beach").clicked() {
                self.setup.seed = (self.setup.seed + 1) % 10_000;
            }
            ui.label(format!("beach {}", self.setup.seed));
        });
        if self.setup.seed != before.seed {
            self.new_beach();
        } else if self.setup != before {
            self.rewalk();
        }
        self.draw(ui);
        if let Some(w) = &self.walk {
            ui.label(RichText::new(format!(
                "body {:.3} m · pebbles that matter: {} · path {:.3} m · tortuosity {:.3} · turns {}{}",
                ant::ANT * w.size,
                w.obstacles,
                w.length,
                w.tortuosity,
                w.turns,
                if w.reached { "" } else { " · did not get across" }
            )).strong());
        }
        self.plot(ui);
        if self.task {
            ui.separator();
            ui.label(RichText::new("Task: find a body size of at most 100 whose path on this beach is within 1 % of straight, then check.").strong());
            if ui.button("Check").clicked() {
                self.feedback = Some(kinolab_design::exercise::nearly_straight(
                    self.setup.seed,
                    self.setup.size,
                ));
            }
            feedback_ui(ui, self.feedback.as_ref());
        }
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.setup, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(s) = link::decode::<Setup>(state)
            && (1.0..=ant::MAX_SIZE).contains(&s.size)
            && s.seed < 10_000
        {
            self.setup = s;
            self.new_beach();
        }
        Ok(())
    }
}
