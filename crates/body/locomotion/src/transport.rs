//! Cost of transport: energy per unit weight per unit distance.

use crate::error::FieldError;

/// Standard gravity, m/s².
pub const STANDARD_GRAVITY: f64 = 9.806_65;

/// `COT = E / (m g d)`: dimensionless; lower is more efficient.
///
/// `energy` in joules, `mass` in kilograms, `distance` in metres, `gravity`
/// in m/s² (use [`STANDARD_GRAVITY`] on Earth).
pub fn cost_of_transport(
    energy: f64,
    mass: f64,
    distance: f64,
    gravity: f64,
) -> Result<f64, FieldError> {
    let energy = kinolab_common::error::non_negative("energy", energy)?;
    let mass = kinolab_common::error::positive("mass", mass)?;
    let distance = kinolab_common::error::positive("distance", distance)?;
    let gravity = kinolab_common::error::positive("gravity", gravity)?;
    Ok(energy / (mass * gravity * distance))
}

/// `COT = P / (m g v)`: the same ratio for a walker that keeps up `power`
/// watts at `speed` m/s, since over any time t it spends E = P t on
/// d = v t. Ties a gait's speed (see [`crate::Gait::speed`]) to its cost.
pub fn cost_of_transport_at_speed(
    power: f64,
    mass: f64,
    speed: f64,
    gravity: f64,
) -> Result<f64, FieldError> {
    let power = kinolab_common::error::non_negative("power", power)?;
    let speed = kinolab_common::error::positive("speed", speed)?;
    // E = P · 1 s over d = v · 1 s.
    cost_of_transport(power, mass, speed, gravity)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_at_speed_matches_energy_over_distance() {
        // 20 kg at 0.5 m/s drawing 98.0665 W: COT = 98.0665 / (20 g 0.5) = 1.
        let cot = cost_of_transport_at_speed(98.066_5, 20.0, 0.5, STANDARD_GRAVITY).unwrap();
        assert!((cot - 1.0).abs() < 1e-12);
        // The same walker over 60 s: E = 5884 J, d = 30 m.
        let e = cost_of_transport(98.066_5 * 60.0, 20.0, 30.0, STANDARD_GRAVITY).unwrap();
        assert!((e - cot).abs() < 1e-12);
        assert_eq!(
            cost_of_transport_at_speed(-1.0, 20.0, 0.5, STANDARD_GRAVITY)
                .unwrap_err()
                .field,
            "power"
        );
        assert_eq!(
            cost_of_transport_at_speed(10.0, 20.0, 0.0, STANDARD_GRAVITY)
                .unwrap_err()
                .field,
            "speed"
        );
    }
}
