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
    let names: Vec<String> = rt.view().into_iter().map(|c| c.name).collect();
    let width = ui.available_width();
    let (response, painter) = canvas(ui, vec2(width, 280.0), Sense::hover());
    let rect = response.rect;
    let ink = ui.visuals().text_color();
    let faint = ui.visuals().weak_text_color();
    let left = rect.left() + 50.0;
    let step = (rect.width() - 60.0) / names.len().max(1) as f32;
    let x_of = |name: &str| {
        names
            .iter()
            .position(|n| n == name)
            .map_or(rect.left() + 14.0, |i| left + step * (i as f32 + 0.5))
    };
    let (top, bottom) = (rect.top() + 24.0, rect.bottom() - 8.0);
    let now = rt.now();
    let from = now - window;
    let y_of = |t: f64| top + ((t - from) / window).clamp(0.0, 1.0) as f32 * (bottom - top);
    for name in &names {
        let x = x_of(name);
        painter.line_segment([pos2(x, top), pos2(x, bottom)], Stroke::new(1.0, faint));
        painter.text(
            pos2(x, rect.top() + 4.0),
            Align2::CENTER_TOP,
            name,
            FontId::proportional(theme::SMALL_SIZE),
            ink,
        );
    }
    painter.text(
        pos2(rect.left() + 4.0, top),
        Align2::LEFT_TOP,
        format!("{:.2} s", from.max(0.0)),
        FontId::proportional(theme::TINY_SIZE),
        faint,
    );
    painter.text(
        pos2(rect.left() + 4.0, bottom),
        Align2::LEFT_BOTTOM,
        format!("{now:.2} s"),
        FontId::proportional(theme::TINY_SIZE),
        faint,
    );
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
    for r in shown {
        let color = theme::pattern_color(r.pattern);
        let (a, y0) = (x_of(&r.from), y_of(r.sent));
        match r.pattern {
            "note" | "state" => {
                if r.sent >= from && !(r.pattern == "state" && r.summary == "running") {
                    let at = pos2(a, y0);
                    painter.circle_filled(at, 3.0, faint);
                    if room(y0) {
                        text_on_canvas(
                            &painter,
                            at + vec2(5.0, 0.0),
                            Align2::LEFT_CENTER,
                            r.summary.clone(),
                            FontId::proportional(theme::SMALL_SIZE),
                            faint,
                        );
                    }
                }
                continue;
            }
            _ => {}
        }
        let b = x_of(&r.to);
        let end = match (r.status, r.delivered) {
            (_, Some(d)) => Some(d.min(now)),
            (Status::InFlight, None) => Some(now),
            _ => None,
        };
        match end {
            Some(d) => arrow(
                &painter,
                pos2(a, y0),
                pos2(b, y_of(d)),
                color,
                r.status == Status::Skipped,
            ),
            None => {
                let mid = pos2((a + b) / 2.0, y0 + 6.0);
                painter.line_segment([pos2(a, y0), mid], Stroke::new(1.5, color));
                marks::cross(&painter, mid, 4.0, Stroke::new(2.0, theme::error_color(ui)));
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
            text_on_canvas(
                &painter,
                pos2((a + b) / 2.0, y0 - 2.0),
                Align2::CENTER_BOTTOM,
                text,
                FontId::proportional(theme::SMALL_SIZE),
                color,
            );
        }
    }
    rect
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
