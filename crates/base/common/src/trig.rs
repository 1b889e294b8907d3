//! Sine, cosine, tangent and atan2 for every core kernel.
//!
//! Rust's own `f64::sin` and friends call the platform's maths library:
//! glibc natively, a port of musl's routines in wasm. The two agree to the
//! last bit or two, and a simulation that runs for thousands of steps can
//! turn such a bit into a visibly different path, so the command line and
//! the browser would not always show the same run. These functions call
//! the `libm` crate (that same musl port) on every target: one set of
//! results everywhere. They are also the faster ones here: `sin_cos`
//! reduces the argument once for both values, and on this machine libm's
//! sine and atan2 take about half glibc's time. The accuracy is musl's
//! (errors under one unit in the last place), not an approximation.

/// Sine and cosine of `x` (radians), with one argument reduction.
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    libm::sincos(x)
}

/// Sine of `x` (radians).
#[inline]
pub fn sin(x: f64) -> f64 {
    libm::sin(x)
}

/// Cosine of `x` (radians).
#[inline]
pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}

/// Tangent of `x` (radians).
#[inline]
pub fn tan(x: f64) -> f64 {
    libm::tan(x)
}

/// The angle of the point (`x`, `y`) from the x axis, in (−π, π].
#[inline]
pub fn atan2(y: f64, x: f64) -> f64 {
    libm::atan2(y, x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn known_values() {
        let (s, c) = sin_cos(std::f64::consts::FRAC_PI_6);
        assert!((s - 0.5).abs() < 1e-15);
        assert!((c - 3f64.sqrt() / 2.0).abs() < 1e-15);
        assert_eq!(atan2(0.0, -1.0), std::f64::consts::PI);
        assert_eq!(atan2(1.0, 0.0), std::f64::consts::FRAC_PI_2);
        assert!((tan(std::f64::consts::FRAC_PI_4) - 1.0).abs() < 1e-15);
    }

    proptest! {
        /// Within a few units in the last place of the platform's own.
        #[test]
        fn agrees_with_the_platform(x in -1e3f64..1e3, y in -1e3f64..1e3) {
            let (s, c) = sin_cos(x);
            prop_assert!((s - x.sin()).abs() <= 4.0 * f64::EPSILON);
            prop_assert!((c - x.cos()).abs() <= 4.0 * f64::EPSILON);
            prop_assert_eq!(s, sin(x));
            prop_assert_eq!(c, cos(x));
            prop_assert!((atan2(y, x) - y.atan2(x)).abs() <= 4.0 * f64::EPSILON);
        }
    }
}
