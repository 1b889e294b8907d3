//! Balance beyond static: the cart-table model (the linear inverted
//! pendulum) and its zero moment point.
//!
//! The body is a point mass at constant height z_c above flat ground; the
//! foot spans `[heel, toe]` along x. The ground can push only through the
//! foot, so the point where the ground's reaction acts (the **ZMP**) must
//! lie on the foot:
//!
//!   p = x − (z_c / g) ẍ
//!
//! Read the other way, the body accelerates away from the ZMP:
//! ẍ = ω² (x − p) with ω = √(g / z_c). An ankle can place p anywhere on the
//! foot and no further. The lab's controller puts p at the **capture
//! point** ξ = x + ẋ / ω, which stops the body over ξ when ξ is on the
//! foot; when a push sends ξ past the toe, the ZMP the motion would need
//! has left the foot, p stays at the toe, and the body falls forwards.

use serde::{Deserialize, Serialize};

use crate::FieldError;
use crate::transport::STANDARD_GRAVITY;

/// A push-recovery run as a file (`*.zmp.json`): the body's height, the
/// foot, where the body starts and how hard it is pushed, and the run's
/// length and step.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PushRun {
    /// z_c, m.
    pub height: f64,
    /// The foot's back and front edges along x, m.
    pub heel: f64,
    pub toe: f64,
    /// Where the body starts, m (at rest).
    #[serde(default)]
    pub x0: f64,
    /// The speed the push gives the body, m/s.
    pub push: f64,
    #[serde(default = "kinolab_common::defaults::whole::<4>")]
    pub duration: f64,
    #[serde(default = "kinolab_common::defaults::reciprocal::<200>")]
    pub dt: f64,
}

impl PushRun {
    /// Read a push-recovery file; errors name the field.
    pub fn from_json(text: &str) -> Result<Self, FieldError> {
        kinolab_common::error::from_json(text)
    }

    /// The run.
    pub fn run(&self) -> Result<Recovery, FieldError> {
        CartTable::new(self.height, self.heel, self.toe)?.push(
            self.x0,
            self.push,
            self.duration,
            self.dt,
        )
    }
}

/// A cart on a table: the body's height and the foot under it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CartTable {
    /// Height of the centre of mass, m.
    pub height: f64,
    /// The foot's back and front edges along x, m.
    pub heel: f64,
    pub toe: f64,
    pub gravity: f64,
}

/// One instant of a push-recovery run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BalanceSample {
    pub t: f64,
    pub x: f64,
    pub xd: f64,
    pub xdd: f64,
    /// The ZMP the ankle produces (on the foot).
    pub zmp: f64,
    /// The ZMP the controller asked for: the capture point.
    pub wanted: f64,
    /// Whether the wanted ZMP is on the foot.
    pub inside: bool,
}

/// How a push ends.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Recovery {
    pub samples: Vec<BalanceSample>,
    /// The body came to rest over the foot.
    pub recovered: bool,
    /// When the wanted ZMP first left the foot, s.
    pub left_foot_at: Option<f64>,
}

/// The longest run and the smallest step, so a run stays bounded.
const MAX_STEPS: f64 = 100_000.0;

impl CartTable {
    /// A body `height` m up over a foot from `heel` to `toe`, on Earth.
    pub fn new(height: f64, heel: f64, toe: f64) -> Result<Self, FieldError> {
        let height = kinolab_common::error::length("height", height)?;
        let heel = kinolab_common::error::bounded("heel", heel, 10.0)?;
        let toe = kinolab_common::error::bounded("toe", toe, 10.0)?;
        if toe <= heel {
            return Err(FieldError::new(
                "toe",
                format!("must be ahead of the heel ({heel}), got {toe}"),
            ));
        }
        Ok(Self {
            height,
            heel,
            toe,
            gravity: STANDARD_GRAVITY,
        })
    }

    /// ω = √(g / z_c), 1/s.
    pub fn omega(&self) -> f64 {
        (self.gravity / self.height).sqrt()
    }

    /// The ZMP of a body at `x` accelerating at `xdd`.
    pub fn zmp(&self, x: f64, xdd: f64) -> f64 {
        x - self.height / self.gravity * xdd
    }

    /// Whether `p` lies on the foot.
    pub fn on_foot(&self, p: f64) -> bool {
        (self.heel..=self.toe).contains(&p)
    }

