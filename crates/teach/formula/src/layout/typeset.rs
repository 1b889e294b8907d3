//! The typesetter: a formula tree to a box of positioned text and strokes,
//! following TeX in spirit.

use std::f32::consts::TAU;

use egui::epaint::text::FontsView;
use egui::{FontId, Rect, Vec2, pos2, vec2};

use crate::tree::{AccentKind, Delimiter, Math, MatrixKind, OpKind, Variant};

use super::fences::*;
use super::*;

/// Lays out one formula with one set of fonts.
pub(super) struct Typesetter<'f, 'v> {
    pub(super) fonts: &'f mut FontsView<'v>,
    pub(super) metrics: Metrics,
    /// Sizes never go below this.
    pub(super) min_size: f32,
}

impl<'f, 'v> Typesetter<'f, 'v> {
    pub(super) fn new(fonts: &'f mut FontsView<'v>, size: f32) -> Self {
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

    pub(super) fn node(&mut self, math: &Math, level: Level, depth: usize) -> MathBox {
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
        // A little room before the sign, so a letter or a bracket before
        // it (s√2) does not touch it.
        let bearing = 0.08 * size;
        let x0 = index
            .as_ref()
            .map_or(bearing, |i| (i.width - 0.55 * sign_width).max(bearing));

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
        let mark = AccentMark::new(kind, body.width, base_y, size, stroke);
        let total_width = body.width.max(mark.width);
        let center_x = total_width / 2.0;
        let body_width = body.width;
        let mut out = MathBox::spacer(total_width);
        out.place(body, vec2((total_width - body_width) / 2.0, 0.0));
        let top = base_y - mark.height - stroke / 2.0;
        for paint in mark.paints {
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
pub(super) fn limits(
    base: MathBox,
    sub: Option<MathBox>,
    sup: Option<MathBox>,
    size: f32,
) -> MathBox {
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
pub(super) struct MatrixGrid {
    pub(super) columns: Vec<f32>,
    /// Ascent and descent of each row, at least a strut's.
    pub(super) rows: Vec<(f32, f32)>,
    pub(super) row_gap: f32,
    pub(super) height: f32,
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
pub(super) enum CellAlign {
    Left,
    Center,
    Right,
}

pub(super) fn cell_alignment(kind: MatrixKind, column: usize) -> CellAlign {
    match kind {
        MatrixKind::Cases => CellAlign::Left,
        MatrixKind::Aligned if column.is_multiple_of(2) => CellAlign::Right,
        MatrixKind::Aligned => CellAlign::Left,
        _ => CellAlign::Center,
    }
}

/// Space after column `column`.
pub(super) fn column_gap(kind: MatrixKind, column: usize, size: f32) -> f32 {
    match kind {
        // `a &= b` reads as one equation: no gap inside a pair.
        MatrixKind::Aligned if column.is_multiple_of(2) => 0.0,
        MatrixKind::Aligned | MatrixKind::Cases => 1.2 * size,
        _ => 0.8 * size,
    }
}

/// The strokes of an accent, centred on x = 0 and sitting on `base_y`.
struct AccentMark {
    paints: Vec<Paint>,
    width: f32,
    height: f32,
}

impl AccentMark {
    fn new(kind: AccentKind, body_width: f32, base_y: f32, size: f32, stroke: f32) -> Self {
        let wide = |fraction: f32| (body_width * fraction).max(0.4 * size);
        let line = |points| Paint::Line {
            points,
            width: stroke,
        };
        match kind {
            AccentKind::Dot => Self::dots(&[0.0], base_y, size),
            AccentKind::Ddot => Self::dots(&[-0.13, 0.13], base_y, size),
            AccentKind::Hat => {
                let width = wide(0.8);
                let height = 0.16 * size + 0.04 * width;
                let points = vec![
                    pos2(-width / 2.0, base_y),
                    pos2(0.0, base_y - height),
                    pos2(width / 2.0, base_y),
                ];
                Self::single(line(points), width, height)
            }
            AccentKind::Bar => {
                let width = (body_width - 0.1 * size).max(0.35 * size);
                let y = base_y - stroke / 2.0;
                let points = vec![pos2(-width / 2.0, y), pos2(width / 2.0, y)];
                Self::single(line(points), width, stroke)
            }
            AccentKind::Vec => {
                let width = wide(0.9);
                let head = 0.13 * size;
                let y = base_y - 0.7 * head;
                let tip = width / 2.0;
                let arrow_head = vec![
                    pos2(tip - head, y - 0.7 * head),
                    pos2(tip, y),
                    pos2(tip - head, y + 0.7 * head),
                ];
                let paints = vec![line(vec![pos2(-tip, y), pos2(tip, y)]), line(arrow_head)];
                Self {
                    paints,
                    width,
                    height: 1.4 * head,
                }
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
                Self::single(line(points), width, 2.0 * amplitude)
            }
        }
    }

    fn single(paint: Paint, width: f32, height: f32) -> Self {
        Self {
            paints: vec![paint],
            width,
            height,
        }
    }

    /// One dot per offset (in ems) from the centre.
    fn dots(offsets: &[f32], base_y: f32, size: f32) -> Self {
        let radius = (0.065 * size).max(0.9);
        let center_y = base_y - radius;
        let paints = offsets
            .iter()
            .map(|dx| Paint::Dot {
                center: pos2(dx * size, center_y),
                radius,
            })
            .collect();
        Self {
            paints,
            width: 0.26 * size + 2.0 * radius,
            height: 2.0 * radius,
        }
    }
}
