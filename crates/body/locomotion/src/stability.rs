//! Static stability of a standing walker seen from above.
//!
//! The feet on the ground span a *support polygon* (their convex hull). A
//! walker that does not move is statically stable when its centre of mass
//! projects inside that polygon; the *stability margin* is how far the
//! centre of mass is from the nearest edge.

use crate::error::FieldError;

/// A point on the ground plane, metres.
pub type Point = [f64; 2];

/// The verdict for one stance.
#[derive(Debug, Clone, PartialEq)]
pub struct Stability {
    /// Corners of the support polygon, counter-clockwise. One corner for a
    /// single foot, two for feet in a line.
    pub polygon: Vec<Point>,
    /// Whether the centre of mass projects strictly inside the polygon.
    pub stable: bool,
    /// Signed distance from the centre of mass to the polygon's boundary:
    /// positive inside, negative outside, 0 on an edge (and never positive
    /// when the feet enclose no area).
    pub margin: f64,
    /// The point of the boundary nearest the centre of mass.
    pub nearest: Point,
}

fn check_point(field: &'static str, p: Point) -> Result<(), FieldError> {
    if p.iter().all(|c| c.is_finite()) {
        Ok(())
    } else {
        Err(FieldError::new(
            field,
            format!("coordinates must be finite, got {p:?}"),
        ))
    }
}

/// z-component of (a − o) × (b − o): positive when o→a→b turns left.
fn cross(o: Point, a: Point, b: Point) -> f64 {
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
}

/// Convex hull by Andrew's monotone chain, counter-clockwise, without
/// collinear corners. Returns one point for coincident input and the two
/// ends for collinear input.
pub fn convex_hull(points: &[Point]) -> Vec<Point> {
    let mut sorted = kinolab_common::order::sorted_by(points.to_vec(), |p| *p);
    sorted.dedup();
    if sorted.len() < 3 {
        return sorted;
    }
    let mut hull: Vec<Point> = Vec::with_capacity(2 * sorted.len());
    for pass in [
        &sorted[..],
        &sorted.iter().rev().copied().collect::<Vec<_>>()[..],
    ] {
        let start = hull.len();
        for &p in pass {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop(); // the last point starts the other chain
    }
    hull
}

/// The point of segment a–b nearest p.
fn nearest_on_segment(p: Point, a: Point, b: Point) -> Point {
    let d = [b[0] - a[0], b[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    [a[0] + t * d[0], a[1] + t * d[1]]
}

fn distance(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Judge the stance of a walker whose feet on the ground are at `feet` and
/// whose centre of mass projects to `com`.
pub fn static_stability(com: Point, feet: &[Point]) -> Result<Stability, FieldError> {
    check_point("com", com)?;
    if feet.is_empty() {
        return Err(FieldError::new("feet", "no foot is on the ground"));
    }
    for &foot in feet {
        check_point("feet", foot)?;
    }
    let polygon = convex_hull(feet);
    let n = polygon.len();
    // Nearest boundary point over every edge (a lone foot is its own edge).
    let mut nearest = polygon[0];
    let mut best = f64::INFINITY;
    for i in 0..n {
        let q = nearest_on_segment(com, polygon[i], polygon[(i + 1) % n]);
        let d = distance(com, q);
        if d < best {
            best = d;
            nearest = q;
        }
    }
    // Inside a counter-clockwise polygon: left of (or on) every edge.
    let inside = n >= 3 && (0..n).all(|i| cross(polygon[i], polygon[(i + 1) % n], com) >= 0.0);
    let margin = if inside { best } else { -best };
    Ok(Stability {
        stable: inside && best > 0.0,
        polygon,
        margin,
        nearest,
    })
}

/// The longitudinal stability margins: how far the support polygon reaches
/// in front of and behind the centre of mass along the direction of
/// travel (+x), on the line through the CoM. `None` when the CoM is not
/// strictly inside a polygon with area.
pub fn longitudinal_margins(com: Point, feet: &[Point]) -> Option<(f64, f64)> {
    let polygon = convex_hull(feet);
    let n = polygon.len();
    let inside = n >= 3 && (0..n).all(|i| cross(polygon[i], polygon[(i + 1) % n], com) > 0.0);
    if !inside {
        return None;
    }
    // Where the line y = com.y crosses each edge.
    let crossings = (0..n).filter_map(|i| {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        let (lo, hi) = if a[1] <= b[1] { (a, b) } else { (b, a) };
        (lo[1] <= com[1] && com[1] <= hi[1] && hi[1] > lo[1])
            .then(|| lo[0] + (com[1] - lo[1]) / (hi[1] - lo[1]) * (hi[0] - lo[0]))
    });
    let (front, rear) = crossings.fold((f64::NEG_INFINITY, f64::INFINITY), |(f, r), x| {
        (f.max(x), r.min(x))
    });
    (front.is_finite() && rear.is_finite()).then(|| (front - com[0], com[0] - rear))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hull_drops_inner_and_collinear_points() {
        let hull = convex_hull(&[
            [0.0, 0.0],
            [2.0, 0.0],
            [1.0, 0.0],
            [2.0, 2.0],
            [0.0, 2.0],
            [1.0, 1.0],
        ]);
        assert_eq!(hull, vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
        assert_eq!(convex_hull(&[[1.0, 1.0], [1.0, 1.0]]), vec![[1.0, 1.0]]);
        assert_eq!(
            convex_hull(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]),
            vec![[0.0, 0.0], [2.0, 2.0]]
        );
    }

    #[test]
    fn longitudinal_margins_reach_front_and_back() {
        // A rectangle 0.6 long and 0.4 wide; the CoM 0.1 ahead of centre.
        let feet = [[0.3, 0.2], [0.3, -0.2], [-0.3, 0.2], [-0.3, -0.2]];
        let (front, rear) = longitudinal_margins([0.1, 0.05], &feet).unwrap();
        assert!((front - 0.2).abs() < 1e-12 && (rear - 0.4).abs() < 1e-12);
        // A triangle: the hind edge slants, so the rear reach depends on y.
        let tri = [[0.3, 0.0], [-0.3, 0.3], [-0.3, -0.3]];
        let (front, rear) = longitudinal_margins([0.0, 0.1], &tri).unwrap();
        // The upper edge from (0.3, 0) to (−0.3, 0.3) has x = 0.3 − 2y there: 0.1.
        assert!((front - 0.1).abs() < 1e-12 && (rear - 0.3).abs() < 1e-12);
        assert_eq!(longitudinal_margins([1.0, 0.0], &feet), None);
        assert_eq!(longitudinal_margins([0.0, 0.0], &feet[..2]), None);
    }
}
