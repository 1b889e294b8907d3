//! Obstacles: a disc, a polygon (convex or not) or a wall (a segment with a
//! thickness). Each may stand still, move along a scripted path, or appear
//! at a given time. Distances and ray casts are parry2d's.

use parry2d_f64::math::Vector as PVec;
use parry2d_f64::query::{PointQuery, Ray, RayCast};
use parry2d_f64::shape::{Ball, Capsule, Polyline};
use parry2d_f64::utils::point_in_poly2d;

use crate::Vec2;

/// What an obstacle looks like where it starts.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    Disc {
        centre: Vec2,
        radius: f64,
    },
    /// A closed polygon, corners in order (either way round).
    Polygon {
        points: Vec<Vec2>,
    },
    /// A segment swollen by half the thickness on every side.
    Wall {
        from: Vec2,
        to: Vec2,
        thickness: f64,
    },
}

impl Shape {
    /// The point the obstacle's path moves: the disc's centre, the
    /// polygon's first corner, the wall's start.
    pub fn anchor(&self) -> Vec2 {
        match self {
            Shape::Disc { centre, .. } => *centre,
            Shape::Polygon { points } => points.first().copied().unwrap_or_default(),
            Shape::Wall { from, .. } => *from,
        }
    }

    /// The same shape moved by `offset`.
    pub fn moved(&self, offset: Vec2) -> Shape {
        match self {
            Shape::Disc { centre, radius } => Shape::Disc {
                centre: centre + offset,
                radius: *radius,
            },
            Shape::Polygon { points } => Shape::Polygon {
                points: points.iter().map(|p| p + offset).collect(),
            },
            Shape::Wall {
                from,
                to,
                thickness,
            } => Shape::Wall {
                from: from + offset,
                to: to + offset,
                thickness: *thickness,
            },
        }
    }
}

/// How a moving obstacle repeats its path.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Repeat {
    /// Back along the path to the start, and again.
    #[default]
    BackAndForth,
    /// From the last waypoint straight to the start, and again.
    Loop,
    /// Stop at the last waypoint.
    Once,
}

/// A scripted path: the anchor moves from where it starts through the
/// waypoints at a constant speed.
#[derive(Debug, Clone, PartialEq)]
pub struct Script {
    /// The anchor's positions, the start first.
    pub points: Vec<Vec2>,
    pub speed: f64,
    pub repeat: Repeat,
    /// Cumulative length at each point.
    lengths: Vec<f64>,
}

impl Script {
    /// `points` start with the anchor; `speed` > 0 (checked by the file reader).
    pub fn new(points: Vec<Vec2>, speed: f64, repeat: Repeat) -> Self {
        let mut lengths = vec![0.0];
        for w in points.windows(2) {
            let last = lengths.last().copied().unwrap_or(0.0);
            lengths.push(last + (w[1] - w[0]).norm());
        }
        if repeat == Repeat::Loop && points.len() > 1 {
            let last = lengths.last().copied().unwrap_or(0.0);
            lengths.push(last + (points[0] - points[points.len() - 1]).norm());
        }
        Self {
            points,
            speed,
            repeat,
            lengths,
        }
    }

    /// The anchor's position at time `t` after the obstacle started moving.
    pub fn position(&self, t: f64) -> Vec2 {
        let total = self.lengths.last().copied().unwrap_or(0.0);
        let Some(&first) = self.points.first() else {
            return Vec2::zeros();
        };
        if total <= 0.0 {
            return first;
        }
        let s = (t.max(0.0) * self.speed).min(1e12);
        let s = match self.repeat {
            Repeat::Once => s.min(total),
            Repeat::Loop => s % total,
            Repeat::BackAndForth => {
                let s = s % (2.0 * total);
                if s > total { 2.0 * total - s } else { s }
            }
        };
        let k = self
            .lengths
            .partition_point(|&l| l <= s)
            .clamp(1, self.lengths.len() - 1);
        let (a, b) = (self.points[k - 1], self.points[k % self.points.len()]);
        let span = self.lengths[k] - self.lengths[k - 1];
        let u = if span > 0.0 {
            (s - self.lengths[k - 1]) / span
        } else {
            0.0
        };
        a + (b - a) * u.clamp(0.0, 1.0)
    }
}

/// The parry2d shape an obstacle is queried through, in its start place.
#[derive(Debug, Clone)]
enum Collider {
    Ball {
        centre: PVec,
        ball: Ball,
    },
    Capsule(Capsule),
    Polygon {
        boundary: Polyline,
        corners: Vec<PVec>,
    },
}

/// An obstacle: its shape, and when and how it moves.
#[derive(Debug, Clone)]
pub struct Obstacle {
    pub shape: Shape,
    pub script: Option<Script>,
    /// Not there before this time (0: always there).
    pub appear_at: f64,
    /// Glass: light and range sensors see through it; only a bumper finds it.
    pub glass: bool,
    collider: Collider,
    /// The start-place bounding box: [x_min, y_min, x_max, y_max].
    aabb: [f64; 4],
}

