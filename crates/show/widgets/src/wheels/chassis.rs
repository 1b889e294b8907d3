//! Drawing a chassis from above: wheels of each kind, zero-motion lines and
//! the ICR. Shared by the wheel workbench and the drive widget.

use egui::{Color32, Painter, Pos2, Shape, Stroke, vec2};
use kinolab_common::display::fixed;
use kinolab_wheels::{Icr, Wheel, WheelKind};

use crate::draw::labels::Labels;
use crate::draw::{PlaneView, local, marks, placed};

/// A plane view with the robot placed in it: robot-frame points go through
/// the pose to the world, then to the screen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RobotView {
    pub plane: PlaneView,
    /// The robot's pose in the world (x, y, θ).
    pub pose: [f64; 3],
}

impl RobotView {
    /// The robot frame itself, P at the centre of `rect`, showing
    /// `half_extent` metres to either side.
    pub fn robot_frame(rect: egui::Rect, half_extent: f64) -> Self {
        Self {
            plane: PlaneView::centred(rect, [0.0, 0.0], half_extent),
            pose: [0.0; 3],
        }
    }

    /// A robot-frame point on screen.
    pub fn robot(&self, p: [f64; 2]) -> Pos2 {
        self.plane.to_screen(placed(self.pose, p))
    }

    /// A screen point in the robot frame.
    pub fn robot_point_at(&self, at: Pos2) -> [f64; 2] {
        local(self.pose, self.plane.to_world(at))
    }

    pub fn scale(&self) -> f32 {
        self.plane.scale
    }
}

/// One colour per wheel, cycling, readable on both themes.
pub(crate) fn wheel_color(i: usize) -> Color32 {
    crate::theme::palette(i)
}

fn add(p: [f64; 2], d: [f64; 2], k: f64) -> [f64; 2] {
    [p[0] + k * d[0], p[1] + k * d[1]]
}

/// Where the wheel touches the ground: the centre, or for a castor the point
/// trailing by d along the wheel plane.
pub(crate) fn contact_point(w: &Wheel) -> [f64; 2] {
    match w.kind {
        WheelKind::Castor { offset } => add(w.position(), w.rolling_direction(), offset),
        _ => w.position(),
    }
}

/// Draw one wheel; `emphasis` draws it thicker.
pub(crate) fn draw_wheel(
    painter: &Painter,
    view: &RobotView,
    w: &Wheel,
    color: Color32,
    emphasis: bool,
) {
    let t = w.rolling_direction();
    let n = w.axle();
    let centre = contact_point(w);
    let half_len = w.radius;
    let half_width = (w.radius * 0.35).max(0.015);
    let stroke = Stroke::new(if emphasis { 3.0 } else { 1.5 }, color);
    if let WheelKind::Castor { .. } = w.kind {
        let mount = view.robot(w.position());
        painter.line_segment([mount, view.robot(centre)], Stroke::new(2.0, color));
        painter.circle_filled(mount, 3.5, color);
    }
    if w.kind == WheelKind::Spherical {
        painter.circle(
            view.robot(centre),
            (w.radius as f32 * view.scale()).max(4.0),
            color.gamma_multiply(0.25),
            stroke,
        );
        return;
    }
    let corners: Vec<Pos2> = [(1.0, 1.0), (1.0, -1.0), (-1.0, -1.0), (-1.0, 1.0)]
        .iter()
        .map(|(a, b)| view.robot(add(add(centre, t, a * half_len), n, b * half_width)))
        .collect();
    painter.add(Shape::convex_polygon(
        corners,
        color.gamma_multiply(0.3),
        stroke,
    ));
    // Forward arrow tip, so a learner sees which way φ̇ > 0 rolls.
    let tip = view.robot(add(centre, t, half_len * 1.35));
    let base = view.robot(add(centre, t, half_len));
    painter.line_segment([base, tip], Stroke::new(2.0, color));
    if let WheelKind::Swedish { gamma } = w.kind {
        // Rollers: short strokes at γ to the axle.
        let (s, c) = gamma.sin_cos();
        let roller = [c * n[0] + s * t[0], c * n[1] + s * t[1]];
        for k in [-0.6, 0.0, 0.6] {
            let mid = add(centre, t, k * half_len);
            painter.line_segment(
                [
                    view.robot(add(mid, roller, -half_width)),
                    view.robot(add(mid, roller, half_width)),
                ],
                Stroke::new(1.2, color),
            );
        }
    }
    if w.kind == WheelKind::Steered {
        painter.circle_stroke(view.robot(centre), 3.0, Stroke::new(1.5, color));
    }
}

