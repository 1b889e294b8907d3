//! Labels that keep out of each other's way.
//!
//! Every drawing that names something on its canvas (a frame, a foot, the
//! ICR, an axis) collects those names in a [`Labels`] and draws them last:
//! each goes to the first of a few spots around its anchor that overlaps no
//! label already placed, no rectangle reserved for a mark, and no line
//! registered as an obstacle (an axis arrow, a link), or to its preferred
//! spot when every one is taken. A label may prefer a side (a foot's number
//! goes outward from the body); plain text and short formulas are placed
//! alike.

use egui::{Align2, Color32, FontId, Painter, Pos2, Rect, Vec2, vec2};
use kinolab_formula::layout::{MathBox, MathMode, MathStyle, layout_math};

/// What a label shows.
#[derive(Debug)]
enum Text {
    Plain(String),
    Formula(String),
}

#[derive(Debug)]
struct Pending {
    anchor: Pos2,
    text: Text,
    color: Color32,
    toward: Vec2,
    clearance: f32,
}

/// A label just added, to say where it would rather go.
#[derive(Debug)]
pub struct Label<'a>(&'a mut Pending);

impl Label<'_> {
    /// Try the spots on the side of `dir` first (a foot's number goes
    /// outward from the body, an axis name beyond the arrow head).
    pub fn toward(self, dir: Vec2) -> Self {
        self.0.toward = dir;
        self
    }

    /// Keep the label `radius` points further from its anchor (a mark of
    /// that size sits on it).
    pub fn beyond(self, radius: f32) -> Self {
        self.0.clearance = radius.max(0.0);
        self
    }
}

/// Labels waiting to be placed, and what they must keep clear of.
#[derive(Debug, Default)]
pub struct Labels {
    taken: Vec<Rect>,
    lines: Vec<[Pos2; 2]>,
    pending: Vec<Pending>,
    /// The canvas the labels must stay inside, if any.
    bounds: Option<Rect>,
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

/// What a new label must keep clear of.
#[derive(Debug, Clone, Copy, Default)]
pub struct Obstacles<'a> {
    pub rects: &'a [Rect],
    pub lines: &'a [[Pos2; 2]],
    /// The area a label must stay inside (a canvas), if any.
    pub bounds: Option<Rect>,
}

impl Obstacles<'_> {
    fn hit(&self, r: Rect) -> bool {
        self.bounds.is_some_and(|b| !b.contains_rect(r))
            || self.rects.iter().any(|t| t.intersects(r))
            || self.lines.iter().any(|&[a, b]| segment_hits(r, a, b))
    }
}

/// Where a label goes relative to its anchor.
#[derive(Debug, Clone, Copy, Default)]
pub struct Preference {
    /// The side to try first (zero: no preference).
    pub toward: Vec2,
    /// Extra distance from the anchor, for a mark of this radius on it.
    pub clearance: f32,
}

/// The rectangle for a label of `size` near `anchor` that hits no
/// obstacle, trying first the spots on the preferred side, or the most
/// preferred spot when every one is hit.
pub fn place(obstacles: Obstacles<'_>, anchor: Pos2, size: Vec2, pref: Preference) -> Rect {
    let Preference { toward, clearance } = pref;
    let rect_at = |(offset, align): (Vec2, Align2), extra: f32| {
        let offset = offset + offset.normalized() * (clearance + extra);
        align.anchor_size(anchor + offset, size).expand(1.0)
    };
    let mut spots = SPOTS;
    if toward != Vec2::ZERO {
        // Stable: equally good spots keep the diagonals-first order.
        spots.sort_by(|a, b| {
            let score = |s: &(Vec2, Align2)| -s.0.normalized().dot(toward.normalized());
            score(a).total_cmp(&score(b))
        });
    }
    // Rings further and further out, so a crowded point still gets its
    // labels apart.
    RINGS
        .iter()
        .flat_map(|&extra| spots.iter().map(move |&s| (s, extra)))
        .map(|(s, extra)| rect_at(s, extra))
        .find(|r| !obstacles.hit(*r))
        .unwrap_or_else(|| rect_at(spots[0], 0.0))
}

/// How much further out each ring of spots lies than the first.
const RINGS: [f32; 4] = [0.0, 14.0, 28.0, 42.0];

/// Whether the segment `a`–`b` passes through `rect` (Liang–Barsky).
fn segment_hits(rect: Rect, a: Pos2, b: Pos2) -> bool {
    let d = b - a;
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    for (p, q) in [
        (-d.x, a.x - rect.left()),
        (d.x, rect.right() - a.x),
        (-d.y, a.y - rect.top()),
        (d.y, rect.bottom() - a.y),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
            if t0 > t1 {
                return false;
            }
        }
    }
    true
}

impl Labels {
    /// Keep every label inside `canvas` (a label half outside it would be
    /// cut off). The canvas, not the painter's clip: that shrinks while the
    /// page scrolls, and labels would jump.
    pub fn within(&mut self, canvas: Rect) {
        self.bounds = Some(canvas);
    }

    /// Keep `rect` free of labels (a handle, a marker).
    pub fn reserve(&mut self, rect: Rect) {
        self.taken.push(rect);
    }

