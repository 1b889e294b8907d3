//! Inverse kinematics (twist → wheel commands), forward kinematics (wheel
//! spins → twist, by least squares) and pose integration.

use kinolab_common::trig;
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};
use serde::Serialize;

use crate::analysis::line_row;
use crate::chassis::{Chassis, group_meeting_point, nearest_half_turn};
use crate::error::{FieldError, finite_at};
use kinolab_common::angle::wrap;

use crate::wheel::{SlidingExtra, Wheel, WheelKind};

/// What one wheel must do for a requested chassis twist.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WheelCommand {
    /// Spin rate φ̇, rad/s.
    pub spin: f64,
    /// Steering angle β, rad: the new one for steered and spherical wheels,
    /// the current one for the rest.
    pub steer: f64,
    /// Steering rate β̇, rad/s (castors swing by themselves at this rate).
    pub steer_rate: f64,
    /// Swedish wheels: surface speed of the rollers, r_sw φ̇_sw, m/s.
    pub roller_speed: Option<f64>,
}

/// A constraint a twist breaks.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Violation {
    pub wheel: usize,
    /// `sliding` for a fixed wheel's sliding row, `steer_group` when a
    /// linkage cannot set its wheels as the twist needs.
    pub constraint: &'static str,
    pub group: Option<String>,
    /// The row's value for this twist, m/s (0 would be satisfied).
    pub residual: f64,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InverseSolution {
    pub feasible: bool,
    pub wheels: Vec<WheelCommand>,
    pub violations: Vec<Violation>,
}

/// The tolerance for "satisfied" rows: 1e-9 of the twist's own size.
fn tolerance(twist: &Vector3<f64>, wheel: &Wheel) -> f64 {
    1e-9 * (twist.x.abs() + twist.y.abs() + twist.z.abs() * (1.0 + wheel.l)).max(1.0)
}

fn check_twist(twist: &Vector3<f64>) -> Result<(), FieldError> {
    for (i, v) in twist.iter().enumerate() {
        finite_at(*v, || format!("twist[{i}]"))?;
    }
    Ok(())
}

impl Chassis {
    /// Inverse kinematics: each wheel's spin (and steering) for a chassis
    /// twist ξ̇_R = (ẋ_R, ẏ_R, θ̇), with every constraint the twist breaks.
    pub fn inverse(&self, twist: Vector3<f64>) -> Result<InverseSolution, FieldError> {
        check_twist(&twist)?;
        let mut violations = Vec::new();
        let wheels: Vec<WheelCommand> = self
            .wheels()
            .iter()
            .zip(self.rows())
            .enumerate()
            .map(|(i, (w, rows))| {
                let rolling_spin = rows.rolling.dot(&twist) / rows.spin_gain;
                match (w.kind, rows.sliding_extra) {
                    (WheelKind::Fixed, _) => {
                        let residual = rows.sliding.dot(&twist);
                        if residual.abs() > tolerance(&twist, w) {
                            violations.push(Violation {
                                wheel: i,
                                constraint: "sliding",
                                group: None,
                                residual,
                            });
                        }
                        command(rolling_spin, w.beta, 0.0)
                    }
                    (WheelKind::Steered, _) => align(w, &twist),
                    (WheelKind::Spherical, _) => roll_ball(w, &twist),
                    (_, SlidingExtra::SteerRate { offset }) => {
                        command(rolling_spin, w.beta, -rows.sliding.dot(&twist) / offset)
                    }
                    (_, SlidingExtra::Rollers { spin_gain }) => WheelCommand {
                        roller_speed: Some(rows.sliding.dot(&twist) - spin_gain * rolling_spin),
                        ..command(rolling_spin, w.beta, 0.0)
                    },
                    _ => command(rolling_spin, w.beta, 0.0),
                }
            })
            .collect();
        let mut rank_c1f = None;
        for input in self.steering_inputs() {
            if input.wheels.len() < 2 {
                continue;
            }
            let rank_c1f = *rank_c1f.get_or_insert_with(|| {
                crate::span::Span3::of(
                    self.wheels()
                        .iter()
                        .zip(self.rows())
                        .filter(|(w, _)| w.kind == WheelKind::Fixed)
                        .map(|(_, r)| r.sliding),
                )
                .rank()
            });
            let row = match group_meeting_point(self.wheels(), &input.wheels) {
                None => Vector3::new(0.0, 0.0, 1.0),
                Some(_) if rank_c1f > 0 => continue,
                Some([cx, cy]) => {
                    let n = cx.hypot(cy);
                    let dir = if n > 1e-9 {
                        [cx / n, cy / n]
                    } else {
                        [0.0, 1.0]
                    };
                    line_row([cx, cy], dir)
                }
            };
            let residual = row.dot(&twist);
            let first = input.wheels[0];
            if residual.abs() > tolerance(&twist, &self.wheels()[first]) {
                violations.push(Violation {
                    wheel: first,
                    constraint: "steer_group",
                    group: input.group.clone(),
                    residual,
                });
            }
        }
        Ok(InverseSolution {
            feasible: violations.is_empty(),
            wheels,
            violations,
        })
    }
}

