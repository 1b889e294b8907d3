//! The reports of `kinolab leg-events` and `kinolab stability`, shared with
//! the JS API (snake_case, as the command-line contract spells fields).

use serde::Serialize;

use crate::error::FieldError;
use crate::stability::{Point, static_stability};

/// N = (2k − 1)! for k legs: exact as a decimal string (it outgrows
/// JavaScript numbers) and as a float.
#[derive(Debug, Clone, Serialize)]
pub struct LegEventsReport {
    pub legs: u32,
    pub events: String,
    pub events_f64: f64,
}

pub fn leg_events(legs: u32) -> Result<LegEventsReport, FieldError> {
    let exact = crate::events::leg_events(legs)?;
    Ok(LegEventsReport {
        legs,
        events: exact.to_string(),
        events_f64: exact as f64,
    })
}

/// Static stability of a standing walker.
#[derive(Debug, Clone, Serialize)]
pub struct StabilityReport {
    pub stable: bool,
    pub margin: f64,
    pub support_polygon: Vec<Point>,
    pub nearest_edge_point: Point,
}

pub fn stability(com: Point, feet: &[Point]) -> Result<StabilityReport, FieldError> {
    let s = static_stability(com, feet)?;
    Ok(StabilityReport {
        stable: s.stable,
        margin: s.margin,
        support_polygon: s.polygon,
        nearest_edge_point: s.nearest,
    })
}

/// One sample of `kinolab gait`.
#[derive(Debug, Clone, Serialize)]
pub struct GaitSampleReport {
    pub tau: f64,
    pub stance: Vec<String>,
    pub feet: Vec<Point>,
    /// `None` (null) with no foot down: the margin is undefined.
    pub margin: Option<f64>,
}

/// `kinolab gait`: the cycle sampled, its smallest margin, and whether it
/// is statically stable.
#[derive(Debug, Clone, Serialize)]
pub struct GaitReport {
    pub name: String,
    pub samples: Vec<GaitSampleReport>,
    /// `None` when some sample has no foot down.
    pub min_margin: Option<f64>,
    pub statically_stable: bool,
    /// How far the body moves forward in one cycle time T: L/β, m (its
    /// speed is L/(βT)).
    pub body_speed_per_cycle: f64,
}

/// The most samples of one `kinolab gait`.
pub const MAX_GAIT_SAMPLES: usize = 100_000;

pub fn gait(g: &crate::Gait, samples: usize) -> Result<GaitReport, FieldError> {
    g.check()?;
    if samples == 0 || samples > MAX_GAIT_SAMPLES {
        return Err(FieldError::new(
            "samples",
            format!("must be from 1 to {MAX_GAIT_SAMPLES}, got {samples}"),
        ));
    }
    let instants = g.sample(samples);
    let min_margin = crate::gait::min_margin(&instants);
    Ok(GaitReport {
        name: g.name.clone(),
        samples: instants
            .into_iter()
            .map(|s| GaitSampleReport {
                tau: s.tau,
                stance: s.stance.iter().map(|&i| g.legs[i].name.clone()).collect(),
                feet: s.feet,
                margin: s.margin,
            })
            .collect(),
        statically_stable: min_margin.is_some_and(|m| m > 0.0),
        min_margin,
        body_speed_per_cycle: g.stride / g.duty_factor,
    })
}

/// `kinolab cpg`: where the oscillators ended and whether they locked.
#[derive(Debug, Clone, Serialize)]
pub struct CpgReport {
    pub legs: Vec<String>,
    /// θᵢ at `duration`, degrees, not wrapped.
    pub final_deg: Vec<f64>,
    /// ((θ₀ − θᵢ)/2π) mod 1.
    pub lag: Vec<f64>,
    /// The lags the coupling aims at in the end: (φᵢ − φ₀) mod 1.
    pub target_lag: Vec<f64>,
    pub locked: bool,
    pub steps: usize,
}

pub fn cpg(c: &crate::Cpg) -> Result<CpgReport, FieldError> {
    Ok(settled(&c.legs, c.run()?))
}

/// What `kinolab cpg` prints for a run that ended at `s` (the lab's CPG
/// widget shows the same numbers at the instant it shows).
pub fn settled(legs: &[String], s: crate::cpg::Settled) -> CpgReport {
    CpgReport {
        legs: legs.to_vec(),
        final_deg: s.theta.iter().map(|t| t.to_degrees()).collect(),
        lag: s.lag,
        target_lag: s.target_lag,
        locked: s.locked,
        steps: s.steps,
    }
}