    /// Keep labels off the line from `a` to `b` (an axis, a link).
    pub fn avoid_line(&mut self, a: Pos2, b: Pos2) {
        self.lines.push([a, b]);
    }

    /// Keep labels off each of `lines` (a frame's axes).
    pub fn avoid_lines(&mut self, lines: &[[Pos2; 2]]) {
        self.lines.extend_from_slice(lines);
    }

    /// A label near `anchor`; say more with the [`Label`] returned.
    pub fn add(&mut self, anchor: Pos2, text: impl Into<String>, color: Color32) -> Label<'_> {
        self.push(anchor, Text::Plain(text.into()), color)
    }

    /// A short formula (`x_R`, `\theta`) near `anchor`, typeset like the
    /// lessons' inline maths.
    pub fn add_formula(&mut self, anchor: Pos2, tex: &str, color: Color32) -> Label<'_> {
        self.push(anchor, Text::Formula(tex.to_owned()), color)
    }

    fn push(&mut self, anchor: Pos2, text: Text, color: Color32) -> Label<'_> {
        self.pending.push(Pending {
            anchor,
            text,
            color,
            toward: Vec2::ZERO,
            clearance: 0.0,
        });
        let last = self.pending.len() - 1;
        Label(&mut self.pending[last])
    }

    /// Draw every label, in the order added, in `font` (formulas at its
    /// size); returns where each went.
    pub fn draw(mut self, painter: &Painter, font: &FontId) -> Vec<Rect> {
        let mut placed = Vec::with_capacity(self.pending.len());
        for p in std::mem::take(&mut self.pending) {
            let laid = lay_out(painter, p.text, font, p.color);
            let obstacles = Obstacles {
                rects: &self.taken,
                lines: &self.lines,
                bounds: self.bounds,
            };
            let pref = Preference {
                toward: p.toward,
                clearance: p.clearance,
            };
            let rect = place(obstacles, p.anchor, laid.size(), pref);
            laid.paint(painter, rect.shrink(1.0).min, p.color);
            self.taken.push(rect);
            placed.push(rect);
        }
        placed
    }
}

/// A label's text, laid out.
enum Laid {
    Galley(std::sync::Arc<egui::Galley>),
    Math(MathBox),
}

impl Laid {
    fn size(&self) -> Vec2 {
        match self {
            Laid::Galley(g) => g.size(),
            Laid::Math(b) => vec2(b.width, b.height()),
        }
    }

    /// Paint with the top-left corner at `min`.
    fn paint(self, painter: &Painter, min: Pos2, color: Color32) {
        match self {
            Laid::Galley(g) => painter.galley(min, g, color),
            Laid::Math(b) => b.paint(painter, min + vec2(0.0, b.ascent), color),
        }
    }
}

/// Plain text as a galley; a formula typeset, or as plain text when it
/// does not parse.
fn lay_out(painter: &Painter, text: Text, font: &FontId, color: Color32) -> Laid {
    let plain = match text {
        Text::Plain(s) => s,
        Text::Formula(tex) => match math_box(painter, &tex, font.size, color) {
            Some(b) => return Laid::Math(b),
            None => tex,
        },
    };
    Laid::Galley(painter.layout_no_wrap(plain, font.clone(), color))
}

/// A short formula laid out like the lessons' inline maths.
fn math_box(painter: &Painter, tex: &str, size: f32, color: Color32) -> Option<MathBox> {
    let math = kinolab_formula::parse(tex).ok()?;
    let style = MathStyle { size, color };
    Some(
        painter
            .ctx()
            .fonts_mut(|f| layout_math(f, &math, &style, MathMode::Inline)),
    )
}
/// A short formula (a subset of TeX, as lessons write it) typeset like the
/// lessons' formulas, at body size; text that does not parse is shown as is.
pub fn formula(ui: &mut egui::Ui, tex: &str) -> egui::Response {
    match kinolab_formula::parse(tex) {
        Ok(math) => {
            let style = MathStyle {
                size: crate::theme::BODY_SIZE,
                color: ui.visuals().text_color(),
            };
            kinolab_formula::layout::math_widget(ui, &math, &style)
        }
        Err(_) => ui.label(tex),
    }
}

/// A short formula (`x_R`, `\\theta`) painted centred on `at`, for a caption
/// that has a fixed place; text that does not parse is painted as it is.
pub fn paint_formula(painter: &Painter, at: Pos2, tex: &str, size: f32, color: Color32) {
    let laid = lay_out(
        painter,
        Text::Formula(tex.to_owned()),
        &FontId::proportional(size),
        color,
    );
    let size = laid.size();
    laid.paint(painter, at - size / 2.0, color);
}

#[cfg(test)]
mod tests {
    use super::*;

    const LABEL: Vec2 = vec2(20.0, 12.0);

    fn free(obstacles: Obstacles<'_>, r: Rect) -> bool {
        !obstacles.hit(r)
    }

