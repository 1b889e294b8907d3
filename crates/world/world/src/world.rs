//! The world: its bounds (a fence the robot cannot leave), obstacles,
//! lights, a start pose and a goal; and what can be asked of it.

use serde::{Deserialize, Serialize};

use crate::obstacle::Obstacle;
use crate::{Pose, Rect, Vec2};

/// A light a robot's light sensors can see.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Light {
    pub x: f64,
    pub y: f64,
    /// Brightness I: a sensor at distance d reads I / (1 + k d²).
    #[serde(default = "kinolab_common::defaults::one")]
    pub intensity: f64,
}

impl Light {
    pub fn at(&self) -> Vec2 {
        Vec2::new(self.x, self.y)
    }
}

/// A world a robot is situated in.
#[derive(Debug, Clone, PartialEq)]
pub struct World {
    pub name: String,
    pub bounds: Rect,
    /// The radius grid planners keep clear (the world file's `robot_radius`).
    pub robot_radius: f64,
    pub obstacles: Vec<Obstacle>,
    pub start: Pose,
    pub goal: Option<Vec2>,
    pub lights: Vec<Light>,
}

impl World {
    /// An empty world inside `bounds`, the robot starting at its centre.
    pub fn empty(name: impl Into<String>, bounds: Rect) -> Self {
        let start = Pose::new(
            (bounds.x_min + bounds.x_max) / 2.0,
            (bounds.y_min + bounds.y_max) / 2.0,
            0.0,
        );
        Self {
            name: name.into(),
            bounds,
            robot_radius: 0.2,
            obstacles: Vec::new(),
            start,
            goal: None,
            lights: Vec::new(),
        }
    }

    /// The distance from `q` to the nearest obstacle at time `t` (0 inside
    /// one); the bounds do not count. Infinite with no obstacle.
    pub fn obstacle_distance(&self, q: Vec2, t: f64) -> f64 {
        let mut best = f64::INFINITY;
        for o in &self.obstacles {
            if o.box_distance(q, t) < best {
                best = best.min(o.distance(q, t));
            }
        }
        best
    }

    /// The nearest thing a robot at `q` could touch at time `t`, obstacles
    /// and the fence alike: its distance and the nearest point.
    pub fn nearest(&self, q: Vec2, t: f64) -> (f64, Vec2) {
        let [fx, fy] = self.bounds.clamp(q.x, q.y);
        let b = &self.bounds;
        let edges = [
            (q.x - b.x_min, Vec2::new(b.x_min, fy)),
            (b.x_max - q.x, Vec2::new(b.x_max, fy)),
            (q.y - b.y_min, Vec2::new(fx, b.y_min)),
            (b.y_max - q.y, Vec2::new(fx, b.y_max)),
        ];
        let (mut best, mut point) =
            edges.into_iter().fold(
                (f64::INFINITY, q),
                |acc, e| if e.0 < acc.0 { e } else { acc },
            );
        best = best.max(0.0);
        for o in &self.obstacles {
            if o.box_distance(q, t) >= best {
                continue;
            }
            if let Some((at, d)) = o.nearest(q, t)
                && d < best
            {
                best = d;
                point = at;
            }
        }
        (best, point)
    }

    /// The nearest point of everything within `within` of `q` at time `t`
    /// (each obstacle and each side of the fence counts once).
    pub fn touching(&self, q: Vec2, within: f64, t: f64) -> Vec<Vec2> {
        let [fx, fy] = self.bounds.clamp(q.x, q.y);
        let b = &self.bounds;
        let mut out: Vec<Vec2> = [
            (q.x - b.x_min, Vec2::new(b.x_min, fy)),
            (b.x_max - q.x, Vec2::new(b.x_max, fy)),
            (q.y - b.y_min, Vec2::new(fx, b.y_min)),
            (b.y_max - q.y, Vec2::new(fx, b.y_max)),
        ]
        .into_iter()
        .filter(|(d, _)| *d <= within)
        .map(|(_, at)| at)
        .collect();
        for o in &self.obstacles {
            if o.box_distance(q, t) <= within
                && let Some((at, d)) = o.nearest(q, t)
                && d <= within
            {
                out.push(at);
            }
        }
        out
    }

    /// How far a ray of light from `origin` along the unit vector `dir`
    /// travels before it meets an obstacle or the fence, up to `max`;
    /// `None` when nothing is within `max`. Glass lets it through.
    pub fn ray(&self, origin: Vec2, dir: Vec2, max: f64, t: f64) -> Option<f64> {
        let mut best = self.fence_ray(origin, dir).filter(|d| *d <= max);
        for o in self.obstacles.iter().filter(|o| !o.glass) {
            let limit = best.unwrap_or(max);
            if let Some(d) = o.ray(origin, dir, limit, t)
                && d <= limit
            {
                best = Some(d);
            }
        }
        best
    }

