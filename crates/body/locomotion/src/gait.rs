//! Periodic gaits: when each leg is on the ground, where its foot is, and
//! whether the walker stays statically stable through the whole cycle.
//!
//! Conventions of the legged reference sheet: normalised time τ ∈ [0, 1);
//! leg i with lift-off phase φᵢ has σᵢ = (τ − φᵢ) mod 1 and swings while
//! σᵢ < 1 − β (β the duty factor), then stands; in stance its foot slides
//! back along the body's x axis from xᵢ + L/2 to xᵢ − L/2 (L the stride).

use kinolab_common::error::{finite, in_range, non_negative};
use serde::{Deserialize, Serialize};

use crate::error::FieldError;
use crate::stability::{Point, static_stability};

/// The most legs a gait may have.
pub const MAX_LEGS: usize = 64;

/// One leg: its name, its foot's neutral point in the body frame, and its
/// lift-off phase.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Leg {
    pub name: String,
    pub x: f64,
    pub y: f64,
    pub phase: f64,
}

/// A periodic gait (the contract's gait file).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a gait file (an object with `duty_factor`, `stride` and `legs`)"
)]
pub struct Gait {
    #[serde(default)]
    pub name: String,
    /// β: the fraction of the cycle each leg is on the ground.
    pub duty_factor: f64,
    /// L, m.
    pub stride: f64,
    /// The centre of mass in the body frame, m.
    #[serde(default)]
    pub com: Point,
    pub legs: Vec<Leg>,
}

/// The walker at one instant of the cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct Instant {
    pub tau: f64,
    /// Indices of the legs in stance, in file order.
    pub stance: Vec<usize>,
    /// Their feet, in the same order.
    pub feet: Vec<Point>,
    /// The static stability margin; `None` with no foot down.
    pub margin: Option<f64>,
}

impl Gait {
    /// Read a gait file; errors name the field as the file spells it.
    pub fn from_json(text: &str) -> Result<Self, FieldError> {
        let gait: Gait = kinolab_common::error::from_json(text)?;
        gait.check()?;
        Ok(gait)
    }

    /// Check every value against what the sheet allows.
    pub fn check(&self) -> Result<(), FieldError> {
        let beta = finite("duty_factor", self.duty_factor)?;
        if !(beta > 0.0 && beta < 1.0) {
            return Err(FieldError::new(
                "duty_factor",
                format!("must lie strictly between 0 and 1, got {beta}"),
            ));
        }
        non_negative("stride", self.stride)?;
        finite("com[0]", self.com[0])?;
        finite("com[1]", self.com[1])?;
        if self.legs.is_empty() || self.legs.len() > MAX_LEGS {
            return Err(FieldError::new(
                "legs",
                format!("needs 1 to {MAX_LEGS} legs, got {}", self.legs.len()),
            ));
        }
        for (i, leg) in self.legs.iter().enumerate() {
            let field = |f: &str| format!("legs[{i}].{f}");
            finite(field("x"), leg.x)?;
            finite(field("y"), leg.y)?;
            let phase = in_range(field("phase"), leg.phase, 0.0, 1.0)?;
            if phase >= 1.0 {
                return Err(FieldError::new(
                    field("phase"),
                    "must be in [0, 1): 1 is the same instant as 0",
                ));
            }
        }
        Ok(())
    }

    /// σ for leg `i` at `tau`: how far through its own cycle it is.
    fn sigma(&self, i: usize, tau: f64) -> f64 {
        (tau - self.legs[i].phase).rem_euclid(1.0)
    }

    /// Whether leg `i` is on the ground at `tau`.
    pub fn in_stance(&self, i: usize, tau: f64) -> bool {
        self.sigma(i, tau) >= 1.0 - self.duty_factor
    }

    /// Where leg `i`'s foot is at `tau` while in stance.
    pub fn foot(&self, i: usize, tau: f64) -> Option<Point> {
        if !self.in_stance(i, tau) {
            return None;
        }
        let (leg, beta, stride) = (&self.legs[i], self.duty_factor, self.stride);
        let through = (self.sigma(i, tau) - (1.0 - beta)) / beta;
        Some([leg.x + stride / 2.0 - stride * through, leg.y])
    }

