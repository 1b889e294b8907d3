//! Typesetting lesson formulas with egui.
//!
//! A [`Math`] tree is turned into a [`MathBox`]:
//! a width, a height above the baseline (ascent) and a depth below it
//! (descent), plus the text and strokes to draw, positioned relative to the
//! left end of the baseline. The rules follow TeX in spirit (scripts at 70 %,
//! fraction bars on the math axis, operator spacing by atom class), scaled to
//! egui's default fonts. Everything that TeX would take from special glyphs —
//! stretchy fences, radical signs, accents, matrix brackets — is drawn as
//! line paths, so it scales to any height.
//!
//! [`layout_math`] only needs egui's fonts, not a window, so the geometry is
//! unit-tested below; [`math_widget`] and [`display_math`] add the box to a
//! [`Ui`].

mod fences;
pub mod fonts;
mod typeset;
mod ui;

#[cfg(test)]
mod tests;

use typeset::Typesetter;
pub use ui::{InlineMath, display_math, math_widget};

use std::sync::Arc;

use egui::emath::GuiRounding as _;
use egui::epaint::text::FontsView;
use egui::{Color32, FontId, Galley, Painter, Pos2, Rect, Shape, Stroke, Vec2, vec2};

use crate::tree::{Delimiter, Math, OpKind};

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MathStyle {
    /// Font size in points of the formula's main level (scripts are smaller).
    pub size: f32,
    /// Colour of text, rules and delimiters.
    pub color: Color32,
}

/// Whether a formula sits in running text or on its own line.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MathMode {
    /// Compact: smaller fractions, limits of `∑` beside it.
    Inline,
    /// Roomy: full-size fractions, larger `∑` with limits above and below.
    Display,
}

/// A typeset formula (or part of one): its extent around the baseline and
/// what to paint, relative to the left end of the baseline (y grows down).
#[derive(Debug, Clone, Default)]
pub struct MathBox {
    /// Horizontal advance.
    pub width: f32,
    /// Height above the baseline.
    pub ascent: f32,
    /// Depth below the baseline.
    pub descent: f32,
    paints: Vec<Paint>,
}

/// One thing to draw, in the coordinates of the box that owns it.
#[derive(Debug, Clone)]
enum Paint {
    /// Laid-out text whose top-left corner is at `pos`; drawn a second time
    /// `embolden` points to the right when bold (egui has no bold face).
    Text {
        pos: Pos2,
        galley: Arc<Galley>,
        embolden: f32,
    },
    /// An open polyline.
    Line { points: Vec<Pos2>, width: f32 },
    /// A filled rectangle, such as a fraction bar.
    Rule(Rect),
    /// A filled dot.
    Dot { center: Pos2, radius: f32 },
}

impl Paint {
    fn translated(self, offset: Vec2) -> Self {
        match self {
            Self::Text {
                pos,
                galley,
                embolden,
            } => Self::Text {
                pos: pos + offset,
                galley,
                embolden,
            },
            Self::Line { points, width } => Self::Line {
                points: points.into_iter().map(|p| p + offset).collect(),
                width,
            },
            Self::Rule(rect) => Self::Rule(rect.translate(offset)),
            Self::Dot { center, radius } => Self::Dot {
                center: center + offset,
                radius,
            },
        }
    }
}

impl MathBox {
    /// Total height, ascent plus descent.
    pub fn height(&self) -> f32 {
        self.ascent + self.descent
    }

    /// Paints the formula with the left end of its baseline at `origin`.
    pub fn paint(&self, painter: &Painter, origin: Pos2, color: Color32) {
        let pixels_per_point = painter.pixels_per_point();
        for paint in &self.paints {
            match paint {
                Paint::Text {
                    pos,
                    galley,
                    embolden,
                } => {
                    // Text is only crisp on whole pixels.
                    let at = (origin + pos.to_vec2()).round_to_pixels(pixels_per_point);
                    painter.galley(at, Arc::clone(galley), color);
                    if *embolden > 0.0 {
                        painter.galley(at + vec2(*embolden, 0.0), Arc::clone(galley), color);
                    }
                }
                Paint::Line { points, width } => {
                    let points = points.iter().map(|p| origin + p.to_vec2()).collect();
                    painter.add(Shape::line(points, Stroke::new(*width, color)));
                }
                Paint::Rule(rect) => {
                    painter.rect_filled(rect.translate(origin.to_vec2()), 0.0, color);
                }
                Paint::Dot { center, radius } => {
                    painter.circle_filled(origin + center.to_vec2(), *radius, color);
                }
            }
        }
    }

    /// An empty box `width` wide.
    fn spacer(width: f32) -> Self {
        Self {
            width,
            ..Self::default()
        }
    }

