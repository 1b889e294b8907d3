//! Angles: one wrapping rule for the whole lab, (−π, π].

use std::f64::consts::{PI, TAU};

/// `angle` wrapped to (−π, π]: π stays π, −π becomes π.
pub fn wrap(angle: f64) -> f64 {
    let a = (angle + PI).rem_euclid(TAU) - PI;
    if a <= -PI { a + TAU } else { a }
}

/// [`wrap`] for angles already within (−3π, 3π], as a controller's are:
/// two comparisons instead of a division, for integrators' inner loops.
/// Outside that range it falls back to [`wrap`].
#[inline]
pub fn wrap_near(angle: f64) -> f64 {
    if angle > PI {
        if angle <= 3.0 * PI {
            angle - TAU
        } else {
            wrap(angle)
        }
    } else if angle <= -PI {
        if angle > -3.0 * PI {
            angle + TAU
        } else {
            wrap(angle)
        }
    } else {
        angle
    }
}

/// Degrees with the last bits rounded away, so that 90° computed from π/2
/// reads 90 and not 89.99999999999999; never −0.
pub fn degrees(radians: f64) -> f64 {
    let d = (radians.to_degrees() * 1e9).round() / 1e9;
    if d == 0.0 { 0.0 } else { d }
}

/// `x` rounded to the nearest multiple of `step` (a grid for dragging);
/// never −0, so a snapped value prints as it looks.
pub fn snap(x: f64, step: f64) -> f64 {
    let s = (x / step).round() * step;
    if s == 0.0 { 0.0 } else { s }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn wrap_lands_in_the_half_open_interval() {
        assert_eq!(wrap(PI), PI);
        assert_eq!(wrap(-PI), PI);
        assert_eq!(wrap(0.0), 0.0);
        assert!((wrap(3.0 * PI / 2.0) + PI / 2.0).abs() < 1e-15);
        assert!((wrap(-7.0 * PI / 2.0) - PI / 2.0).abs() < 1e-12);
    }

    #[test]
    fn degrees_and_snap_never_print_minus_zero() {
        assert_eq!(degrees(PI / 2.0), 90.0);
        assert_eq!(degrees(-1e-20).to_string(), "0");
        assert_eq!(snap(-0.01, 0.05).to_string(), "0");
        assert_eq!(snap(0.126, 0.05), 0.15000000000000002);
    }

    proptest! {
        #[test]
        fn wrap_is_in_range_and_keeps_the_direction(a in -1e4f64..1e4) {
            let w = wrap(a);
            prop_assert!(w > -PI && w <= PI);
            prop_assert!((w.sin() - a.sin()).abs() < 1e-9 && (w.cos() - a.cos()).abs() < 1e-9);
        }

        #[test]
        fn near_wrap_agrees_with_wrap_everywhere(a in -50.0f64..50.0) {
            prop_assert!((wrap_near(a) - wrap(a)).abs() < 1e-12);
        }
    }
}
