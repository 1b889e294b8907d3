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
    let exact = crate::gait::leg_events(legs)?;
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
