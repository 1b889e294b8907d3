//! Typesetting lesson formulas with egui.
//!
//! A [`Math`] tree from `kinolab_lessons::math` is turned into a [`MathBox`]:
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

use std::f32::consts::TAU;
use std::sync::Arc;

use egui::emath::GuiRounding as _;
use egui::epaint::text::FontsView;
use egui::{
    Color32, FontId, Galley, Painter, Pos2, Rect, Response, Sense, Shape, Stroke, Ui, Vec2, pos2,
    vec2,
};
use kinolab_lessons::math::{AccentKind, Delimiter, Math, MatrixKind, OpKind, Variant};

/// Size and colour of a formula.
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

// ----- Widgets -----------------------------------------------------------------

/// Shows `math` inline, among text of `style.size`.
///
/// The widget is at least one text row tall and is centred on the same line
/// as the text around it, so in `ui.horizontal_wrapped` its baseline lines
/// up with that of neighbouring labels. Tall formulas grow symmetrically;
/// egui does not move widgets already placed in the row, so labels before a
/// tall formula only stay aligned if the row is made tall enough up front
/// with `ui.set_row_height` (see [`inline_size`]).
pub fn math_widget(ui: &mut Ui, math: &Math, style: &MathStyle) -> Response {
    let (layout, placement) = layout_inline(ui, math, style);
    let (rect, response) = ui.allocate_exact_size(placement.size, Sense::hover());
    if ui.is_rect_visible(rect) {
        let origin = rect.left_top() + vec2(0.0, placement.baseline);
        layout.paint(ui.painter(), origin, style.color);
    }
    response
}

/// The size [`math_widget`] will allocate for `math`, for callers that want
/// to size a row of text before filling it.
pub fn inline_size(ui: &Ui, math: &Math, style: &MathStyle) -> Vec2 {
    layout_inline(ui, math, style).1.size
}

fn layout_inline(ui: &Ui, math: &Math, style: &MathStyle) -> (MathBox, InlinePlacement) {
    let (layout, line) = ui.ctx().fonts_mut(|fonts| {
        (
            layout_math(fonts, math, style, MathMode::Inline),
            TextLine::measure(fonts, style.size),
        )
    });
    let placement = inline_placement(&layout, line);
    (layout, placement)
}

/// How much larger a display formula is than the text around it.
const DISPLAY_SCALE: f32 = 1.2;

/// Shows `math` as a display formula: centred on its own line, at a larger
/// size, with fractions at full size and limits above and below `∑`.
pub fn display_math(ui: &mut Ui, math: &Math, style: &MathStyle) -> Response {
    let style = MathStyle {
        size: style.size * DISPLAY_SCALE,
        ..*style
    };
    let layout = ui
        .ctx()
        .fonts_mut(|fonts| layout_math(fonts, math, &style, MathMode::Display));
    let padding = 0.3 * style.size;
    // Horizontal layouts and scroll areas may offer unbounded width.
    let available = ui.available_width();
    let width = if available.is_finite() {
        available.max(layout.width)
    } else {
        layout.width
    };
    let size = vec2(width, layout.height() + 2.0 * padding);
    let (rect, response) = ui.allocate_exact_size(size, Sense::hover());
    if ui.is_rect_visible(rect) {
        let origin = pos2(
            rect.center().x - layout.width / 2.0,
            rect.top() + padding + layout.ascent,
        );
        layout.paint(ui.painter(), origin, style.color);
    }
    response
}

/// Where a label's text sits in its row: the baseline's distance from the
/// top, and the row height.
#[derive(Debug, Clone, Copy, PartialEq)]
struct TextLine {
    ascent: f32,
    row_height: f32,
}

impl TextLine {
    fn measure(fonts: &mut FontsView<'_>, size: f32) -> Self {
        let galley = fonts.layout_delayed_color(
            "x".to_owned(),
            FontId::proportional(sanitize_size(size)),
            f32::INFINITY,
        );
        Self {
            ascent: galley_baseline(&galley),
            row_height: galley.rect.height(),
        }
    }
}

/// The size to allocate for an inline formula and its baseline's distance
/// from the top of that rect.
#[derive(Debug, Clone, Copy, PartialEq)]
struct InlinePlacement {
    size: Vec2,
    baseline: f32,
}

/// Centres the formula on the middle of a text row, like a label would be,
/// and keeps its baseline where the label's baseline is.
fn inline_placement(layout: &MathBox, line: TextLine) -> InlinePlacement {
    // How far the text baseline lies below the middle of its row.
    let baseline_below_middle = line.ascent - line.row_height / 2.0;
    let half_height = (line.row_height / 2.0)
        .max(layout.ascent - baseline_below_middle)
        .max(layout.descent + baseline_below_middle);
    InlinePlacement {
        size: vec2(layout.width, 2.0 * half_height),
        baseline: half_height + baseline_below_middle,
    }
}

// ----- Layout ------------------------------------------------------------------

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

/// Lays out one formula with one set of fonts.
struct Typesetter<'f, 'v> {
    fonts: &'f mut FontsView<'v>,
    metrics: Metrics,
    /// Sizes never go below this.
    min_size: f32,
}

