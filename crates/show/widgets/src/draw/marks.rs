//! Small marks plane drawings share: dashed circles, crosses, pluses, stars,
//! and an arrow whose head keeps a readable size.

use egui::{Color32, Painter, Pos2, Shape, Stroke, Vec2, vec2};

/// A dashed circle.
pub fn dashed_circle(painter: &Painter, centre: Pos2, radius: f32, stroke: Stroke) {
    let n = ((radius * 0.6) as usize).clamp(16, 160);
    let points: Vec<Pos2> = (0..=n)
        .map(|i| {
            let a = std::f32::consts::TAU * i as f32 / n as f32;
            centre + vec2(a.cos(), a.sin()) * radius
        })
        .collect();
    painter.extend(Shape::dashed_line(&points, stroke, 5.0, 4.0));
}

/// An × of half-size `size`.
pub fn cross(painter: &Painter, at: Pos2, size: f32, stroke: Stroke) {
    painter.line_segment([at + vec2(-size, -size), at + vec2(size, size)], stroke);
    painter.line_segment([at + vec2(-size, size), at + vec2(size, -size)], stroke);
}

/// A + of half-size `size`.
pub fn plus(painter: &Painter, at: Pos2, size: f32, stroke: Stroke) {
    painter.line_segment([at - vec2(size, 0.0), at + vec2(size, 0.0)], stroke);
    painter.line_segment([at - vec2(0.0, size), at + vec2(0.0, size)], stroke);
}

/// A five-pointed star (a goal).
pub fn star(painter: &Painter, at: Pos2, size: f32, fill: Color32, stroke: Stroke) {
    let points: Vec<Pos2> = (0..10)
        .map(|i| {
            let r = if i % 2 == 0 { size } else { size * 0.45 };
            let a = -std::f32::consts::FRAC_PI_2 + std::f32::consts::PI * i as f32 / 5.0;
            at + vec2(a.cos(), a.sin()) * r
        })
        .collect();
    // A star is not convex: draw it as five triangles round the centre.
    for k in 0..5 {
        let tri = vec![
            at,
            points[2 * k],
            points[(2 * k + 1) % 10],
            points[(2 * k + 2) % 10],
        ];
        painter.add(Shape::convex_polygon(tri, fill, Stroke::NONE));
    }
    let mut outline = points;
    outline.push(outline[0]);
    painter.add(Shape::line(outline, stroke));
}

/// An arrow from `from` along `along`, its head at most `head` points long.
pub fn arrow(painter: &Painter, from: Pos2, along: Vec2, head: f32, stroke: Stroke) {
    let length = along.length();
    if length < 0.5 {
        return;
    }
    let tip = from + along;
    let dir = along / length;
    let h = head.min(length * 0.45);
    let normal = vec2(-dir.y, dir.x);
    painter.line_segment([from, tip], stroke);
    painter.add(Shape::convex_polygon(
        vec![
            tip,
            tip - dir * h + normal * h * 0.5,
            tip - dir * h - normal * h * 0.5,
        ],
        stroke.color,
        Stroke::NONE,
    ));
}
