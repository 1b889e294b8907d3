//! The player on screen: a row of buttons with the time, and a scrub bar
//! the widget may colour (who had control, bumps). Every button is a
//! button (Tab reaches it, a tap presses it); the scrub bar takes the
//! keyboard when focused: ← and → step a tick, Shift with them a second,
//! Home and End go to the ends, Space plays and pauses.

use egui::{Key, Painter, Rect, Sense, Stroke, pos2, vec2};
use kinolab_common::display::fixed;

use super::{Player, Simulation, Speed};
use crate::theme;

/// How a widget colours the scrub bar: the painter, the bar, where tick
/// `k` falls along it, and the ticks recorded.
pub type Paint<'a, T> = &'a mut dyn FnMut(&Painter, Rect, &dyn Fn(usize) -> f32, &[T]);

impl<S: Simulation> Player<S> {
    /// Run on as the wall clock says, at most `most` ticks this frame, and
    /// ask for the next frame while playing (paused when scrolled away).
    pub fn run(&mut self, ui: &egui::Ui, most: usize) {
        let seconds = f64::from(ui.input(|i| i.stable_dt).min(0.1));
        self.advance(seconds, most);
        if self.playing || self.catching_up() {
            crate::widget::animate(ui);
        }
    }

    /// Restart, a tick back, play or pause, a tick on, the speed, and the time.
    pub fn controls(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            if ui
                .button("Restart")
                .on_hover_text("Back to the start, and play")
                .clicked()
            {
                self.restart();
            }
            if ui
                .button("Back")
                .on_hover_text("One tick back (←)")
                .clicked()
            {
                self.step_back();
            }
            let label = if self.playing { "Pause" } else { "Play" };
            let play = ui.button(label).on_hover_text("Play or pause (Space)");
            crate::probe::publish(ui.ctx(), "player.play", play.rect.center());
            if play.clicked() {
                self.toggle();
            }
            if ui.button("Step").on_hover_text("One tick on (→)").clicked() {
                self.playing = false;
                self.step_forward();
            }
            for speed in Speed::ALL {
                let chosen = crate::widget::choose(ui, &mut self.speed, speed, speed.label())
                    .on_hover_text("Playing speed against the clock");
                if crate::probe::enabled(ui.ctx()) {
                    let name = format!("player.speed {}", speed.label());
                    crate::probe::publish(ui.ctx(), &name, chosen.rect.center());
                }
            }
            ui.label(self.time_label());
        });
    }

    /// "t = 12.40 s", with how far the run has been recorded when the
    /// instant shown is earlier, and why it stopped.
    pub fn time_label(&self) -> String {
        let decimals = self.decimals();
        let mut text = format!("t = {} s", fixed(self.time(), decimals));
        if let Some(c) = &self.catching {
            let target = fixed(c.instant, decimals.min(1));
            text += &format!(" (running on to the link's {target} s…)");
        } else if !self.at_end() {
            let recorded = fixed(self.time_at(self.len()), decimals.min(1));
            text += &format!(" (recorded to {recorded} s)");
        }
        if self.full() {
            text += &format!("; the recording is full at {} ticks", super::MAX_TICKS);
        }
        text
    }

    /// Decimals enough to tell one tick from the next (2 to 4).
    fn decimals(&self) -> usize {
        let dt = self.live.dt().max(1e-4);
        (-dt.log10()).ceil().clamp(2.0, 4.0) as usize
    }

    fn toggle(&mut self) {
        if self.playing {
            self.playing = false;
        } else {
            if self.at_end() && self.over() {
                self.cursor = 0;
            }
            self.playing = true;
        }
    }

    /// The scrub bar, `expected` ticks long (the run's length when known,
    /// else what is recorded), coloured by `paint`; `name` is what a
    /// screen reader calls it.
    pub fn timeline(
        &mut self,
        ui: &mut egui::Ui,
        name: &str,
        expected: usize,
        paint: Paint<'_, S::Tick>,
    ) {
        let width = ui.available_width();
        let (rect, response) = ui.allocate_exact_size(vec2(width, 22.0), Sense::click_and_drag());
        let total = expected.max(self.len()).max(1);
        let x = |k: usize| rect.left() + width * k as f32 / total as f32;
        let painter = ui.painter_at(rect.expand(3.0));
        painter.rect_filled(rect, 3.0, ui.visuals().extreme_bg_color);
        let recorded = egui::Rect::from_min_max(rect.min, pos2(x(self.len()), rect.max.y));
        painter.rect_filled(recorded, 3.0, ui.visuals().widgets.inactive.bg_fill);
        paint(&painter, rect, &x, self.ticks());
        let cx = x(self.cursor());
        let ink = ui.visuals().text_color();
        painter.line_segment(
            [pos2(cx, rect.top() - 3.0), pos2(cx, rect.bottom() + 3.0)],
            Stroke::new(2.5, ink),
        );
        if response.has_focus() {
            painter.rect_stroke(
                rect,
                3.0,
                Stroke::new(2.0, theme::accent(ui)),
                egui::StrokeKind::Outside,
            );
        }
        if let Some(p) = response.interact_pointer_pos()
            && (response.clicked() || response.dragged())
        {
            response.request_focus();
            self.playing = false;
            let k = ((p.x - rect.left()) / width * total as f32)
                .round()
                .max(0.0) as usize;
            self.seek(k.min(self.len()));
        }
        self.keys(ui, &response);
        let value = self.time();
        response.widget_info(|| {
            let mut info = egui::WidgetInfo::labeled(egui::Role::Slider, true, name);
            info.value = Some(value);
            info
        });
    }

    /// The keyboard on a focused scrub bar.
    fn keys(&mut self, ui: &egui::Ui, response: &egui::Response) {
        if !response.has_focus() {
            return;
        }
        ui.memory_mut(|m| {
            m.set_focus_lock_filter(
                response.id,
                egui::EventFilter {
                    horizontal_arrows: true,
                    ..Default::default()
                },
            );
        });
        let (left, right, home, end, space, shift) = ui.input(|i| {
            (
                i.key_pressed(Key::ArrowLeft),
                i.key_pressed(Key::ArrowRight),
                i.key_pressed(Key::Home),
                i.key_pressed(Key::End),
                i.key_pressed(Key::Space),
                i.modifiers.shift,
            )
        });
        let second = (1.0 / self.live.dt().max(1e-9)).round().max(1.0) as usize;
        let jump = if shift { second } else { 1 };
        if left {
            self.playing = false;
            self.seek(self.cursor().saturating_sub(jump));
        }
        if right {
            self.playing = false;
            self.seek((self.cursor() + jump).min(self.len().max(self.cursor() + jump)));
        }
        if home {
            self.playing = false;
            self.seek(0);
        }
        if end {
            self.playing = false;
            self.seek(self.len());
        }
        if space {
            self.toggle();
        }
    }
}