impl<'f, 'v> Typesetter<'f, 'v> {
    fn new(fonts: &'f mut FontsView<'v>, size: f32) -> Self {
        let metrics = Metrics::measure(fonts, size);
        Self {
            fonts,
            metrics,
            min_size: (size * MIN_SCALE).max(2.0),
        }
    }

    fn axis(&self, size: f32) -> f32 {
        self.metrics.axis * size
    }

    fn x_height(&self, size: f32) -> f32 {
        self.metrics.x_height * size
    }

    fn node(&mut self, math: &Math, level: Level, depth: usize) -> MathBox {
        if depth > MAX_DEPTH {
            return MathBox::default();
        }
        let depth = depth + 1;
        let size = level.size;
        match math {
            Math::Row(items) => self.row(items, level, depth, None),
            Math::Group(body) => self.node(body, level, depth),
            Math::Ident { text, variant } | Math::Number { text, variant } => {
                self.styled_text(text, *variant, size)
            }
            Math::Symbol(text) => dots(text, size, self.axis(size))
                .or_else(|| primes(text, size))
                .unwrap_or_else(|| self.text(text, size, false)),
            Math::Op {
                text,
                kind: OpKind::Large,
            } => self.large_operator(text, level),
            Math::Op { text, .. } | Math::Function(text) | Math::Text(text) => {
                self.text(text, size, false)
            }
            Math::Space(em) => MathBox::spacer(em * size),
            Math::Frac { num, den } => self.fraction(num, den, level, depth),
            Math::Scripts { base, sub, sup } => {
                self.scripts(base, sub.as_deref(), sup.as_deref(), level, depth)
            }
            Math::Sqrt { index, body } => self.radical(index.as_deref(), body, level, depth),
            Math::Accent { kind, body } => self.accent(*kind, body, level, depth),
            Math::Fenced { open, close, body } => self.fenced(*open, *close, body, level, depth),
            Math::Matrix { kind, rows } => self.matrix(*kind, rows, level, depth),
        }
    }

    /// Lays atoms side by side with TeX's spacing between them. `leading` is
    /// the class of an atom assumed to come before the first (used for the
    /// right-hand sides in `aligned`).
    fn row(
        &mut self,
        items: &[Math],
        level: Level,
        depth: usize,
        leading: Option<Class>,
    ) -> MathBox {
        let mu = level.size / 18.0;
        let mut row = MathBox::default();
        let mut x = 0.0;
        let mut previous = leading;
        for (item, class) in items.iter().zip(resolve_classes(items, leading)) {
            if let Some(class) = class {
                if let Some(previous) = previous {
                    x += space_between(previous, class, level.script) * mu;
                }
                previous = Some(class);
            }
            let child = self.node(item, level, depth);
            let width = child.width;
            row.place(child, vec2(x, 0.0));
            x += width;
        }
        row.width = x.max(0.0);
        row
    }

    /// Lays out one cell or argument as a row, so `leading` applies to it.
    fn as_row(
        &mut self,
        math: &Math,
        level: Level,
        depth: usize,
        leading: Option<Class>,
    ) -> MathBox {
        match math {
            Math::Row(items) => self.row(items, level, depth, leading),
            other => self.row(std::slice::from_ref(other), level, depth, leading),
        }
    }

    // ----- Text ------------------------------------------------------------

    fn styled_text(&mut self, text: &str, variant: Variant, size: f32) -> MathBox {
        match variant {
            Variant::Italic | Variant::Upright => self.text(text, size, false),
            Variant::Bold | Variant::BoldItalic => self.text(text, size, true),
            Variant::DoubleStruck => match double_struck(text) {
                Some(letters) if self.font_for(&letters, size).is_some() => {
                    self.text(&letters, size, false)
                }
                // The closest look the default fonts offer.
                _ => self.text(text, size, true),
            },
        }
    }

    /// A font that has every glyph of `text`: the proportional one if it
    /// can, else the monospace one (which brings many math symbols).
    fn font_for(&mut self, text: &str, size: f32) -> Option<FontId> {
        [FontId::proportional(size), FontId::monospace(size)]
            .into_iter()
            .find(|font| self.fonts.has_glyphs(font, text))
    }

    /// Text set as one galley, measured by its ink so stacking is tight.
    fn text(&mut self, text: &str, size: f32, bold: bool) -> MathBox {
        let (text, font) = match self.font_for(text, size) {
            Some(font) => (text.to_owned(), font),
            None => {
                let substitute: String = text.chars().map(fallback_char).collect();
                let font = self
                    .font_for(&substitute, size)
                    .unwrap_or_else(|| FontId::proportional(size));
                (substitute, font)
            }
        };
        let galley = self.fonts.layout_delayed_color(text, font, f32::INFINITY);
        let baseline = galley_baseline(&galley);
        let ink = galley.mesh_bounds;
        let (ascent, descent) = if ink.is_positive() {
            (
                (baseline - ink.min.y).max(0.0),
                (ink.max.y - baseline).max(0.0),
            )
        } else {
            (0.0, 0.0)
        };
        let embolden = if bold { (size * 0.04).max(0.5) } else { 0.0 };
        MathBox {
            width: galley.rect.width() + embolden,
            ascent,
            descent,
            paints: vec![Paint::Text {
                pos: pos2(0.0, -baseline),
                galley,
                embolden,
            }],
        }
    }

