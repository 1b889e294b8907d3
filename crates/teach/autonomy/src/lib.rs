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

use kinolab_common::error::non_negative;
use kinolab_common::{FieldError, SplitMix64};

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

/// Probability that a point uniform in a disc of `radius` lies within
/// `tolerance` of the centre.
fn within_tolerance(radius: f64, tolerance: f64) -> f64 {
    if radius <= tolerance {
        1.0
    } else {
        (tolerance / radius).powi(2)
    }
}

impl PickCell {
    /// A cell, checked: every length finite and non-negative.
    pub fn new(
        placement_error: f64,
        gripper_tolerance: f64,
        sensor_error: f64,
    ) -> Result<Self, FieldError> {
        for (field, value) in [
            ("placement_error", placement_error),
            ("gripper_tolerance", gripper_tolerance),
            ("sensor_error", sensor_error),
        ] {
            non_negative(field, value)?;
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
        let mut rng = SplitMix64::new(seed);
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

/// What the cell did with a batch of parts: the long-run rates and the
/// seeded counts, as the JS API returns them.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct PickReport {
    pub scripted_success: f64,
    pub sensing_success: f64,
    pub scripted_grasped: usize,
    pub sensing_grasped: usize,
    pub parts: Vec<[f64; 2]>,
}

impl PickCell {
    /// [`PickCell::run`] summed up.
    pub fn report(&self, count: usize, seed: u64) -> PickReport {
        let trials = self.run(count, seed);
        PickReport {
            scripted_success: self.scripted_success(),
            sensing_success: self.sensing_success(),
            scripted_grasped: trials.iter().filter(|t| t.scripted_grasped).count(),
            sensing_grasped: trials.iter().filter(|t| t.sensing_grasped).count(),
            parts: trials.iter().map(|t| t.part).collect(),
        }
    }
}
