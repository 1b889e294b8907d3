//! Grids and axes, for a sense of scale and direction.

use egui::{Color32, Painter, Pos2, Rect, Stroke};

use super::labels::Labels;
use super::view::PlaneView;

/// Lines every `step` metres across the part of the world `rect` shows.
pub fn grid(painter: &Painter, view: &PlaneView, rect: Rect, step: f64, color: Color32) {
    let (min, max) = view.visible(rect);
    // Never more than 200 lines a direction, whatever the zoom.
    let step = step.max((max[0] - min[0]).max(max[1] - min[1]) / 200.0);
    let stroke = Stroke::new(1.0, color);
    let mut x = (min[0] / step).floor() * step;
    while x <= max[0] {
        painter.line_segment(
            [view.to_screen([x, min[1]]), view.to_screen([x, max[1]])],
            stroke,
        );
        x += step;
    }
    let mut y = (min[1] / step).floor() * step;
    while y <= max[1] {
        painter.line_segment(
            [view.to_screen([min[0], y]), view.to_screen([max[0], y])],
            stroke,
        );
        y += step;
    }
}

/// Two labelled axis arrows from `origin` to `x_tip` and `y_tip`; the
/// names are short formulas (`x`, `y_R`), placed beyond the arrow heads
/// when that is free, and the arrows are kept clear of other labels.
pub fn axes(
    painter: &Painter,
    labels: &mut Labels,
    origin: Pos2,
    tips: [(Pos2, &str); 2],
    color: Color32,
) {
    let stroke = Stroke::new(1.5, color);
    for (tip, name) in tips {
        painter.arrow(origin, tip - origin, stroke);
        labels.avoid_line(origin, tip);
        labels.add_formula(tip, name, color).toward(tip - origin);
    }
}

/// 0.1, 0.2, 0.5, 1, 2, … near a fifth of `extent`.
pub fn nice_step(extent: f64) -> f64 {
    let raw = (extent / 5.0).max(1e-3);
    let p = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * p)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_steps_are_round_numbers() {
        assert_eq!(nice_step(1.0), 0.2);
        assert_eq!(nice_step(2.4), 0.5);
        assert_eq!(nice_step(0.3), 0.1);
    }
}
