//! What a robot can sense, and the percepts one reading gives.
//!
//! Every reading's noise is drawn from the run's seed, the step number and
//! the channel (which ray, which sensor), so the same run always reads the
//! same numbers.

use kinolab_common::angle::wrap;
use kinolab_common::error::{in_range, non_negative, positive};
use kinolab_common::random::gaussian_hash;
use kinolab_common::trig;
use serde::{Deserialize, Serialize};

use crate::{FieldError, Pose, Vec2, World, unit};

/// A fan of range rays, evenly spread over the field of view.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Rays {
    pub count: usize,
    pub fov_deg: f64,
    pub max_range: f64,
    /// Standard deviation of the range noise, m.
    #[serde(default)]
    pub noise: f64,
}

impl Rays {
    /// The rays' directions in the robot frame, right to left.
    pub fn angles(&self) -> impl Iterator<Item = f64> + '_ {
        let fov = self.fov_deg.to_radians();
        let n = self.count;
        // A full circle does not repeat its first ray at the end.
        let gaps = if self.fov_deg >= 360.0 {
            n
        } else {
            n.saturating_sub(1).max(1)
        };
        (0..n).map(move |i| {
            if n == 1 {
                0.0
            } else {
                -fov / 2.0 + fov * i as f64 / gaps as f64
            }
        })
    }
}

/// A sonar: the nearest echo within a cone ahead.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sonar {
    pub cone_deg: f64,
    pub max_range: f64,
    #[serde(default)]
    pub noise: f64,
}

/// Two light sensors on the rim, left and right of the nose, each facing
/// outwards. A sensor reads I / (1 + k d²) · max(0, cos φ) summed over the
/// lights it can see, φ being the angle between where it faces and the
/// light: a sensor sees best straight ahead of itself.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightSensors {
    /// Each sensor's angle from the nose (it faces that way too).
    #[serde(default = "default_light_angle")]
    pub angle_deg: f64,
    /// k in I / (1 + k d²).
    #[serde(default = "default_falloff")]
    pub falloff: f64,
    #[serde(default)]
    pub noise: f64,
}

fn default_light_angle() -> f64 {
    25.0
}

fn default_falloff() -> f64 {
    1.0
}

impl Default for LightSensors {
    fn default() -> Self {
        Self {
            angle_deg: default_light_angle(),
            falloff: default_falloff(),
            noise: 0.0,
        }
    }
}

/// Odometry that drifts: each wheel's measured speed is off by a random
/// fraction with this standard deviation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Odometry {
    pub drift: f64,
}

/// The sensors a robot carries. Bumpers and the goal's bearing and distance
/// always come with it.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sensors {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rays: Option<Rays>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sonar: Option<Sonar>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lights: Option<LightSensors>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub odometry: Option<Odometry>,
}

impl Sensors {
    /// A ring of `count` rays over `fov_deg`, `max_range` long, no noise.
    pub fn rays(count: usize, fov_deg: f64, max_range: f64) -> Self {
        Self {
            rays: Some(Rays {
                count,
                fov_deg,
                max_range,
                noise: 0.0,
            }),
            ..Self::default()
        }
    }

    /// Check every number; errors name the field.
    pub fn check(&self) -> Result<(), FieldError> {
        if let Some(r) = &self.rays {
            if !(1..=360).contains(&r.count) {
                return Err(FieldError::new(
                    "rays.count",
                    format!("must be from 1 to 360, got {}", r.count),
                ));
            }
            in_range("rays.fov_deg", r.fov_deg, 0.0, 360.0)?;
            positive("rays.max_range", r.max_range)?;
            non_negative("rays.noise", r.noise)?;
        }
        if let Some(s) = &self.sonar {
            in_range("sonar.cone_deg", s.cone_deg, 0.0, 180.0)?;
            positive("sonar.max_range", s.max_range)?;
            non_negative("sonar.noise", s.noise)?;
        }
        if let Some(l) = &self.lights {
            in_range("lights.angle_deg", l.angle_deg, 0.0, 90.0)?;
            non_negative("lights.falloff", l.falloff)?;
            non_negative("lights.noise", l.noise)?;
        }
        if let Some(o) = &self.odometry {
            in_range("odometry.drift", o.drift, 0.0, 1.0)?;
        }
        Ok(())
    }
}