    /// `∑`, `∫`, …: larger in display style, centred on the math axis.
    fn large_operator(&mut self, text: &str, level: Level) -> MathBox {
        let integral = matches!(text, "∫" | "∬" | "∮");
        let scale = match (level.display, integral) {
            (true, true) => 2.0,
            (true, false) => 1.45,
            (false, true) => 1.3,
            (false, false) => 1.1,
        };
        let glyph = self.text(text, level.size * scale, false);
        let center = (glyph.descent - glyph.ascent) / 2.0;
        let shift = -self.axis(level.size) - center;
        let mut out = MathBox::spacer(glyph.width);
        out.place(glyph, vec2(0.0, shift));
        out
    }

    // ----- Fractions and scripts -----------------------------------------

    fn fraction(&mut self, num: &Math, den: &Math, level: Level, depth: usize) -> MathBox {
        let part = level.fraction_part(self.min_size);
        let num = self.node(num, part, depth);
        let den = self.node(den, part, depth);
        let size = level.size;
        let thickness = rule_thickness(size);
        let axis = self.axis(size);
        let gap = if level.display { 0.18 } else { 0.1 } * size;
        // TeX's minimum shifts keep simple fractions alike whatever letters
        // they hold.
        let (min_up, min_down) = if level.display {
            (0.68, 0.69)
        } else {
            (0.45, 0.38)
        };
        let shift_up = (axis + thickness / 2.0 + gap + num.descent).max(min_up * size);
        let shift_down = (-axis + thickness / 2.0 + gap + den.ascent).max(min_down * size);
        let side = 0.1 * size;
        let rule_width = num.width.max(den.width) + 0.16 * size;
        let width = rule_width + 2.0 * side;

        let mut out = MathBox::spacer(width);
        let (num_width, den_width) = (num.width, den.width);
        out.place(num, vec2((width - num_width) / 2.0, -shift_up));
        out.place(den, vec2((width - den_width) / 2.0, shift_down));
        let rule = Rect::from_min_max(
            pos2(side, -axis - thickness / 2.0),
            pos2(side + rule_width, -axis + thickness / 2.0),
        );
        out.draw(Paint::Rule(rule), rule.top(), rule.bottom());
        out
    }

    fn scripts(
        &mut self,
        base: &Math,
        sub: Option<&Math>,
        sup: Option<&Math>,
        level: Level,
        depth: usize,
    ) -> MathBox {
        let base_box = self.node(base, level, depth);
        let script = level.script(self.min_size);
        let sub = sub.map(|m| self.node(m, script, depth));
        let sup = sup.map(|m| self.node(m, script, depth));
        if level.display && takes_limits(base) {
            return limits(base_box, sub, sup, level.size);
        }

        let size = level.size;
        let x_height = self.x_height(size);
        let (mut up, mut down) = if is_single_symbol(base) {
            (0.0, 0.0)
        } else {
            (
                base_box.ascent - 0.39 * script.size,
                base_box.descent + 0.05 * script.size,
            )
        };
        if let Some(sup) = &sup {
            let minimum = if level.display { 0.41 } else { 0.36 } * size;
            up = up.max(minimum).max(sup.descent + x_height / 4.0);
        }
        match (&sub, &sup) {
            (Some(sub), None) => {
                down = down.max(0.15 * size).max(sub.ascent - 0.8 * x_height);
            }
            (Some(sub), Some(sup)) => {
                down = down.max(0.25 * size);
                // Keep the two scripts apart; lift both if they would touch.
                let min_gap = 4.0 * rule_thickness(script.size);
                let gap = (up - sup.descent) - (sub.ascent - down);
                if gap < min_gap {
                    down += min_gap - gap;
                    let lift = 0.8 * x_height - (up - sup.descent);
                    if lift > 0.0 {
                        up += lift;
                        down -= lift;
                    }
                }
            }
            _ => {}
        }

        let x = base_box.width;
        let script_width = sub
            .as_ref()
            .map_or(0.0, |b| b.width)
            .max(sup.as_ref().map_or(0.0, |b| b.width));
        let mut out = MathBox::spacer(x + script_width + 0.05 * size);
        out.place(base_box, Vec2::ZERO);
        if let Some(sup) = sup {
            out.place(sup, vec2(x, -up));
        }
        if let Some(sub) = sub {
            out.place(sub, vec2(x, down));
        }
        out
    }

    // ----- Radicals, accents, fences, matrices ----------------------------

