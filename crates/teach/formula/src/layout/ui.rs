//! Formulas in a `Ui`: inline with text, or displayed on their own line.

use egui::epaint::text::FontsView;
use egui::{FontId, Response, Sense, Ui, Vec2, pos2, vec2};

use crate::tree::Math;

use super::*;

/// Shows `math` inline, among text of `style.size`.
///
/// The widget is at least one text row tall and is centred on the same line
/// as the text around it, so in `ui.horizontal_wrapped` its baseline lines
/// up with that of neighbouring labels. Tall formulas grow symmetrically;
/// egui does not move widgets already placed in the row, so labels before a
/// tall formula only stay aligned if the row is made tall enough up front
/// with `ui.set_row_height` (see [`InlineMath::size`]).
pub fn math_widget(ui: &mut Ui, math: &Math, style: &MathStyle) -> Response {
    InlineMath::new(ui, math, style).show(ui, style.color)
}

/// An inline formula laid out once: measure it (to decide where a row of
/// text wraps), then show it, without laying it out twice.
#[derive(Debug, Clone)]
pub struct InlineMath<'a> {
    math: &'a Math,
    layout: MathBox,
    placement: InlinePlacement,
}

impl<'a> InlineMath<'a> {
    pub fn new(ui: &Ui, math: &'a Math, style: &MathStyle) -> Self {
        let (layout, placement) = layout_inline(ui, math, style);
        Self {
            math,
            layout,
            placement,
        }
    }

    /// The size [`InlineMath::show`] will allocate.
    pub fn size(&self) -> Vec2 {
        self.placement.size
    }

    /// Allocates the formula's box in `ui` and paints it in `color`.
    pub fn show(&self, ui: &mut Ui, color: egui::Color32) -> Response {
        let (rect, response) = ui.allocate_exact_size(self.placement.size, Sense::hover());
        if ui.is_rect_visible(rect) {
            let origin = rect.left_top() + vec2(0.0, self.placement.baseline);
            self.layout.paint(ui.painter(), origin, color);
        }
        speak(&response, self.math);
        response
    }
}

/// A formula's words for a screen reader (built only when one listens).
fn speak(response: &Response, math: &Math) {
    response.widget_info(|| {
        egui::WidgetInfo::labeled(egui::accesskit::Role::Label, true, crate::spoken(math))
    });
}

pub(super) fn layout_inline(ui: &Ui, math: &Math, style: &MathStyle) -> (MathBox, InlinePlacement) {
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
pub(super) const DISPLAY_SCALE: f32 = 1.2;

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
    speak(&response, math);
    response
}

/// Where a label's text sits in its row: the baseline's distance from the
/// top, and the row height.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct TextLine {
    pub(super) ascent: f32,
    pub(super) row_height: f32,
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
pub(super) struct InlinePlacement {
    pub(super) size: Vec2,
    pub(super) baseline: f32,
}

/// Centres the formula on the middle of a text row, like a label would be,
/// and keeps its baseline where the label's baseline is.
pub(super) fn inline_placement(layout: &MathBox, line: TextLine) -> InlinePlacement {
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