    /// Adds `child` with its baseline origin at `offset` from ours, growing
    /// the ascent and descent to cover it. The width is the caller's business.
    fn place(&mut self, child: Self, offset: Vec2) {
        self.ascent = self.ascent.max(child.ascent - offset.y);
        self.descent = self.descent.max(child.descent + offset.y);
        self.paints
            .extend(child.paints.into_iter().map(|p| p.translated(offset)));
    }

    /// Adds a drawing and grows the box vertically to cover `extent`
    /// (top and bottom y, relative to the baseline).
    fn draw(&mut self, paint: Paint, top: f32, bottom: f32) {
        self.ascent = self.ascent.max(-top);
        self.descent = self.descent.max(bottom);
        self.paints.push(paint);
    }
}

/// Lays out `math` at `style.size` without painting it.
pub fn layout_math(
    fonts: &mut FontsView<'_>,
    math: &Math,
    style: &MathStyle,
    mode: MathMode,
) -> MathBox {
    let size = sanitize_size(style.size);
    let mut typesetter = Typesetter::new(fonts, size);
    let level = Level {
        size,
        display: mode == MathMode::Display,
        script: false,
    };
    typesetter.node(math, level, 0)
}

/// A usable font size even for nonsense input.
fn sanitize_size(size: f32) -> f32 {
    if size.is_finite() {
        size.clamp(2.0, 400.0)
    } else {
        14.0
    }
}

/// Scripts are this much smaller than their base.
const SCRIPT_SCALE: f32 = 0.7;
/// Numerators and denominators of inline fractions are this much smaller.
const FRACTION_SCALE: f32 = 0.85;
/// Nothing is set smaller than this fraction of the formula's size.
const MIN_SCALE: f32 = 0.45;
/// Deeper trees are not laid out (the parser never produces them).
const MAX_DEPTH: usize = 200;

/// Font size and style of one part of a formula.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Level {
    size: f32,
    /// Display style: big operators and full-size fractions.
    display: bool,
    /// Script style: no medium or thick spaces around operators.
    script: bool,
}

impl Level {
    fn script(self, min_size: f32) -> Self {
        Self {
            size: (self.size * SCRIPT_SCALE).max(min_size),
            display: false,
            script: true,
        }
    }

    fn fraction_part(self, min_size: f32) -> Self {
        if self.display {
            Self {
                display: false,
                ..self
            }
        } else {
            Self {
                size: (self.size * FRACTION_SCALE).max(min_size),
                ..self
            }
        }
    }
}

/// Font-dependent proportions, in em.
#[derive(Debug, Clone, Copy)]
struct Metrics {
    /// Height of a lower-case `x`.
    x_height: f32,
    /// Height of the math axis (the middle of `+` and of fraction bars).
    axis: f32,
}

impl Metrics {
    fn measure(fonts: &mut FontsView<'_>, size: f32) -> Self {
        let ink = |fonts: &mut FontsView<'_>, text: &str| {
            let galley = fonts.layout_delayed_color(
                text.to_owned(),
                FontId::proportional(size),
                f32::INFINITY,
            );
            let baseline = galley_baseline(&galley);
            let bounds = galley.mesh_bounds;
            bounds
                .is_positive()
                .then_some((baseline - bounds.min.y, baseline - bounds.max.y))
        };
        let x_height = ink(fonts, "x")
            .map_or(0.5, |(top, _)| top / size)
            .clamp(0.35, 0.7);
        let axis = ink(fonts, "+")
            .map_or(0.27, |(top, bottom)| (top + bottom) / 2.0 / size)
            .clamp(0.15, 0.4);
        Self { x_height, axis }
    }
}

/// Distance from a galley's top to the baseline of its first row.
fn galley_baseline(galley: &Galley) -> f32 {
    galley
        .rows
        .first()
        .and_then(|row| row.glyphs.first().map(|glyph| row.pos.y + glyph.pos.y))
        .unwrap_or(galley.rect.height() * 0.8)
}

/// Thickness of fraction bars and radical overlines.
fn rule_thickness(size: f32) -> f32 {
    (size * 0.055).max(1.0)
}

/// Width of drawn delimiters and accents.
fn stroke_width(size: f32) -> f32 {
    (size * 0.06).max(0.9)
}

/// The TeX atom classes that decide spacing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Class {
    Ord,
    Op,
    Bin,
    Rel,
    Open,
    Close,
    Punct,
    Inner,
}

