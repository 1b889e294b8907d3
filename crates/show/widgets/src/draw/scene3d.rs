//! A small 3D view drawn with egui's painter: an orthographic camera that
//! orbits, zooms and pans, or a fixed plan (top) or side view, and helpers
//! to draw frames and capsules through it.

#[cfg(test)]
use egui::vec2;
use egui::{Color32, Pos2, Rect, Response, Stroke, Vec2, pos2};
use kinolab_mechanism::{Pose, Vector3};

use super::nice_step;

/// Which way the scene is looked at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ViewKind {
    /// Orbiting 3D camera.
    Orbit,
    /// From above: x to the right, y up the screen.
    Plan,
    /// From the side: x to the right, z up the screen.
    Side,
}

impl ViewKind {
    pub fn parse(text: &str) -> Option<Self> {
        match text {
            "3d" => Some(Self::Orbit),
            "plan" => Some(Self::Plan),
            "side" => Some(Self::Side),
            _ => None,
        }
    }

    pub fn key(self) -> &'static str {
        match self {
            Self::Orbit => "3d",
            Self::Plan => "plan",
            Self::Side => "side",
        }
    }

    pub fn label(self) -> &'static str {
        match self {
            Self::Orbit => "3D",
            Self::Plan => "top",
            Self::Side => "side",
        }
    }
}

/// Camera state: view kind, orbit angles (rad), pixels per metre at zoom
/// 1, zoom and pan (pixels).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    pub kind: ViewKind,
    pub yaw: f32,
    pub pitch: f32,
    pub zoom: f32,
    pub pan: Vec2,
    /// The point of the world drawn at the centre (before panning).
    pub centre: [f64; 3],
    /// Half the size of the scene, m: sets the scale at zoom 1.
    pub extent: f64,
}

/// What one key press does to a focused view: radians of orbit, points of
/// pan, the zoom factor.
const KEY_TURN: f32 = 0.1;
const KEY_PAN: f32 = 20.0;
const KEY_ZOOM: f32 = 1.25;

impl Camera {
    pub fn new(kind: ViewKind, centre: [f64; 3], extent: f64) -> Self {
        Self {
            kind,
            yaw: -0.6,
            pitch: 0.45,
            zoom: 1.0,
            pan: Vec2::ZERO,
            centre,
            extent: extent.max(0.05),
        }
    }

    /// Screen coordinates of world point `p` in `rect`, and its depth
    /// (larger is nearer the viewer).
    pub fn project(&self, rect: Rect, p: &Vector3<f64>) -> (Pos2, f32) {
        let d = [
            p.x - self.centre[0],
            p.y - self.centre[1],
            p.z - self.centre[2],
        ];
        let (sx, sy, depth) = match self.kind {
            ViewKind::Plan => (d[0], d[1], d[2]),
            ViewKind::Side => (d[0], d[2], -d[1]),
            ViewKind::Orbit => {
                let (sy_, cy_) = (self.yaw as f64).sin_cos();
                let (sp, cp) = (self.pitch as f64).sin_cos();
                // Turn about z by yaw, then tip the view down by pitch.
                let x = cy_ * d[0] - sy_ * d[1];
                let y = sy_ * d[0] + cy_ * d[1];
                let z = d[2];
                (x, cp * z - sp * y, cp * y + sp * z)
            }
        };
        let scale = self.scale(rect);
        let c = rect.center() + self.pan;
        (
            pos2(c.x + sx as f32 * scale, c.y - sy as f32 * scale),
            -depth as f32,
        )
    }

    /// Pixels per metre.
    pub fn scale(&self, rect: Rect) -> f32 {
        0.45 * rect.width().min(rect.height()) / self.extent as f32 * self.zoom
    }

    /// The world shift that moves a point by `delta` pixels on screen, in
    /// the screen plane through the scene.
    pub fn unproject_delta(&self, rect: Rect, delta: Vec2) -> Vector3<f64> {
        let s = self.scale(rect) as f64;
        let (dx, dy) = (delta.x as f64 / s, -delta.y as f64 / s);
        match self.kind {
            ViewKind::Plan => Vector3::new(dx, dy, 0.0),
            ViewKind::Side => Vector3::new(dx, 0.0, dy),
            ViewKind::Orbit => {
                let (sy_, cy_) = (self.yaw as f64).sin_cos();
                let (sp, cp) = (self.pitch as f64).sin_cos();
                // Screen right and screen up, back in the world.
                let right = Vector3::new(cy_, -sy_, 0.0);
                let up = Vector3::new(-sp * sy_, -sp * cy_, cp);
                right * dx + up * dy
            }
        }
    }

