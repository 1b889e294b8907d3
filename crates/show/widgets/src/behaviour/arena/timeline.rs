//! Play, pause, step and restart; the timeline of who had control, which
//! doubles as the scrub bar.

use egui::{Pos2, RichText, Sense, Stroke, pos2, vec2};
use kinolab_common::display::fixed;

use super::Arena;
use super::canvas::in_control_color;

impl Arena {
    pub(super) fn controls(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            let label = if self.playing { "Pause" } else { "Play" };
            if ui.button(label).clicked() {
                if self.playing {
                    self.playing = false;
                } else {
                    self.resume_from_cursor();
                    if self.runner.as_ref().is_some_and(|r| r.done()) {
                        self.rebuild();
                    }
                    self.playing = true;
                }
            }
            if ui.button("Step").clicked() {
                self.playing = false;
                if self.cursor < self.records.len() {
                    self.cursor += 1;
                } else {
                    self.step();
                }
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
            ui.label(format!("t = {} s", fixed(self.shown_time(), 1)));
            let shown = &self.records[..self.cursor];
            let bumps = shown.iter().filter(|r| r.bump).count();
            if let Some(r) = shown.iter().find(|r| r.goal) {
                ui.label(
                    RichText::new(format!("goal reached at {} s", fixed(r.t, 1)))
                        .color(crate::theme::good_color(ui)),
                );
            }
            if bumps > 0 {
                ui.label(
                    RichText::new(format!("{bumps} bump{}", if bumps == 1 { "" } else { "s" }))
                        .color(crate::theme::error_color(ui)),
                );
            }
        });
    }

    /// A band coloured by the behaviour in control at each step; click or
    /// drag on it to scrub.
    pub(super) fn timeline(&mut self, ui: &mut egui::Ui) {
        let steps = (super::DURATION / self.setup.as_ref().map_or(0.05, |s| s.dt))
            .round()
            .max(1.0) as usize;
        let width = ui.available_width();
        let (rect, response) = ui.allocate_exact_size(vec2(width, 20.0), Sense::click_and_drag());
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 3.0, ui.visuals().extreme_bg_color);
        let x = |k: usize| rect.left() + width * k as f32 / steps as f32;
        for (k, r) in self.records.iter().enumerate() {
            let c = in_control_color(r.in_control);
            let cell = egui::Rect::from_min_max(
                pos2(x(k), rect.top()),
                pos2(x(k + 1) + 0.5, rect.bottom()),
            );
            painter.rect_filled(
                cell,
                0.0,
                c.gamma_multiply(if k < self.cursor { 0.9 } else { 0.35 }),
            );
            if r.bump {
                painter.line_segment(
                    [pos2(x(k), rect.top()), pos2(x(k), rect.bottom())],
                    Stroke::new(2.0, crate::theme::error_color(ui)),
                );
            }
        }
        let cx = x(self.cursor);
        painter.line_segment(
            [
                Pos2::new(cx, rect.top() - 2.0),
                Pos2::new(cx, rect.bottom() + 2.0),
            ],
            Stroke::new(2.0, ui.visuals().text_color()),
        );
        if let Some(p) = response.interact_pointer_pos()
            && (response.clicked() || response.dragged())
        {
            let k = (((p.x - rect.left()) / width) * steps as f32)
                .round()
                .max(0.0) as usize;
            self.cursor = k.min(self.records.len());
            self.playing = false;
        }
        response.widget_info(|| {
            egui::WidgetInfo::labeled(egui::Role::Slider, true, "Timeline: who had control")
        });
        ui.label(RichText::new("Timeline: the colour of the behaviour in control at each moment; red ticks are bumps. Click or drag on it to go back.").small());
    }
}