/// One range ray's reading.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RayReading {
    /// Direction in the robot frame, rad (0 ahead, positive to the left).
    pub angle: f64,
    /// Measured range, m; the maximum range when nothing is seen.
    pub range: f64,
    pub hit: bool,
}

/// Where the goal is, seen from the robot.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GoalPercept {
    /// Angle from the robot's heading, rad, in (−π, π].
    pub bearing: f64,
    pub distance: f64,
}

/// Bumper sectors, in the order of [`Percepts::bumpers`].
pub const BUMPERS: [&str; 4] = ["front", "left", "back", "right"];

/// Everything one reading of the sensors gives.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Percepts {
    pub time: f64,
    pub rays: Vec<RayReading>,
    /// The nearest sonar echo, m.
    pub sonar: Option<f64>,
    /// Front, left, back, right: touching something there.
    pub bumpers: [bool; 4],
    /// Left and right light readings.
    pub light: [f64; 2],
    pub goal: Option<GoalPercept>,
    /// Where odometry thinks the robot is.
    pub odometry: Pose,
    /// The robot's own speed: forward (m/s) and turn rate (rad/s).
    pub speed: [f64; 2],
}

impl Percepts {
    /// The shortest ray reading within `half_width` of `angle` (robot
    /// frame), or `None` if no ray looks that way.
    pub fn nearest_within(&self, angle: f64, half_width: f64) -> Option<f64> {
        self.rays
            .iter()
            .filter(|r| wrap(r.angle - angle).abs() <= half_width + 1e-9)
            .map(|r| r.range)
            .min_by(f64::total_cmp)
    }

    /// Whether any bumper is pressed.
    pub fn bumped(&self) -> bool {
        self.bumpers.iter().any(|b| *b)
    }
}

/// Noise channels, so each sensor draws its own numbers.
const RAY_CHANNEL: u64 = 0;
const SONAR_CHANNEL: u64 = 1_000;
const LIGHT_CHANNEL: u64 = 2_000;

/// Where the sensors are and what they read at one moment.
pub(crate) struct Reading<'a> {
    pub world: &'a World,
    pub pose: Pose,
    pub radius: f64,
    pub time: f64,
    pub step: u64,
    pub seed: u64,
}

