//! A chassis: wheels on a rigid body, checked once when it is built, and
//! the stacked constraint matrices of the reference sheet.

use kinolab_common::trig;
use nalgebra::{DMatrix, Vector3};

use crate::error::{FieldError, bounded, finite, length};
use kinolab_common::angle::wrap;

use crate::wheel::{Wheel, WheelKind, WheelRows};

/// The most wheels a chassis may have; keeps every computation small.
pub const MAX_WHEELS: usize = 64;

/// Two wheel centres closer than this are one spot.
const COINCIDENT: f64 = 1e-6;

/// One steering input: a steered wheel of its own, or wheels that a belt
/// or a linkage turns together.
#[derive(Debug, Clone, PartialEq)]
pub struct SteeringInput {
    /// The `steer_group` name, or `None` for a wheel steered on its own.
    pub group: Option<String>,
    /// Indices of the wheels it turns.
    pub wheels: Vec<usize>,
}

/// A validated set of wheels on one rigid chassis.
#[derive(Debug, Clone, PartialEq)]
pub struct Chassis {
    name: String,
    wheels: Vec<Wheel>,
    /// Each wheel's constraint rows, computed once: a chassis never changes
    /// (steering makes a new one), and the trigonometry is most of the work.
    rows: Vec<WheelRows>,
    inputs: Vec<SteeringInput>,
}

impl Chassis {
    /// Check every wheel and build the chassis, or say which field is wrong.
    pub fn new(name: impl Into<String>, wheels: Vec<Wheel>) -> Result<Self, FieldError> {
        if wheels.is_empty() {
            return Err(FieldError::new(
                "wheels",
                "a robot needs at least one wheel",
            ));
        }
        if wheels.len() > MAX_WHEELS {
            return Err(FieldError::new(
                "wheels",
                format!("at most {MAX_WHEELS} wheels, got {}", wheels.len()),
            ));
        }
        for (i, w) in wheels.iter().enumerate() {
            check_wheel(i, w)?;
        }
        for (i, a) in wheels.iter().enumerate() {
            for (j, b) in wheels.iter().enumerate().take(i) {
                let [ax, ay] = a.position();
                let [bx, by] = b.position();
                if (ax - bx).hypot(ay - by) < COINCIDENT {
                    return Err(FieldError::new(
                        format!("wheels[{i}]"),
                        format!(
                            "sits on the same spot as wheels[{j}] ({ax:.3}, {ay:.3}); two wheels cannot share a contact point"
                        ),
                    ));
                }
            }
        }
        let inputs = steering_inputs(&wheels);
        let rows = wheels.iter().map(Wheel::rows).collect();
        Ok(Self {
            name: name.into(),
            wheels,
            rows,
            inputs,
        })
    }

    pub fn name(&self) -> &str {
        &self.name
    }

    pub fn wheels(&self) -> &[Wheel] {
        &self.wheels
    }

    /// The constraint rows of every wheel, in wheel order.
    pub fn rows(&self) -> &[WheelRows] {
        &self.rows
    }

    /// The steering inputs: one per group, one per ungrouped steered wheel.
    pub fn steering_inputs(&self) -> &[SteeringInput] {
        &self.inputs
    }

