//! One wheel: its kind, where it sits on the chassis, and the two
//! constraint rows it contributes (reference sheet, "One row per constraint").

use kinolab_common::angle::wrap;
use kinolab_common::trig;
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

/// The five kinds of wheel, with the parameters only that kind has.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum WheelKind {
    /// A standard wheel bolted to the chassis: β never changes.
    Fixed,
    /// A standard wheel turned about a vertical axis through its centre.
    Steered,
    /// A wheel that trails behind its vertical steering axis by `offset` d,
    /// so it swings into line with the motion by itself.
    Castor { offset: f64 },
    /// A wheel with free rollers on its rim at angle `gamma` (radians) to the
    /// wheel plane: 0 is the 90° "omni" wheel, π/4 the mecanum wheel.
    Swedish { gamma: f64 },
    /// A ball: rolls in any direction.
    Spherical,
}

impl WheelKind {
    /// The kind's name in robot files.
    pub fn name(&self) -> &'static str {
        match self {
            WheelKind::Fixed => "fixed",
            WheelKind::Steered => "steered",
            WheelKind::Castor { .. } => "castor",
            WheelKind::Swedish { .. } => "swedish",
            WheelKind::Spherical => "spherical",
        }
    }

    /// Only fixed and steered standard wheels restrict how the chassis moves;
    /// every other kind can follow any chassis motion.
    pub fn constrains_chassis(&self) -> bool {
        matches!(self, WheelKind::Fixed | WheelKind::Steered)
    }

    /// Whether β is a steering angle that may change.
    pub fn is_steerable(&self) -> bool {
        matches!(self, WheelKind::Steered | WheelKind::Castor { .. })
    }
}

/// A wheel on the chassis. Angles in radians, lengths in metres.
#[derive(Debug, Clone, PartialEq)]
pub struct Wheel {
    pub kind: WheelKind,
    /// Direction of the wheel centre from the chassis point P.
    pub alpha: f64,
    /// Angle of the wheel plane relative to the line from P to the wheel
    /// (for steered wheels and castors: the current steering angle).
    pub beta: f64,
    /// Distance of the wheel centre from P.
    pub l: f64,
    pub radius: f64,
    /// Wheels with the same name are turned by one steering input.
    pub steer_group: Option<String>,
}

/// What a wheel's sliding row carries besides the chassis twist.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SlidingExtra {
    /// Standard wheels: `sliding · ξ̇_R = 0`.
    None,
    /// Castor: `sliding · ξ̇_R + d β̇ = 0`.
    SteerRate { offset: f64 },
    /// Swedish: `sliding · ξ̇_R − r sin γ φ̇ − r_sw φ̇_sw = 0`; the rollers
    /// absorb whatever is left.
    Rollers { spin_gain: f64 },
    /// Spherical: the ball has no sliding constraint at all.
    Free,
}

/// A wheel's two constraint rows, with ξ̇_R = [ẋ_R, ẏ_R, θ̇]ᵀ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelRows {
    /// Rolling: `rolling · ξ̇_R = spin_gain · φ̇`.
    pub rolling: Vector3<f64>,
    pub spin_gain: f64,
    /// Sliding (orthogonal to the wheel plane, or to the rollers).
    pub sliding: Vector3<f64>,
    pub sliding_extra: SlidingExtra,
}

impl Wheel {
    pub fn new(kind: WheelKind, alpha: f64, beta: f64, l: f64, radius: f64) -> Self {
        Self {
            kind,
            alpha,
            beta,
            l,
            radius,
            steer_group: None,
        }
    }

    /// The same wheel, steered by the input called `group`.
    pub fn in_group(mut self, group: &str) -> Self {
        self.steer_group = Some(group.to_owned());
        self
    }

    /// A wheel placed by its centre (x, y) in the robot frame and the
    /// direction it rolls forward, `heading` (radians from the x axis).
    /// Converts to the (l, α, β) of the reference sheet.
    pub fn at(kind: WheelKind, x: f64, y: f64, heading: f64, radius: f64) -> Self {
        let l = x.hypot(y);
        let alpha = if l > 0.0 { trig::atan2(y, x) } else { 0.0 };
        // Rolling forward along (sin(α+β), −cos(α+β)) = (cos h, sin h)
        // means α + β = h + π/2.
        let beta = wrap(heading + std::f64::consts::FRAC_PI_2 - alpha);
        Self::new(kind, alpha, beta, l, radius)
    }

    /// Centre of the wheel in the robot frame.
    pub fn position(&self) -> [f64; 2] {
        [
            self.l * trig::cos(self.alpha),
            self.l * trig::sin(self.alpha),
        ]
    }

    /// Unit vector along the axle, n = (cos(α+β), sin(α+β)): the wheel
    /// cannot slide this way.
    pub fn axle(&self) -> [f64; 2] {
        let (s, c) = trig::sin_cos(self.alpha + self.beta);
        [c, s]
    }

    /// Unit vector the wheel rolls along when φ̇ > 0: (sin(α+β), −cos(α+β)).
    pub fn rolling_direction(&self) -> [f64; 2] {
        let [c, s] = self.axle();
        [s, -c]
    }

    /// The wheel's zero-motion line: through the centre, along the axle.
    /// For a standard wheel the ICR must lie on it.
    pub fn zero_motion_line(&self) -> ([f64; 2], [f64; 2]) {
        (self.position(), self.axle())
    }

