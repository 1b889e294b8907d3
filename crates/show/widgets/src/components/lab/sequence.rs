//! The sequence diagram: one lifeline per component, time running down
//! over the last `window` seconds, an arrow for every message from its
//! sender at the time it left to its receiver at the time it arrived (a
//! cross where a lost one vanished), and the components' notes.

use egui::{Align2, Color32, FontId, Pos2, Sense, Stroke, pos2, vec2};
use kinolab_components::Status;

use kinolab_components::Runtime;

use crate::draw::{canvas, marks, text_on_canvas};
use crate::theme;

/// Most arrows labelled; beyond this only the arrows are drawn.
const LABELLED: usize = 24;

/// The diagram of `rt`'s last `window` seconds; where it was drawn.
pub fn show(ui: &mut egui::Ui, rt: &Runtime, window: f64) -> egui::Rect {
    let width = ui.available_width();
    let (response, painter) = canvas(ui, vec2(width, 280.0), Sense::hover());
    let now = rt.now();
    let frame = Frame {
        rect: response.rect,
        names: rt.view().into_iter().map(|c| c.name).collect(),
        from: now - window,
        now,
    };
    let ink = Ink {
        text: ui.visuals().text_color(),
        faint: ui.visuals().weak_text_color(),
        lost: theme::error_color(ui),
    };
    frame.lifelines(&painter, &ink);
    frame.messages(&painter, rt, &ink);
    frame.rect
}

/// Where things go: a lifeline per component across, time running down.
struct Frame {
    rect: egui::Rect,
    names: Vec<String>,
    /// The window shown, s.
    from: f64,
    now: f64,
}

struct Ink {
    text: Color32,
    faint: Color32,
    lost: Color32,
}

impl Frame {
    fn top(&self) -> f32 {
        self.rect.top() + 24.0
    }

    fn bottom(&self) -> f32 {
        self.rect.bottom() - 8.0
    }

    /// A component's lifeline (the left margin for one not shown).
    fn x_of(&self, name: &str) -> f32 {
        let step = (self.rect.width() - 60.0) / self.names.len().max(1) as f32;
        self.names
            .iter()
            .position(|n| n == name)
            .map_or(self.rect.left() + 14.0, |i| {
                self.rect.left() + 50.0 + step * (i as f32 + 0.5)
            })
    }

    fn y_of(&self, t: f64) -> f32 {
        let share = ((t - self.from) / (self.now - self.from)).clamp(0.0, 1.0) as f32;
        self.top() + share * (self.bottom() - self.top())
    }

    /// The lifelines with their names, and the window's two times.
    fn lifelines(&self, painter: &egui::Painter, ink: &Ink) {
        let (top, bottom) = (self.top(), self.bottom());
        for name in &self.names {
            let x = self.x_of(name);
            painter.line_segment([pos2(x, top), pos2(x, bottom)], Stroke::new(1.0, ink.faint));
            painter.text(
                pos2(x, self.rect.top() + 4.0),
                Align2::CENTER_TOP,
                name,
                FontId::proportional(theme::SMALL_SIZE),
                ink.text,
            );
        }
        let left = self.rect.left() + 4.0;
        let tiny = FontId::proportional(theme::TINY_SIZE);
        let from = format!("{:.2} s", self.from.max(0.0));
        painter.text(
            pos2(left, top),
            Align2::LEFT_TOP,
            from,
            tiny.clone(),
            ink.faint,
        );
        let now = format!("{:.2} s", self.now);
        painter.text(
            pos2(left, bottom),
            Align2::LEFT_BOTTOM,
            now,
            tiny,
            ink.faint,
        );
    }

    /// Every message of the window: an arrow (a cross where a lost one
    /// vanished), notes as dots, labels while there are few.
    fn messages(&self, painter: &egui::Painter, rt: &Runtime, ink: &Ink) {
        let (from, now) = (self.from, self.now);
        let trace = rt.trace();
        let start = trace.partition_point(|r| r.sent < from - 1.0);
        let shown: Vec<_> = trace[start..]
            .iter()
            .filter(|r| r.sent <= now && r.delivered.unwrap_or(now) >= from)
            .collect();
        let label = shown.len() <= LABELLED;
        // Labels at least a line apart, so they never pile up.
        let mut last_label = f32::NEG_INFINITY;
        let mut room = |y: f32| {
            let free = label && y - last_label >= theme::SMALL_SIZE + 2.0;
            if free {
                last_label = y;
            }
            free
        };
        let small = FontId::proportional(theme::SMALL_SIZE);
        for r in shown {
            let (a, y0) = (self.x_of(&r.from), self.y_of(r.sent));
            if matches!(r.pattern, "note" | "state") {
                if r.sent >= from && !(r.pattern == "state" && r.summary == "running") {
                    let at = pos2(a, y0);
                    painter.circle_filled(at, 3.0, ink.faint);
                    if room(y0) {
                        let text = r.summary.clone();
                        let at = at + vec2(5.0, 0.0);
                        text_on_canvas(
                            painter,
                            at,
                            Align2::LEFT_CENTER,
                            text,
                            small.clone(),
                            ink.faint,
                        );
                    }
                }
                continue;
            }
            let color = theme::pattern_color(r.pattern);
            let b = self.x_of(&r.to);
            let end = match (r.status, r.delivered) {
                (_, Some(d)) => Some(d.min(now)),
                (Status::InFlight, None) => Some(now),
                _ => None,
            };
            match end {
                Some(d) => {
                    let faded = r.status == Status::Skipped;
                    arrow(painter, pos2(a, y0), pos2(b, self.y_of(d)), color, faded);
                }
                None => {
                    let mid = pos2((a + b) / 2.0, y0 + 6.0);
                    painter.line_segment([pos2(a, y0), mid], Stroke::new(1.5, color));
                    marks::cross(painter, mid, 4.0, Stroke::new(2.0, ink.lost));
                }
            }
            if room(y0) {
                let skipped = if r.status == Status::Skipped {
                    " (skipped)"
                } else {
                    ""
                };
                // On the canvas's colour: a label between lifelines further
                // apart than their neighbours crosses the ones in between.
                let text = format!("{} {}{skipped}", r.kind, r.summary);
                let at = pos2((a + b) / 2.0, y0 - 2.0);
                text_on_canvas(
                    painter,
                    at,
                    Align2::CENTER_BOTTOM,
                    text,
                    small.clone(),
                    color,
                );
            }
        }
    }
}

/// A message's arrow from `a` to `b`, faded when it went nowhere.
fn arrow(painter: &egui::Painter, a: Pos2, b: Pos2, color: Color32, faded: bool) {
    let color = if faded {
        color.gamma_multiply(0.4)
    } else {
        color
    };
    marks::arrow(painter, a, b - a, 7.0, Stroke::new(1.5, color));
}