impl PartialEq for Obstacle {
    fn eq(&self, other: &Self) -> bool {
        self.shape == other.shape
            && self.script == other.script
            && self.appear_at == other.appear_at
            && self.glass == other.glass
    }
}

fn p(v: Vec2) -> PVec {
    PVec::new(v.x, v.y)
}

fn v(p: PVec) -> Vec2 {
    Vec2::new(p.x, p.y)
}

impl Obstacle {
    /// A standing obstacle. The shape must already be valid (the file reader
    /// checks it): positive radius, at least three corners.
    pub fn new(shape: Shape) -> Self {
        let (collider, aabb) = match &shape {
            Shape::Disc { centre, radius } => (
                Collider::Ball {
                    centre: p(*centre),
                    ball: Ball::new(*radius),
                },
                [
                    centre.x - radius,
                    centre.y - radius,
                    centre.x + radius,
                    centre.y + radius,
                ],
            ),
            Shape::Wall {
                from,
                to,
                thickness,
            } => {
                let r = thickness / 2.0;
                (
                    Collider::Capsule(Capsule::new(p(*from), p(*to), r)),
                    [
                        from.x.min(to.x) - r,
                        from.y.min(to.y) - r,
                        from.x.max(to.x) + r,
                        from.y.max(to.y) + r,
                    ],
                )
            }
            Shape::Polygon { points } => {
                let corners: Vec<PVec> = points.iter().map(|q| p(*q)).collect();
                let n = corners.len() as u32;
                let indices = (0..n).map(|i| [i, (i + 1) % n]).collect();
                let boundary = Polyline::new(corners.clone(), Some(indices));
                let mut aabb = [
                    f64::INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::NEG_INFINITY,
                ];
                for q in points {
                    aabb = [
                        aabb[0].min(q.x),
                        aabb[1].min(q.y),
                        aabb[2].max(q.x),
                        aabb[3].max(q.y),
                    ];
                }
                (Collider::Polygon { boundary, corners }, aabb)
            }
        };
        Self {
            shape,
            script: None,
            appear_at: 0.0,
            glass: false,
            collider,
            aabb,
        }
    }

    /// The same obstacle, moving along `script`.
    pub fn moving(mut self, script: Script) -> Self {
        self.script = Some(script);
        self
    }

    /// The same obstacle made of glass.
    pub fn glazed(mut self) -> Self {
        self.glass = true;
        self
    }

    /// The same obstacle, appearing at `t` seconds.
    pub fn appearing_at(mut self, t: f64) -> Self {
        self.appear_at = t;
        self
    }

    /// Whether it is there at time `t`.
    pub fn present(&self, t: f64) -> bool {
        t >= self.appear_at
    }

    /// How far it has moved from its start place at time `t`.
    pub fn offset(&self, t: f64) -> Vec2 {
        match &self.script {
            Some(s) => s.position(t - self.appear_at) - self.shape.anchor(),
            None => Vec2::zeros(),
        }
    }

    /// The shape where it is at time `t`.
    pub fn shape_at(&self, t: f64) -> Shape {
        self.shape.moved(self.offset(t))
    }

    /// Whether it never moves.
    pub fn is_static(&self) -> bool {
        self.script.is_none()
    }

    /// The nearest point of the obstacle to `q` at time `t` and its distance
    /// (0 inside). `None` when the obstacle is not there yet.
    pub fn nearest(&self, q: Vec2, t: f64) -> Option<(Vec2, f64)> {
        if !self.present(t) {
            return None;
        }
        let offset = self.offset(t);
        let local = p(q - offset);
        let (point, inside) = match &self.collider {
            Collider::Ball { centre, ball } => {
                let proj = ball.project_local_point(local - *centre, true);
                (proj.point + *centre, proj.is_inside)
            }
            Collider::Capsule(c) => {
                let proj = c.project_local_point(local, true);
                (proj.point, proj.is_inside)
            }
            Collider::Polygon { boundary, corners } => {
                let proj = boundary.project_local_point(local, false);
                (proj.point, point_in_poly2d(local, corners))
            }
        };
        let point = v(point) + offset;
        Some((point, if inside { 0.0 } else { (q - point).norm() }))
    }

    /// The distance from `q` to the obstacle at time `t` (0 inside, infinite
    /// while it is not there).
    pub fn distance(&self, q: Vec2, t: f64) -> f64 {
        self.nearest(q, t).map_or(f64::INFINITY, |(_, d)| d)
    }