    /// Indices of the fixed standard wheels, then of the steered ones.
    fn indices(&self, kind: WheelKind) -> impl Iterator<Item = usize> + '_ {
        self.wheels
            .iter()
            .enumerate()
            .filter(move |(_, w)| std::mem::discriminant(&w.kind) == std::mem::discriminant(&kind))
            .map(|(i, _)| i)
    }

    fn stack(&self, rows: impl Iterator<Item = Vector3<f64>>) -> DMatrix<f64> {
        let rows: Vec<Vector3<f64>> = rows.collect();
        DMatrix::from_fn(rows.len(), 3, |i, j| rows[i][j])
    }

    /// C₁f: the sliding rows of the fixed standard wheels.
    pub fn c1f(&self) -> DMatrix<f64> {
        self.stack(self.indices(WheelKind::Fixed).map(|i| self.rows[i].sliding))
    }

    /// C₁s(β_s): the sliding rows of the steered standard wheels.
    pub fn c1s(&self) -> DMatrix<f64> {
        self.stack(
            self.indices(WheelKind::Steered)
                .map(|i| self.rows[i].sliding),
        )
    }

    /// C₁(β_s) = [C₁f; C₁s(β_s)].
    pub fn c1(&self) -> DMatrix<f64> {
        self.stack(
            self.indices(WheelKind::Fixed)
                .chain(self.indices(WheelKind::Steered))
                .map(|i| self.rows[i].sliding),
        )
    }

    /// J₁(β_s): the rolling rows of the fixed then the steered wheels.
    pub fn j1(&self) -> DMatrix<f64> {
        self.stack(
            self.indices(WheelKind::Fixed)
                .chain(self.indices(WheelKind::Steered))
                .map(|i| self.rows[i].rolling),
        )
    }

    /// J₂: the diagonal matrix of those wheels' radii.
    pub fn j2(&self) -> DMatrix<f64> {
        let radii: Vec<f64> = self
            .indices(WheelKind::Fixed)
            .chain(self.indices(WheelKind::Steered))
            .map(|i| self.wheels[i].radius)
            .collect();
        DMatrix::from_diagonal(&nalgebra::DVector::from_vec(radii))
    }

    /// Which wheel each row of C₁ and J₁ belongs to.
    pub fn c1_wheels(&self) -> Vec<usize> {
        self.indices(WheelKind::Fixed)
            .chain(self.indices(WheelKind::Steered))
            .collect()
    }

    /// The same chassis with wheel `index` steered to `beta`, and every wheel
    /// that shares its steering input following as its linkage makes it:
    /// wheels that are parallel now (a synchro belt) turn by the same angle;
    /// wheels whose axles meet at a point (an Ackermann linkage) turn so
    /// their axles keep meeting, at the point where the turned wheel's axle
    /// now crosses the fixed wheels' common axle line (or the line through
    /// P and the old meeting point when there is none).
    pub fn steer(&self, index: usize, beta: f64) -> Result<Self, FieldError> {
        let field = format!("wheels[{index}]");
        let Some(wheel) = self.wheels.get(index) else {
            return Err(FieldError::new(field, "no such wheel"));
        };
        if !wheel.kind.is_steerable() {
            return Err(FieldError::new(
                format!("{field}.beta"),
                format!("a {} wheel cannot be steered", wheel.kind.name()),
            ));
        }
        bounded(
            format!("{field}.beta_deg"),
            beta.to_degrees(),
            MAX_ANGLE_DEG,
        )?;
        let mut wheels = self.wheels.clone();
        let group: Vec<usize> = self
            .inputs
            .iter()
            .find(|input| input.wheels.contains(&index))
            .map(|input| input.wheels.clone())
            .unwrap_or_else(|| vec![index]);
        if group.len() > 1 {
            match group_meeting_point(&self.wheels, &group) {
                None => {
                    let delta = beta - wheel.beta;
                    for &i in &group {
                        wheels[i].beta = wrap(wheels[i].beta + delta);
                    }
                }
                Some(old) => {
                    let mut turned = wheel.clone();
                    turned.beta = beta;
                    let locus = crate::analysis::fixed_axle_line(&self.wheels)
                        .unwrap_or_else(|| locus_through_p(old));
                    if let Some(icr) = intersect(turned.zero_motion_line(), locus) {
                        for &i in &group {
                            wheels[i].beta = beta_towards(&wheels[i], icr);
                        }
                    } else {
                        // The turned axle runs parallel to the locus: the
                        // meeting point is at infinity, all axles parallel.
                        let [dx, dy] = turned.axle();
                        for &i in &group {
                            let target = trig::atan2(dy, dx) - wheels[i].alpha;
                            wheels[i].beta = nearest_half_turn(wheels[i].beta, target);
                        }
                    }
                }
            }
        }
        wheels[index].beta = beta;
        Self::new(self.name.clone(), wheels)
    }
}

fn locus_through_p(point: [f64; 2]) -> ([f64; 2], [f64; 2]) {
    let norm = point[0].hypot(point[1]);
    if norm > COINCIDENT {
        ([0.0, 0.0], [point[0] / norm, point[1] / norm])
    } else {
        ([0.0, 0.0], [0.0, 1.0])
    }
}

/// The point where the axles of a group of wheels meet, or `None` when they
/// are all parallel.
pub(crate) fn group_meeting_point(wheels: &[Wheel], group: &[usize]) -> Option<[f64; 2]> {
    let first = wheels[group[0]].zero_motion_line();
    group[1..]
        .iter()
        .find_map(|&i| intersect(first, wheels[i].zero_motion_line()))
}

