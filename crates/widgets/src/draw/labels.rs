//! Labels that keep out of each other's way.
//!
//! A drawing collects its labels in a [`Labels`] and draws them at the end:
//! each goes to the first of a few spots around its anchor that overlaps
//! no label already placed (and no rectangle reserved for something else),
//! or to its preferred spot when every one is taken.

use egui::{Align2, Color32, FontId, Painter, Pos2, Rect, Vec2, vec2};

/// Labels waiting to be placed.
#[derive(Debug, Default)]
pub struct Labels {
    taken: Vec<Rect>,
    pending: Vec<(Pos2, String, Color32)>,
}

/// Where a label may go, relative to its anchor: the four diagonals first
/// (they keep clear of lines through the anchor), then the four sides.
const SPOTS: [(Vec2, Align2); 8] = [
    (vec2(8.0, -8.0), Align2::LEFT_BOTTOM),
    (vec2(8.0, 8.0), Align2::LEFT_TOP),
    (vec2(-8.0, -8.0), Align2::RIGHT_BOTTOM),
    (vec2(-8.0, 8.0), Align2::RIGHT_TOP),
    (vec2(0.0, -10.0), Align2::CENTER_BOTTOM),
    (vec2(0.0, 10.0), Align2::CENTER_TOP),
    (vec2(10.0, 0.0), Align2::LEFT_CENTER),
    (vec2(-10.0, 0.0), Align2::RIGHT_CENTER),
];

/// The rectangle for a label of `size` near `anchor` that overlaps nothing
/// in `taken`, or the preferred one when every spot overlaps.
pub fn place(taken: &[Rect], anchor: Pos2, size: Vec2) -> Rect {
    let rect_at =
        |(offset, align): (Vec2, Align2)| align.anchor_size(anchor + offset, size).expand(1.0);
    SPOTS
        .iter()
        .map(|&s| rect_at(s))
        .find(|r| !taken.iter().any(|t| t.intersects(*r)))
        .unwrap_or_else(|| rect_at(SPOTS[0]))
}

impl Labels {
    /// Keep `rect` free of labels (a handle, a marker).
    pub fn reserve(&mut self, rect: Rect) {
        self.taken.push(rect);
    }

    /// A label near `anchor`.
    pub fn add(&mut self, anchor: Pos2, text: impl Into<String>, color: Color32) {
        self.pending.push((anchor, text.into(), color));
    }

    /// Draw every label, in the order added.
    pub fn draw(mut self, painter: &Painter, font: &FontId) {
        for (anchor, text, color) in std::mem::take(&mut self.pending) {
            let galley = painter.layout_no_wrap(text, font.clone(), color);
            let rect = place(&self.taken, anchor, galley.size());
            self.taken.push(rect);
            painter.galley(rect.shrink(1.0).min, galley, color);
        }
    }
}

/// A short formula (a subset of TeX, as lessons write it) typeset like the
/// lessons' formulas, at body size; text that does not parse is shown as is.
pub fn formula(ui: &mut egui::Ui, tex: &str) -> egui::Response {
    match kinolab_formula::parse(tex) {
        Ok(math) => {
            let style = kinolab_formula::layout::MathStyle {
                size: crate::theme::BODY_SIZE,
                color: ui.visuals().text_color(),
            };
            kinolab_formula::layout::math_widget(ui, &math, &style)
        }
        Err(_) => ui.label(tex),
    }
}

/// A short formula (`x_R`, `\\theta`) painted centred on `at`, set like the
/// lessons' formulas, for the labels of a drawing; text that does not parse
/// is painted as it is.
pub fn paint_formula(painter: &Painter, at: Pos2, tex: &str, size: f32, color: Color32) {
    use kinolab_formula::layout::{MathMode, MathStyle, layout_math};
    match kinolab_formula::parse(tex) {
        Ok(math) => {
            let style = MathStyle { size, color };
            let b = painter
                .ctx()
                .fonts_mut(|f| layout_math(f, &math, &style, MathMode::Inline));
            let origin = Pos2::new(at.x - b.width / 2.0, at.y - b.height() / 2.0 + b.ascent);
            b.paint(painter, origin, color);
        }
        Err(_) => {
            painter.text(
                at,
                Align2::CENTER_CENTER,
                tex,
                FontId::proportional(size),
                color,
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crowded_labels_do_not_overlap_each_other_or_the_marker() {
        let anchor = Pos2::new(100.0, 100.0);
        let marker = Rect::from_center_size(anchor, vec2(12.0, 12.0));
        let mut taken = vec![marker];
        // Four labels fit around one point (one per diagonal).
        for _ in 0..4 {
            let r = place(&taken, anchor, vec2(20.0, 12.0));
            assert!(
                !taken.iter().any(|t| t.intersects(r)),
                "{r:?} overlaps {taken:?}"
            );
            taken.push(r);
        }
        // With every spot taken, a label still goes somewhere near its anchor.
        let mut full = taken.clone();
        for _ in 0..4 {
            full.push(place(&full, anchor, vec2(20.0, 12.0)));
        }
        let last = full[full.len() - 1];
        assert!(last.distance_to_pos(anchor) < 20.0);
    }
}