    /// Orbit with a primary drag, pan with a secondary drag or with Shift,
    /// zoom with Ctrl + wheel or a pinch. With the view focused (Tab, or a
    /// click), the keyboard does the same: arrows orbit, Shift + arrows
    /// pan, + and − zoom. Returns whether anything changed.
    pub fn handle(&mut self, ui: &egui::Ui, response: &Response, orbit_allowed: bool) -> bool {
        let before = *self;
        if response.clicked() {
            response.request_focus();
        }
        if response.has_focus() {
            self.keyboard(ui, orbit_allowed);
            let focus = ui.visuals().selection.stroke;
            ui.painter()
                .rect_stroke(response.rect, 2.0, focus, egui::StrokeKind::Inside);
        }
        let shift = ui.input(|i| i.modifiers.shift);
        if response.dragged_by(egui::PointerButton::Secondary)
            || (response.dragged_by(egui::PointerButton::Primary)
                && (shift || self.kind != ViewKind::Orbit))
        {
            self.pan += response.drag_delta();
        } else if orbit_allowed && response.dragged_by(egui::PointerButton::Primary) {
            let d = response.drag_delta();
            self.yaw += d.x * 0.01;
            self.pitch = (self.pitch + d.y * 0.01).clamp(-1.5, 1.5);
        }
        if response.hovered() {
            let zoom = ui.input(|i| i.zoom_delta());
            if zoom != 1.0 {
                self.zoom = (self.zoom * zoom).clamp(0.2, 8.0);
            }
        }
        *self != before
    }

    /// The keyboard's orbit, pan and zoom on a focused view.
    fn keyboard(&mut self, ui: &egui::Ui, orbit_allowed: bool) {
        let (arrows, shift, zoom_in, zoom_out) = ui.input(|i| {
            (
                super::handle::arrows(i),
                i.modifiers.shift,
                i.key_pressed(egui::Key::Plus) || i.key_pressed(egui::Key::Equals),
                i.key_pressed(egui::Key::Minus),
            )
        });
        if shift || !orbit_allowed || self.kind != ViewKind::Orbit {
            self.pan += arrows * KEY_PAN;
        } else {
            self.yaw += arrows.x * KEY_TURN;
            self.pitch = (self.pitch + arrows.y * KEY_TURN).clamp(-1.5, 1.5);
        }
        let factor = match (zoom_in, zoom_out) {
            (true, false) => KEY_ZOOM,
            (false, true) => 1.0 / KEY_ZOOM,
            _ => 1.0,
        };
        self.zoom = (self.zoom * factor).clamp(0.2, 8.0);
    }

    /// Zoom buttons and a reset, for those without a wheel or touchpad.
    pub fn buttons(&mut self, ui: &mut egui::Ui) {
        if ui
            .small_button("+")
            .on_hover_text("zoom in (or Ctrl + wheel)")
            .clicked()
        {
            self.zoom = (self.zoom * 1.25).min(8.0);
        }
        if ui.small_button("−").on_hover_text("zoom out").clicked() {
            self.zoom = (self.zoom / 1.25).max(0.2);
        }
        if ui.small_button("reset view").clicked() {
            *self = Camera::new(self.kind, self.centre, self.extent);
        }
    }
}

/// Draw a frame's three axes, `length` metres long; returns them on
/// screen, for labels to keep clear of.
pub fn draw_frame(
    painter: &egui::Painter,
    camera: &Camera,
    rect: Rect,
    pose: &Pose,
    length: f64,
    alpha: f32,
    width: f32,
) -> [[Pos2; 2]; 3] {
    let (o, _) = camera.project(rect, &pose.translation.vector);
    let mut segments = [[o, o]; 3];
    for (k, color) in crate::theme::AXIS_COLORS.iter().enumerate() {
        let mut axis = Vector3::zeros();
        axis[k] = length;
        let (tip, _) = camera.project(rect, &(pose.rotation * axis + pose.translation.vector));
        painter.line_segment([o, tip], Stroke::new(width, color.gamma_multiply(alpha)));
        segments[k] = [o, tip];
    }
    segments
}

/// Draw a capsule (two ends, m; radius, m) as a thick rounded stroke.
pub fn draw_capsule(
    painter: &egui::Painter,
    camera: &Camera,
    rect: Rect,
    a: &Vector3<f64>,
    b: &Vector3<f64>,
    radius: f64,
    fill: Color32,
) {
    let (pa, _) = camera.project(rect, a);
    let (pb, _) = camera.project(rect, b);
    let r = (radius as f32 * camera.scale(rect)).max(1.0);
    painter.line_segment([pa, pb], Stroke::new(2.0 * r, fill));
    painter.circle_filled(pa, r, fill);
    painter.circle_filled(pb, r, fill);
}

/// A faint ground grid in the x–y plane (or the line z = 0 from the side).
pub fn draw_grid(painter: &egui::Painter, camera: &Camera, rect: Rect, color: Color32) {
    let stroke = Stroke::new(1.0, color);
    let step = nice_step(camera.extent / camera.zoom as f64);
    let (c, n) = grid_centre(camera, rect, step);
    let line = |a: Vector3<f64>, b: Vector3<f64>| {
        let (pa, _) = camera.project(rect, &a);
        let (pb, _) = camera.project(rect, &b);
        painter.line_segment([pa, pb], stroke);
    };
    let span = n as f64 * step;
    match camera.kind {
        ViewKind::Side => {
            line(
                Vector3::new(c[0] - span, 0.0, 0.0),
                Vector3::new(c[0] + span, 0.0, 0.0),
            );
        }
        _ => {
            for i in -n..=n {
                let o = i as f64 * step;
                line(
                    Vector3::new(c[0] + o, c[1] - span, 0.0),
                    Vector3::new(c[0] + o, c[1] + span, 0.0),
                );
                line(
                    Vector3::new(c[0] - span, c[1] + o, 0.0),
                    Vector3::new(c[0] + span, c[1] + o, 0.0),
                );
            }
        }
    }
}