    /// The walker at `tau`.
    pub fn at(&self, tau: f64) -> Instant {
        let (stance, feet): (Vec<usize>, Vec<Point>) = (0..self.legs.len())
            .filter_map(|i| self.foot(i, tau).map(|f| (i, f)))
            .unzip();
        let margin = static_stability(self.com, &feet).ok().map(|s| s.margin);
        Instant {
            tau,
            stance,
            feet,
            margin,
        }
    }

    /// The body's speed, m/s, when one cycle takes `period` seconds: each
    /// foot slides back a stride `L` while it stands for `βT`, so
    /// `v = L / (βT)`.
    pub fn speed(&self, period: f64) -> Result<f64, FieldError> {
        let period = kinolab_common::error::positive("period", period)?;
        Ok(self.stride / (self.duty_factor * period))
    }

    /// `n` instants at τ = (k + ½)/n.
    pub fn sample(&self, n: usize) -> Vec<Instant> {
        (0..n)
            .map(|k| self.at((k as f64 + 0.5) / n as f64))
            .collect()
    }
}

/// The named gaits: (id, duty factor, legs as (name, x, y, lift-off
/// phase)). Quadruped feet at (±0.3, ±0.2) m, hexapod feet at x = 0.3, 0,
/// −0.3 m and y = ±0.25 m; stride 0.2 m. All but the last two are the
/// reference sheet's; the ripple and the transverse gallop come from the
/// gait literature (Hildebrand's footfall patterns) and are marked so.
const NAMED: [(&str, f64, &[LegRow]); 9] = [
    ("quadruped-crawl", 0.75, &QUADRUPED_CRAWL),
    (
        "quadruped-trot",
        0.5,
        &[
            ("LF", 0.3, 0.2, 0.0),
            ("RF", 0.3, -0.2, 0.5),
            ("LH", -0.3, 0.2, 0.5),
            ("RH", -0.3, -0.2, 0.0),
        ],
    ),
    (
        "quadruped-pace",
        0.5,
        &[
            ("LF", 0.3, 0.2, 0.0),
            ("RF", 0.3, -0.2, 0.5),
            ("LH", -0.3, 0.2, 0.0),
            ("RH", -0.3, -0.2, 0.5),
        ],
    ),
    (
        "quadruped-bound",
        0.5,
        &[
            ("LF", 0.3, 0.2, 0.0),
            ("RF", 0.3, -0.2, 0.0),
            ("LH", -0.3, 0.2, 0.5),
            ("RH", -0.3, -0.2, 0.5),
        ],
    ),
    (
        "hexapod-tripod",
        0.5,
        &hexapod([0.0, 0.5, 0.0, 0.5, 0.0, 0.5]),
    ),
    (
        "hexapod-wave",
        5.0 / 6.0,
        &hexapod([2.0 / 6.0, 1.0 / 6.0, 0.0, 5.0 / 6.0, 4.0 / 6.0, 3.0 / 6.0]),
    ),
    (
        "hexapod-tetrapod",
        2.0 / 3.0,
        &hexapod([2.0 / 3.0, 1.0 / 3.0, 0.0, 1.0 / 3.0, 0.0, 2.0 / 3.0]),
    ),
    // Beyond the sheet: a back-to-front wave on each side, the two sides
    // half a cycle apart, so one leg per side swings at any instant.
    (
        "hexapod-ripple",
        2.0 / 3.0,
        &hexapod([2.0 / 3.0, 1.0 / 3.0, 0.0, 1.0 / 6.0, 5.0 / 6.0, 0.5]),
    ),
    // Beyond the sheet: the transverse gallop, hind pair then fore pair,
    // each pair's feet a tenth of a cycle apart, then a flight.
    (
        "quadruped-gallop",
        0.3,
        &[
            ("LF", 0.3, 0.2, 0.4),
            ("RF", 0.3, -0.2, 0.5),
            ("LH", -0.3, 0.2, 0.0),
            ("RH", -0.3, -0.2, 0.1),
        ],
    ),
];