    /// A quick lower bound on the distance: to the bounding box.
    pub fn box_distance(&self, q: Vec2, t: f64) -> f64 {
        let o = self.offset(t);
        let [x0, y0, x1, y1] = self.aabb;
        let dx = (x0 + o.x - q.x).max(q.x - x1 - o.x).max(0.0);
        let dy = (y0 + o.y - q.y).max(q.y - y1 - o.y).max(0.0);
        dx.hypot(dy)
    }

    /// Where a ray from `origin` along the unit vector `dir` first meets the
    /// obstacle's edge at time `t`, as a distance up to `max`.
    pub fn ray(&self, origin: Vec2, dir: Vec2, max: f64, t: f64) -> Option<f64> {
        if !self.present(t) || self.box_distance(origin, t) > max {
            return None;
        }
        let offset = self.offset(t);
        let ray = Ray::new(p(origin - offset), p(dir));
        match &self.collider {
            Collider::Ball { centre, ball } => {
                let ray = Ray::new(ray.origin - *centre, ray.dir);
                ball.cast_local_ray(&ray, max, true)
            }
            Collider::Capsule(c) => c.cast_local_ray(&ray, max, true),
            Collider::Polygon { boundary, corners } => {
                if point_in_poly2d(ray.origin, corners) {
                    Some(0.0)
                } else {
                    boundary.cast_local_ray(&ray, max, false)
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_to_each_shape() {
        let disc = Obstacle::new(Shape::Disc {
            centre: Vec2::new(1.0, 1.0),
            radius: 0.5,
        });
        assert!((disc.distance(Vec2::new(3.0, 1.0), 0.0) - 1.5).abs() < 1e-12);
        assert_eq!(disc.distance(Vec2::new(1.1, 1.0), 0.0), 0.0);
        let wall = Obstacle::new(Shape::Wall {
            from: Vec2::new(0.0, 0.0),
            to: Vec2::new(0.0, 2.0),
            thickness: 0.2,
        });
        assert!((wall.distance(Vec2::new(1.0, 1.0), 0.0) - 0.9).abs() < 1e-12);
        assert!((wall.distance(Vec2::new(0.0, 3.0), 0.0) - 0.9).abs() < 1e-12);
        // A U (concave): the notch is outside, the arms inside.
        let u = Obstacle::new(Shape::Polygon {
            points: [
                [0.0, 0.0],
                [3.0, 0.0],
                [3.0, 3.0],
                [2.0, 3.0],
                [2.0, 1.0],
                [1.0, 1.0],
                [1.0, 3.0],
                [0.0, 3.0],
            ]
            .iter()
            .map(|q| Vec2::new(q[0], q[1]))
            .collect(),
        });
        assert!((u.distance(Vec2::new(1.5, 2.0), 0.0) - 0.5).abs() < 1e-12);
        assert_eq!(u.distance(Vec2::new(0.5, 2.0), 0.0), 0.0);
        assert!((u.distance(Vec2::new(-1.0, 1.5), 0.0) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn rays_hit_the_near_edge() {
        let disc = Obstacle::new(Shape::Disc {
            centre: Vec2::new(2.0, 0.0),
            radius: 0.5,
        });
        let hit = disc.ray(Vec2::zeros(), Vec2::new(1.0, 0.0), 10.0, 0.0);
        assert!((hit.unwrap() - 1.5).abs() < 1e-12);
        assert_eq!(disc.ray(Vec2::zeros(), Vec2::new(1.0, 0.0), 1.0, 0.0), None);
        assert_eq!(
            disc.ray(Vec2::zeros(), Vec2::new(0.0, 1.0), 10.0, 0.0),
            None
        );
    }

    #[test]
    fn scripts_move_and_appear() {
        let start = Vec2::new(0.0, 0.0);
        let script = Script::new(vec![start, Vec2::new(2.0, 0.0)], 1.0, Repeat::BackAndForth);
        let disc = Obstacle::new(Shape::Disc {
            centre: start,
            radius: 0.1,
        })
        .moving(script)
        .appearing_at(1.0);
        assert!(!disc.present(0.5));
        assert_eq!(disc.distance(Vec2::new(5.0, 0.0), 0.5), f64::INFINITY);
        assert!((disc.offset(2.5).x - 1.5).abs() < 1e-12);
        assert!((disc.offset(4.0).x - 1.0).abs() < 1e-12, "on its way back");
        let looped = Script::new(
            vec![start, Vec2::new(1.0, 0.0), Vec2::new(1.0, 1.0)],
            1.0,
            Repeat::Loop,
        );
        let total = 2.0 + 2f64.sqrt();
        assert!((looped.position(total) - start).norm() < 1e-12);
        assert!((looped.position(total + 0.5) - Vec2::new(0.5, 0.0)).norm() < 1e-12);
        let once = Script::new(vec![start, Vec2::new(1.0, 0.0)], 2.0, Repeat::Once);
        assert_eq!(once.position(100.0), Vec2::new(1.0, 0.0));
    }
}
