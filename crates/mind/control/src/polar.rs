//! The polar go-to-pose controller (Siegwart, Nourbakhsh & Scaramuzza §3.6).
//!
//! Put the goal at the origin with heading 0. Seen from the robot, the goal
//! is at distance ρ and bearing α off its nose; β is the heading the robot
//! would still have to turn through once it got there. The control law is
//! linear in these three numbers: v = k_ρ ρ, ω = k_α α + k_β β.

use kinolab_common::trig;
use std::f64::consts::{FRAC_PI_2, PI};

use nalgebra::{Complex, Matrix3};
use serde::{Deserialize, Serialize};

use crate::error::{FieldError, finite};
use kinolab_common::angle::{wrap, wrap_near};

use crate::pose::Pose;

/// The three gains (k_ρ, k_α, k_β).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Gains {
    pub k_rho: f64,
    pub k_alpha: f64,
    pub k_beta: f64,
}

/// The textbook example, (3, 8, −1.5): strongly stable.
pub const TEXTBOOK_GAINS: Gains = Gains {
    k_rho: 3.0,
    k_alpha: 8.0,
    k_beta: -1.5,
};

/// Which way the robot drives to the goal.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Direction {
    /// Decide once, at the start: forward when the goal lies in front
    /// (α ∈ (−π/2, π/2]), else backward. As in the textbook, the choice is
    /// then kept, so the closed loop is one smooth system.
    #[default]
    Auto,
    Forward,
    Backward,
}

/// The goal as the robot sees it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Polar {
    /// Distance to the goal, m.
    pub rho: f64,
    /// Bearing of the goal off the driving direction, rad, (−π, π].
    pub alpha: f64,
    /// Heading still to turn at the goal, rad, (−π, π].
    pub beta: f64,
    /// Whether these are the backward-driving angles α_b, β_b.
    pub backward: bool,
}

impl Polar {
    /// ρ, α, β of a pose given in the goal frame, for forward driving.
    /// At the goal itself (ρ = 0) the bearing is taken as 0: no NaN.
    pub fn forward(pose: &Pose) -> Self {
        Self::near(pose.x, pose.y, wrap(pose.theta), false)
    }

    /// The same pose seen by a robot driving rear first: α_b = wrap(α − π),
    /// β_b = wrap(−θ − α_b).
    pub fn backward(pose: &Pose) -> Self {
        Self::near(pose.x, pose.y, wrap(pose.theta), true)
    }

    /// The integrator's fast path: θ must lie within (−2π, 2π].
    ///
    /// With the bearing b = atan2(Δy, Δx) of the goal: α = b − θ and, since
    /// β = −θ − α, β = −b. Driving backward turns the robot's nose by π:
    /// α_b = b − θ − π and β_b = π − b (all wrapped).
    #[inline(always)]
    pub(crate) fn near(x: f64, y: f64, theta: f64, backward: bool) -> Self {
        let (dx, dy) = (-x, -y);
        let bearing = trig::atan2(dy, dx);
        let rho = (dx * dx + dy * dy).sqrt();
        if backward {
            Self {
                rho,
                alpha: wrap_near(wrap_near(bearing - theta) - PI),
                beta: wrap_near(PI - bearing),
                backward,
            }
        } else {
            Self {
                rho,
                alpha: wrap_near(bearing - theta),
                beta: wrap_near(-bearing),
                backward,
            }
        }
    }

    /// Is the goal in front of the robot, α ∈ (−π/2, π/2]?
    pub fn goal_in_front(&self) -> bool {
        self.alpha > -FRAC_PI_2 && self.alpha <= FRAC_PI_2
    }
}

/// One local condition on the gains, with the number it tests.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Condition {
    /// The inequality, as a learner would write it.
    pub expression: &'static str,
    /// Its left-hand side for these gains (must be > 0, or < 0 for k_β).
    pub value: f64,
    pub holds: bool,
}

/// What the gains promise: local exponential stability, strong stability,
/// and the linearised closed loop behind both.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Stability {
    /// k_ρ > 0, k_β < 0, k_α − k_ρ > 0.
    pub locally_stable: bool,
    /// Locally stable and k_α + (5/3) k_β − (2/π) k_ρ > 0: α never leaves
    /// the half-plane it starts in, so the robot never reverses its choice.
    pub strongly_stable: bool,
    /// The three local conditions, then the strong one.
    pub conditions: Vec<Condition>,
    /// Eigenvalues of the linearised closed loop, [re, im] each.
    pub eigenvalues: [[f64; 2]; 3],
    /// One sentence: inside the region, or which condition fails and what
    /// the robot does then.
    pub explanation: String,
}

impl Gains {
    /// Gains with finite values (any signs: unstable gains are worth
    /// simulating too).
    pub fn new(k_rho: f64, k_alpha: f64, k_beta: f64) -> Result<Self, FieldError> {
        Ok(Self {
            k_rho: finite("k_rho", k_rho)?,
            k_alpha: finite("k_alpha", k_alpha)?,
            k_beta: finite("k_beta", k_beta)?,
        })
    }

