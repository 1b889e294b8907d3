//! The frog and two flies: the plainest case of blending against choosing.
//! Each fly releases a "snap at it" pull of length 1 towards it. Blended,
//! the pulls add up to a direction between the flies; chosen, the nearer
//! fly's pull alone decides.

use serde::Serialize;

use crate::Vec2;

/// How the two pulls are combined.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Combine {
    /// Vector summation.
    Blend,
    /// Winner takes all: the nearest fly.
    Choose,
}

/// Where the tongue goes and what it catches.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Strike {
    /// Unit direction of the tongue.
    pub direction: [f64; 2],
    /// How far it reaches, m: as far as the farthest fly.
    pub reach: f64,
    /// The fly it catches, if any.
    pub caught: Option<usize>,
}

/// A fly is caught when the tongue passes within this distance, m.
pub const FLY_RADIUS: f64 = 0.05;

/// The frog at `frog` snaps at `flies`, combining their pulls by `how`.
pub fn strike(frog: Vec2, flies: &[Vec2], how: Combine) -> Option<Strike> {
    let pulls: Vec<(usize, Vec2, f64)> = flies
        .iter()
        .enumerate()
        .filter_map(|(i, f)| {
            let d = (f - frog).norm();
            (d > 1e-9).then(|| (i, (f - frog) / d, d))
        })
        .collect();
    let direction = match how {
        Combine::Blend => pulls.iter().map(|p| p.1).sum::<Vec2>(),
        Combine::Choose => pulls.iter().min_by(|a, b| a.2.total_cmp(&b.2))?.1,
    };
    let direction = direction.try_normalize(1e-12)?;
    let reach = pulls.iter().map(|p| p.2).fold(0.0, f64::max);
    let caught = flies
        .iter()
        .enumerate()
        .filter(|(_, f)| {
            let along = (*f - frog).dot(&direction).clamp(0.0, reach);
            ((*f - frog) - direction * along).norm() <= FLY_RADIUS
        })
        .min_by(|a, b| (a.1 - frog).norm().total_cmp(&(b.1 - frog).norm()))
        .map(|(i, _)| i);
    Some(Strike {
        direction: [direction.x, direction.y],
        reach,
        caught,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blending_two_flies_misses_both_and_choosing_catches_one() {
        let frog = Vec2::new(0.0, 0.0);
        let flies = [Vec2::new(-0.3, 0.4), Vec2::new(0.35, 0.45)];
        let blend = strike(frog, &flies, Combine::Blend).unwrap();
        assert_eq!(blend.caught, None);
        // Two pulls of length 1 at ±37° and 38° from straight up add to a
        // direction close to straight up.
        assert!(blend.direction[0].abs() < 0.05 && blend.direction[1] > 0.99);
        let choose = strike(frog, &flies, Combine::Choose).unwrap();
        assert_eq!(choose.caught, Some(0), "the nearer fly");
        // Two flies in a line: blending works as well as choosing.
        let lined = [Vec2::new(0.0, 0.3), Vec2::new(0.0, 0.6)];
        assert_eq!(
            strike(frog, &lined, Combine::Blend).unwrap().caught,
            Some(0)
        );
        assert_eq!(strike(frog, &[], Combine::Choose), None);
    }
}