    /// The body starts at rest at `x0` and is pushed to speed `push` (m/s);
    /// the ankle holds the ZMP at the capture point as far as the foot
    /// allows. Runs `duration` s in steps of `dt` (exact for each step:
    /// the pendulum's solution with p held).
    pub fn push(&self, x0: f64, push: f64, duration: f64, dt: f64) -> Result<Recovery, FieldError> {
        let x0 = kinolab_common::error::bounded("x0", x0, 10.0)?;
        let push = kinolab_common::error::bounded("push", push, 20.0)?;
        let dt = kinolab_common::error::in_range("dt", dt, 1e-4, 0.1)?;
        let duration = kinolab_common::error::in_range("duration", duration, 0.0, 60.0)?;
        if duration / dt > MAX_STEPS {
            return Err(FieldError::new(
                "dt",
                format!("{duration} s at {dt} s a step is more than {MAX_STEPS} steps"),
            ));
        }
        let w = self.omega();
        let (mut x, mut xd) = (x0, push);
        let mut samples = Vec::new();
        let mut left_foot_at = None;
        let steps = (duration / dt).round() as usize;
        for k in 0..=steps {
            let t = k as f64 * dt;
            let wanted = x + xd / w;
            let zmp = wanted.clamp(self.heel, self.toe);
            let inside = self.on_foot(wanted);
            if !inside && left_foot_at.is_none() {
                left_foot_at = Some(t);
            }
            samples.push(BalanceSample {
                t,
                x,
                xd,
                xdd: w * w * (x - zmp),
                zmp,
                wanted,
                inside,
            });
            // x − p follows cosh/sinh while p is held.
            let (c, s) = ((w * dt).cosh(), (w * dt).sinh());
            let e = x - zmp;
            x = zmp + e * c + xd / w * s;
            xd = e * w * s + xd * c;
            if (x - zmp).abs() > 10.0 * self.height {
                break;
            }
        }
        let last = samples.last().copied();
        Ok(Recovery {
            recovered: left_foot_at.is_none() && last.is_some_and(|s| s.xd.abs() < 1e-3),
            left_foot_at,
            samples,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table() -> CartTable {
        // A body 0.8 m up over a foot from 5 cm behind to 15 cm ahead.
        CartTable::new(0.8, -0.05, 0.15).unwrap()
    }

    #[test]
    fn the_zmp_is_the_com_less_the_acceleration_term() {
        let t = table();
        // At rest the ZMP is under the CoM; accelerating forwards at g/4
        // moves it back by z_c / 4.
        assert_eq!(t.zmp(0.1, 0.0), 0.1);
        assert!((t.zmp(0.1, t.gravity / 4.0) - (0.1 - 0.2)).abs() < 1e-12);
    }

    #[test]
    fn a_small_push_is_caught_and_a_large_one_is_not() {
        let t = table();
        let w = t.omega();
        // The capture point starts at ẋ/ω: on the foot below 0.15 ω m/s.
        let small = t.push(0.0, 0.1 * w, 5.0, 0.005).unwrap();
        assert!(small.recovered && small.left_foot_at.is_none());
        // It comes to rest over the capture point, 0.1 m ahead.
        let end = small.samples.last().unwrap();
        assert!((end.x - 0.1).abs() < 1e-6, "{}", end.x);
        let large = t.push(0.0, 0.2 * w, 5.0, 0.005).unwrap();
        assert!(!large.recovered);
        assert_eq!(large.left_foot_at, Some(0.0));
        // The ZMP stays on the foot (at the toe) while the body falls.
        assert!(large.samples.iter().all(|s| t.on_foot(s.zmp)));
        assert!(large.samples.last().unwrap().x > 1.0);
    }

    #[test]
    fn each_sample_keeps_the_cart_table_relation() {
        let t = table();
        let run = t.push(0.02, 0.3, 2.0, 0.01).unwrap();
        for s in &run.samples {
            assert!((t.zmp(s.x, s.xdd) - s.zmp).abs() < 1e-9);
        }
    }

    #[test]
    fn a_table_needs_its_toe_ahead_of_its_heel() {
        assert_eq!(CartTable::new(0.8, 0.1, 0.0).unwrap_err().field, "toe");
    }
}
