//! Poses in the plane and the change to the goal's frame.

use kinolab_common::angle::wrap;
use serde::{Deserialize, Serialize};

/// A robot pose (x, y, θ): metres and radians, in the world frame unless
/// said otherwise.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Pose {
    pub x: f64,
    pub y: f64,
    pub theta: f64,
}

impl Pose {
    pub const fn new(x: f64, y: f64, theta: f64) -> Self {
        Self { x, y, theta }
    }

    /// This pose seen from `frame`: `frame` becomes the origin with heading 0.
    pub fn relative_to(&self, frame: &Pose) -> Pose {
        let (s, c) = frame.theta.sin_cos();
        let (dx, dy) = (self.x - frame.x, self.y - frame.y);
        Pose::new(c * dx + s * dy, -s * dx + c * dy, self.theta - frame.theta)
    }

    /// The inverse of [`Pose::relative_to`]: a pose given in `frame`, back
    /// in the world.
    pub fn from_frame(&self, frame: &Pose) -> Pose {
        let (s, c) = frame.theta.sin_cos();
        Pose::new(
            frame.x + c * self.x - s * self.y,
            frame.y + s * self.x + c * self.y,
            self.theta + frame.theta,
        )
    }

    /// Distance between the positions, metres.
    pub fn distance(&self, other: &Pose) -> f64 {
        (self.x - other.x).hypot(self.y - other.y)
    }

    /// Heading difference self − other, wrapped to (−π, π].
    pub fn heading_error(&self, other: &Pose) -> f64 {
        wrap(self.theta - other.theta)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_round_trip() {
        let frame = Pose::new(1.0, -2.0, 0.7);
        let p = Pose::new(0.3, 0.4, -1.2);
        let back = p.relative_to(&frame).from_frame(&frame);
        assert!((back.x - p.x).abs() < 1e-12 && (back.y - p.y).abs() < 1e-12);
        assert!((back.theta - p.theta).abs() < 1e-12);
        // A point one metre ahead of a frame facing +y sits at (0, 1) in the world.
        let ahead =
            Pose::new(1.0, 0.0, 0.0).from_frame(&Pose::new(0.0, 0.0, std::f64::consts::FRAC_PI_2));
        assert!(ahead.x.abs() < 1e-12 && (ahead.y - 1.0).abs() < 1e-12);
    }
}
