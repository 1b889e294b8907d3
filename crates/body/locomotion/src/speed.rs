//! Speed and gait: which gait suits a speed, measured against the walker's
//! size by the Froude number, and how fast the oscillators must turn for
//! that gait to carry the body at that speed.

use serde::Serialize;

use crate::error::FieldError;
use crate::gait::{Gait, named};
use crate::transport::STANDARD_GRAVITY;

/// The Froude number v² / (g l) of a walker with leg length `leg` (m)
/// moving at `speed` (m/s): the ratio that makes walkers of every size
/// comparable.
pub fn froude(speed: f64, leg: f64) -> Result<f64, FieldError> {
    let speed = kinolab_common::error::bounded("speed", speed, 100.0)?;
    let leg = kinolab_common::error::length("leg", leg)?;
    Ok(speed * speed / (STANDARD_GRAVITY * leg))
}

/// The quadruped gait animals of every size choose at Froude number `fr`
/// (after Alexander and Jayes): walk below about 0.5, trot up to about
/// 2.5, gallop above.
pub fn quadruped_gait_for(fr: f64) -> &'static str {
    if fr < 0.5 {
        "walk"
    } else if fr < 2.5 {
        "trot"
    } else {
        "gallop"
    }
}

/// A quadruped moving at a chosen speed: the gait it picks and the rhythm
/// that gait needs.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Pace {
    pub speed: f64,
    pub froude: f64,
    /// The named gait (`quadruped-crawl`, `-trot` or `-gallop`) with the
    /// walker's stride.
    #[serde(skip)]
    pub gait: Gait,
    /// f = βv / L, Hz: from v = L / (βT) with T = 1/f.
    pub frequency: f64,
}

/// The pace of a quadruped with legs `leg` m long and stride `stride` m at
/// `speed` m/s. The stride is held fixed; real animals also lengthen it as
/// they speed up, which lowers the frequency this returns.
pub fn quadruped_pace(speed: f64, leg: f64, stride: f64) -> Result<Pace, FieldError> {
    let fr = froude(speed, leg)?;
    let stride = kinolab_common::error::length("stride", stride)?;
    let id = match quadruped_gait_for(fr) {
        "walk" => "quadruped-crawl",
        "trot" => "quadruped-trot",
        _ => "quadruped-gallop",
    };
    let mut gait = named(id).ok_or_else(|| FieldError::new("gait", format!("no gait {id}")))?;
    gait.stride = stride;
    let frequency = gait.duty_factor * speed / stride;
    Ok(Pace {
        speed,
        froude: fr,
        gait,
        frequency,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn froude_numbers_and_gaits() {
        // A 0.5 m leg at 1.566 m/s: Fr = 1.566² / (9.80665 · 0.5) ≈ 0.5.
        let fr = froude(1.566, 0.5).unwrap();
        assert!((fr - 0.5).abs() < 1e-3, "{fr}");
        assert_eq!(quadruped_gait_for(0.2), "walk");
        assert_eq!(quadruped_gait_for(1.0), "trot");
        assert_eq!(quadruped_gait_for(3.0), "gallop");
        assert_eq!(froude(1.0, 0.0).unwrap_err().field, "leg");
    }

    #[test]
    fn the_pace_switches_gait_at_the_froude_thresholds() {
        // l = 0.5 m: Fr = 0.5 at √(0.5 g l) ≈ 1.566 m/s, 2.5 at ≈ 3.501 m/s.
        let switch = |fr: f64| (fr * STANDARD_GRAVITY * 0.5).sqrt();
        let ids: Vec<String> = [
            0.5,
            switch(0.5) - 1e-3,
            switch(0.5) + 1e-3,
            3.0,
            switch(2.5) + 1e-3,
        ]
        .iter()
        .map(|&v| quadruped_pace(v, 0.5, 0.4).unwrap().gait.name)
        .collect();
        assert_eq!(
            ids,
            [
                "quadruped-crawl",
                "quadruped-crawl",
                "quadruped-trot",
                "quadruped-trot",
                "quadruped-gallop"
            ]
        );
    }

    #[test]
    fn the_frequency_carries_the_body_at_the_speed() {
        for v in [0.3, 1.2, 2.0, 3.3, 4.5] {
            let pace = quadruped_pace(v, 0.5, 0.4).unwrap();
            let back = pace.gait.speed(1.0 / pace.frequency).unwrap();
            assert!((back - v).abs() < 1e-12, "{v}: {back}");
            assert_eq!(pace.gait.stride, 0.4);
        }
        assert_eq!(quadruped_pace(1.0, 0.5, 0.0).unwrap_err().field, "stride");
        assert_eq!(
            quadruped_pace(f64::NAN, 0.5, 0.4).unwrap_err().field,
            "speed"
        );
    }
}