/// A long thin line through a standard wheel along its axle.
pub(crate) fn draw_zero_motion_line(
    painter: &Painter,
    labels: &mut Labels,
    view: &RobotView,
    w: &Wheel,
    color: Color32,
    reach: f64,
) {
    let (p, n) = w.zero_motion_line();
    let ends = [view.robot(add(p, n, -reach)), view.robot(add(p, n, reach))];
    painter.line_segment(ends, Stroke::new(1.0, color.gamma_multiply(0.6)));
    labels.avoid_line(ends[0], ends[1]);
}

/// Mark the ICR: a ring at a point, a bold line for a line, an arrow for a
/// translation. Points off the drawing get an arrow at the edge.
pub(crate) fn draw_icr(
    painter: &Painter,
    labels: &mut Labels,
    view: &RobotView,
    icr: &Icr,
    color: Color32,
    clip: egui::Rect,
) {
    let stroke = Stroke::new(2.5, color);
    match *icr {
        Icr::Point { x, y } => {
            let at = view.robot([x, y]);
            if clip.shrink(6.0).contains(at) {
                painter.circle_stroke(at, 7.0, stroke);
                marks::plus(painter, at, 10.0, stroke);
                labels.reserve(egui::Rect::from_center_size(at, vec2(20.0, 20.0)));
                labels.add(at, "ICR", color).beyond(6.0);
            } else {
                let from = view.robot([0.0, 0.0]);
                let dir = (at - from).normalized();
                let edge = clamp_ray(clip.shrink(14.0), from, dir);
                painter.arrow(edge - dir * 26.0, dir * 22.0, stroke);
                labels.avoid_line(edge - dir * 26.0, edge - dir * 4.0);
                let text = format!("ICR ({}, {})", fixed(x, 2), fixed(y, 2));
                labels.add(edge - dir * 30.0, text, color).toward(-dir);
            }
        }
        Icr::Line { point, direction } => {
            let ends = [
                view.robot(add(point, direction, -50.0)),
                view.robot(add(point, direction, 50.0)),
            ];
            painter.line_segment(ends, Stroke::new(3.0, color.gamma_multiply(0.7)));
            labels.avoid_line(ends[0], ends[1]);
        }
        Icr::Infinity { direction } => {
            let from = view.robot([0.0, 0.0]);
            let to = view.robot(direction);
            let dir = (to - from).normalized();
            painter.arrow(from, dir * 60.0, stroke);
            painter.arrow(
                from,
                -dir * 60.0,
                Stroke::new(1.5, color.gamma_multiply(0.5)),
            );
        }
        Icr::Anywhere | Icr::None => {}
    }
}

/// The point where a ray from `from` along `dir` leaves `rect`.
fn clamp_ray(rect: egui::Rect, from: Pos2, dir: egui::Vec2) -> Pos2 {
    let mut t = f32::INFINITY;
    if dir.x > 1e-6 {
        t = t.min((rect.right() - from.x) / dir.x);
    } else if dir.x < -1e-6 {
        t = t.min((rect.left() - from.x) / dir.x);
    }
    if dir.y > 1e-6 {
        t = t.min((rect.bottom() - from.y) / dir.y);
    } else if dir.y < -1e-6 {
        t = t.min((rect.top() - from.y) / dir.y);
    }
    if t.is_finite() {
        from + dir * t.max(0.0)
    } else {
        from
    }
}

/// The chassis point P and the robot's x (forward) and y (left) axes.
pub(crate) fn draw_frame(
    painter: &Painter,
    labels: &mut Labels,
    view: &RobotView,
    color: Color32,
    length: f64,
) {
    let p = view.robot([0.0, 0.0]);
    crate::draw::axes(
        painter,
        labels,
        p,
        [
            (view.robot([length, 0.0]), "x"),
            (view.robot([0.0, length]), "y"),
        ],
        color,
    );
    painter.circle_filled(p, 3.0, color);
    labels.add(p, "P", color).toward(vec2(-1.0, 1.0));
}

/// Where the wheels are on screen, for labels to keep clear of.
pub(crate) fn wheel_rects(view: &RobotView, wheels: &[kinolab_wheels::Wheel]) -> Vec<egui::Rect> {
    wheels
        .iter()
        .map(|w| egui::Rect::from_center_size(view.robot(w.position()), vec2(30.0, 30.0)))
        .collect()
}