    #[test]
    fn crowded_labels_do_not_overlap_each_other_or_the_marker() {
        let anchor = Pos2::new(100.0, 100.0);
        let marker = Rect::from_center_size(anchor, vec2(12.0, 12.0));
        let mut taken = vec![marker];
        // Four labels fit around one point (one per diagonal).
        for _ in 0..4 {
            let o = Obstacles {
                rects: &taken,
                lines: &[],
                bounds: None,
            };
            let r = place(o, anchor, LABEL, Preference::default());
            assert!(free(o, r), "{r:?} overlaps {taken:?}");
            taken.push(r);
        }
        // Eight more still find room, further out but near their anchor.
        for _ in 0..8 {
            let o = Obstacles {
                rects: &taken,
                lines: &[],
                bounds: None,
            };
            let r = place(o, anchor, LABEL, Preference::default());
            assert!(free(o, r), "{r:?} overlaps {taken:?}");
            assert!(r.distance_to_pos(anchor) < 45.0, "{r:?}");
            taken.push(r);
        }
    }

    #[test]
    fn a_label_keeps_off_the_lines_through_its_anchor() {
        // Three axes from one origin, as a frame at the zero pose draws
        // them: right, up-right and up-left.
        let o = Pos2::new(50.0, 50.0);
        let lines = [
            [o, o + vec2(60.0, 0.0)],
            [o, o + vec2(40.0, -40.0)],
            [o, o + vec2(-40.0, -40.0)],
        ];
        let obstacles = Obstacles {
            rects: &[],
            lines: &lines,
            bounds: None,
        };
        let r = place(obstacles, o, LABEL, Preference::default());
        for [a, b] in lines {
            assert!(!segment_hits(r, a, b), "{r:?} crosses {a:?}-{b:?}");
        }
        // The first spot (up and to the right) is crossed by the second axis.
        let first = place(Obstacles::default(), o, LABEL, Preference::default());
        assert!(segment_hits(first, lines[1][0], lines[1][1]));
        assert_ne!(r, first);
    }

    #[test]
    fn a_preferred_side_wins_when_free() {
        let o = Pos2::new(0.0, 0.0);
        for toward in [vec2(0.0, 1.0), vec2(-1.0, 0.0), vec2(1.0, -1.0)] {
            let pref = Preference {
                toward,
                clearance: 0.0,
            };
            let r = place(Obstacles::default(), o, LABEL, pref);
            let side = r.center() - o;
            assert!(
                side.normalized().dot(toward.normalized()) > 0.7,
                "{toward:?} -> {side:?}"
            );
        }
    }

    #[test]
    fn a_label_clears_a_big_mark_on_its_anchor() {
        // A foot drawn as a circle of radius 13 sits on the anchor.
        let o = Pos2::new(0.0, 0.0);
        let foot = [Rect::from_center_size(o, vec2(26.0, 26.0))];
        let obstacles = Obstacles {
            rects: &foot,
            lines: &[],
            bounds: None,
        };
        let pref = Preference {
            toward: vec2(0.0, 1.0),
            clearance: 13.0,
        };
        let clear = place(obstacles, o, LABEL, pref);
        assert!(!obstacles.hit(clear), "{clear:?}");
        assert!(clear.center().y > 0.0, "it went below, as asked");
    }

    #[test]
    fn a_label_at_the_edge_of_its_canvas_turns_inward() {
        // A dot 10 points from the canvas's right edge, its name wanted to
        // the right: it goes to the left rather than be cut off.
        let canvas = Rect::from_min_max(Pos2::new(0.0, 0.0), Pos2::new(200.0, 100.0));
        let dot = Pos2::new(190.0, 50.0);
        let obstacles = Obstacles {
            bounds: Some(canvas),
            ..Obstacles::default()
        };
        let pref = Preference {
            toward: vec2(1.0, 0.0),
            clearance: 0.0,
        };
        let r = place(obstacles, dot, LABEL, pref);
        assert!(canvas.contains_rect(r), "{r:?}");
        assert!(r.center().x < dot.x, "{r:?}");
        // Without the canvas it would have gone right, past the edge.
        let unbounded = place(Obstacles::default(), dot, LABEL, pref);
        assert!(!canvas.contains_rect(unbounded), "{unbounded:?}");
    }

    #[test]
    fn segments_and_rectangles_meet_where_geometry_says() {
        let r = Rect::from_min_max(Pos2::new(0.0, 0.0), Pos2::new(10.0, 10.0));
        assert!(segment_hits(r, Pos2::new(-5.0, 5.0), Pos2::new(15.0, 5.0)));
        assert!(segment_hits(r, Pos2::new(2.0, 2.0), Pos2::new(3.0, 3.0)));
        assert!(!segment_hits(
            r,
            Pos2::new(-5.0, -1.0),
            Pos2::new(15.0, -1.0)
        ));
        assert!(!segment_hits(
            r,
            Pos2::new(11.0, 0.0),
            Pos2::new(20.0, 10.0)
        ));
        assert!(segment_hits(r, Pos2::new(-1.0, 5.0), Pos2::new(5.0, -1.0)));
        assert!(!segment_hits(r, Pos2::new(-3.0, 1.0), Pos2::new(1.0, -3.0)));
    }
}
