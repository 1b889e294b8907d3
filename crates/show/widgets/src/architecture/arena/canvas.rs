//! The arena's controls, its picture (the world, three robots, one robot's
//! beliefs) and the scrub bar.

use egui::{Color32, Rect, RichText, Sense, Stroke, pos2, vec2};
use kinolab_architectures::map::Cartographer;
use kinolab_architectures::paradigm::Belief;
use kinolab_common::display::fixed;

use super::{ArchitectureArena, WORLDS};
use crate::behaviour::world_view::{draw_robot, draw_trail, draw_world};
use crate::draw::PlaneView;
use crate::theme;

pub(super) const NAMES: [&str; 3] = ["Hierarchical", "Reactive", "Hybrid"];

/// The surprises that can be sprung while the robots run.
const SPRINGS: [(&str, &str); 3] = [
    ("door", "Close the door"),
    ("person", "Send a person in"),
    ("moved-goal", "Move the goal"),
];

impl ArchitectureArena {
    pub(super) fn controls(&mut self, ui: &mut egui::Ui) {
        let before = self.design.clone();
        ui.horizontal_wrapped(|ui| {
            egui::ComboBox::new(ui.scope_id().with("world"), "world")
                .selected_text(self.design.world.clone())
                .show_ui(ui, |ui| {
                    for w in WORLDS {
                        ui.selectable_value(&mut self.design.world, w.to_owned(), w);
                    }
                });
            egui::ComboBox::new(ui.scope_id().with("surprise"), "surprise")
                .selected_text(self.design.surprise.clone())
                .show_ui(ui, |ui| {
                    for s in kinolab_architectures::surprise::ids() {
                        ui.selectable_value(&mut self.design.surprise, s.to_owned(), s);
                    }
                });
        });
        ui.add(
            egui::Slider::new(&mut self.design.planning_cost_ms, 0.0..=20.0)
                .step_by(0.5)
                .text("planning cost (ms/cell)"),
        );
        if self.design != before {
            self.playing = false;
            self.rebuild();
        }
        ui.horizontal_wrapped(|ui| {
            let done = self
                .arena
                .as_ref()
                .is_some_and(kinolab_architectures::Arena::done);
            let label = if self.playing { "Pause" } else { "Play" };
            if ui.button(label).clicked() {
                if done {
                    self.rebuild();
                }
                self.cursor = self.frames.len();
                self.playing = !self.playing;
            }
            if ui.button("Step").clicked() {
                self.playing = false;
                self.step();
            }
            if ui.button("Restart").clicked() {
                self.rebuild();
                self.playing = true;
            }
            for (speed, text) in [(1, "1×"), (4, "4×")] {
                if ui.selectable_label(self.speed == speed, text).clicked() {
                    self.speed = speed;
                }
            }
            let t = self
                .frames
                .get(self.cursor.saturating_sub(1))
                .map_or(0.0, |f| f.t);
            ui.label(format!("t = {} s", fixed(t, 1)));
        });
        ui.horizontal_wrapped(|ui| {
            ui.label("Spring now:");
            for (id, text) in SPRINGS {
                let possible = self.design.world == "office";
                if ui.add_enabled(possible, egui::Button::new(text)).clicked() {
                    self.spring(id);
                }
            }
        });
        ui.horizontal_wrapped(|ui| {
            ui.label("Beliefs of:");
            for (i, name) in NAMES.iter().enumerate() {
                let text = RichText::new(*name).color(theme::ARCHITECTURE_COLORS[i]);
                if ui.selectable_label(self.focus == i, text).clicked() {
                    self.focus = i;
                }
            }
        });
    }

    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) {
        let Some(arena) = &self.arena else { return };
        let Some(first) = arena.entrants.first() else {
            return;
        };
        let world = &first.sim.world;
        let b = world.bounds;
        let width = ui.available_width();
        let height = (width * (b.height() / b.width()) as f32).clamp(180.0, 520.0);
        let (response, painter) = ui.allocate_painter(vec2(width, height), Sense::hover());
        let view = PlaneView::fit(
            response.rect.shrink(6.0),
            [b.x_min, b.y_min],
            [b.x_max, b.y_max],
        );
        let shown = self.cursor.clamp(1, self.frames.len().max(1));
        let t = self.frames.get(shown - 1).map_or(0.0, |f| f.t);
        draw_world(ui, &painter, &view, world, t);
        if let Some(e) = arena.entrants.get(self.focus) {
            draw_belief(
                &painter,
                &view,
                &e.controller.belief(),
                theme::ARCHITECTURE_COLORS[self.focus],
            );
        }
        let ink = ui.visuals().text_color();
        for (i, e) in arena.entrants.iter().enumerate() {
            let trail = self.frames[..shown]
                .iter()
                .filter_map(|f| f.poses.get(i))
                .map(|p| [p.x, p.y]);
            draw_trail(
                &painter,
                &view,
                trail,
                theme::ARCHITECTURE_COLORS[i].gamma_multiply(0.8),
            );
            if let Some(pose) = self.frames.get(shown - 1).and_then(|f| f.poses.get(i)) {
                draw_robot(
                    &painter,
                    &view,
                    pose,
                    e.sim.body.radius(),
                    theme::ARCHITECTURE_COLORS[i],
                    ink,
                );
            }
        }
    }

    /// A bar across the run so far: click or drag to look back.
    pub(super) fn scrubber(&mut self, ui: &mut egui::Ui) {
        let width = ui.available_width();
        let (rect, response) = ui.allocate_exact_size(vec2(width, 14.0), Sense::click_and_drag());
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 3.0, ui.visuals().extreme_bg_color);
        let total = self.arena.as_ref().map_or(1.0, |a| a.duration).max(1e-9);
        let x = |t: f64| rect.left() + width * (t / total).clamp(0.0, 1.0) as f32;
        let end = self.frames.last().map_or(0.0, |f| f.t);
        let at = self
            .frames
            .get(self.cursor.saturating_sub(1))
            .map_or(0.0, |f| f.t);
        painter.rect_filled(
            Rect::from_min_max(rect.min, pos2(x(end), rect.bottom())),
            3.0,
            theme::accent(ui).gamma_multiply(0.3),
        );
        painter.line_segment(
            [pos2(x(at), rect.top()), pos2(x(at), rect.bottom())],
            Stroke::new(2.0, ui.visuals().text_color()),
        );
        if let Some(p) = response.interact_pointer_pos() {
            let t = f64::from((p.x - rect.left()) / width) * total;
            self.playing = false;
            self.cursor = self.frames.partition_point(|f| f.t <= t).max(1);
        }
    }
}