    /// The control law: (v, ω) for the goal as the robot sees it.
    #[inline]
    pub fn command(&self, p: &Polar) -> (f64, f64) {
        let v = self.k_rho * p.rho;
        let omega = self.k_alpha * p.alpha + self.k_beta * p.beta;
        if p.backward { (-v, omega) } else { (v, omega) }
    }

    /// The closed loop near the goal, d/dt (ρ, α, β) = A (ρ, α, β), from
    /// ρ̇ = −k_ρ ρ cos α, α̇ = k_ρ sin α − k_α α − k_β β, β̇ = −k_ρ sin α.
    pub fn linearised(&self) -> Matrix3<f64> {
        let Gains {
            k_rho,
            k_alpha,
            k_beta,
        } = *self;
        Matrix3::new(
            -k_rho,
            0.0,
            0.0, //
            0.0,
            -(k_alpha - k_rho),
            -k_beta, //
            0.0,
            -k_rho,
            0.0,
        )
    }

    /// Eigenvalues of [`Gains::linearised`] in closed form: −k_ρ, and the
    /// roots of λ² + (k_α − k_ρ) λ − k_ρ k_β = 0.
    pub fn eigenvalues(&self) -> [Complex<f64>; 3] {
        let b = self.k_alpha - self.k_rho;
        let c = -self.k_rho * self.k_beta;
        let disc = b * b - 4.0 * c;
        let (l1, l2) = if disc >= 0.0 {
            let root = disc.sqrt();
            // The numerically stable pair: no cancellation in either root.
            let q = -0.5 * (b + b.signum() * root);
            if q == 0.0 {
                (Complex::new(0.0, 0.0), Complex::new(-b, 0.0))
            } else {
                (Complex::new(q, 0.0), Complex::new(c / q, 0.0))
            }
        } else {
            let im = 0.5 * (-disc).sqrt();
            (Complex::new(-0.5 * b, im), Complex::new(-0.5 * b, -im))
        };
        [Complex::new(-self.k_rho, 0.0), l1, l2]
    }