impl Reading<'_> {
    fn noise(&self, channel: u64, sd: f64) -> f64 {
        if sd > 0.0 {
            sd * gaussian_hash(self.seed, self.step, channel)
        } else {
            0.0
        }
    }

    fn position(&self) -> Vec2 {
        Vec2::new(self.pose.x, self.pose.y)
    }

    pub fn rays(&self, rays: &Rays) -> Vec<RayReading> {
        let o = self.position();
        rays.angles()
            .enumerate()
            .map(|(i, angle)| {
                let dir = unit(self.pose.theta + angle);
                let hit = self.world.ray(o, dir, rays.max_range, self.time);
                let measured =
                    hit.unwrap_or(rays.max_range) + self.noise(RAY_CHANNEL + i as u64, rays.noise);
                RayReading {
                    angle,
                    range: measured.clamp(0.0, rays.max_range),
                    hit: hit.is_some(),
                }
            })
            .collect()
    }

    pub fn sonar(&self, sonar: &Sonar) -> Option<f64> {
        let beams = ((sonar.cone_deg / 3.0).ceil() as usize).max(3);
        let cone = sonar.cone_deg.to_radians();
        let o = self.position();
        let nearest = (0..beams)
            .filter_map(|i| {
                let a = -cone / 2.0 + cone * i as f64 / (beams - 1) as f64;
                self.world
                    .ray(o, unit(self.pose.theta + a), sonar.max_range, self.time)
            })
            .min_by(f64::total_cmp)?;
        Some((nearest + self.noise(SONAR_CHANNEL, sonar.noise)).clamp(0.0, sonar.max_range))
    }

    pub fn lights(&self, sensors: &LightSensors) -> [f64; 2] {
        let angle = sensors.angle_deg.to_radians();
        let mut out = [0.0; 2];
        for (side, sign) in [1.0, -1.0].into_iter().enumerate() {
            let facing = unit(self.pose.theta + sign * angle);
            let at = self.position() + facing * self.radius;
            let mut total = 0.0;
            for light in &self.world.lights {
                let to = light.at() - at;
                let d2 = to.norm_squared();
                let cos = if d2 > 0.0 {
                    facing.dot(&to) / d2.sqrt()
                } else {
                    1.0
                };
                if cos > 0.0 && self.world.line_of_sight(at, light.at(), self.time) {
                    total += light.intensity / (1.0 + sensors.falloff * d2) * cos;
                }
            }
            out[side] = (total + self.noise(LIGHT_CHANNEL + side as u64, sensors.noise)).max(0.0);
        }
        out
    }

    pub fn goal(&self) -> Option<GoalPercept> {
        let goal = self.world.goal?;
        let to = goal - self.position();
        Some(GoalPercept {
            bearing: wrap(trig::atan2(to.y, to.x) - self.pose.theta),
            distance: to.norm(),
        })
    }
}

/// Which bumper a contact at `point` presses, for a robot at `pose`.
pub(crate) fn bumper(pose: &Pose, point: Vec2) -> usize {
    let bearing = wrap(trig::atan2(point.y - pose.y, point.x - pose.x) - pose.theta);
    let quarter = std::f64::consts::FRAC_PI_4;
    if bearing.abs() <= quarter {
        0
    } else if bearing > quarter && bearing <= 3.0 * quarter {
        1
    } else if bearing < -quarter && bearing >= -3.0 * quarter {
        3
    } else {
        2
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rays_spread_over_the_field_of_view() {
        let r = Rays {
            count: 5,
            fov_deg: 180.0,
            max_range: 1.0,
            noise: 0.0,
        };
        let a: Vec<f64> = r.angles().map(f64::to_degrees).collect();
        for (got, want) in a.iter().zip([-90.0, -45.0, 0.0, 45.0, 90.0]) {
            assert!((got - want).abs() < 1e-9);
        }
        let ring = Rays {
            count: 4,
            fov_deg: 360.0,
            max_range: 1.0,
            noise: 0.0,
        };
        let a: Vec<f64> = ring.angles().map(f64::to_degrees).collect();
        assert!((a[3] - 90.0).abs() < 1e-9, "{a:?}");
    }

    #[test]
    fn bad_sensors_name_the_field() {
        let mut s = Sensors::rays(0, 90.0, 2.0);
        assert_eq!(s.check().unwrap_err().field, "rays.count");
        s = Sensors::rays(8, 90.0, -2.0);
        assert_eq!(s.check().unwrap_err().field, "rays.max_range");
        s.rays = None;
        s.sonar = Some(Sonar {
            cone_deg: 30.0,
            max_range: 3.0,
            noise: f64::NAN,
        });
        assert_eq!(s.check().unwrap_err().field, "sonar.noise");
    }

    #[test]
    fn bumpers_split_the_rim_in_four() {
        let pose = Pose::new(0.0, 0.0, std::f64::consts::FRAC_PI_2);
        assert_eq!(bumper(&pose, Vec2::new(0.0, 1.0)), 0);
        assert_eq!(bumper(&pose, Vec2::new(-1.0, 0.0)), 1);
        assert_eq!(bumper(&pose, Vec2::new(0.0, -1.0)), 2);
        assert_eq!(bumper(&pose, Vec2::new(1.0, 0.0)), 3);
    }
}
