//! The floor of the controller playground: grid, start and goal poses that
//! can be dragged and turned, paths, and the robot drawn along a path.

use egui::{Color32, Painter, Pos2, Rect, Stroke, vec2};
use kinolab_control::{Pose, Sample};

use crate::draw::labels::Labels;
use crate::draw::{PlaneView, grid};

/// Length of a pose's heading arrow, m.
pub(super) const ARROW: f64 = 0.3;
/// Radius of the drawn robot body, m.
const BODY: f64 = 0.1;

/// The world bounds to show start, goal and some room around them.
pub(super) fn bounds(points: &[Pose], margin: f64) -> ([f64; 2], [f64; 2]) {
    let mut min = [f64::INFINITY; 2];
    let mut max = [f64::NEG_INFINITY; 2];
    for p in points {
        min = [min[0].min(p.x), min[1].min(p.y)];
        max = [max[0].max(p.x), max[1].max(p.y)];
    }
    (
        [min[0] - margin, min[1] - margin],
        [max[0] + margin, max[1] + margin],
    )
}

/// Where a pose's heading handle is.
pub(super) fn heading_tip(p: &Pose) -> [f64; 2] {
    [p.x + ARROW * p.theta.cos(), p.y + ARROW * p.theta.sin()]
}

pub(super) fn floor(painter: &Painter, view: &PlaneView, rect: Rect, ink: Color32) {
    grid(painter, view, rect, 0.25, ink.gamma_multiply(0.08));
    grid(painter, view, rect, 1.0, ink.gamma_multiply(0.16));
}

/// A pose as a dot with a heading arrow and a round handle to turn it.
pub(super) fn pose(
    painter: &Painter,
    labels: &mut Labels,
    view: &PlaneView,
    p: &Pose,
    color: Color32,
    label: &str,
    handles: bool,
) {
    let at = view.to_screen([p.x, p.y]);
    let tip = view.to_screen(heading_tip(p));
    painter.arrow(at, tip - at, Stroke::new(2.5, color));
    painter.circle_filled(at, 5.0, color);
    if handles {
        painter.circle_stroke(tip, 6.0, Stroke::new(1.5, color));
    }
    labels.avoid_line(at, tip);
    labels.reserve(egui::Rect::from_center_size(at, vec2(10.0, 10.0)));
    if !label.is_empty() {
        labels.add(at, label, color).toward(at - tip);
    }
}

/// A path through the samples' positions.
pub(super) fn path(painter: &Painter, view: &PlaneView, samples: &[Sample], stroke: Stroke) {
    let points: Vec<Pos2> = samples
        .iter()
        .map(|s| view.to_screen([s.pose.x, s.pose.y]))
        .filter(|p| p.x.is_finite() && p.y.is_finite())
        .collect();
    if points.len() > 1 {
        painter.add(egui::Shape::line(points, stroke));
    }
}

/// A differential-drive robot from above: body, nose, two wheels.
/// The screen area [`robot`] covers, for labels to keep clear of.
pub(super) fn robot_area(view: &PlaneView, p: &Pose) -> Rect {
    let reach = view.length(BODY * 1.3).max(8.0) + 3.0;
    Rect::from_center_size(view.to_screen([p.x, p.y]), vec2(2.0 * reach, 2.0 * reach))
}

pub(super) fn robot(painter: &Painter, view: &PlaneView, p: &Pose, color: Color32) {
    let (s, c) = p.theta.sin_cos();
    let local = |x: f64, y: f64| view.to_screen([p.x + c * x - s * y, p.y + s * x + c * y]);
    let centre = local(0.0, 0.0);
    painter.circle(
        centre,
        view.length(BODY).max(6.0),
        color.gamma_multiply(0.25),
        Stroke::new(2.0, color),
    );
    painter.line_segment([centre, local(BODY * 1.3, 0.0)], Stroke::new(2.5, color));
    for side in [-1.0, 1.0] {
        painter.line_segment(
            [local(-0.04, side * BODY), local(0.04, side * BODY)],
            Stroke::new(4.0, color),
        );
    }
}

/// The sample at time `t` (the last one not after it).
pub(super) fn at_time(samples: &[Sample], t: f64) -> Option<&Sample> {
    let i = samples.partition_point(|s| s.t <= t);
    samples.get(i.saturating_sub(1))
}
