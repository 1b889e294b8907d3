//! One instant of a robot's run in the plane, as every run report writes
//! it: time, pose and the speeds it was driven with.

use serde::{Deserialize, Serialize};

/// A sample of a trajectory: `t` (s), the pose (`x`, `y` in m, the heading
/// in degrees) and the driven speeds (`v` in m/s, `omega` in rad/s).
/// Reports put it first in their own samples (`#[serde(flatten)]`) and add
/// what they know beside it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Sample {
    pub t: f64,
    pub x: f64,
    pub y: f64,
    pub theta_deg: f64,
    pub v: f64,
    pub omega: f64,
}

impl Sample {
    /// The sample at `t` of a robot at (`x`, `y`) heading `theta` (rad),
    /// driven at `v` and `omega`.
    pub fn new(t: f64, [x, y, theta]: [f64; 3], v: f64, omega: f64) -> Self {
        Self {
            t,
            x,
            y,
            theta_deg: crate::angle::degrees(theta),
            v,
            omega,
        }
    }

    /// The heading in radians.
    pub fn theta(&self) -> f64 {
        self.theta_deg.to_radians()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sample_writes_degrees_and_reads_back_radians() {
        let s = Sample::new(1.5, [2.0, -1.0, std::f64::consts::FRAC_PI_2], 0.4, -0.2);
        assert_eq!(s.theta_deg, 90.0);
        assert!((s.theta() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        assert_eq!(
            serde_json::to_string(&s).unwrap_or_default(),
            r#"{"t":1.5,"x":2.0,"y":-1.0,"theta_deg":90.0,"v":0.4,"omega":-0.2}"#
        );
    }
}