fn command(spin: f64, steer: f64, steer_rate: f64) -> WheelCommand {
    WheelCommand {
        spin,
        steer,
        steer_rate,
        roller_speed: None,
    }
}

/// Steer a wheel so it rolls along its contact point's velocity (the
/// solution nearest its current angle), and spin it to match.
fn align(w: &Wheel, twist: &Vector3<f64>) -> WheelCommand {
    let [ux, uy] = w.contact_velocity(twist);
    let speed = ux.hypot(uy);
    if speed <= 1e-12 * (1.0 + twist.norm()) {
        // The wheel sits on the ICR: any angle works, keep the current one.
        return command(0.0, w.beta, 0.0);
    }
    // Rolling direction (sin(α+β), −cos(α+β)) ∥ u ⇔ α + β = atan2(u_x, −u_y).
    let beta = nearest_half_turn(w.beta, trig::atan2(ux, -uy) - w.alpha);
    let mut steered = w.clone();
    steered.beta = beta;
    let [tx, ty] = steered.rolling_direction();
    command((tx * ux + ty * uy) / w.radius, beta, 0.0)
}

/// A ball rolls the way its contact point moves: report that direction as
/// its β and a spin that is never negative.
fn roll_ball(w: &Wheel, twist: &Vector3<f64>) -> WheelCommand {
    let [ux, uy] = w.contact_velocity(twist);
    let speed = ux.hypot(uy);
    if speed <= 1e-12 * (1.0 + twist.norm()) {
        return command(0.0, w.beta, 0.0);
    }
    command(speed / w.radius, wrap(trig::atan2(ux, -uy) - w.alpha), 0.0)
}

/// Forward kinematics: the chassis twist that best explains the spins.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ForwardSolution {
    pub twist: [f64; 3],
    /// ‖A ξ̇ − b‖ over every rolling and sliding row used.
    pub residual: f64,
    /// The residual is within 1e-9 of ‖b‖: the spins agree with each other.
    pub consistent: bool,
    /// The known spins pin the twist down (rank 3). When false the twist is
    /// the smallest one that fits.
    pub determined: bool,
    /// How many rows were used.
    pub rows: usize,
}

impl Chassis {
    /// Forward kinematics from one spin per wheel (`None`: unknown, its
    /// rolling row is left out). Sliding rows of fixed and steered wheels
    /// always take part; castor and Swedish sliding rows carry unknowns
    /// (β̇, roller spin) and a ball's spin has no direction, so those are
    /// left out.
    pub fn forward(&self, spins: &[Option<f64>]) -> Result<ForwardSolution, FieldError> {
        if spins.len() != self.wheels().len() {
            return Err(FieldError::new(
                "wheels",
                format!(
                    "expected one spin per wheel ({}), got {}",
                    self.wheels().len(),
                    spins.len()
                ),
            ));
        }
        let rows = self.known_rows(spins)?;
        let b_norm = rows.iter().map(|(_, b)| b * b).sum::<f64>().sqrt();
        let within = |residual: f64| residual <= 1e-9 * b_norm || residual <= 1e-12;
        // Fast path: the 3×3 normal equations. They square the rows'
        // conditioning, so when their answer leaves a residual the SVD of the
        // rows themselves decides (it also gives the smallest twist when the
        // spins leave some motion free).
        let (twist, determined) = match solve_normal(&rows) {
            Some((twist, conditioning))
                if conditioning > WELL_CONDITIONED || within(residual_of(&rows, &twist)) =>
            {
                (twist, true)
            }
            _ => solve_svd(&rows),
        };
        let residual = residual_of(&rows, &twist);
        Ok(ForwardSolution {
            twist: [twist.x, twist.y, twist.z],
            residual,
            consistent: within(residual),
            determined,
            rows: rows.len(),
        })
    }

