//! Closed versus open worlds, measured.
//!
//! A pick-and-place cell receives parts near a nominal spot. In a closed
//! world every part lies exactly there, and a robot that replays one
//! recorded motion (a *scripted* robot) never misses. Open the world up and
//! each part lands somewhere within `placement_error` of the spot: the
//! scripted robot now succeeds only when the part happens to lie within its
//! gripper's tolerance, while a *sensing* robot measures each part (with its
//! own small sensor error) and goes where the part really is.
//!
//! Offsets and sensor errors are uniform over a disc, which gives closed
//! forms for both success rates; [`PickCell::run`] draws seeded random
//! trials that the lab animates and that converge to those closed forms.

use std::f64::consts::TAU;
use std::fmt;

/// The cell's parameters, all in metres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PickCell {
    /// Radius of the disc a part can land in around the nominal spot.
    pub placement_error: f64,
    /// How far off the gripper may be and still grasp the part.
    pub gripper_tolerance: f64,
    /// Radius of the disc the sensing robot's measurement error lies in.
    pub sensor_error: f64,
}

/// One part and what each robot did with it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PickTrial {
    /// Where the part really lies, relative to the nominal spot.
    pub part: [f64; 2],
    /// Where the sensing robot believes it lies.
    pub measured: [f64; 2],
    pub scripted_grasped: bool,
    pub sensing_grasped: bool,
}

/// A parameter that is not a finite, non-negative length.
#[derive(Debug, Clone, PartialEq)]
pub struct CellError {
    pub field: &'static str,
    pub value: f64,
}

impl fmt::Display for CellError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}: must be a finite length ≥ 0 m, got {}",
            self.field, self.value
        )
    }
}

impl std::error::Error for CellError {}

/// Probability that a point uniform in a disc of `radius` lies within
/// `tolerance` of the centre.
fn within_tolerance(radius: f64, tolerance: f64) -> f64 {
    if radius <= tolerance {
        1.0
    } else {
        (tolerance / radius).powi(2)
    }
}

/// A small, fast, seedable generator (SplitMix64): the same seed always
/// gives the same parts, so a lesson's figure is reproducible.
#[derive(Debug, Clone)]
struct SplitMix64(u64);

impl SplitMix64 {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform over a disc of `radius` around the origin.
    fn in_disc(&mut self, radius: f64) -> [f64; 2] {
        let r = radius * self.unit().sqrt();
        let angle = TAU * self.unit();
        [r * angle.cos(), r * angle.sin()]
    }
}

impl PickCell {
    /// A cell, checked: every length finite and non-negative.
    pub fn new(
        placement_error: f64,
        gripper_tolerance: f64,
        sensor_error: f64,
    ) -> Result<Self, CellError> {
        for (field, value) in [
            ("placement_error", placement_error),
            ("gripper_tolerance", gripper_tolerance),
            ("sensor_error", sensor_error),
        ] {
            if !(value.is_finite() && value >= 0.0) {
                return Err(CellError { field, value });
            }
        }
        Ok(Self {
            placement_error,
            gripper_tolerance,
            sensor_error,
        })
    }

    /// Long-run share of parts the scripted robot grasps.
    pub fn scripted_success(&self) -> f64 {
        within_tolerance(self.placement_error, self.gripper_tolerance)
    }

    /// Long-run share of parts the sensing robot grasps: only its sensor
    /// error matters, not where the part lies.
    pub fn sensing_success(&self) -> f64 {
        within_tolerance(self.sensor_error, self.gripper_tolerance)
    }

    /// Draw `count` parts from `seed` and let both robots try each one.
    pub fn run(&self, count: usize, seed: u64) -> Vec<PickTrial> {
        let mut rng = SplitMix64(seed);
        let tolerance = self.gripper_tolerance;
        (0..count)
            .map(|_| {
                let part = rng.in_disc(self.placement_error);
                let noise = rng.in_disc(self.sensor_error);
                let measured = [part[0] + noise[0], part[1] + noise[1]];
                PickTrial {
                    part,
                    measured,
                    scripted_grasped: part[0].hypot(part[1]) <= tolerance,
                    sensing_grasped: noise[0].hypot(noise[1]) <= tolerance,
                }
            })
            .collect()
    }
}