/// A leg of a named gait: name, x, y, lift-off phase.
type LegRow = (&'static str, f64, f64, f64);

const QUADRUPED_CRAWL: [LegRow; 4] = [
    ("LF", 0.3, 0.2, 0.25),
    ("RF", 0.3, -0.2, 0.75),
    ("LH", -0.3, 0.2, 0.0),
    ("RH", -0.3, -0.2, 0.5),
];

/// A hexapod's legs L1 L2 L3 R1 R2 R3 (front to back) with these phases.
const fn hexapod(phases: [f64; 6]) -> [LegRow; 6] {
    [
        ("L1", 0.3, 0.25, phases[0]),
        ("L2", 0.0, 0.25, phases[1]),
        ("L3", -0.3, 0.25, phases[2]),
        ("R1", 0.3, -0.25, phases[3]),
        ("R2", 0.0, -0.25, phases[4]),
        ("R3", -0.3, -0.25, phases[5]),
    ]
}

/// The ids of the named gaits.
pub fn named_ids() -> impl Iterator<Item = &'static str> {
    NAMED_IDS.into_iter()
}

/// Every named gait's id, in catalogue order.
pub const NAMED_IDS: [&str; NAMED.len()] = ids_with_legs::<{ NAMED.len() }>(None);
/// The four-legged gaits' ids.
pub const QUADRUPED_IDS: [&str; count_with_legs(4)] =
    ids_with_legs::<{ count_with_legs(4) }>(Some(4));
/// The six-legged gaits' ids.
pub const HEXAPOD_IDS: [&str; count_with_legs(6)] =
    ids_with_legs::<{ count_with_legs(6) }>(Some(6));

/// How many named gaits have `legs` legs.
const fn count_with_legs(legs: usize) -> usize {
    let (mut count, mut i) = (0, 0);
    while i < NAMED.len() {
        if NAMED[i].2.len() == legs {
            count += 1;
        }
        i += 1;
    }
    count
}

/// The ids of the `K` named gaits with `legs` legs (any number: `None`).
const fn ids_with_legs<const K: usize>(legs: Option<usize>) -> [&'static str; K] {
    let mut ids = [""; K];
    let (mut k, mut i) = (0, 0);
    while i < NAMED.len() && k < K {
        let fits = match legs {
            Some(n) => NAMED[i].2.len() == n,
            None => true,
        };
        if fits {
            ids[k] = NAMED[i].0;
            k += 1;
        }
        i += 1;
    }
    ids
}

/// A named gait of the sheet (`quadruped-crawl`, `hexapod-tripod`, …).
pub fn named(id: &str) -> Option<Gait> {
    let (id, beta, legs) = NAMED.iter().find(|(name, _, _)| *name == id)?;
    Some(Gait {
        name: (*id).to_owned(),
        duty_factor: *beta,
        stride: 0.2,
        com: [0.0, 0.0],
        legs: legs
            .iter()
            .map(|&(name, x, y, phase)| Leg {
                name: name.to_owned(),
                x,
                y,
                phase,
            })
            .collect(),
    })
}