    /// The rows forward kinematics can use, each with its right-hand side:
    /// rolling rows of wheels with a known spin, sliding rows of wheels that
    /// constrain the chassis.
    fn known_rows(&self, spins: &[Option<f64>]) -> Result<Vec<(Vector3<f64>, f64)>, FieldError> {
        let mut rows = Vec::with_capacity(2 * spins.len());
        for (i, ((w, r), spin)) in self.wheels().iter().zip(self.rows()).zip(spins).enumerate() {
            if let Some(spin) = spin {
                finite_at(*spin, || format!("wheels[{i}]"))?;
                if w.kind != WheelKind::Spherical {
                    rows.push((r.rolling, r.spin_gain * spin));
                }
            }
            if w.kind.constrains_chassis() {
                rows.push((r.sliding, 0.0));
            }
        }
        Ok(rows)
    }
}

/// ‖Av − b‖ over the rows, computed row by row for accuracy.
fn residual_of(rows: &[(Vector3<f64>, f64)], twist: &Vector3<f64>) -> f64 {
    rows.iter()
        .map(|(row, b)| (row.dot(twist) - b).powi(2))
        .sum::<f64>()
        .sqrt()
}

/// det(AᵀA) / ‖AᵀA‖³ above this: the normal equations keep enough digits.
const WELL_CONDITIONED: f64 = 1e-6;

/// Least squares by AᵀA v = Aᵀb with the 3×3 inverse, and det(AᵀA)/‖AᵀA‖³
/// (how far from singular); `None` when AᵀA is (nearly) singular.
fn solve_normal(rows: &[(Vector3<f64>, f64)]) -> Option<(Vector3<f64>, f64)> {
    let mut normal = Matrix3::zeros();
    let mut rhs = Vector3::zeros();
    for (row, b) in rows {
        normal += row * row.transpose();
        rhs += row * *b;
    }
    let scale = normal.norm();
    let conditioning = normal.determinant().abs() / (scale * scale * scale);
    if conditioning.is_nan() || conditioning <= 1e-12 {
        return None;
    }
    normal
        .try_inverse()
        .map(|inverse| (inverse * rhs, conditioning))
}

/// Least squares by the SVD of A itself: the minimum-norm twist, and
/// whether the rows pin all three components down.
fn solve_svd(rows: &[(Vector3<f64>, f64)]) -> (Vector3<f64>, bool) {
    if rows.is_empty() {
        return (Vector3::zeros(), false);
    }
    let a = DMatrix::from_fn(rows.len(), 3, |i, j| rows[i].0[j]);
    let b = DVector::from_iterator(rows.len(), rows.iter().map(|(_, b)| *b));
    let svd = a.svd(true, true);
    let eps = 1e-9 * svd.singular_values.max();
    let rank = svd.rank(eps);
    match svd.solve(&b, eps) {
        Ok(v) => (Vector3::new(v[0], v[1], v[2]), rank == 3),
        Err(_) => (Vector3::zeros(), false),
    }
}

/// R(θ): maps inertial motion to robot-frame motion, ξ̇_R = R(θ) ξ̇_I.
pub fn rotation(theta: f64) -> Matrix3<f64> {
    let (s, c) = trig::sin_cos(theta);
    Matrix3::new(c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0)
}

/// Robot-frame twist to inertial motion: ξ̇_I = R(θ)ᵀ ξ̇_R.
pub fn to_inertial(theta: f64, twist: Vector3<f64>) -> Vector3<f64> {
    rotation(theta).transpose() * twist
}

/// The pose after driving with a constant robot-frame twist for `dt`
/// seconds from `pose` = (x, y, θ). Exact: the robot follows a circular arc
/// (or a line), integrated in closed form with a sinc that stays accurate as
/// θ̇ → 0.
pub fn integrate(pose: [f64; 3], twist: Vector3<f64>, dt: f64) -> [f64; 3] {
    let [x, y, theta] = pose;
    let half = twist.z * dt / 2.0;
    let mid = theta + half;
    let sinc = if half.abs() < 1e-4 {
        1.0 - half * half / 6.0
    } else {
        trig::sin(half) / half
    };
    let (s, c) = trig::sin_cos(mid);
    let k = dt * sinc;
    [
        x + k * (twist.x * c - twist.y * s),
        y + k * (twist.x * s + twist.y * c),
        theta + twist.z * dt,
    ]
}
