//! Drawn glyphs: stretchy fences, radical signs and braces as line paths,
//! and the dots and primes TeX takes from special fonts.

use egui::{Pos2, Rect, pos2, vec2};

use crate::tree::Delimiter;

use super::*;

/// Wraps `body` in delimiters spanning `top`..`bottom`. A missing delimiter
/// takes `null_space`.
pub(super) fn fence(
    body: MathBox,
    open: Delimiter,
    close: Delimiter,
    top: f32,
    bottom: f32,
    size: f32,
    null_space: f32,
) -> MathBox {
    let mut out = MathBox::default();
    let mut x = 0.0;
    x += draw_delimiter(&mut out, open, x, top, bottom, size, null_space);
    let body_width = body.width;
    out.place(body, vec2(x, 0.0));
    x += body_width;
    x += draw_delimiter(&mut out, close, x, top, bottom, size, null_space);
    out.width = x;
    out
}

/// Draws one delimiter at `x` into `out`; returns the width it takes.
pub(super) fn draw_delimiter(
    out: &mut MathBox,
    delimiter: Delimiter,
    x: f32,
    top: f32,
    bottom: f32,
    size: f32,
    null_space: f32,
) -> f32 {
    let Some((outline, mirrored)) = outline_of(delimiter) else {
        return null_space;
    };
    let height = bottom - top;
    let padding = 0.08 * size;
    let shape = Rect::from_min_max(
        pos2(x + padding, top),
        pos2(x + padding + outline.width(height, size), bottom),
    );
    let stroke = stroke_width(size) * (1.0 + 0.05 * (height / size - 1.0).max(0.0)).min(1.5);
    for points in outline.polylines(shape, size) {
        let points = if mirrored {
            points
                .into_iter()
                .map(|p| pos2(shape.left() + shape.right() - p.x, p.y))
                .collect()
        } else {
            points
        };
        out.draw(
            Paint::Line {
                points,
                width: stroke,
            },
            top,
            bottom,
        );
    }
    shape.width() + 2.0 * padding
}

/// The drawn shapes of stretchy delimiters, in their left-hand form.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Outline {
    Paren,
    Bracket,
    Brace,
    Bar,
    DoubleBar,
    Angle,
    Floor,
    Ceil,
}

/// The outline of a delimiter and whether it is the mirrored, right-hand form.
pub(super) fn outline_of(delimiter: Delimiter) -> Option<(Outline, bool)> {
    use Delimiter as D;
    Some(match delimiter {
        D::None => return None,
        D::LeftParen => (Outline::Paren, false),
        D::RightParen => (Outline::Paren, true),
        D::LeftBracket => (Outline::Bracket, false),
        D::RightBracket => (Outline::Bracket, true),
        D::LeftBrace => (Outline::Brace, false),
        D::RightBrace => (Outline::Brace, true),
        D::Bar => (Outline::Bar, false),
        D::DoubleBar => (Outline::DoubleBar, false),
        D::LeftAngle => (Outline::Angle, false),
        D::RightAngle => (Outline::Angle, true),
        D::LeftFloor => (Outline::Floor, false),
        D::RightFloor => (Outline::Floor, true),
        D::LeftCeil => (Outline::Ceil, false),
        D::RightCeil => (Outline::Ceil, true),
    })
}

impl Outline {
    /// Width of the drawn shape; curved ones widen a little as they grow.
    fn width(self, height: f32, size: f32) -> f32 {
        match self {
            Self::Paren => (0.2 * size + 0.04 * height).min(0.5 * size),
            Self::Brace => (0.25 * size + 0.04 * height).min(0.55 * size),
            Self::Angle => (0.22 * size + 0.03 * height).min(0.45 * size),
            Self::Bracket | Self::Floor | Self::Ceil => 0.22 * size,
            Self::Bar => 0.0,
            Self::DoubleBar => 0.16 * size,
        }
    }

    /// Polylines tracing the left-hand form inside `rect`.
    fn polylines(self, rect: Rect, size: f32) -> Vec<Vec<Pos2>> {
        let (left, right, top, bottom) = (rect.left(), rect.right(), rect.top(), rect.bottom());
        let middle = rect.center().y;
        match self {
            Self::Paren => vec![paren_arc(rect)],
            Self::Bracket => vec![vec![
                pos2(right, top),
                pos2(left, top),
                pos2(left, bottom),
                pos2(right, bottom),
            ]],
            Self::Floor => vec![vec![
                pos2(left, top),
                pos2(left, bottom),
                pos2(right, bottom),
            ]],
            Self::Ceil => vec![vec![pos2(right, top), pos2(left, top), pos2(left, bottom)]],
            Self::Angle => vec![vec![
                pos2(right, top),
                pos2(left, middle),
                pos2(right, bottom),
            ]],
            Self::Bar => vec![vec![pos2(left, top), pos2(left, bottom)]],
            Self::DoubleBar => vec![
                vec![pos2(left, top), pos2(left, bottom)],
                vec![pos2(right, top), pos2(right, bottom)],
            ],
            Self::Brace => vec![brace(rect, size)],
        }
    }
}

