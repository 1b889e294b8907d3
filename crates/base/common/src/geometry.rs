//! Places in the plane: a pose (x, y, θ) and an axis-aligned rectangle.

use serde::{Deserialize, Serialize};

use crate::angle::wrap;
use crate::error::{FieldError, finite_at};

/// A pose (x, y, θ): metres and radians, in the world frame unless said
/// otherwise.
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
        let (s, c) = crate::trig::sin_cos(frame.theta);
        let (dx, dy) = (self.x - frame.x, self.y - frame.y);
        Pose::new(c * dx + s * dy, -s * dx + c * dy, self.theta - frame.theta)
    }

    /// The inverse of [`Pose::relative_to`]: a pose given in `frame`, back
    /// in the world.
    pub fn from_frame(&self, frame: &Pose) -> Pose {
        let (s, c) = crate::trig::sin_cos(frame.theta);
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

/// An axis-aligned rectangle, written `[x_min, y_min, x_max, y_max]` in files.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(from = "[f64; 4]", into = "[f64; 4]")]
pub struct Rect {
    pub x_min: f64,
    pub y_min: f64,
    pub x_max: f64,
    pub y_max: f64,
}

impl From<[f64; 4]> for Rect {
    fn from([x_min, y_min, x_max, y_max]: [f64; 4]) -> Self {
        Self {
            x_min,
            y_min,
            x_max,
            y_max,
        }
    }
}

impl From<Rect> for [f64; 4] {
    fn from(r: Rect) -> Self {
        [r.x_min, r.y_min, r.x_max, r.y_max]
    }
}

impl Rect {
    /// A rectangle with finite corners, the minimum below the maximum;
    /// errors name `field`.
    pub fn new(field: &str, corners: [f64; 4]) -> Result<Self, FieldError> {
        for (i, v) in corners.iter().enumerate() {
            finite_at(*v, || format!("{field}[{i}]"))?;
        }
        let r = Rect::from(corners);
        if r.x_min < r.x_max && r.y_min < r.y_max {
            Ok(r)
        } else {
            Err(FieldError::new(
                field,
                format!("needs x_min < x_max and y_min < y_max, got {corners:?}"),
            ))
        }
    }

    /// This rectangle checked as [`Rect::new`] checks a new one.
    pub fn checked(self, field: &str) -> Result<Self, FieldError> {
        Rect::new(field, self.into())
    }

    pub fn width(&self) -> f64 {
        self.x_max - self.x_min
    }

    pub fn height(&self) -> f64 {
        self.y_max - self.y_min
    }

    /// Whether (x, y) lies inside or on the edge.
    pub fn contains(&self, x: f64, y: f64) -> bool {
        (self.x_min..=self.x_max).contains(&x) && (self.y_min..=self.y_max).contains(&y)
    }

    /// The point of the rectangle nearest to (x, y).
    pub fn clamp(&self, x: f64, y: f64) -> [f64; 2] {
        [
            x.clamp(self.x_min, self.x_max),
            y.clamp(self.y_min, self.y_max),
        ]
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

    #[test]
    fn rectangles_are_checked_and_round_trip() {
        let r = Rect::new("bounds", [0.0, 0.0, 10.0, 6.0]).unwrap();
        assert_eq!((r.width(), r.height()), (10.0, 6.0));
        assert!(r.contains(10.0, 0.0) && !r.contains(10.1, 1.0));
        assert_eq!(r.clamp(-1.0, 7.0), [0.0, 6.0]);
        let json = serde_json::to_string(&r).unwrap();
        assert_eq!(json, "[0.0,0.0,10.0,6.0]");
        assert_eq!(serde_json::from_str::<Rect>(&json).unwrap(), r);
        let e = Rect::new("bounds", [0.0, 0.0, 0.0, 1.0]).unwrap_err();
        assert_eq!(e.field, "bounds");
        let e = Rect::new("box", [0.0, f64::NAN, 1.0, 1.0]).unwrap_err();
        assert_eq!(e.field, "box[1]");
    }
}
