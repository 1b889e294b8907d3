//! How a widget opens a drawing: a rounded area in the page's canvas
//! colour (with a ground grid for a 3D view), and a line of text at its
//! top-left corner.

use egui::{Align2, Color32, FontId, Painter, Pos2, Rect, Response, Sense, Vec2, vec2};

use super::scene3d::{Camera, draw_grid};
use crate::theme;

/// Corner radius of a canvas, points.
const CORNER: f32 = 6.0;

/// Allocates `size` sensing `sense` and paints it in the page's canvas
/// colour; the painter is clipped to the area (`response.rect`).
pub fn canvas(ui: &mut egui::Ui, size: Vec2, sense: Sense) -> (Response, Painter) {
    let (response, painter) = ui.allocate_painter(size, sense);
    painter.rect_filled(response.rect, CORNER, ui.visuals().extreme_bg_color);
    (response, painter)
}

/// [`canvas()`] for a 3D view: the background and `camera`'s faint ground
/// grid.
pub fn canvas_3d(
    ui: &mut egui::Ui,
    size: Vec2,
    sense: Sense,
    camera: &Camera,
) -> (Response, Painter) {
    let (response, painter) = canvas(ui, size, sense);
    let faint = ui.visuals().text_color().gamma_multiply(0.08);
    draw_grid(&painter, camera, response.rect, faint);
    (response, painter)
}

/// A line of text at the top-left corner of `rect`, `line` lines down (0
/// for the first): a canvas's title, read-out or verdict.
pub fn corner_text(painter: &Painter, rect: Rect, line: usize, text: String, color: Color32) {
    let at = rect.left_top() + vec2(8.0, 6.0 + 18.0 * line as f32);
    let font = FontId::proportional(theme::TITLE_SIZE);
    text_on_canvas(painter, at, Align2::LEFT_TOP, text, font, color);
}

/// Text on a patch of the canvas's own colour, so the lines, arrows and
/// shading under it cannot make it unreadable; where it went.
pub fn text_on_canvas(
    painter: &Painter,
    at: Pos2,
    align: Align2,
    text: String,
    font: FontId,
    color: Color32,
) -> Rect {
    let galley = painter.layout_no_wrap(text, font, color);
    let rect = align.anchor_size(at, galley.size());
    let backdrop = painter.ctx().global_style().visuals.extreme_bg_color;
    painter.rect_filled(rect.expand(2.0), 3.0, backdrop.gamma_multiply(0.9));
    painter.galley(rect.min, galley, color);
    rect
}
