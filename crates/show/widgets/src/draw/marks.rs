//! Small marks plane drawings share: dashed circles, crosses, pluses, stars,
//! an arrow whose head keeps a readable size, filled grid cells, and long
//! paths drawn without their sub-pixel steps.

use egui::{Color32, Mesh, Painter, Pos2, Rect, Shape, Stroke, Vec2, vec2};

/// A dashed circle: 5 px dashes with 4 px gaps, both stretched on a large
/// circle so that it has at most [`MOST_DASHES`] (every dash is a shape to
/// draw, and a field's range circles are redrawn on every frame of a drag).
pub fn dashed_circle(painter: &Painter, centre: Pos2, radius: f32, stroke: Stroke) {
    let stretch = (std::f32::consts::TAU * radius / (9.0 * MOST_DASHES)).max(1.0);
    let n = ((radius * 0.6) as usize).clamp(16, 160);
    let points: Vec<Pos2> = (0..=n)
        .map(|i| {
            let a = std::f32::consts::TAU * i as f32 / n as f32;
            centre + vec2(a.cos(), a.sin()) * radius
        })
        .collect();
    painter.extend(Shape::dashed_line(
        &points,
        stroke,
        5.0 * stretch,
        4.0 * stretch,
    ));
}

/// The most dashes [`dashed_circle`] draws.
const MOST_DASHES: f32 = 48.0;

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

/// A path through screen points, leaving out every point that lies within
/// half a pixel of the line through its kept neighbours (Douglas and
/// Peucker's simplification; the ends always stay). A streamline or a
/// trail of thousands of steps is mostly straight at the scale of a pixel,
/// and a descent bunches its last steps within one: the stroke looks the
/// same and costs a fraction to draw.
pub fn path(painter: &Painter, points: impl IntoIterator<Item = Pos2>, stroke: Stroke) {
    let points = thinned(points.into_iter().collect());
    if points.len() > 1 {
        painter.add(Shape::line(points, stroke));
    }
}

/// How far, px, a left-out point may be from the path [`path`] draws.
const TOLERANCE: f32 = 0.5;

/// The most points [`simplified`] takes at once.
const BLOCK: usize = 64;

/// The points [`path`] draws, in order: first every point less than a
/// pixel from the last one kept goes (one pass, however many there are),
/// then the simplification runs on what is left.
fn thinned(points: Vec<Pos2>) -> Vec<Pos2> {
    let mut stepped: Vec<Pos2> = Vec::with_capacity(points.len());
    let mut skipped = None;
    for p in points {
        match stepped.last() {
            Some(last) if last.distance_sq(p) < 1.0 => skipped = Some(p),
            _ => {
                stepped.push(p);
                skipped = None;
            }
        }
    }
    stepped.extend(skipped);
    simplified(stepped)
}

/// Douglas and Peucker's simplification of `points` to [`TOLERANCE`].
fn simplified(points: Vec<Pos2>) -> Vec<Pos2> {
    let n = points.len();
    if n < 3 {
        return points;
    }
    let mut keep = vec![false; n];
    // The path is taken a block at a time (each block's ends kept), so the
    // work stays linear in its length however it winds. Spans still to
    // split: each split keeps one more point, so at most n are pushed.
    let mut spans: Vec<(usize, usize)> = (0..n - 1)
        .step_by(BLOCK)
        .map(|a| (a, (a + BLOCK).min(n - 1)))
        .collect();
    for &(a, b) in &spans {
        keep[a] = true;
        keep[b] = true;
    }
    while let Some((a, b)) = spans.pop() {
        let (far, distance) = (a + 1..b)
            .map(|i| (i, off_chord_sq(points[i], points[a], points[b])))
            .fold((a, 0.0), |best, x| if x.1 > best.1 { x } else { best });
        if distance > TOLERANCE * TOLERANCE {
            keep[far] = true;
            spans.push((a, far));
            spans.push((far, b));
        }
    }
    points
        .into_iter()
        .zip(keep)
        .filter_map(|(p, k)| k.then_some(p))
        .collect()
}

/// How far `p` is from the segment `a`–`b`, squared, px².
fn off_chord_sq(p: Pos2, a: Pos2, b: Pos2) -> f32 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.length_sq().max(f32::MIN_POSITIVE)).clamp(0.0, 1.0);
    p.distance_sq(a + ab * t)
}

