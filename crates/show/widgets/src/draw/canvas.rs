//! How a widget opens a drawing: a rounded area in the page's canvas
//! colour (with a ground grid for a 3D view), and a line of text at its
//! top-left corner.

use egui::{Color32, FontId, Painter, Rect, Response, Sense, Vec2, vec2};

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
    let galley = painter.layout_no_wrap(text, FontId::proportional(theme::TITLE_SIZE), color);
    // On the canvas's own colour, so arrows and shading under the text
    // cannot make it unreadable.
    let backdrop = painter.ctx().global_style().visuals.extreme_bg_color;
    painter.rect_filled(
        Rect::from_min_size(at, galley.size()).expand(2.0),
        3.0,
        backdrop.gamma_multiply(0.9),
    );
    painter.galley(at, galley, color);
}