/// Where the floor grid is centred (on the world point under the middle
/// of the view, so a panned view still shows grid) and how many lines it
/// draws each way.
fn grid_centre(camera: &Camera, rect: Rect, step: f64) -> ([f64; 2], i32) {
    let scale = f64::from(camera.scale(rect)).max(1e-6);
    let pan = [
        f64::from(camera.pan.x) / scale,
        f64::from(camera.pan.y) / scale,
    ];
    let (x, y, extra) = match camera.kind {
        ViewKind::Plan => (camera.centre[0] - pan[0], camera.centre[1] + pan[1], 0.0),
        ViewKind::Side => (camera.centre[0] - pan[0], camera.centre[1], 0.0),
        // Orbiting, the ground under the middle is harder to find: widen
        // the grid by how far the view was panned.
        ViewKind::Orbit => (
            camera.centre[0],
            camera.centre[1],
            pan[0].hypot(pan[1]) / step,
        ),
    };
    let n = (12.0 + extra.ceil()).min(60.0) as i32;
    ([(x / step).round() * step, (y / step).round() * step], n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_focused_view_turns_pans_and_zooms_from_the_keyboard() {
        let start = Camera::new(ViewKind::Orbit, [0.0, 0.0, 0.0], 1.0);
        let mut h = egui_kittest::Harness::new_ui_state(
            |ui, (camera, focused): &mut (Camera, bool)| {
                let sense = egui::Sense::click_and_drag();
                let (_, response) = ui.allocate_exact_size(vec2(300.0, 200.0), sense);
                if !*focused {
                    response.request_focus();
                    *focused = true;
                }
                camera.handle(ui, &response, true);
            },
            (start, false),
        );
        h.run();
        h.key_press(egui::Key::ArrowRight);
        h.run();
        let turned = h.state().0;
        assert!((turned.yaw - (start.yaw + KEY_TURN)).abs() < 1e-6);
        assert_eq!(turned.pan, start.pan);
        h.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::ArrowDown);
        h.run();
        assert_eq!(h.state().0.pan, start.pan + vec2(0.0, KEY_PAN));
        assert_eq!(h.state().0.yaw, turned.yaw);
        h.key_press(egui::Key::Plus);
        h.run();
        assert!((h.state().0.zoom - start.zoom * KEY_ZOOM).abs() < 1e-6);
    }

    #[test]
    fn a_panned_plan_view_keeps_its_grid_under_the_middle() {
        let rect = Rect::from_min_size(pos2(0.0, 0.0), vec2(600.0, 400.0));
        let mut camera = Camera::new(ViewKind::Plan, [0.0, 0.0, 0.0], 1.0);
        camera.pan = vec2(-900.0, 300.0);
        let step = nice_step(camera.extent);
        let (c, n) = grid_centre(&camera, rect, step);
        // The grid's centre lands within a step of the middle of the view.
        let (at, _) = camera.project(rect, &Vector3::new(c[0], c[1], 0.0));
        let scale = camera.scale(rect);
        assert!(
            (at - rect.center()).length() <= step as f32 * scale,
            "{at:?}"
        );
        assert_eq!(n, 12);
    }

    #[test]
    fn plan_and_side_views_put_axes_where_a_reader_expects() {
        let rect = Rect::from_min_size(pos2(0.0, 0.0), vec2(200.0, 200.0));
        let plan = Camera::new(ViewKind::Plan, [0.0; 3], 1.0);
        let (o, _) = plan.project(rect, &Vector3::zeros());
        let (x, _) = plan.project(rect, &Vector3::x());
        let (y, _) = plan.project(rect, &Vector3::y());
        assert!(x.x > o.x && (x.y - o.y).abs() < 1e-4);
        assert!(y.y < o.y, "y points up the screen");
        let side = Camera::new(ViewKind::Side, [0.0; 3], 1.0);
        let (z, _) = side.project(rect, &Vector3::z());
        assert!(z.y < o.y, "z points up the screen");
        // Dragging by a projected step moves back by the same world step.
        let orbit = Camera::new(ViewKind::Orbit, [0.0; 3], 1.0);
        let p = Vector3::new(0.3, -0.2, 0.5);
        let (a, _) = orbit.project(rect, &p);
        let moved = p + orbit.unproject_delta(rect, vec2(10.0, -4.0));
        let (b, _) = orbit.project(rect, &moved);
        assert!(((b - a) - vec2(10.0, -4.0)).length() < 1e-3, "{:?}", b - a);
    }
}