    /// The rolling and sliding rows exactly as in the reference sheet.
    pub fn rows(&self) -> WheelRows {
        let (l, a, b, r) = (self.l, self.alpha, self.beta, self.radius);
        let (sab, cab) = trig::sin_cos(a + b);
        let (sb, cb) = trig::sin_cos(b);
        let standard_rolling = Vector3::new(sab, -cab, -l * cb);
        let standard_sliding = Vector3::new(cab, sab, l * sb);
        match self.kind {
            WheelKind::Fixed | WheelKind::Steered => WheelRows {
                rolling: standard_rolling,
                spin_gain: r,
                sliding: standard_sliding,
                sliding_extra: SlidingExtra::None,
            },
            WheelKind::Castor { offset } => WheelRows {
                rolling: standard_rolling,
                spin_gain: r,
                sliding: Vector3::new(cab, sab, offset + l * sb),
                sliding_extra: SlidingExtra::SteerRate { offset },
            },
            WheelKind::Swedish { gamma } => {
                let (sabg, cabg) = trig::sin_cos(a + b + gamma);
                let (sbg, cbg) = trig::sin_cos(b + gamma);
                WheelRows {
                    rolling: Vector3::new(sabg, -cabg, -l * cbg),
                    spin_gain: r * trig::cos(gamma),
                    sliding: Vector3::new(cabg, sabg, l * sbg),
                    sliding_extra: SlidingExtra::Rollers {
                        spin_gain: r * trig::sin(gamma),
                    },
                }
            }
            WheelKind::Spherical => WheelRows {
                rolling: standard_rolling,
                spin_gain: r,
                sliding: standard_sliding,
                sliding_extra: SlidingExtra::Free,
            },
        }
    }

    /// Velocity of the wheel's contact point for a chassis twist, in the
    /// robot frame: (ẋ − θ̇ y, ẏ + θ̇ x) at the wheel centre (x, y).
    pub fn contact_velocity(&self, twist: &Vector3<f64>) -> [f64; 2] {
        let [x, y] = self.position();
        [twist.x - twist.z * y, twist.y + twist.z * x]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

    fn close(a: &Vector3<f64>, b: [f64; 3]) -> bool {
        (a - Vector3::from(b)).norm() < 1e-12
    }

    #[test]
    fn fixed_wheel_rows_match_the_sheet() {
        // Siegwart's left wheel: α = π/2, β = 0, l = 1.
        let w = Wheel::new(WheelKind::Fixed, FRAC_PI_2, 0.0, 1.0, 1.0);
        let rows = w.rows();
        assert!(close(&rows.rolling, [1.0, 0.0, -1.0]));
        assert!(close(&rows.sliding, [0.0, 1.0, 0.0]));
        // Right wheel: α = −π/2, β = π.
        let w = Wheel::new(WheelKind::Fixed, -FRAC_PI_2, PI, 1.0, 1.0);
        assert!(close(&w.rows().rolling, [1.0, 0.0, 1.0]));
        assert!(close(&w.rows().sliding, [0.0, 1.0, 0.0]));
    }

    #[test]
    fn castor_and_swedish_rows_carry_their_extra_terms() {
        let c = Wheel::new(WheelKind::Castor { offset: 0.04 }, PI, 0.0, 0.3, 0.05);
        let rows = c.rows();
        assert!(close(&rows.sliding, [-1.0, 0.0, 0.04]));
        assert_eq!(rows.sliding_extra, SlidingExtra::SteerRate { offset: 0.04 });
        let s = Wheel::new(WheelKind::Swedish { gamma: FRAC_PI_4 }, 0.0, 0.0, 0.2, 0.05);
        let rows = s.rows();
        let h = FRAC_PI_4.sin();
        assert!(close(&rows.rolling, [h, -h, -0.2 * h]));
        assert!(close(&rows.sliding, [h, h, 0.2 * h]));
        assert!((rows.spin_gain - 0.05 * h).abs() < 1e-15);
    }

    #[test]
    fn rows_are_the_contact_velocity_along_and_across_the_wheel() {
        let w = Wheel::new(WheelKind::Steered, 0.7, -1.1, 0.45, 0.1);
        let twist = Vector3::new(0.3, -0.8, 1.7);
        let u = w.contact_velocity(&twist);
        let n = w.axle();
        let t = w.rolling_direction();
        let rows = w.rows();
        assert!((rows.sliding.dot(&twist) - (n[0] * u[0] + n[1] * u[1])).abs() < 1e-12);
        assert!((rows.rolling.dot(&twist) - (t[0] * u[0] + t[1] * u[1])).abs() < 1e-12);
    }

    #[test]
    fn placing_by_position_and_heading() {
        let w = Wheel::at(WheelKind::Fixed, 0.0, 0.25, 0.0, 0.1);
        assert!((w.alpha - FRAC_PI_2).abs() < 1e-15 && w.beta.abs() < 1e-15);
        let [tx, ty] = w.rolling_direction();
        assert!((tx - 1.0).abs() < 1e-15 && ty.abs() < 1e-15);
        let w = Wheel::at(WheelKind::Fixed, 0.0, -0.25, 0.0, 0.1);
        assert!((w.beta.abs() - PI).abs() < 1e-12);
    }

    #[test]
    fn wrap_lands_in_half_open_interval() {
        assert_eq!(wrap(PI), PI);
        assert!((wrap(-PI) - PI).abs() < 1e-15);
        assert!((wrap(3.0 * PI + 0.1) - (-PI + 0.1)).abs() < 1e-12);
        assert!((wrap(-0.5) + 0.5).abs() < 1e-15);
    }
}
