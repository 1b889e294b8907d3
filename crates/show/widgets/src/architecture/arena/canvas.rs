//! The arena's controls, its picture (the world, three robots, one robot's
//! beliefs) and its scrub bar.

use egui::{Color32, Rect, RichText, Sense, Stroke, pos2, vec2};
use kinolab_architectures::Architecture;
use kinolab_architectures::map::Cartographer;
use kinolab_architectures::paradigm::Belief;

use super::ArchitectureArena;
use super::race::Spring;
use super::settings::{Scripted, WorldId};
use crate::behaviour::world_view::{draw_robot, draw_trail, draw_world};
use crate::draw::{PlaneView, canvas, marks};
use crate::theme;
use crate::widget::range;

pub(super) const NAMES: [&str; 3] = ["Hierarchical", "Reactive", "Hybrid"];

impl ArchitectureArena {
    pub(super) fn controls(&mut self, ui: &mut egui::Ui) {
        let before = self.settings.clone();
        let s = &mut self.settings;
        ui.horizontal_wrapped(|ui| {
            egui::ComboBox::new(ui.scope_id().with("world"), "world")
                .selected_text(s.world.id())
                .show_ui(ui, |ui| {
                    for w in WorldId::ALL {
                        crate::widget::choose(ui, &mut s.world, w, w.id());
                    }
                });
            egui::ComboBox::new(ui.scope_id().with("surprise"), "surprise")
                .selected_text(s.surprise.id())
                .show_ui(ui, |ui| {
                    for k in Scripted::ALL {
                        crate::widget::choose(ui, &mut s.surprise, k, k.id());
                    }
                });
        });
        ui.add(
            egui::Slider::new(&mut s.planning_cost, range(super::NAME, "planning_cost"))
                .step_by(0.5)
                .text("planning cost (ms/cell)"),
        );
        ui.horizontal_wrapped(|ui| {
            ui.label("Beliefs of (and Save run for):");
            for (i, name) in NAMES.iter().enumerate() {
                let text = RichText::new(*name).color(theme::ARCHITECTURE_COLORS[i]);
                let kind = Architecture::ALL[i];
                if crate::widget::choice(ui, s.focus == kind, text).clicked() {
                    s.focus = kind;
                }
            }
        });
        let changed = |a: &super::Settings, b: &super::Settings| {
            (a.world, a.surprise, a.planning_cost) != (b.world, b.surprise, b.planning_cost)
        };
        if changed(&self.settings, &before) {
            self.rebuild();
        }
    }

    /// The surprise buttons: each springs at the instant shown.
    pub(super) fn springs(&mut self, ui: &mut egui::Ui) {
        let possible = self.player.is_some();
        ui.horizontal_wrapped(|ui| {
            ui.label("Spring now:");
            for kind in Spring::ALL {
                if ui
                    .add_enabled(possible, egui::Button::new(kind.label()))
                    .on_hover_text("At the instant shown; what came after it is run again")
                    .clicked()
                {
                    self.spring(kind);
                }
            }
        });
        if let Some(notice) = &self.notice {
            ui.label(RichText::new(notice).color(theme::error_color(ui)));
        }
    }

    /// The world, the chosen robot's beliefs, every robot's trail and
    /// pose at the instant shown; where it was drawn.
    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) -> Option<Rect> {
        let focus = self.settings.focus_index();
        let player = self.player.as_mut()?;
        let trails: Vec<Vec<[f64; 2]>> = (0..self.first.len())
            .map(|i| {
                let later = player
                    .ticks_shown()
                    .iter()
                    .filter_map(|f| f.robots.get(i))
                    .map(|(s, _)| [s.motion.x, s.motion.y]);
                self.first
                    .get(i)
                    .map(|s| [s.motion.x, s.motion.y])
                    .into_iter()
                    .chain(later)
                    .collect()
            })
            .collect();
        let t = player.time();
        let arena = &player.state().arena;
        let world = &arena.entrants.first()?.sim.world;
        let b = world.bounds;
        let width = ui.available_width();
        let height = (width * (b.height() / b.width()) as f32).clamp(180.0, 520.0);
        let (response, painter) = canvas(ui, vec2(width, height), Sense::hover());
        let view = PlaneView::fit(
            response.rect.shrink(6.0),
            [b.x_min, b.y_min],
            [b.x_max, b.y_max],
        );
        draw_world(ui, &painter, &view, world, t);
        if let Some(e) = arena.entrants.get(focus) {
            let color = theme::ARCHITECTURE_COLORS[focus];
            draw_belief(&painter, &view, &e.controller.belief(), color);
        }
        let ink = ui.visuals().text_color();
        for (i, (e, trail)) in arena.entrants.iter().zip(trails).enumerate() {
            let color = theme::ARCHITECTURE_COLORS[i % 3];
            draw_trail(
                &painter,
                &view,
                trail.into_iter(),
                color.gamma_multiply(0.8),
            );
            draw_robot(
                &painter,
                &view,
                &e.sim.pose,
                e.sim.body.radius(),
                color,
                ink,
            );
        }
        Some(response.rect)
    }

    /// The scrub bar, with a mark where each surprise was sprung.
    pub(super) fn timeline(&mut self, ui: &mut egui::Ui) {
        let Some(player) = &mut self.player else {
            return;
        };
        let (duration, dt) = self
            .setup
            .as_ref()
            .map_or((1.0, 1.0), |s| (s.duration, s.dt));
        let sprung: Vec<usize> = player
            .events()
            .iter()
            .map(|(t, _)| (t / dt).round() as usize)
            .collect();
        let red = theme::error_color(ui);
        player.timeline(
            ui,
            "Time in the arena",
            (duration / dt).round() as usize,
            &mut |painter, rect, x, _| {
                for k in &sprung {
                    painter.line_segment(
                        [pos2(x(*k), rect.top()), pos2(x(*k), rect.bottom())],
                        Stroke::new(2.0, red),
                    );
                }
            },
        );
        player.run(ui, 8);
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
        let searched = p.searching.expanded().iter().map(|&c| {
            let q = p.grid.centre(c);
            let r = Rect::from_two_pos(
                view.to_screen([q.x - half, q.y + half]),
                view.to_screen([q.x + half, q.y - half]),
            );
            (r, color.gamma_multiply(0.12))
        });
        marks::cells(painter, searched);
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
    let occupied = map.occupied_cells().filter(|c| inner(*c)).map(|c| {
        let q = map.centre(c);
        let (_, felt) = map.evidence(c);
        let r = Rect::from_two_pos(
            view.to_screen([q.x - half, q.y + half]),
            view.to_screen([q.x + half, q.y - half]),
        );
        (r, color.gamma_multiply(if felt { 0.75 } else { 0.35 }))
    });
    marks::cells(painter, occupied);
}
