//! Reproducible slip and disturbances.
//!
//! Time is cut into fixed intervals of [`NOISE_INTERVAL`]; in each one the
//! wheels slip (the robot covers a random fraction less distance, and turns
//! a random fraction less, than commanded) and the world gives the robot a
//! random push. Every random number is a hash of (seed, interval, channel), not the
//! next draw of a stream, so a run with half the time step meets exactly the
//! same slip at the same moments: only the integration changes.

use serde::{Deserialize, Serialize};

use crate::error::{FieldError, finite};

/// Seconds between changes of slip and push.
pub const NOISE_INTERVAL: f64 = 0.05;

/// What can go wrong, and how badly.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Noise {
    pub seed: u64,
    /// The wheels lose up to this fraction of the commanded motion (0 to
    /// 0.9): one random fraction for driving, another for turning.
    pub slip: f64,
    /// Random push in each world axis, up to this speed, m/s.
    pub push_speed: f64,
    /// Random twist from the ground, up to this rate, rad/s.
    pub push_turn: f64,
}

impl Noise {
    pub(crate) fn check(&self) -> Result<(), FieldError> {
        if !(0.0..=0.9).contains(&finite("noise.slip", self.slip)?) {
            return Err(FieldError::new(
                "noise.slip",
                format!("must be from 0 to 0.9, got {}", self.slip),
            ));
        }
        // Named as run files spell them: the turn push in degrees.
        kinolab_common::error::non_negative("noise.push_speed", self.push_speed)?;
        kinolab_common::error::non_negative("noise.push_turn_deg", self.push_turn.to_degrees())?;
        Ok(())
    }

    /// A number in [0, 1) for this interval and channel.
    pub fn uniform(&self, interval: u64, channel: u64) -> f64 {
        kinolab_common::random::unit_hash(self.seed, interval, channel)
    }

    /// Fractions of v and of ω lost to slip during `interval`.
    pub fn slip_of(&self, interval: u64) -> [f64; 2] {
        [
            self.slip * self.uniform(interval, 16),
            self.slip * self.uniform(interval, 17),
        ]
    }

    /// World-frame push (ẋ, ẏ, θ̇) during `interval`.
    pub fn push(&self, interval: u64) -> [f64; 3] {
        let centred = |c| 2.0 * self.uniform(interval, c) - 1.0;
        [
            self.push_speed * centred(0),
            self.push_speed * centred(1),
            self.push_turn * centred(2),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_numbers_look_uniform_and_repeat() {
        let n = Noise {
            seed: 42,
            slip: 0.2,
            push_speed: 0.1,
            push_turn: 0.0,
        };
        let draws: Vec<f64> = (0..20_000).map(|k| n.uniform(k, 0)).collect();
        assert!(draws.iter().all(|u| (0.0..1.0).contains(u)));
        let mean = draws.iter().sum::<f64>() / draws.len() as f64;
        // Standard error of the mean: √(1/12/20000) ≈ 0.002; allow 4σ.
        assert!((mean - 0.5).abs() < 0.0082, "{mean}");
        assert_eq!(n.uniform(7, 3), n.uniform(7, 3));
        assert_ne!(n.uniform(7, 3), n.uniform(7, 4));
        let other = Noise { seed: 43, ..n };
        assert_ne!(n.uniform(7, 3), other.uniform(7, 3));
        assert!(n.slip_of(5).iter().all(|s| (0.0..=0.2).contains(s)));
        assert!(n.push(9)[2] == 0.0 && n.push(9)[0].abs() <= 0.1);
    }
}