    /// Where a ray from inside the bounds leaves them.
    fn fence_ray(&self, o: Vec2, d: Vec2) -> Option<f64> {
        let b = &self.bounds;
        let exit = |pos: f64, dir: f64, lo: f64, hi: f64| {
            if dir > 0.0 {
                (hi - pos) / dir
            } else if dir < 0.0 {
                (lo - pos) / dir
            } else {
                f64::INFINITY
            }
        };
        let t = exit(o.x, d.x, b.x_min, b.x_max).min(exit(o.y, d.y, b.y_min, b.y_max));
        (t.is_finite()).then_some(t.max(0.0))
    }

    /// Whether one can see from `a` to `b`: no obstacle but glass between.
    pub fn line_of_sight(&self, a: Vec2, b: Vec2, t: f64) -> bool {
        let span = b - a;
        let length = span.norm();
        if length < 1e-12 {
            return self.obstacle_distance(a, t) > 0.0;
        }
        let dir = span / length;
        self.obstacles
            .iter()
            .all(|o| o.glass || o.ray(a, dir, length, t).is_none())
    }

    /// The obstacles (with where they are) present at time `t`.
    pub fn obstacles_at(&self, t: f64) -> impl Iterator<Item = (usize, crate::Shape)> + '_ {
        self.obstacles
            .iter()
            .enumerate()
            .filter(move |(_, o)| o.present(t))
            .map(move |(i, o)| (i, o.shape_at(t)))
    }

    /// Whether anything in the world moves or appears.
    pub fn is_static(&self) -> bool {
        self.obstacles
            .iter()
            .all(|o| o.is_static() && o.appear_at <= 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Shape;

    fn room() -> World {
        let mut w = World::empty("room", Rect::from([0.0, 0.0, 4.0, 3.0]));
        w.obstacles.push(Obstacle::new(Shape::Disc {
            centre: Vec2::new(3.0, 1.5),
            radius: 0.5,
        }));
        w
    }

    #[test]
    fn rays_stop_at_obstacles_and_at_the_fence() {
        let w = room();
        let o = Vec2::new(1.0, 1.5);
        assert!((w.ray(o, Vec2::new(1.0, 0.0), 10.0, 0.0).unwrap() - 1.5).abs() < 1e-12);
        assert!((w.ray(o, Vec2::new(-1.0, 0.0), 10.0, 0.0).unwrap() - 1.0).abs() < 1e-12);
        assert!((w.ray(o, Vec2::new(0.0, 1.0), 10.0, 0.0).unwrap() - 1.5).abs() < 1e-12);
        assert_eq!(w.ray(o, Vec2::new(0.0, 1.0), 1.0, 0.0), None);
        // Along y = x − 1 the ray passes 0.354 m from the disc's centre, so
        // it clips the disc where (u − 2)² + (u − 1.5)² = 0.25, u = 1.5.
        let d = Vec2::new(1.0, 1.0).normalize();
        let hit = w.ray(Vec2::new(1.0, 0.0), d, 10.0, 0.0).unwrap();
        assert!((hit - 1.5 * 2f64.sqrt()).abs() < 1e-12, "{hit}");
    }

    #[test]
    fn glass_lets_light_and_rays_through_but_not_the_robot() {
        let mut w = World::empty("window", Rect::from([0.0, 0.0, 4.0, 3.0]));
        w.obstacles.push(
            Obstacle::new(Shape::Wall {
                from: Vec2::new(2.0, 0.0),
                to: Vec2::new(2.0, 3.0),
                thickness: 0.1,
            })
            .glazed(),
        );
        let o = Vec2::new(1.0, 1.5);
        // The ray runs on to the fence 3 m away, not to the glass 0.95 m away.
        assert!((w.ray(o, Vec2::new(1.0, 0.0), 10.0, 0.0).unwrap() - 3.0).abs() < 1e-12);
        assert!(w.line_of_sight(o, Vec2::new(3.5, 1.5), 0.0));
        let (d, _) = w.nearest(o, 0.0);
        assert!((d - 0.95).abs() < 1e-12, "{d}");
    }

    #[test]
    fn the_nearest_thing_includes_the_fence() {
        let w = room();
        let (d, at) = w.nearest(Vec2::new(0.3, 1.5), 0.0);
        assert!((d - 0.3).abs() < 1e-12 && at == Vec2::new(0.0, 1.5));
        let (d, at) = w.nearest(Vec2::new(2.2, 1.5), 0.0);
        assert!((d - 0.3).abs() < 1e-12 && (at - Vec2::new(2.5, 1.5)).norm() < 1e-12);
        assert!(w.line_of_sight(Vec2::new(1.0, 0.5), Vec2::new(3.5, 0.5), 0.0));
        assert!(!w.line_of_sight(Vec2::new(1.0, 1.5), Vec2::new(3.9, 1.5), 0.0));
    }
}
