//! A connection's timing: a fixed latency, seeded jitter and seeded loss.
//! Messages on one connection keep their order (as over one socket), so
//! jitter delays but never overtakes.

use kinolab_common::error::in_range;
use kinolab_common::random::unit_hash;
use serde::{Deserialize, Serialize};

use crate::FieldError;

/// Latency and loss of one connection.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Latency {
    /// Every message takes at least this long, s.
    #[serde(default = "default_fixed")]
    pub fixed: f64,
    /// Plus a seeded delay spread evenly over [0, jitter), s.
    #[serde(default)]
    pub jitter: f64,
    /// The chance that a message is lost, in [0, 1].
    #[serde(default)]
    pub loss: f64,
}

fn default_fixed() -> f64 {
    0.005
}

impl Default for Latency {
    fn default() -> Self {
        Self {
            fixed: default_fixed(),
            jitter: 0.0,
            loss: 0.0,
        }
    }
}

/// Hash channels for jitter and loss.
const JITTER: u64 = 11;
const LOSS: u64 = 12;

impl Latency {
    pub fn check(&self) -> Result<(), FieldError> {
        in_range("fixed", self.fixed, 0.0, 10.0)?;
        in_range("jitter", self.jitter, 0.0, 10.0)?;
        in_range("loss", self.loss, 0.0, 1.0)?;
        Ok(())
    }

    /// When message `seq` sent at `now` arrives (`None`: lost), given the
    /// delivery time of the previous message in the same direction.
    pub fn arrival(&self, seed: u64, seq: u64, now: f64, previous: f64) -> Option<f64> {
        if self.loss > 0.0 && unit_hash(seed, seq, LOSS) < self.loss {
            return None;
        }
        let delay = self.fixed + self.jitter * unit_hash(seed, seq, JITTER);
        Some((now + delay).max(previous))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jitter_delays_within_its_range_and_keeps_order() {
        let l = Latency {
            fixed: 0.01,
            jitter: 0.05,
            loss: 0.0,
        };
        let mut last = 0.0;
        for seq in 0..500 {
            let now = seq as f64 * 0.001;
            let at = l.arrival(7, seq, now, last).unwrap();
            assert!(at >= now + 0.01 && at <= now + 0.06 + 1e-12 || at == last);
            assert!(at >= last);
            last = at;
        }
    }

    #[test]
    fn loss_drops_about_its_share_and_is_seeded() {
        let l = Latency {
            fixed: 0.0,
            jitter: 0.0,
            loss: 0.25,
        };
        let lost = (0..4000)
            .filter(|&s| l.arrival(3, s, 0.0, 0.0).is_none())
            .count();
        assert!((900..1100).contains(&lost), "{lost}");
        let again = (0..4000)
            .filter(|&s| l.arrival(3, s, 0.0, 0.0).is_none())
            .count();
        assert_eq!(lost, again);
        let bad = Latency { loss: 1.5, ..l };
        assert_eq!(bad.check().unwrap_err().field, "loss");
    }
}