/// Filled, square-cornered cells (a map's occupied cells, a search's
/// expanded ones, a field's shading) as one mesh: the tessellator then sees
/// one shape rather than one per cell, which on a slow phone is the
/// difference between a smooth arena and a stuttering one.
pub fn cells(painter: &Painter, cells: impl IntoIterator<Item = (Rect, Color32)>) {
    let mesh = cell_mesh(cells);
    if !mesh.is_empty() {
        painter.add(mesh);
    }
}

/// The mesh [`cells`] draws: two triangles per cell.
fn cell_mesh(cells: impl IntoIterator<Item = (Rect, Color32)>) -> Mesh {
    let mut mesh = Mesh::default();
    for (rect, color) in cells {
        mesh.add_colored_rect(rect, color);
    }
    mesh
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_make_one_mesh_of_two_triangles_each_in_their_colours() {
        let red = Color32::from_rgb(200, 30, 30);
        let grey = Color32::from_gray(90);
        let a = Rect::from_min_max(Pos2::new(0.0, 0.0), Pos2::new(10.0, 10.0));
        let b = Rect::from_min_max(Pos2::new(10.0, 0.0), Pos2::new(20.0, 10.0));
        let mesh = cell_mesh([(a, red), (b, grey)]);
        assert_eq!(mesh.vertices.len(), 8);
        assert_eq!(mesh.indices.len(), 12);
        let corners = |k: usize| &mesh.vertices[4 * k..4 * k + 4];
        assert!(
            corners(0)
                .iter()
                .all(|v| v.color == red && a.contains(v.pos))
        );
        assert!(
            corners(1)
                .iter()
                .all(|v| v.color == grey && b.contains(v.pos))
        );
        // Every triangle of the second cell indexes its own corners.
        assert!(mesh.indices[6..].iter().all(|&i| (4..8).contains(&i)));
        assert!(cell_mesh([]).is_empty());
    }

    #[test]
    fn a_path_keeps_its_ends_and_only_the_points_that_bend_it() {
        // A descent slowing down along x: steps of 10, 5, 2.5, … px.
        let mut x = 0.0;
        let mut step = 10.0;
        let mut descent = vec![Pos2::new(0.0, 0.0)];
        for _ in 0..200 {
            x += step;
            step *= 0.5;
            descent.push(Pos2::new(x, 0.0));
        }
        let kept = thinned(descent.clone());
        assert_eq!(kept, [descent[0], descent[200]]);
        // A circle of radius 100 px in 1 000 steps: a polygon whose sides
        // stray at most half a pixel from the arc, so a few dozen corners.
        let circle: Vec<Pos2> = (0..=1000)
            .map(|i| {
                let a = std::f32::consts::TAU * i as f32 / 1000.0;
                Pos2::new(100.0 * a.cos(), 100.0 * a.sin())
            })
            .collect();
        let kept = thinned(circle.clone());
        assert!((20..=80).contains(&kept.len()), "{} corners", kept.len());
        assert_eq!((kept[0], kept[kept.len() - 1]), (circle[0], circle[1000]));
        // Every point left out is within the tolerance of the kept path.
        for p in &circle {
            let near = kept
                .windows(2)
                .map(|s| off_chord_sq(*p, s[0], s[1]).sqrt())
                .fold(f32::INFINITY, f32::min);
            assert!(near <= TOLERANCE + 1e-3, "{p:?} is {near} px off");
        }
        // A zigzag of one-pixel teeth keeps every corner.
        let zigzag: Vec<Pos2> = (0..40)
            .map(|i| Pos2::new(i as f32 * 3.0, (i % 2) as f32 * 1.5))
            .collect();
        assert_eq!(thinned(zigzag.clone()), zigzag);
        // A long straight trail keeps its ends and each block's.
        let trail: Vec<Pos2> = (0..=1000).map(|i| Pos2::new(i as f32, 5.0)).collect();
        let kept = thinned(trail.clone());
        assert_eq!(kept.len(), 1000 / BLOCK + 2);
        assert!(kept.iter().all(|p| trail.contains(p)));
        // A descent that ends in a crawl along a line keeps only its ends.
        let crawl: Vec<Pos2> = (0..5000)
            .map(|i| Pos2::new(50.0 + i as f32 * 1e-4, 0.0))
            .collect();
        let kept = thinned(
            [Pos2::new(0.0, 0.0)]
                .into_iter()
                .chain(crawl.clone())
                .collect(),
        );
        assert_eq!(kept, [Pos2::new(0.0, 0.0), crawl[4999]]);
        assert!(thinned(Vec::new()).is_empty());
    }
}
