//! A field: primitives summed, and the goal they lead to.

use kinolab_world::Shape;

use crate::custom::Custom;
use crate::primitive::{Primitive, Sense, Source};
use crate::{Mat2, Vec2};

/// Points closer than this to a kink or a jump count as on it, m.
pub const SMOOTH_TOLERANCE: f64 = 1e-7;

/// A potential field: the sum of its primitives.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Field {
    pub name: String,
    /// Where the robot should end up, if anywhere.
    pub goal: Option<Vec2>,
    pub primitives: Vec<Primitive>,
    /// Learners' primitives, summed with the others.
    pub custom: Vec<Custom>,
}

impl Field {
    pub fn new(name: impl Into<String>, goal: Option<Vec2>, primitives: Vec<Primitive>) -> Self {
        Self {
            name: name.into(),
            goal,
            primitives,
            custom: Vec::new(),
        }
    }

    /// The vector the robot feels at `p`.
    pub fn vector(&self, p: Vec2) -> Vec2 {
        let built_in: Vec2 = self.primitives.iter().map(|q| q.vector(p)).sum();
        if self.custom.is_empty() {
            return built_in;
        }
        built_in + self.custom.iter().map(|c| c.vector(p)).sum::<Vec2>()
    }

    /// The vector at `p` and its Jacobian.
    pub fn linearise(&self, p: Vec2) -> (Vec2, Mat2) {
        self.primitives
            .iter()
            .map(|q| q.linearise(p))
            .chain(self.custom.iter().map(|c| c.linearise(p)))
            .fold((Vec2::zeros(), Mat2::zeros()), |(f, j), (df, dj)| {
                (f + df, j + dj)
            })
    }

    /// The error that stopped a learner's primitive, if one did (the
    /// field reads it as zero from then on).
    pub fn failed(&self) -> Option<kinolab_script::ScriptError> {
        self.custom.iter().find_map(Custom::failed)
    }

    /// Whether every primitive is differentiable at `p`.
    pub fn smooth_at(&self, p: Vec2) -> bool {
        self.primitives
            .iter()
            .all(|q| q.smooth_at(p, SMOOTH_TOLERANCE))
    }

    /// A size for tolerances: 1 plus the sum of the gains.
    pub fn scale(&self) -> f64 {
        1.0 + self.primitives.iter().map(|q| q.gain).sum::<f64>()
    }

    /// The things a robot must not drive into: each repulsive disc, and
    /// each segment that pushes away.
    pub fn obstacles(&self) -> Vec<Shape> {
        self.primitives
            .iter()
            .filter_map(|q| match q.source {
                Source::Repulsive { centre, radius } => Some(Shape::Disc {
                    centre,
                    radius: radius.max(0.01),
                }),
                Source::Perpendicular {
                    from,
                    to,
                    sense: Sense::Away,
                } => Some(Shape::Wall {
                    from,
                    to,
                    thickness: 0.0,
                }),
                _ => None,
            })
            .collect()
    }

    /// The vector at every point of an `nx` × `ny` grid of cell centres
    /// over `area`.
    pub fn arrows(&self, area: &kinolab_world::Rect, nx: usize, ny: usize) -> Vec<(Vec2, Vec2)> {
        let (nx, ny) = (nx.clamp(1, 512), ny.clamp(1, 512));
        let (dx, dy) = (area.width() / nx as f64, area.height() / ny as f64);
        let mut out = Vec::with_capacity(nx * ny);
        for j in 0..ny {
            for i in 0..nx {
                let p = Vec2::new(
                    area.x_min + (i as f64 + 0.5) * dx,
                    area.y_min + (j as f64 + 0.5) * dy,
                );
                out.push((p, self.vector(p)));
            }
        }
        out
    }
}