    /// The stability conditions of the reference sheet, checked.
    pub fn stability(&self) -> Stability {
        let Gains {
            k_rho,
            k_alpha,
            k_beta,
        } = *self;
        let strong_value = k_alpha + 5.0 / 3.0 * k_beta - 2.0 / PI * k_rho;
        let conditions = vec![
            Condition {
                expression: "k_rho > 0",
                value: k_rho,
                holds: k_rho > 0.0,
            },
            Condition {
                expression: "k_beta < 0",
                value: k_beta,
                holds: k_beta < 0.0,
            },
            Condition {
                expression: "k_alpha - k_rho > 0",
                value: k_alpha - k_rho,
                holds: k_alpha - k_rho > 0.0,
            },
            Condition {
                expression: "k_alpha + 5/3 k_beta - 2/pi k_rho > 0",
                value: strong_value,
                holds: strong_value > 0.0,
            },
        ];
        let locally_stable = conditions[..3].iter().all(|c| c.holds);
        let strongly_stable = locally_stable && conditions[3].holds;
        let explanation = if strongly_stable {
            "Strongly stable: the robot converges and never turns its back on the goal.".to_string()
        } else if locally_stable {
            "Locally stable but not strongly: the robot still converges, but α may leave its half-plane on the way (a wide swing).".to_string()
        } else if !conditions[0].holds {
            if k_rho == 0.0 {
                "k_ρ = 0: the robot never drives towards the goal, only turns.".to_string()
            } else {
                "k_ρ < 0: the robot drives away from the goal.".to_string()
            }
        } else if !conditions[1].holds {
            if k_beta == 0.0 {
                "k_β = 0: nothing corrects the final heading; on the boundary the heading error does not decay.".to_string()
            } else {
                "k_β > 0: the heading term pushes the wrong way; the robot reaches the goal's position but arrives facing backwards.".to_string()
            }
        } else if k_alpha == k_rho {
            "k_α = k_ρ: on the boundary; the bearing error oscillates without decaying.".to_string()
        } else {
            "k_α < k_ρ: the robot steers too weakly for its speed and the bearing error grows."
                .to_string()
        };
        let e = self.eigenvalues();
        Stability {
            locally_stable,
            strongly_stable,
            conditions,
            eigenvalues: e.map(|z| [z.re, z.im]),
            explanation,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_contract_start_sees_the_goal_ahead_and_left() {
        // Start (−1, 0.5) facing +x; the goal (origin) is ahead and to the right.
        let p = Polar::forward(&Pose::new(-1.0, 0.5, 0.0));
        assert!((p.rho - 1.25f64.sqrt()).abs() < 1e-15);
        assert!((p.alpha - (-0.5f64).atan2(1.0)).abs() < 1e-15);
        assert!((p.beta + (-0.5f64).atan2(1.0)).abs() < 1e-15);
        assert!(p.goal_in_front());
    }

    #[test]
    fn backward_angles_follow_the_reference_sheet() {
        // Goal straight behind a robot facing +x.
        let pose = Pose::new(1.0, 0.0, 0.0);
        let f = Polar::forward(&pose);
        assert!((f.alpha - PI).abs() < 1e-15 && !f.goal_in_front());
        let b = Polar::backward(&pose);
        assert!(b.alpha.abs() < 1e-15 && b.beta.abs() < 1e-15 && b.backward);
        assert_eq!(TEXTBOOK_GAINS.command(&b), (-3.0, 0.0));
        // β_b = wrap(−θ − α_b) for a skewed pose.
        let pose = Pose::new(0.7, -0.4, 2.5);
        let b = Polar::backward(&pose);
        let f = Polar::forward(&pose);
        assert!((b.alpha - wrap(f.alpha - PI)).abs() < 1e-12);
        assert!((b.beta - wrap(-2.5 - b.alpha)).abs() < 1e-12);
    }

    #[test]
    fn at_the_goal_nothing_is_nan() {
        for pose in [
            Pose::new(0.0, 0.0, 0.0),
            Pose::new(0.0, 0.0, 1.0),
            Pose::new(1e-300, -1e-300, 0.0),
        ] {
            for p in [Polar::forward(&pose), Polar::backward(&pose)] {
                let (v, w) = TEXTBOOK_GAINS.command(&p);
                assert!(v.is_finite() && w.is_finite() && p.rho.is_finite());
            }
        }
    }

    #[test]
    fn a_positive_k_beta_arrives_facing_backwards() {
        // What the explanation promises: on the goal's position, heading off by 180°.
        let g = Gains::new(3.0, 8.0, 1.5).unwrap_or_else(|e| panic!("{e}"));
        assert!(
            g.stability()
                .explanation
                .contains("arrives facing backwards")
        );
        let run = crate::sim::Run::polar(Pose::new(-1.0, 0.5, 0.0), Pose::default(), g)
            .unwrap_or_else(|e| panic!("{e}"));
        let t = run.simulate().unwrap_or_else(|e| panic!("{e}"));
        assert!(!t.reached);
        assert!(t.final_position_error < 1e-3, "{}", t.final_position_error);
        assert!(
            t.final_heading_error.abs() > 179.0f64.to_radians(),
            "{}",
            t.final_heading_error
        );
    }

    #[test]
    fn closed_form_eigenvalues_match_nalgebra() {
        for g in [
            TEXTBOOK_GAINS,
            Gains::new(1.0, 1.5, -4.0).unwrap_or_else(|e| panic!("{e}")),
            Gains::new(2.0, 1.0, 0.5).unwrap_or_else(|e| panic!("{e}")),
            Gains::new(0.5, 30.0, -0.1).unwrap_or_else(|e| panic!("{e}")),
        ] {
            let mut ours: Vec<(f64, f64)> = g.eigenvalues().iter().map(|z| (z.re, z.im)).collect();
            let mut theirs: Vec<(f64, f64)> = g
                .linearised()
                .complex_eigenvalues()
                .iter()
                .map(|z| (z.re, z.im))
                .collect();
            let key = |a: &(f64, f64), b: &(f64, f64)| {
                a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal)
            };
            ours.sort_by(key);
            theirs.sort_by(key);
            for (a, b) in ours.iter().zip(&theirs) {
                assert!(
                    (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9,
                    "{g:?}: {ours:?} vs {theirs:?}"
                );
            }
        }
    }

    #[test]
    fn stability_inside_outside_and_on_the_boundary() {
        let s = TEXTBOOK_GAINS.stability();
        assert!(s.locally_stable && s.strongly_stable);
        // 8 − 2.5 − 6/π
        assert!((s.conditions[3].value - (5.5 - 6.0 / PI)).abs() < 1e-12);
        assert!(s.eigenvalues.iter().all(|e| e[0] < 0.0));

        let weak = Gains::new(3.0, 4.0, -1.5)
            .unwrap_or_else(|e| panic!("{e}"))
            .stability();
        assert!(weak.locally_stable && !weak.strongly_stable);

        for (g, failing) in [
            ((3.0, 8.0, 1.0), 1),
            ((-1.0, 8.0, -1.5), 0),
            ((3.0, 2.0, -1.5), 2),
        ] {
            let s = Gains::new(g.0, g.1, g.2)
                .unwrap_or_else(|e| panic!("{e}"))
                .stability();
            assert!(!s.locally_stable, "{g:?}");
            assert!(!s.conditions[failing].holds);
            // Some eigenvalue has a positive real part.
            assert!(
                s.eigenvalues.iter().any(|e| e[0] > 0.0),
                "{g:?} {:?}",
                s.eigenvalues
            );
        }
        // Boundaries: the strict inequalities fail and an eigenvalue sits on
        // the imaginary axis.
        for g in [(3.0, 3.0, -1.5), (3.0, 8.0, 0.0)] {
            let s = Gains::new(g.0, g.1, g.2)
                .unwrap_or_else(|e| panic!("{e}"))
                .stability();
            assert!(!s.locally_stable, "{g:?}");
            assert!(s.eigenvalues.iter().any(|e| e[0].abs() < 1e-12), "{g:?}");
        }
        assert!(Gains::new(f64::NAN, 1.0, 1.0).is_err_and(|e| e.field == "k_rho"));
    }
}
