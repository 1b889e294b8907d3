//! Legs: how many ways they can lift and land, when a standing walker is
//! statically stable, and how a gait keeps (or loses) that through its cycle.

pub mod cpg_lab;
pub mod gait_studio;
pub mod leg_events;
pub mod support_polygon;
pub mod walker;
pub mod zmp;

use egui::{Color32, Painter, Pos2, Rect, Shape, Stroke, vec2};
use kinolab_locomotion::Stability;

use crate::draw::PlaneView;
use crate::draw::labels::Labels;

/// The values a `Choice` parameter of `widget` allows, from its schema
/// (so a list of gaits is written only there).
fn options(widget: &str, param: &str) -> &'static [&'static str] {
    match kinolab_schema::find(widget)
        .and_then(|w| w.param(param))
        .map(|p| &p.kind)
    {
        Some(kinolab_schema::Kind::Choice { options }) => options,
        _ => &[],
    }
}

/// The range each number of a `Numbers` or `Groups` parameter of
/// `widget` allows, from its schema.
fn numbers_range(widget: &str, param: &str) -> std::ops::RangeInclusive<f64> {
    match kinolab_schema::find(widget)
        .and_then(|w| w.param(param))
        .map(|p| &p.kind)
    {
        Some(
            kinolab_schema::Kind::Numbers { min, max, .. }
            | kinolab_schema::Kind::Groups { min, max, .. },
        ) => *min..=*max,
        _ => crate::widget::range(widget, param),
    }
}

/// The support polygon (filled when it has an area), the shortest line from
/// the centre of mass to its edge, and both kept clear of labels.
fn draw_support(
    painter: &Painter,
    labels: &mut Labels,
    view: &PlaneView,
    s: &Stability,
    com: [f64; 2],
    color: Color32,
) {
    let corners: Vec<Pos2> = s.polygon.iter().map(|&p| view.to_screen(p)).collect();
    for (k, &a) in corners.iter().enumerate() {
        labels.avoid_line(a, corners[(k + 1) % corners.len()]);
    }
    match corners.len() {
        n if n >= 3 => {
            painter.add(Shape::convex_polygon(
                corners,
                color.gamma_multiply(0.18),
                Stroke::new(2.0, color),
            ));
        }
        2 => {
            painter.line_segment([corners[0], corners[1]], Stroke::new(2.0, color));
        }
        _ => {}
    }
    let (from, to) = (view.to_screen(com), view.to_screen(s.nearest));
    painter.line_segment([from, to], Stroke::new(1.5, color));
    labels.avoid_line(from, to);
}

/// A foot seen from above (filled when it stands), its name placed outward
/// from the body when that is free.
fn draw_foot(
    painter: &Painter,
    labels: &mut Labels,
    at: Pos2,
    standing: bool,
    out: egui::Vec2,
    name: &str,
    ink: Color32,
) {
    if standing {
        painter.circle(at, 9.0, ink.gamma_multiply(0.8), Stroke::new(2.0, ink));
    } else {
        painter.circle_stroke(at, 9.0, Stroke::new(2.0, ink.gamma_multiply(0.5)));
        painter.circle_stroke(at, 13.0, Stroke::new(1.0, ink.gamma_multiply(0.3)));
    }
    labels.reserve(Rect::from_center_size(at, vec2(26.0, 26.0)));
    labels.add(at, name, ink).toward(out).beyond(8.0);
}
