//! Textbook special cases. The general model must agree with each of them;
//! the tests check that it does.

use crate::error::{FieldError, finite, positive};
use kinolab_common::trig;

/// A differential drive's motion from its wheel ground speeds.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct DiffDriveMotion {
    /// Forward speed v = (V_R + V_L)/2.
    pub v: f64,
    /// Turn rate ω = (V_R − V_L)/W.
    pub omega: f64,
    /// Turn radius R = W(V_R + V_L)/(2(V_R − V_L)) from the axle centre to
    /// the ICR (positive: to the left); `None` when driving straight.
    pub radius: Option<f64>,
}

/// Differential drive with wheel separation `track` W and left/right wheel
/// ground speeds V_L, V_R (m/s).
pub fn differential_drive(
    track: f64,
    v_left: f64,
    v_right: f64,
) -> Result<DiffDriveMotion, FieldError> {
    let w = positive("track", track)?;
    finite("v_left", v_left)?;
    finite("v_right", v_right)?;
    let diff = v_right - v_left;
    Ok(DiffDriveMotion {
        v: (v_right + v_left) / 2.0,
        omega: diff / w,
        radius: (diff != 0.0).then(|| w * (v_right + v_left) / (2.0 * diff)),
    })
}

/// A tricycle's (or bicycle's) motion from its steered front wheel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TricycleMotion {
    /// R = L/tan s, from the rear-axle centre to the ICR; `None` when straight.
    pub turn_radius: Option<f64>,
    /// R_d = L/sin s, the front wheel's path radius; `None` when straight.
    pub front_radius: Option<f64>,
    /// θ̇ = v sin s / L.
    pub omega: f64,
    /// Speed of the rear-axle centre, v cos s.
    pub rear_speed: f64,
}

/// Front wheel at `wheelbase` L ahead of the rear-axle centre, steered by
/// `steer` s (rad, positive left), rolling at ground speed `front_speed` v.
pub fn tricycle(
    wheelbase: f64,
    steer: f64,
    front_speed: f64,
) -> Result<TricycleMotion, FieldError> {
    let l = positive("wheelbase", wheelbase)?;
    finite("steer", steer)?;
    finite("front_speed", front_speed)?;
    if trig::cos(steer).abs() < 1e-12 {
        return Err(FieldError::new(
            "steer",
            "at ±90° the front wheel pushes sideways and the rear axle cannot follow",
        ));
    }
    let (s, c) = trig::sin_cos(steer);
    let straight = s == 0.0;
    Ok(TricycleMotion {
        turn_radius: (!straight).then(|| l * c / s),
        front_radius: (!straight).then(|| l / s),
        omega: front_speed * s / l,
        rear_speed: front_speed * c,
    })
}

/// The outer wheel's steering angle for an Ackermann linkage, from the
/// inner one: cot s_o − cot s_i = w/L (both angles positive, inner larger).
pub fn ackermann_outer(wheelbase: f64, track: f64, inner: f64) -> Result<f64, FieldError> {
    let l = positive("wheelbase", wheelbase)?;
    let w = positive("track", track)?;
    finite("inner", inner)?;
    if inner <= 0.0 || inner >= std::f64::consts::FRAC_PI_2 {
        return Err(FieldError::new(
            "inner",
            "the inner steering angle must lie strictly between 0 and 90°",
        ));
    }
    let cot_outer = 1.0 / trig::tan(inner) + w / l;
    Ok((1.0 / cot_outer).atan())
}

/// Gear pair: the driven gear's speed and torque from the driving gear's,
/// ω₂ = (r₁/r₂) ω₁ and τ₂ = (r₂/r₁) τ₁ (losses ignored).
pub fn gear(r1: f64, r2: f64, omega1: f64, torque1: f64) -> Result<(f64, f64), FieldError> {
    let r1 = positive("r1", r1)?;
    let r2 = positive("r2", r2)?;
    finite("omega1", omega1)?;
    finite("torque1", torque1)?;
    Ok((r1 / r2 * omega1, r2 / r1 * torque1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn differential_drive_golden_values() {
        let m = differential_drive(0.5, 0.2, 0.4).unwrap();
        assert!((m.v - 0.3).abs() < 1e-15);
        assert!((m.omega - 0.4).abs() < 1e-15);
        assert!((m.radius.unwrap() - 0.75).abs() < 1e-15);
        assert_eq!(differential_drive(0.5, 1.0, 1.0).unwrap().radius, None);
        assert_eq!(
            differential_drive(0.0, 1.0, 1.0).unwrap_err().field,
            "track"
        );
    }

    #[test]
    fn tricycle_and_ackermann() {
        let t = tricycle(1.0, std::f64::consts::FRAC_PI_4, 2.0).unwrap();
        assert!((t.turn_radius.unwrap() - 1.0).abs() < 1e-12);
        assert!((t.front_radius.unwrap() - 2f64.sqrt()).abs() < 1e-12);
        assert!((t.omega - 2f64.sqrt()).abs() < 1e-12);
        // Inner 45° on L = 2, w = 1: cot s_o = 1 + 0.5.
        let outer = ackermann_outer(2.0, 1.0, std::f64::consts::FRAC_PI_4).unwrap();
        assert!((1.0 / outer.tan() - 1.5).abs() < 1e-12);
        assert!(ackermann_outer(2.0, 1.0, 0.0).is_err());
    }

    #[test]
    fn gears_trade_speed_for_torque() {
        let (w2, t2) = gear(0.01, 0.04, 100.0, 0.5).unwrap();
        assert!((w2 - 25.0).abs() < 1e-12 && (t2 - 2.0).abs() < 1e-12);
        assert!((w2 * t2 - 100.0 * 0.5).abs() < 1e-12, "power is kept");
    }
}