    fn radical(
        &mut self,
        index: Option<&Math>,
        body: &Math,
        level: Level,
        depth: usize,
    ) -> MathBox {
        let size = level.size;
        let body = self.node(body, level, depth);
        let thickness = rule_thickness(size);
        let gap = thickness + if level.display { 0.15 } else { 0.08 } * size;
        let top = -(body.ascent.max(0.65 * size) + gap + thickness / 2.0);
        let bottom = body.descent.max(0.2 * size);
        let height = bottom - top;
        let sign_width = (0.5 * size + 0.05 * height).min(size);
        let tick = height.min(1.2 * size);
        let padding = 0.08 * size;

        let index = index.map(|m| {
            let tiny = level.script(self.min_size).script(self.min_size);
            self.node(m, tiny, depth)
        });
        let x0 = index
            .as_ref()
            .map_or(0.0, |i| (i.width - 0.55 * sign_width).max(0.0));

        let body_x = x0 + sign_width + padding;
        let end_x = body_x + body.width + padding;
        let points = vec![
            pos2(x0, bottom - 0.42 * tick),
            pos2(x0 + 0.2 * sign_width, bottom - 0.5 * tick),
            pos2(x0 + 0.5 * sign_width, bottom),
            pos2(x0 + sign_width, top),
            pos2(end_x, top),
        ];
        let mut out = MathBox::spacer(end_x + 0.05 * size);
        out.draw(
            Paint::Line {
                points,
                width: thickness,
            },
            top - thickness / 2.0 - 0.05 * size,
            bottom + thickness / 2.0,
        );
        out.place(body, vec2(body_x, 0.0));
        if let Some(index) = index {
            let index_width = index.width;
            let baseline = bottom - 0.55 * height;
            out.place(index, vec2(x0 + 0.55 * sign_width - index_width, baseline));
        }
        out
    }

    fn accent(&mut self, kind: AccentKind, body: &Math, level: Level, depth: usize) -> MathBox {
        let size = level.size;
        let body = self.node(body, level, depth);
        let stroke = stroke_width(size);
        let base_y = -body.ascent.max(self.x_height(size)) - 0.1 * size;
        let wide = |fraction: f32| (body.width * fraction).max(0.4 * size);
        let (paints, width, height) = match kind {
            AccentKind::Dot | AccentKind::Ddot => {
                let radius = (0.065 * size).max(0.9);
                let center_y = base_y - radius;
                let offsets: &[f32] = if kind == AccentKind::Dot {
                    &[0.0]
                } else {
                    &[-0.13, 0.13]
                };
                let paints = offsets
                    .iter()
                    .map(|dx| Paint::Dot {
                        center: pos2(dx * size, center_y),
                        radius,
                    })
                    .collect();
                (paints, 0.26 * size + 2.0 * radius, 2.0 * radius)
            }
            AccentKind::Hat => {
                let width = wide(0.8);
                let height = 0.16 * size + 0.04 * width;
                let points = vec![
                    pos2(-width / 2.0, base_y),
                    pos2(0.0, base_y - height),
                    pos2(width / 2.0, base_y),
                ];
                (
                    vec![Paint::Line {
                        points,
                        width: stroke,
                    }],
                    width,
                    height,
                )
            }
            AccentKind::Bar => {
                let width = (body.width - 0.1 * size).max(0.35 * size);
                let y = base_y - stroke / 2.0;
                let points = vec![pos2(-width / 2.0, y), pos2(width / 2.0, y)];
                (
                    vec![Paint::Line {
                        points,
                        width: stroke,
                    }],
                    width,
                    stroke,
                )
            }
            AccentKind::Vec => {
                let width = wide(0.9);
                let head = 0.13 * size;
                let y = base_y - 0.7 * head;
                let tip = width / 2.0;
                let shaft = vec![pos2(-tip, y), pos2(tip, y)];
                let arrow_head = vec![
                    pos2(tip - head, y - 0.7 * head),
                    pos2(tip, y),
                    pos2(tip - head, y + 0.7 * head),
                ];
                let paints = vec![
                    Paint::Line {
                        points: shaft,
                        width: stroke,
                    },
                    Paint::Line {
                        points: arrow_head,
                        width: stroke,
                    },
                ];
                (paints, width, 1.4 * head)
            }
            AccentKind::Tilde => {
                let width = wide(0.8);
                let amplitude = 0.06 * size;
                let center_y = base_y - amplitude;
                let points = (0..=16)
                    .map(|i| {
                        let u = i as f32 / 16.0;
                        pos2((u - 0.5) * width, center_y - amplitude * (TAU * u).sin())
                    })
                    .collect();
                (
                    vec![Paint::Line {
                        points,
                        width: stroke,
                    }],
                    width,
                    2.0 * amplitude,
                )
            }
        };

        let total_width = body.width.max(width);
        let center_x = total_width / 2.0;
        let body_width = body.width;
        let mut out = MathBox::spacer(total_width);
        out.place(body, vec2((total_width - body_width) / 2.0, 0.0));
        let top = base_y - height - stroke / 2.0;
        for paint in paints {
            out.draw(paint.translated(vec2(center_x, 0.0)), top, 0.0);
        }
        out
    }

