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
    if !(energy.is_finite() && energy >= 0.0) {
        return Err(FieldError::new(
            "energy",
            format!("must be a finite number ≥ 0, got {energy}"),
        ));
    }
    let mass = kinolab_common::error::positive("mass", mass)?;
    let distance = kinolab_common::error::positive("distance", distance)?;
    let gravity = kinolab_common::error::positive("gravity", gravity)?;
    Ok(energy / (mass * gravity * distance))
}
