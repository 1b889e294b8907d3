//! Drawing a chassis from above: wheels of each kind, zero-motion lines and
//! the ICR. Shared by the wheel workbench and the drive widget.

use egui::{Color32, Painter, Pos2, Shape, Stroke, pos2, vec2};
use kinolab_wheels::{Icr, Wheel, WheelKind};

/// Maps metres to screen points: a pose (x, y, θ) of the robot frame in the
/// world, a world point at the screen centre, and a scale.
#[derive(Debug, Clone, Copy)]
pub(crate) struct View {
    pub centre: Pos2,
    pub scale: f32,
    /// The world point drawn at `centre`.
    pub look_at: [f64; 2],
    /// The robot's pose in the world.
    pub pose: [f64; 3],
}

impl View {
    /// A view of the robot frame itself, P at the centre of `rect`, showing
    /// `half_extent` metres either side.
    pub fn robot_frame(rect: egui::Rect, half_extent: f64) -> Self {
        let scale = (rect.width().min(rect.height()) / 2.0) / half_extent as f32;
        Self {
            centre: rect.center(),
            scale,
            look_at: [0.0, 0.0],
            pose: [0.0, 0.0, 0.0],
        }
    }

    /// A world point on screen (y up in the world, down on screen).
    pub fn world(&self, p: [f64; 2]) -> Pos2 {
        pos2(
            self.centre.x + ((p[0] - self.look_at[0]) as f32) * self.scale,
            self.centre.y - ((p[1] - self.look_at[1]) as f32) * self.scale,
        )
    }

    /// A robot-frame point in the world.
    pub fn robot_to_world(&self, p: [f64; 2]) -> [f64; 2] {
        let [x, y, th] = self.pose;
        let (s, c) = th.sin_cos();
        [x + c * p[0] - s * p[1], y + s * p[0] + c * p[1]]
    }

    /// A robot-frame direction in the world.
    pub fn robot_dir(&self, d: [f64; 2]) -> [f64; 2] {
        let (s, c) = self.pose[2].sin_cos();
        [c * d[0] - s * d[1], s * d[0] + c * d[1]]
    }

    /// A robot-frame point on screen.
    pub fn robot(&self, p: [f64; 2]) -> Pos2 {
        self.world(self.robot_to_world(p))
    }

    /// A screen point in the robot frame.
    pub fn robot_point_at(&self, at: Pos2) -> [f64; 2] {
        let wx = self.look_at[0] + f64::from((at.x - self.centre.x) / self.scale);
        let wy = self.look_at[1] - f64::from((at.y - self.centre.y) / self.scale);
        let [x, y, th] = self.pose;
        let (s, c) = th.sin_cos();
        let (dx, dy) = (wx - x, wy - y);
        [c * dx + s * dy, -s * dx + c * dy]
    }
}

/// One colour per wheel, cycling, readable on both themes.
pub(crate) fn wheel_color(i: usize) -> Color32 {
    const PALETTE: [Color32; 6] = [
        Color32::from_rgb(230, 120, 40),
        Color32::from_rgb(60, 150, 220),
        Color32::from_rgb(90, 170, 80),
        Color32::from_rgb(200, 80, 160),
        Color32::from_rgb(170, 140, 40),
        Color32::from_rgb(120, 110, 220),
    ];
    PALETTE[i % PALETTE.len()]
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
    view: &View,
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
            (w.radius as f32 * view.scale).max(4.0),
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
    view: &View,
    w: &Wheel,
    color: Color32,
    reach: f64,
) {
    let (p, n) = w.zero_motion_line();
    painter.line_segment(
        [view.robot(add(p, n, -reach)), view.robot(add(p, n, reach))],
        Stroke::new(1.0, color.gamma_multiply(0.6)),
    );
}

/// Mark the ICR: a ring at a point, a bold line for a line, an arrow for a
/// translation. Points off the drawing get an arrow at the edge.
pub(crate) fn draw_icr(
    painter: &Painter,
    view: &View,
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
                painter.line_segment([at - vec2(10.0, 0.0), at + vec2(10.0, 0.0)], stroke);
                painter.line_segment([at - vec2(0.0, 10.0), at + vec2(0.0, 10.0)], stroke);
                painter.text(
                    at + vec2(10.0, -10.0),
                    egui::Align2::LEFT_BOTTOM,
                    "ICR",
                    egui::FontId::proportional(12.0),
                    color,
                );
            } else {
                let from = view.robot([0.0, 0.0]);
                let dir = (at - from).normalized();
                let edge = clamp_ray(clip.shrink(14.0), from, dir);
                painter.arrow(edge - dir * 26.0, dir * 22.0, stroke);
                painter.text(
                    edge - dir * 30.0 + vec2(0.0, -6.0),
                    egui::Align2::CENTER_BOTTOM,
                    format!("ICR ({x:.2}, {y:.2})"),
                    egui::FontId::proportional(12.0),
                    color,
                );
            }
        }
        Icr::Line { point, direction } => {
            painter.line_segment(
                [
                    view.robot(add(point, direction, -50.0)),
                    view.robot(add(point, direction, 50.0)),
                ],
                Stroke::new(3.0, color.gamma_multiply(0.7)),
            );
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

/// A faint grid every `step` metres of the world, for a sense of scale.
pub(crate) fn draw_grid(
    painter: &Painter,
    view: &View,
    rect: egui::Rect,
    step: f64,
    color: Color32,
) {
    let half_w = f64::from(rect.width() / 2.0 / view.scale);
    let half_h = f64::from(rect.height() / 2.0 / view.scale);
    let stroke = Stroke::new(1.0, color);
    let [cx, cy] = view.look_at;
    let mut x = ((cx - half_w) / step).floor() * step;
    while x <= cx + half_w {
        let a = view.world([x, cy - half_h]);
        let b = view.world([x, cy + half_h]);
        painter.line_segment([a, b], stroke);
        x += step;
    }
    let mut y = ((cy - half_h) / step).floor() * step;
    while y <= cy + half_h {
        let a = view.world([cx - half_w, y]);
        let b = view.world([cx + half_w, y]);
        painter.line_segment([a, b], stroke);
        y += step;
    }
}

/// The chassis point P and the robot's x (forward) and y (left) axes.
pub(crate) fn draw_frame(painter: &Painter, view: &View, color: Color32, length: f64) {
    let p = view.robot([0.0, 0.0]);
    let stroke = Stroke::new(1.5, color);
    painter.arrow(p, view.robot([length, 0.0]) - p, stroke);
    painter.arrow(p, view.robot([0.0, length]) - p, stroke);
    let font = egui::FontId::proportional(12.0);
    painter.text(
        view.robot([length * 1.12, 0.0]),
        egui::Align2::CENTER_CENTER,
        "x",
        font.clone(),
        color,
    );
    painter.text(
        view.robot([0.0, length * 1.12]),
        egui::Align2::CENTER_CENTER,
        "y",
        font.clone(),
        color,
    );
    painter.circle_filled(p, 3.0, color);
    painter.text(
        p + vec2(-6.0, 6.0),
        egui::Align2::RIGHT_TOP,
        "P",
        font,
        color,
    );
}