    fn fenced(
        &mut self,
        open: Delimiter,
        close: Delimiter,
        body: &Math,
        level: Level,
        depth: usize,
    ) -> MathBox {
        let size = level.size;
        let body = self.node(body, level, depth);
        let axis = self.axis(size);
        let half = (body.ascent - axis)
            .max(body.descent + axis)
            .max(0.5 * size)
            + 0.1 * size;
        fence(
            body,
            open,
            close,
            -axis - half,
            -axis + half,
            size,
            0.12 * size,
        )
    }

    fn matrix(
        &mut self,
        kind: MatrixKind,
        rows: &[Vec<Math>],
        level: Level,
        depth: usize,
    ) -> MathBox {
        let size = level.size;
        let cell_level = Level {
            display: false,
            ..level
        };
        let cells: Vec<Vec<MathBox>> = rows
            .iter()
            .map(|row| {
                row.iter()
                    .enumerate()
                    .map(|(column, cell)| {
                        // In `aligned`, `&=` continues the left-hand side.
                        let leading = (kind == MatrixKind::Aligned && !column.is_multiple_of(2))
                            .then_some(Class::Ord);
                        self.as_row(cell, cell_level, depth, leading)
                    })
                    .collect()
            })
            .collect();
        let grid = MatrixGrid::measure(&cells, size);
        let axis = self.axis(size);
        let top = -axis - grid.height / 2.0;

        let mut body = MathBox::spacer(grid.width(kind, size));
        let mut y = top;
        for (row, (ascent, descent)) in cells.into_iter().zip(grid.rows.iter().copied()) {
            y += ascent;
            let mut x = 0.0;
            for (column, (cell, column_width)) in row
                .into_iter()
                .zip(grid.columns.iter().copied())
                .enumerate()
            {
                let free = column_width - cell.width;
                let dx = match cell_alignment(kind, column) {
                    CellAlign::Left => 0.0,
                    CellAlign::Center => free / 2.0,
                    CellAlign::Right => free,
                };
                body.place(cell, vec2(x + dx, y));
                x += column_width + column_gap(kind, column, size);
            }
            y += descent + grid.row_gap;
        }
        body.ascent = body.ascent.max(-top);
        body.descent = body.descent.max(top + grid.height);

        let (open, close) = kind.delimiters();
        let pad = 0.12 * size;
        fence(
            body,
            open,
            close,
            top - pad,
            top + grid.height + pad,
            size,
            0.0,
        )
    }
}

/// Places scripts centred above and below a big operator.
fn limits(base: MathBox, sub: Option<MathBox>, sup: Option<MathBox>, size: f32) -> MathBox {
    let width = [Some(&base), sub.as_ref(), sup.as_ref()]
        .into_iter()
        .flatten()
        .map(|b| b.width)
        .fold(0.0, f32::max);
    let gap = 0.12 * size;
    let (base_ascent, base_descent, base_width) = (base.ascent, base.descent, base.width);
    let mut out = MathBox::spacer(width);
    out.place(base, vec2((width - base_width) / 2.0, 0.0));
    if let Some(sup) = sup {
        let offset = vec2(
            (width - sup.width) / 2.0,
            -(base_ascent + gap + sup.descent),
        );
        out.place(sup, offset);
    }
    if let Some(sub) = sub {
        let offset = vec2((width - sub.width) / 2.0, base_descent + gap + sub.ascent);
        out.place(sub, offset);
    }
    out
}

/// Column widths, row heights and total height of a matrix.
#[derive(Debug)]
struct MatrixGrid {
    columns: Vec<f32>,
    /// Ascent and descent of each row, at least a strut's.
    rows: Vec<(f32, f32)>,
    row_gap: f32,
    height: f32,
}

impl MatrixGrid {
    fn measure(cells: &[Vec<MathBox>], size: f32) -> Self {
        let column_count = cells.iter().map(Vec::len).max().unwrap_or(0);
        let columns: Vec<f32> = (0..column_count)
            .map(|j| {
                cells
                    .iter()
                    .filter_map(|row| row.get(j))
                    .map(|cell| cell.width)
                    .fold(0.0, f32::max)
            })
            .collect();
        let rows: Vec<(f32, f32)> = cells
            .iter()
            .map(|row| {
                row.iter().fold((0.7 * size, 0.3 * size), |(a, d), cell| {
                    (a.max(cell.ascent), d.max(cell.descent))
                })
            })
            .collect();
        let row_gap = 0.25 * size;
        let height = rows.iter().map(|(a, d)| a + d).sum::<f32>()
            + row_gap * rows.len().saturating_sub(1) as f32;
        Self {
            columns,
            rows,
            row_gap,
            height,
        }
    }

    fn width(&self, kind: MatrixKind, size: f32) -> f32 {
        let gaps: f32 = (0..self.columns.len().saturating_sub(1))
            .map(|j| column_gap(kind, j, size))
            .sum();
        self.columns.iter().sum::<f32>() + gaps
    }
}

#[derive(Debug, Clone, Copy)]
enum CellAlign {
    Left,
    Center,
    Right,
}

