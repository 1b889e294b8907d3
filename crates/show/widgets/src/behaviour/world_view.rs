//! Drawing a world and the robots in it, shared by the behaviour widgets.

use egui::{Color32, Painter, Pos2, Shape, Stroke, vec2};
use kinolab_behaviours::{Behaviour, Named};
use kinolab_world::{Pose, Shape as Obstacle, World};

use crate::draw::PlaneView;
use crate::draw::marks::star;
use crate::theme;

/// Each behaviour's colour, the same for a kind of behaviour in every
/// lesson (avoiding is always the first of the palette, heading for the
/// goal the second, …); a second behaviour of a kind already coloured
/// takes the next colour no other behaviour of the robot has.
pub fn colors(behaviours: &[Named]) -> Vec<Color32> {
    let mut used = Vec::new();
    for b in behaviours {
        let preferred = match b.behaviour {
            Behaviour::Avoid { .. } => 0,
            Behaviour::GoToGoal { .. } | Behaviour::Dock { .. } => 1,
            Behaviour::Wander { .. } => 2,
            Behaviour::FollowWall { .. } | Behaviour::Corridor { .. } => 3,
            Behaviour::SeekLight { .. } | Behaviour::Braitenberg(_) => 4,
            _ => 5,
        };
        let free = (0..theme::PALETTE_LEN)
            .map(|k| (preferred + k) % theme::PALETTE_LEN)
            .find(|k| !used.contains(k));
        used.push(free.unwrap_or(used.len() % theme::PALETTE_LEN));
    }
    used.into_iter().map(theme::palette).collect()
}

/// The fence, the obstacles where they are at time `t`, lights and goal.
pub fn draw_world(ui: &egui::Ui, painter: &Painter, view: &PlaneView, world: &World, t: f64) {
    let ink = ui.visuals().text_color();
    let solid = theme::solid_color(ui);
    let b = &world.bounds;
    let fence = egui::Rect::from_two_pos(
        view.to_screen([b.x_min, b.y_min]),
        view.to_screen([b.x_max, b.y_max]),
    );
    painter.rect_filled(fence, 4.0, ui.visuals().extreme_bg_color);
    painter.rect_stroke(
        fence,
        4.0,
        Stroke::new(2.0, solid),
        egui::StrokeKind::Middle,
    );
    let glass = theme::GLASS.gamma_multiply(0.7);
    for (i, shape) in world.obstacles_at(t) {
        let see_through = world.obstacles.get(i).is_some_and(|o| o.glass);
        draw_obstacle(
            painter,
            view,
            &shape,
            if see_through { glass } else { solid },
        );
    }
    for light in &world.lights {
        let at = view.to_screen([light.x, light.y]);
        let glow = theme::YELLOW;
        painter.circle_filled(at, 14.0, glow.gamma_multiply(0.25));
        painter.circle_filled(at, 6.0, glow);
        for k in 0..8 {
            let a = k as f32 * std::f32::consts::FRAC_PI_4;
            let d = vec2(a.cos(), a.sin());
            painter.line_segment([at + d * 9.0, at + d * 13.0], Stroke::new(1.5, glow));
        }
    }
    if let Some(g) = world.goal {
        star(
            painter,
            view.to_screen([g.x, g.y]),
            10.0,
            theme::good_color(ui),
            Stroke::new(1.0, ink),
        );
    }
}

fn draw_obstacle(painter: &Painter, view: &PlaneView, shape: &Obstacle, color: Color32) {
    match shape {
        Obstacle::Disc { centre, radius } => {
            painter.circle_filled(
                view.to_screen([centre.x, centre.y]),
                view.length(*radius),
                color,
            );
        }
        Obstacle::Wall {
            from,
            to,
            thickness,
        } => {
            let width = view.length(*thickness).max(2.5);
            let (a, b) = (
                view.to_screen([from.x, from.y]),
                view.to_screen([to.x, to.y]),
            );
            painter.line_segment([a, b], Stroke::new(width, color));
            painter.circle_filled(a, width / 2.0, color);
            painter.circle_filled(b, width / 2.0, color);
        }
        Obstacle::Polygon { points } => {
            let pts: Vec<Pos2> = points.iter().map(|p| view.to_screen([p.x, p.y])).collect();
            if convex(&pts) {
                painter.add(Shape::convex_polygon(pts, color, Stroke::NONE));
            } else {
                let mut closed = pts.clone();
                closed.push(pts[0]);
                painter.add(Shape::line(closed, Stroke::new(3.0, color)));
            }
        }
    }
}

/// Whether a polygon turns the same way at every corner.
fn convex(pts: &[Pos2]) -> bool {
    let n = pts.len();
    let turns: Vec<f32> = (0..n)
        .map(|i| {
            let (a, b, c) = (pts[i], pts[(i + 1) % n], pts[(i + 2) % n]);
            (b - a).x * (c - b).y - (b - a).y * (c - b).x
        })
        .collect();
    turns.iter().all(|t| *t >= 0.0) || turns.iter().all(|t| *t <= 0.0)
}

/// A round robot with a nose line showing its heading.
pub fn draw_robot(
    painter: &Painter,
    view: &PlaneView,
    pose: &Pose,
    radius: f64,
    color: Color32,
    ink: Color32,
) {
    let at = view.to_screen([pose.x, pose.y]);
    let r = view.length(radius).max(4.0);
    painter.circle(at, r, color.gamma_multiply(0.55), Stroke::new(1.5, ink));
    let nose = at + vec2(pose.theta.cos() as f32, -pose.theta.sin() as f32) * r;
    painter.line_segment([at, nose], Stroke::new(2.0, ink));
}

/// A trail of positions.
pub fn draw_trail(
    painter: &Painter,
    view: &PlaneView,
    points: impl Iterator<Item = [f64; 2]>,
    color: Color32,
) {
    let pts = points.map(|p| view.to_screen(p));
    crate::draw::marks::path(painter, pts, Stroke::new(1.5, color));
}

#[cfg(test)]
mod tests {
    use super::*;

    fn named(name: &str, kind: serde_json::Value) -> Named {
        let mut v = kind;
        v["name"] = name.into();
        serde_json::from_value(v).unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn a_kind_of_behaviour_keeps_its_colour_wherever_it_is_listed() {
        let avoid = || {
            named(
                "avoid",
                serde_json::json!({ "kind": "avoid", "range": 0.5, "gain": 1.0 }),
            )
        };
        let goal = || {
            named(
                "goal",
                serde_json::json!({ "kind": "go_to_goal", "gain": 1.0 }),
            )
        };
        let first = colors(&[avoid(), goal()]);
        let second = colors(&[goal(), avoid()]);
        assert_eq!(first[0], second[1], "avoid");
        assert_eq!(first[1], second[0], "go to goal");
        // Two wall followers in one robot: two colours.
        let wall = |side: &str| {
            named(
                side,
                serde_json::json!({ "kind": "follow_wall", "side": side, "distance": 0.4, "gain": 1.0 }),
            )
        };
        let both = colors(&[wall("left"), wall("right"), avoid()]);
        assert_ne!(both[0], both[1]);
        assert_eq!(both[2], first[0]);
    }
}