fn class_of(math: &Math) -> Option<Class> {
    Some(match math {
        Math::Space(_) => return None,
        Math::Op { kind, .. } => match kind {
            OpKind::Binary => Class::Bin,
            OpKind::Relation => Class::Rel,
            OpKind::Punct => Class::Punct,
            OpKind::Large => Class::Op,
            OpKind::Open => Class::Open,
            OpKind::Close => Class::Close,
        },
        Math::Function(_) => Class::Op,
        Math::Scripts { base, .. } => class_of(base).unwrap_or(Class::Ord),
        Math::Frac { .. } | Math::Fenced { .. } => Class::Inner,
        Math::Matrix { kind, .. } if kind.delimiters() != (Delimiter::None, Delimiter::None) => {
            Class::Inner
        }
        _ => Class::Ord,
    })
}

/// Classes of a row's atoms after TeX's rule that a binary operator with
/// nothing to combine on one side (`−x`, `(−1)`, `= −a`) is a plain sign.
fn resolve_classes(items: &[Math], leading: Option<Class>) -> Vec<Option<Class>> {
    let mut classes: Vec<Option<Class>> = Vec::with_capacity(items.len());
    let mut last: Option<usize> = None;
    for item in items {
        let Some(mut class) = class_of(item) else {
            classes.push(None);
            continue;
        };
        let previous = last
            .and_then(|i| classes.get(i).copied().flatten())
            .or(leading);
        if class == Class::Bin
            && !matches!(previous, Some(Class::Ord | Class::Close | Class::Inner))
        {
            class = Class::Ord;
        }
        if matches!(class, Class::Rel | Class::Close | Class::Punct)
            && previous == Some(Class::Bin)
            && let Some(slot) = last.and_then(|i| classes.get_mut(i))
        {
            *slot = Some(Class::Ord);
        }
        last = Some(classes.len());
        classes.push(Some(class));
    }
    if let Some(slot) = last.and_then(|i| classes.get_mut(i))
        && *slot == Some(Class::Bin)
    {
        *slot = Some(Class::Ord);
    }
    classes
}

/// Space between two adjacent atoms in eighteenths of an em (TeX's mu).
fn space_between(left: Class, right: Class, script: bool) -> f32 {
    use Class::{Bin, Close, Inner, Op, Open, Ord, Punct, Rel};
    const THIN: f32 = 3.0;
    const MEDIUM: f32 = 4.0;
    const THICK: f32 = 5.0;
    // Thin spaces around operators stay in scripts; the rest only in text.
    let loose = |mu: f32| if script { 0.0 } else { mu };
    match (left, right) {
        (Ord | Close | Inner, Op) | (Op, Ord | Op) => THIN,
        (Ord | Close | Inner, Bin) | (Bin, Ord | Op | Open | Inner) => loose(MEDIUM),
        (Ord | Op | Close | Inner, Rel) | (Rel, Ord | Op | Open | Inner) => loose(THICK),
        (Ord | Op | Close, Inner) | (Inner, Ord | Open | Punct | Inner) => loose(THIN),
        (Punct, Ord | Op | Rel | Open | Close | Punct | Inner) => loose(THIN),
        _ => 0.0,
    }
}

/// Functions whose scripts go above and below in display formulas.
const LIMIT_FUNCTIONS: &[&str] = &[
    "lim", "max", "min", "sup", "inf", "det", "gcd", "Pr", "argmax", "argmin",
];

fn takes_limits(base: &Math) -> bool {
    match base {
        Math::Op {
            text,
            kind: OpKind::Large,
        } => !matches!(text.as_str(), "∫" | "∬" | "∮"),
        Math::Function(name) => LIMIT_FUNCTIONS.contains(&name.as_str()),
        _ => false,
    }
}

/// Whether a base is a single character-sized symbol, whose scripts are
/// placed by fixed shifts rather than relative to the base's height.
fn is_single_symbol(base: &Math) -> bool {
    match base {
        Math::Op { kind, .. } => *kind != OpKind::Large,
        Math::Ident { .. } | Math::Number { .. } | Math::Symbol(_) | Math::Function(_) => true,
        _ => false,
    }
}

/// Glyphs the default fonts lack, and a look-alike they have.
fn fallback_char(c: char) -> char {
    match c {
        'ϵ' => 'ε',
        'ϑ' => 'θ',
        'ϕ' => 'φ',
        'ϖ' => 'π',
        'ϱ' => 'ρ',
        '⊥' => '⟂',
        '∥' => '‖',
        'ℏ' => 'ħ',
        '∮' => '∫',
        '⟶' => '→',
        '∣' => '|',
        '△' => 'Δ',
        _ => c,
    }
}

/// The double-struck letters in Unicode's Basic Multilingual Plane.
fn double_struck(text: &str) -> Option<String> {
    text.chars()
        .map(|c| {
            Some(match c {
                'C' => 'ℂ',
                'H' => 'ℍ',
                'N' => 'ℕ',
                'P' => 'ℙ',
                'Q' => 'ℚ',
                'R' => 'ℝ',
                'Z' => 'ℤ',
                _ => return None,
            })
        })
        .collect()
}