fn cell_alignment(kind: MatrixKind, column: usize) -> CellAlign {
    match kind {
        MatrixKind::Cases => CellAlign::Left,
        MatrixKind::Aligned if column.is_multiple_of(2) => CellAlign::Right,
        MatrixKind::Aligned => CellAlign::Left,
        _ => CellAlign::Center,
    }
}

/// Space after column `column`.
fn column_gap(kind: MatrixKind, column: usize, size: f32) -> f32 {
    match kind {
        // `a &= b` reads as one equation: no gap inside a pair.
        MatrixKind::Aligned if column.is_multiple_of(2) => 0.0,
        MatrixKind::Aligned | MatrixKind::Cases => 1.2 * size,
        _ => 0.8 * size,
    }
}

/// Wraps `body` in delimiters spanning `top`..`bottom`. A missing delimiter
/// takes `null_space`.
fn fence(
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
fn draw_delimiter(
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
enum Outline {
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
fn outline_of(delimiter: Delimiter) -> Option<(Outline, bool)> {
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
fn paren_arc(rect: Rect) -> Vec<Pos2> {
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
fn brace(rect: Rect, size: f32) -> Vec<Pos2> {
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
fn quadratic(a: Pos2, control: Pos2, b: Pos2) -> impl Iterator<Item = Pos2> {
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
fn dots(text: &str, size: f32, axis: f32) -> Option<MathBox> {
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
fn primes(text: &str, size: f32) -> Option<MathBox> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use kinolab_lessons::math::parse;

    const STYLE: MathStyle = MathStyle {
        size: 16.0,
        color: Color32::WHITE,
    };

    /// Runs `f` inside one egui pass, where fonts are available.
    fn with_fonts<R>(f: impl FnOnce(&mut FontsView<'_>) -> R) -> R {
        let ctx = egui::Context::default();
        let mut f = Some(f);
        let mut result = None;
        let output = ctx.run_ui(egui::RawInput::default(), |ui| {
            if let Some(f) = f.take() {
                result = Some(ui.ctx().fonts_mut(f));
            }
        });
        output.drop_without_applying_deltas();
        result.expect("the pass ran")
    }

    fn layout(src: &str, mode: MathMode) -> MathBox {
        let math = parse(src).expect("test formula parses");
        with_fonts(|fonts| layout_math(fonts, &math, &STYLE, mode))
    }

    fn inline(src: &str) -> MathBox {
        layout(src, MathMode::Inline)
    }

    fn count_text(b: &MathBox) -> usize {
        b.paints
            .iter()
            .filter(|p| matches!(p, Paint::Text { .. }))
            .count()
    }

    #[test]
    fn atoms_have_ink_metrics() {
        let x = inline("x");
        assert!(x.width > 0.0);
        assert!(
            x.ascent > 0.3 * STYLE.size && x.ascent < 0.8 * STYLE.size,
            "{x:?}"
        );
        assert!(x.descent < 0.1 * STYLE.size);
        let y = inline("y");
        assert!(y.descent > 0.1 * STYLE.size, "y has a descender: {y:?}");
        let b = inline("b");
        assert!(b.ascent > x.ascent);
    }

    #[test]
    fn fraction_is_taller_than_its_parts() {
        let num = inline("a+b");
        let fraction = inline("\\frac{a+b}{c}");
        assert!(fraction.height() > num.height() + inline("c").height());
        assert!(fraction.ascent > num.ascent, "numerator is raised");
        assert!(
            fraction.descent > 0.3 * STYLE.size,
            "denominator is lowered"
        );
        assert!(fraction.width >= num.width * FRACTION_SCALE);
        assert!(fraction.paints.iter().any(|p| matches!(p, Paint::Rule(_))));
        // Display fractions keep full size.
        let display = layout("\\frac{a+b}{c}", MathMode::Display);
        assert!(display.width > fraction.width);
        assert!(display.height() > fraction.height());
    }

    #[test]
    fn fraction_bar_sits_on_the_axis() {
        let fraction = inline("\\frac{1}{2}");
        let plus = inline("+");
        let Some(Paint::Rule(rule)) = fraction.paints.iter().find(|p| matches!(p, Paint::Rule(_)))
        else {
            panic!("no fraction bar");
        };
        let plus_middle = (plus.descent - plus.ascent) / 2.0;
        assert!(
            (rule.center().y - plus_middle).abs() < 1.5,
            "{rule:?} vs {plus_middle}"
        );
    }

    #[test]
    fn superscripts_rise_and_subscripts_drop() {
        let x = inline("x");
        let squared = inline("x^2");
        assert!(squared.ascent > x.ascent + 0.2 * STYLE.size, "{squared:?}");
        assert!(squared.width > x.width);
        let indexed = inline("x_i");
        assert!(
            indexed.descent > x.descent + 0.1 * STYLE.size,
            "{indexed:?}"
        );
        assert!(indexed.ascent < squared.ascent);
        let both = inline("x_i^2");
        assert!(both.ascent >= squared.ascent - 0.5 && both.descent >= indexed.descent - 0.5);
        // Scripts are smaller than their base.
        let two = inline("2");
        let script_two = squared.width - x.width;
        assert!(script_two < two.width);
    }

    #[test]
    fn display_sums_take_limits_above_and_below() {
        let inline_sum = inline("\\sum_{i=1}^n x_i");
        let display_sum = layout("\\sum_{i=1}^n x_i", MathMode::Display);
        assert!(display_sum.height() > inline_sum.height() * 1.3);
        let display_sum_alone = layout("\\sum", MathMode::Display);
        let with_limits = layout("\\sum_{i=1}^{n}", MathMode::Display);
        // Limits stack: the box is no wider than its widest part plus a little.
        assert!(with_limits.width < display_sum_alone.width + inline("i=1").width);
    }

    #[test]
    fn matrices_grow_with_their_cells() {
        let cell = inline("a");
        let one = inline("\\begin{bmatrix} a \\end{bmatrix}");
        let two = inline("\\begin{bmatrix} a & b \\\\ c & d \\end{bmatrix}");
        assert!(one.width > cell.width, "brackets add width");
        assert!(two.width > one.width + cell.width);
        assert!(two.height() > one.height() + cell.height());
        let lines = two
            .paints
            .iter()
            .filter(|p| matches!(p, Paint::Line { .. }))
            .count();
        assert_eq!(lines, 2, "two drawn brackets");
        assert_eq!(count_text(&two), 4);
        // A plain matrix draws no delimiters and is narrower.
        let plain = inline("\\begin{matrix} a & b \\\\ c & d \\end{matrix}");
        assert!(plain.width < two.width);
        assert!(!plain.paints.iter().any(|p| matches!(p, Paint::Line { .. })));
    }

    #[test]
    fn fences_stretch_to_their_body() {
        let small = inline("\\left( x \\right)");
        let tall = inline("\\left( \\frac{a}{b} \\right)");
        assert!(tall.height() > small.height());
        let frac = inline("\\frac{a}{b}");
        assert!(tall.ascent >= frac.ascent && tall.descent >= frac.descent);
        assert!(inline("\\left. x \\right|").width < small.width);
    }

    #[test]
    fn radicals_and_accents_add_height() {
        let x = inline("x");
        let root = inline("\\sqrt{x}");
        assert!(root.width > x.width && root.ascent > x.ascent);
        let cube = inline("\\sqrt[3]{x}");
        assert!(cube.width >= root.width);
        for accent in ["\\dot", "\\ddot", "\\hat", "\\bar", "\\vec", "\\tilde"] {
            let accented = inline(&format!("{accent}{{x}}"));
            assert!(
                accented.ascent > x.ascent + 0.1 * STYLE.size,
                "{accent}: {accented:?}"
            );
            assert!((accented.descent - x.descent).abs() < 0.01, "{accent}");
        }
        let wide = inline("\\overline{ABC}");
        assert!(wide.width >= inline("ABC").width);
    }

    #[test]
    fn operators_get_space_but_signs_do_not() {
        let a = inline("a");
        let b = inline("b");
        let sum = inline("a+b");
        let plus = inline("+");
        let tight = a.width + plus.width + b.width;
        assert!(
            sum.width > tight + 0.3 * STYLE.size,
            "medium spaces around +"
        );
        let equation = inline("a=b");
        let equals = inline("=");
        assert!(equation.width > a.width + equals.width + b.width + 0.4 * STYLE.size);
        // A leading minus is a sign.
        let negative = inline("-b");
        let minus = inline("-");
        assert!((negative.width - (minus.width + b.width)).abs() < 0.01);
        // No medium space in scripts.
        assert_eq!(
            resolve_classes(&[], None),
            Vec::<Option<Class>>::new(),
            "empty rows are fine"
        );
        assert_eq!(space_between(Class::Ord, Class::Bin, true), 0.0);
        assert_eq!(space_between(Class::Op, Class::Ord, true), 3.0);
    }

    #[test]
    fn bold_and_fallback_glyphs_render_as_text() {
        let bold = inline("\\mathbf{v}");
        let plain = inline("v");
        assert!(bold.width > plain.width);
        // Letters the default fonts lack are replaced, not dropped.
        for src in [
            "\\epsilon",
            "\\vartheta",
            "\\phi",
            "\\perp",
            "\\parallel",
            "\\mathbb{R}",
            "\\to",
        ] {
            let b = inline(src);
            assert!(b.width > 0.0 && b.ascent > 0.0, "{src}: {b:?}");
        }
        let dots = inline("\\cdots");
        assert_eq!(count_text(&dots), 0, "dots are drawn");
        assert!(dots.width > 0.5 * STYLE.size);
    }

    #[test]
    fn inline_placement_keeps_the_text_baseline() {
        let line = TextLine {
            ascent: 13.0,
            row_height: 18.0,
        };
        let small = MathBox {
            width: 10.0,
            ascent: 8.0,
            descent: 2.0,
            paints: Vec::new(),
        };
        let placed = inline_placement(&small, line);
        assert_eq!(placed.size, vec2(10.0, 18.0));
        assert_eq!(placed.baseline, 13.0);
        // A tall formula grows on both sides of the row's middle.
        let tall = MathBox {
            ascent: 20.0,
            descent: 10.0,
            ..small
        };
        let placed = inline_placement(&tall, line);
        assert!(placed.baseline >= tall.ascent);
        assert!(placed.size.y - placed.baseline >= tall.descent);
        let middle_offset = placed.baseline - placed.size.y / 2.0;
        assert!((middle_offset - (line.ascent - line.row_height / 2.0)).abs() < 1e-4);
    }

    #[test]
    fn widgets_allocate_their_layout() {
        let math =
            parse("v = r\\dot\\varphi + \\frac{1}{2} \\begin{pmatrix} a \\\\ b \\end{pmatrix}")
                .expect("parses");
        let ctx = egui::Context::default();
        let mut rects = Vec::new();
        let output = ctx.run_ui(egui::RawInput::default(), |ui| {
            ui.horizontal_wrapped(|ui| {
                ui.label("speed");
                rects.push(math_widget(ui, &math, &STYLE).rect);
            });
            rects.push(display_math(ui, &math, &STYLE).rect);
        });
        output.drop_without_applying_deltas();
        let expected = with_fonts(|fonts| layout_math(fonts, &math, &STYLE, MathMode::Inline));
        let [inline_rect, display_rect] = rects[..] else {
            panic!("two widgets: {rects:?}");
        };
        assert!(
            (inline_rect.width() - expected.width).abs() < 0.1,
            "{inline_rect:?} vs {}",
            expected.width
        );
        assert!(inline_rect.height() >= expected.height());
        assert!(display_rect.width() >= inline_rect.width());
        assert!(display_rect.height() > inline_rect.height());
    }

    #[test]
    fn baseline_matches_labels_in_a_sized_row() {
        let math = parse("\\frac{a}{b} + x^2").expect("parses");
        let ctx = egui::Context::default();
        let mut rects = Vec::new();
        let output = ctx.run_ui(egui::RawInput::default(), |ui| {
            ui.horizontal_wrapped(|ui| {
                ui.set_row_height(inline_size(ui, &math, &STYLE).y);
                rects.push(ui.label(egui::RichText::new("x").size(STYLE.size)).rect);
                rects.push(math_widget(ui, &math, &STYLE).rect);
                rects.push(ui.label(egui::RichText::new("y").size(STYLE.size)).rect);
            });
        });
        output.drop_without_applying_deltas();
        let [before, formula, after] = rects[..] else {
            panic!("three widgets: {rects:?}");
        };
        // Labels and formula are centred on one line, so baselines agree.
        assert!(
            (before.center().y - formula.center().y).abs() < 0.5,
            "{rects:?}"
        );
        assert!(
            (after.center().y - formula.center().y).abs() < 0.5,
            "{rects:?}"
        );
        assert!(formula.height() > before.height());
    }

    #[test]
    fn primes_are_drawn_after_their_base() {
        let f = inline("f");
        let prime = inline("f'");
        let double = inline("f''");
        assert!(prime.width > f.width && double.width > prime.width);
        assert!(prime.ascent >= f.ascent);
        assert_eq!(count_text(&prime), 1);
    }

    #[test]
    fn every_construct_lays_out_finitely() {
        let sources = [
            "",
            "x",
            "\\alpha\\beta\\Gamma",
            "f'(x) = \\lim_{h \\to 0} \\frac{f(x+h)-f(x)}{h}",
            "\\sqrt[3]{\\frac{a}{b}}",
            "\\left\\{ x \\right\\} \\left\\langle y \\right\\rangle \\left\\lfloor z \\right\\rceil",
            "\\left\\| v \\right\\|",
            "\\begin{cases} 1 & x > 0 \\\\ 0 & \\text{otherwise} \\end{cases}",
            "\\begin{aligned} a &= b \\\\ c &= d + e \\end{aligned}",
            "\\begin{vmatrix} a & b \\\\ c & d \\end{vmatrix} \\begin{Vmatrix} a \\end{Vmatrix}",
            "\\begin{bmatrix}\\end{bmatrix}",
            "R^\\top \\mathbf{x}_{i}^{2} \\int_0^1 x\\,dx \\quad \\dots \\ldots \\vdots \\ddots",
            "a\\!b~c\\;d",
            "^2",
        ];
        for src in sources {
            for mode in [MathMode::Inline, MathMode::Display] {
                let b = layout(src, mode);
                assert!(
                    b.width.is_finite() && b.ascent.is_finite() && b.descent.is_finite(),
                    "{src}: {b:?}"
                );
                assert!(
                    b.width >= 0.0 && b.ascent >= 0.0 && b.descent >= 0.0,
                    "{src}"
                );
            }
        }
    }

    #[test]
    fn odd_sizes_do_not_break_layout() {
        let math = parse("\\frac{x}{y}").expect("parses");
        for size in [f32::NAN, -3.0, 0.0, 1e9] {
            let style = MathStyle { size, ..STYLE };
            let b = with_fonts(|fonts| layout_math(fonts, &math, &style, MathMode::Inline));
            assert!(b.height().is_finite() && b.width.is_finite(), "{size}");
        }
    }
}