/// A parenthesis: an elliptic arc bulging left, steep at its ends.
pub(super) fn paren_arc(rect: Rect) -> Vec<Pos2> {
    const STEPS: usize = 24;
    const END_ANGLE: f32 = 1.1;
    let half_height = rect.height() / 2.0;
    let middle = rect.center().y;
    (0..=STEPS)
        .map(|i| {
            let angle = -END_ANGLE + 2.0 * END_ANGLE * i as f32 / STEPS as f32;
            let bulge = (angle.cos() - END_ANGLE.cos()) / (1.0 - END_ANGLE.cos());
            pos2(
                rect.right() - rect.width() * bulge,
                middle + half_height * angle.sin() / END_ANGLE.sin(),
            )
        })
        .collect()
}

/// A curly brace: two curls joined by straight stems, pointing left.
pub(super) fn brace(rect: Rect, size: f32) -> Vec<Pos2> {
    let (left, right, top, bottom) = (rect.left(), rect.right(), rect.top(), rect.bottom());
    let stem = (left + right) / 2.0;
    let middle = rect.center().y;
    let curl = (rect.width() / 2.0)
        .min(rect.height() / 4.0)
        .min(0.3 * size);
    let segments = [
        [pos2(right, top), pos2(stem, top), pos2(stem, top + curl)],
        [
            pos2(stem, middle - curl),
            pos2(stem, middle),
            pos2(left, middle),
        ],
        [
            pos2(left, middle),
            pos2(stem, middle),
            pos2(stem, middle + curl),
        ],
        [
            pos2(stem, bottom - curl),
            pos2(stem, bottom),
            pos2(right, bottom),
        ],
    ];
    segments
        .iter()
        .flat_map(|&[a, b, c]| quadratic(a, b, c))
        .collect()
}

/// Samples a quadratic Bézier curve, end points included.
pub(super) fn quadratic(a: Pos2, control: Pos2, b: Pos2) -> impl Iterator<Item = Pos2> {
    const STEPS: usize = 8;
    (0..=STEPS).map(move |i| {
        let t = i as f32 / STEPS as f32;
        let u = 1.0 - t;
        (a.to_vec2() * (u * u) + control.to_vec2() * (2.0 * u * t) + b.to_vec2() * (t * t))
            .to_pos2()
    })
}

/// `…`, `⋯`, `⋮` and `⋱` drawn as dots: the default fonts lack most of them
/// and the glyphs that exist sit at different heights.
pub(super) fn dots(text: &str, size: f32, axis: f32) -> Option<MathBox> {
    let radius = (0.055 * size).max(0.8);
    let step = 0.28 * size;
    let side = 0.1 * size;
    let centers: [Pos2; 3] = match text {
        "…" => [0.0, 1.0, 2.0].map(|k| pos2(k * step, -radius)),
        "⋯" => [0.0, 1.0, 2.0].map(|k| pos2(k * step, -axis)),
        "⋮" => [0.0, 1.0, 2.0].map(|k| pos2(0.0, -radius - k * step)),
        "⋱" => [0.0, 1.0, 2.0].map(|k| pos2(k * step, -0.75 * size + k * step)),
        _ => return None,
    };
    let mut out = MathBox::default();
    let mut right: f32 = 0.0;
    for center in centers {
        let center = center + vec2(side + radius, 0.0);
        right = right.max(center.x + radius);
        out.draw(
            Paint::Dot { center, radius },
            center.y - radius,
            center.y + radius,
        );
    }
    out.width = right + side;
    Some(out)
}

/// `′`, `″`, `‴` drawn as raised slanted strokes: the fonts' primes are
/// acute-like marks that sit too low and too far apart.
pub(super) fn primes(text: &str, size: f32) -> Option<MathBox> {
    let count = text.chars().try_fold(0, |count, c| match c {
        '′' => Some(count + 1),
        '″' => Some(count + 2),
        '‴' => Some(count + 3),
        _ => None,
    })?;
    let width = 1.4 * stroke_width(size);
    let (top, bottom) = (-0.78 * size, -0.42 * size);
    let step = 0.16 * size;
    let mut out = MathBox::default();
    for k in 0..count {
        let x = 0.05 * size + k as f32 * step;
        let points = vec![pos2(x + 0.12 * size, top), pos2(x + 0.04 * size, bottom)];
        out.draw(Paint::Line { points, width }, top - width / 2.0, 0.0);
    }
    out.width = 0.1 * size + 0.08 * size + count as f32 * step;
    Some(out)
}