/// One robot's beliefs: the cells its map holds occupied (felt ones
/// darker), the search in progress, and the plan still ahead.
fn draw_belief(painter: &egui::Painter, view: &PlaneView, belief: &Belief<'_>, color: Color32) {
    if let Some(map) = belief.map {
        draw_map(painter, view, map, color);
    }
    if let Some(p) = belief.planning {
        let half = p.grid.cell / 2.0;
        for &c in p.searching.expanded() {
            let q = p.grid.centre(c);
            let r = Rect::from_two_pos(
                view.to_screen([q.x - half, q.y + half]),
                view.to_screen([q.x + half, q.y - half]),
            );
            painter.rect_filled(r, 0.0, color.gamma_multiply(0.12));
        }
    }
    if !belief.plan.is_empty() {
        let pts: Vec<_> = belief.plan.iter().map(|p| view.to_screen(*p)).collect();
        let dash = egui::Shape::dashed_line(&pts, Stroke::new(2.5, color), 8.0, 5.0);
        painter.extend(dash);
        for p in &pts {
            painter.circle_stroke(*p, 4.0, Stroke::new(1.5, color));
        }
    }
}

fn draw_map(painter: &egui::Painter, view: &PlaneView, map: &Cartographer, color: Color32) {
    let half = map.cell / 2.0;
    // The fence is drawn already; its row of cells would only fringe it.
    let inner = |(i, j): (usize, usize)| i > 0 && j > 0 && i + 1 < map.nx && j + 1 < map.ny;
    for c in map.occupied_cells().filter(|c| inner(*c)) {
        let q = map.centre(c);
        let (_, felt) = map.evidence(c);
        let r = Rect::from_two_pos(
            view.to_screen([q.x - half, q.y + half]),
            view.to_screen([q.x + half, q.y - half]),
        );
        painter.rect_filled(r, 0.0, color.gamma_multiply(if felt { 0.75 } else { 0.35 }));
    }
}