/// The smallest margin over `instants`: `None` when some instant has no
/// foot down (the margin is undefined there, and the gait not static).
pub fn min_margin(instants: &[Instant]) -> Option<f64> {
    instants
        .iter()
        .map(|s| s.margin)
        .try_fold(f64::INFINITY, |m, s| s.map(|s| m.min(s)))
        .filter(|m| m.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(crate) fn crawl(beta: f64) -> Gait {
        let leg = |name: &str, x: f64, y: f64, phase: f64| Leg {
            name: name.into(),
            x,
            y,
            phase,
        };
        Gait {
            name: "quadruped-crawl".into(),
            duty_factor: beta,
            stride: 0.2,
            com: [0.0, 0.0],
            legs: vec![
                leg("LF", 0.3, 0.2, 0.25),
                leg("RF", 0.3, -0.2, 0.75),
                leg("LH", -0.3, 0.2, 0.0),
                leg("RH", -0.3, -0.2, 0.5),
            ],
        }
    }

    #[test]
    fn a_foot_touches_down_ahead_and_lifts_off_behind() {
        let g = crawl(0.75);
        // LH lifts off at τ = 0 and touches down at σ = 1 − β = 0.25.
        assert!(!g.in_stance(2, 0.1));
        let down = g.foot(2, 0.25 + 1e-12).unwrap();
        assert!((down[0] - (-0.3 + 0.1)).abs() < 1e-9, "{down:?}");
        let halfway = g.foot(2, 0.625).unwrap();
        assert!((halfway[0] + 0.3).abs() < 1e-12);
        let up = g.foot(2, 1.0 - 1e-12).unwrap();
        assert!((up[0] - (-0.3 - 0.1)).abs() < 1e-9);
    }

    #[test]
    fn each_leg_stands_for_the_duty_factor_of_the_cycle() {
        for beta in [0.5, 0.75, 5.0 / 6.0] {
            let g = crawl(beta);
            let n = 1200;
            let stance: usize = g.sample(n).iter().map(|s| s.stance.len()).sum();
            let mean = stance as f64 / n as f64;
            assert!((mean - 4.0 * beta).abs() < 4.0 / n as f64, "{beta}: {mean}");
        }
    }

    #[test]
    fn the_crawl_is_static_and_the_trot_is_not() {
        let crawl = crawl(0.75);
        let m = min_margin(&crawl.sample(400)).unwrap();
        assert!(m > 0.0, "{m}");
        let mut trot = crawl.clone();
        trot.duty_factor = 0.5;
        for (leg, phase) in trot.legs.iter_mut().zip([0.0, 0.5, 0.5, 0.0]) {
            leg.phase = phase;
        }
        let m = min_margin(&trot.sample(400)).unwrap();
        // Two diagonal feet through the CoM: the margin is 0 at best.
        assert!(m <= 1e-12, "{m}");
    }

    #[test]
    fn the_named_walks_are_static_and_the_dynamic_gaits_are_not() {
        for id in named_ids() {
            let g = named(id).unwrap();
            g.check().unwrap();
            let m = min_margin(&g.sample(600));
            let stable = m.is_some_and(|m| m > 0.0);
            let dynamic = [
                "quadruped-trot",
                "quadruped-pace",
                "quadruped-bound",
                "quadruped-gallop",
            ]
            .contains(&id);
            assert_eq!(stable, !dynamic, "{id}: {m:?}");
        }
        assert!(named("biped-hop").is_none());
    }

    #[test]
    fn the_ripple_keeps_four_feet_down_and_the_gallop_flies() {
        let ripple = named("hexapod-ripple").unwrap();
        for s in ripple.sample(600) {
            assert_eq!(s.stance.len(), 4, "{}", s.tau);
            // One leg per side in the air.
            let left = s.stance.iter().filter(|&&i| i < 3).count();
            assert_eq!(left, 2, "{}", s.tau);
        }
        // The gallop's feet land hind, hind, fore, fore (LH 0.7, RH 0.8,
        // LF 0.1, RF 0.2) and it flies from RF's lift-off at 0.5 to LH's
        // touch-down at 0.7: a fifth of the cycle with no foot down.
        let gallop = named("quadruped-gallop").unwrap();
        let samples = gallop.sample(1000);
        let airborne: Vec<f64> = samples
            .iter()
            .filter(|s| s.stance.is_empty())
            .map(|s| s.tau)
            .collect();
        assert_eq!(airborne.len(), 200);
        assert!(airborne.iter().all(|t| (0.5..0.7).contains(t)));
        assert!(min_margin(&samples).is_none());
    }

    #[test]
    fn speed_is_stride_over_stance_time() {
        // The lesson's example: L = 0.2 m, β = 3/4, T = 2 s → 0.1333 m/s.
        let v = crawl(0.75).speed(2.0).unwrap();
        assert!((v - 0.2 / 1.5).abs() < 1e-12);
        // A stance foot moves at −v in the body frame.
        let g = crawl(0.75);
        let (t0, t1) = (0.5, 0.6);
        let dx = g.foot(2, t1).unwrap()[0] - g.foot(2, t0).unwrap()[0];
        assert!((dx / ((t1 - t0) * 2.0) + v).abs() < 1e-12);
        assert_eq!(g.speed(0.0).unwrap_err().field, "period");
    }

    #[test]
    fn bad_gaits_name_the_field() {
        let mut g = crawl(1.0);
        assert_eq!(g.check().unwrap_err().field, "duty_factor");
        g.duty_factor = 0.75;
        g.legs[2].phase = 1.0;
        assert_eq!(g.check().unwrap_err().field, "legs[2].phase");
        g.legs.clear();
        assert_eq!(g.check().unwrap_err().field, "legs");
        let e = Gait::from_json(r#"{"duty_factor": 0.5, "stride": 0.1, "legs": [{"name": "a", "x": 0, "y": 0, "phase": "x"}]}"#)
            .unwrap_err();
        assert_eq!(e.field, "legs[0].phase");
    }
}