/// Where two lines (point, unit direction) cross, or `None` if parallel.
pub(crate) fn intersect(a: ([f64; 2], [f64; 2]), b: ([f64; 2], [f64; 2])) -> Option<[f64; 2]> {
    let ([px, py], [ux, uy]) = a;
    let ([qx, qy], [vx, vy]) = b;
    let den = ux * vy - uy * vx;
    if den.abs() < crate::span::RANK_TOLERANCE {
        return None;
    }
    let t = ((qx - px) * vy - (qy - py) * vx) / den;
    Some([px + t * ux, py + t * uy])
}

/// The steering angle, nearest the wheel's current one, that points its
/// axle at `icr`. A wheel sitting on the ICR keeps its angle.
pub(crate) fn beta_towards(wheel: &Wheel, icr: [f64; 2]) -> f64 {
    let [x, y] = wheel.position();
    let (dx, dy) = (icr[0] - x, icr[1] - y);
    if dx.hypot(dy) < COINCIDENT {
        return wheel.beta;
    }
    nearest_half_turn(wheel.beta, trig::atan2(dy, dx) - wheel.alpha)
}

/// Of `target` and `target + π`, the one nearest `current`, written close to
/// `current` so angles do not jump by full turns.
pub(crate) fn nearest_half_turn(current: f64, target: f64) -> f64 {
    let d = wrap(target - current);
    let d = if d > std::f64::consts::FRAC_PI_2 {
        d - std::f64::consts::PI
    } else if d <= -std::f64::consts::FRAC_PI_2 {
        d + std::f64::consts::PI
    } else {
        d
    };
    current + d
}

/// The largest wheel angle a file may give, degrees (ten turns).
const MAX_ANGLE_DEG: f64 = 3600.0;

fn check_wheel(i: usize, w: &Wheel) -> Result<(), FieldError> {
    // Fields named as files spell them; angles checked in degrees.
    let field = |name: &str| format!("wheels[{i}].{name}");
    bounded(field("alpha_deg"), w.alpha.to_degrees(), MAX_ANGLE_DEG)?;
    bounded(field("beta_deg"), w.beta.to_degrees(), MAX_ANGLE_DEG)?;
    finite(field("l"), w.l)?;
    if w.l < 0.0 {
        return Err(FieldError::new(
            field("l"),
            format!("a distance cannot be negative, got {}", w.l),
        ));
    }
    length(field("radius"), w.radius)?;
    match w.kind {
        WheelKind::Castor { offset } => {
            finite(field("offset"), offset)?;
            if offset > 0.0 {
                length(field("offset"), offset)?;
            } else {
                return Err(FieldError::new(
                    field("offset"),
                    format!(
                        "a castor needs an offset d above 0 (with d = 0 it is a steered wheel), got {offset}"
                    ),
                ));
            }
        }
        WheelKind::Swedish { gamma } => {
            bounded(field("gamma_deg"), gamma.to_degrees(), MAX_ANGLE_DEG)?;
            if trig::cos(gamma) < 1e-6 {
                return Err(FieldError::new(
                    field("gamma_deg"),
                    format!(
                        "the roller angle must lie strictly between -90° and 90°, got {:.3}°",
                        gamma.to_degrees()
                    ),
                ));
            }
        }
        WheelKind::Fixed | WheelKind::Steered | WheelKind::Spherical => {}
    }
    if let Some(group) = &w.steer_group {
        if w.kind != WheelKind::Steered {
            return Err(FieldError::new(
                field("steer_group"),
                format!(
                    "only steered wheels share a steering input; this one is {}",
                    w.kind.name()
                ),
            ));
        }
        if group.is_empty()
            || !group
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
        {
            return Err(FieldError::new(
                field("steer_group"),
                format!("use letters, digits, - and _ only, got {group:?}"),
            ));
        }
    }
    Ok(())
}

fn steering_inputs(wheels: &[Wheel]) -> Vec<SteeringInput> {
    let mut inputs: Vec<SteeringInput> = Vec::new();
    for (i, w) in wheels.iter().enumerate() {
        if w.kind != WheelKind::Steered {
            continue;
        }
        match &w.steer_group {
            Some(name) => {
                if let Some(input) = inputs
                    .iter_mut()
                    .find(|input| input.group.as_deref() == Some(name.as_str()))
                {
                    input.wheels.push(i);
                } else {
                    inputs.push(SteeringInput {
                        group: Some(name.clone()),
                        wheels: vec![i],
                    });
                }
            }
            None => inputs.push(SteeringInput {
                group: None,
                wheels: vec![i],
            }),
        }
    }
    inputs
}
