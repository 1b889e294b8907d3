//! Denavit–Hartenberg chains, standard and modified (Craig), turned into
//! the one internal tree.
//!
//! - Standard: link i's frame is `Rz(θᵢ) Tz(dᵢ) Tx(aᵢ) Rx(αᵢ)` after link i−1's.
//! - Modified: `Rx(αᵢ₋₁) Tx(aᵢ₋₁) Rz(θᵢ) Tz(dᵢ)`: the twist and length of
//!   the previous link come first.
//!
//! A revolute joint's variable is θ (θ = q + offset, d fixed); a prismatic
//! joint's is d (d = q + offset, θ fixed).

use nalgebra::{Translation3, UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

use crate::error::{FieldError, finite_at};
use crate::model::{JointKind, Model, ModelBuilder, Pose};

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Convention {
    StandardDh,
    ModifiedDh,
}

/// One row of a DH table. For a revolute joint `theta` is unused (the
/// joint sets it); for a prismatic joint `d` is unused.
#[derive(Debug, Clone, PartialEq)]
pub struct DhRow {
    pub name: String,
    pub kind: JointKind,
    pub a: f64,
    pub alpha: f64,
    pub d: f64,
    pub theta: f64,
    pub offset: f64,
    pub limits: Option<[f64; 2]>,
}

pub(crate) fn rot_x(angle: f64) -> Pose {
    Pose::from_parts(
        Translation3::identity(),
        UnitQuaternion::from_axis_angle(&Vector3::x_axis(), angle),
    )
}

pub(crate) fn rot_z(angle: f64) -> Pose {
    Pose::from_parts(
        Translation3::identity(),
        UnitQuaternion::from_axis_angle(&Vector3::z_axis(), angle),
    )
}

pub(crate) fn shift(x: f64, y: f64, z: f64) -> Pose {
    Pose::translation(x, y, z)
}

/// Build a serial chain: world → `base` (fixed at `base`) → one body per
/// row, named after the row → a `tool` frame at `tool` on the last body.
pub fn chain(
    name: &str,
    convention: Convention,
    rows: &[DhRow],
    base: Pose,
    tool: Pose,
) -> Result<Model, FieldError> {
    chain_builder(name, convention, rows, base, tool)?.build()
}

/// [`chain`] before it is checked, so more can be added (shapes,
/// commands). Body `i + 2` carries row `i` (0 is the world, 1 the base).
pub fn chain_builder(
    name: &str,
    convention: Convention,
    rows: &[DhRow],
    base: Pose,
    tool: Pose,
) -> Result<ModelBuilder, FieldError> {
    let mut b = ModelBuilder::new(name);
    let mut parent = b.fixed_base(base);
    for (i, r) in rows.iter().enumerate() {
        // Named as files spell them: angles in degrees.
        let offset = match r.kind {
            JointKind::Prismatic => ("offset", r.offset),
            _ => ("offset_deg", r.offset.to_degrees()),
        };
        for (field, v) in [
            ("a", r.a),
            ("alpha_deg", r.alpha.to_degrees()),
            ("d", r.d),
            ("theta_deg", r.theta.to_degrees()),
            offset,
        ] {
            finite_at(v, || format!("joints[{i}].{field}"))?;
        }
        if r.kind == JointKind::Fixed {
            return Err(FieldError::new(
                format!("joints[{i}].type"),
                "a DH row must be revolute, continuous or prismatic",
            ));
        }
        let prismatic = r.kind == JointKind::Prismatic;
        let (origin, post) = match (convention, prismatic) {
            (Convention::StandardDh, false) => (
                Pose::identity(),
                shift(0.0, 0.0, r.d) * shift(r.a, 0.0, 0.0) * rot_x(r.alpha),
            ),
            (Convention::StandardDh, true) => {
                (rot_z(r.theta), shift(r.a, 0.0, 0.0) * rot_x(r.alpha))
            }
            // Rz(θ) and Tz(d) commute, so the fixed part can go first.
            (Convention::ModifiedDh, false) => (
                rot_x(r.alpha) * shift(r.a, 0.0, 0.0) * shift(0.0, 0.0, r.d),
                Pose::identity(),
            ),
            (Convention::ModifiedDh, true) => (
                rot_x(r.alpha) * shift(r.a, 0.0, 0.0) * rot_z(r.theta),
                Pose::identity(),
            ),
        };
        parent = b.joint(
            r.name.clone(),
            r.kind,
            parent,
            origin,
            Vector3::z_axis(),
            r.offset,
            post,
            r.limits,
        );
    }
    b.frame("tool", parent, tool);
    Ok(b)
}

/// One DH link as a transform: from frame i−1 to frame i for the row
/// (a, α, d, θ), all fixed numbers.
pub fn link(convention: Convention, a: f64, alpha: f64, d: f64, theta: f64) -> Pose {
    let [p1, p2, p3, p4] = steps(convention, a, alpha, d, theta);
    p1 * p2 * p3 * p4
}

/// The four elementary motions of a DH link in the order they apply:
/// standard `Rz(θ) Tz(d) Tx(a) Rx(α)`, modified `Rx(α) Tx(a) Rz(θ) Tz(d)`.
pub fn steps(convention: Convention, a: f64, alpha: f64, d: f64, theta: f64) -> [Pose; 4] {
    match convention {
        Convention::StandardDh => [
            rot_z(theta),
            shift(0.0, 0.0, d),
            shift(a, 0.0, 0.0),
            rot_x(alpha),
        ],
        Convention::ModifiedDh => [
            rot_x(alpha),
            shift(a, 0.0, 0.0),
            rot_z(theta),
            shift(0.0, 0.0, d),
        ],
    }
}
