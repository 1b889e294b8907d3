//! Model files (`*.model.json`) in the command-line contract's format:
//! a serial chain in standard or modified DH, with optional base and tool
//! transforms. Angles are in degrees (`_deg`); errors name the JSON path.

use serde::Deserialize;

use crate::dh::{Convention, DhRow, chain};
use crate::error::MechanismError;
use crate::model::{JointKind, Model, Pose};

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct JointFile {
    name: String,
    #[serde(rename = "type")]
    kind: JointKind,
    #[serde(default)]
    a: f64,
    #[serde(default)]
    alpha_deg: f64,
    /// Revolute: the fixed offset d. Prismatic: unused.
    #[serde(default)]
    d: f64,
    /// Prismatic: the fixed angle θ. Revolute: unused.
    #[serde(default)]
    theta_deg: f64,
    /// Revolute: θ = q + offset.
    #[serde(default)]
    offset_deg: f64,
    /// Prismatic: d = q + offset.
    #[serde(default)]
    offset: f64,
    limits_deg: Option<[f64; 2]>,
    limits: Option<[f64; 2]>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ModelFile {
    name: String,
    convention: Convention,
    joints: Vec<JointFile>,
    base: Option<[[f64; 4]; 4]>,
    tool: Option<[[f64; 4]; 4]>,
}

/// The model-file example of the command-line contract, verbatim.
pub const CONTRACT_EXAMPLE: &str = r#"{
  "name": "puma560",
  "convention": "standard_dh",
  "joints": [
    { "name": "q1", "type": "revolute", "a": 0.0, "d": 0.6718, "alpha_deg": 90, "offset_deg": 0, "limits_deg": [-160, 160] },
    { "name": "q3", "type": "prismatic", "a": 0.0, "theta_deg": 0, "alpha_deg": 0, "offset": 0.0, "limits": [0.0, 0.5] }
  ],
  "base": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]],
  "tool": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]
}"#;

/// A 4×4 homogeneous matrix as a pose; it must be a rotation and a shift.
pub fn pose_from_matrix(field: &str, m: &[[f64; 4]; 4]) -> Result<Pose, MechanismError> {
    use nalgebra::{Matrix3, Rotation3, Translation3, UnitQuaternion};
    if m.iter().flatten().any(|v| !v.is_finite()) {
        return Err(MechanismError::new(field, "must be finite numbers"));
    }
    let r = Matrix3::from_fn(|i, j| m[i][j]);
    let orthogonal =
        (r.transpose() * r - Matrix3::identity()).norm() < 1e-6 && r.determinant() > 0.0;
    if !orthogonal || m[3] != [0.0, 0.0, 0.0, 1.0] {
        return Err(MechanismError::new(
            field,
            "must be a rigid transform: a rotation (orthonormal, determinant 1) and a translation, last row 0 0 0 1",
        ));
    }
    let rotation = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(r));
    Ok(Pose::from_parts(
        Translation3::new(m[0][3], m[1][3], m[2][3]),
        rotation,
    ))
}

/// A pose as a row-major 4×4 matrix.
pub fn matrix_of(p: &Pose) -> [[f64; 4]; 4] {
    let h = p.to_homogeneous();
    std::array::from_fn(|i| std::array::from_fn(|j| h[(i, j)]))
}

/// Parse a model file.
pub fn from_json(text: &str) -> Result<Model, MechanismError> {
    let mut de = serde_json::Deserializer::from_str(text);
    let file: ModelFile = serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = e.path().to_string();
        let message = e.into_inner().to_string();
        let message = message
            .split(" at line ")
            .next()
            .unwrap_or(&message)
            .to_string();
        MechanismError::new(if path == "." { String::new() } else { path }, message)
    })?;
    if file.joints.is_empty() {
        return Err(MechanismError::new(
            "joints",
            "a model needs at least one joint",
        ));
    }
    let mut rows = Vec::with_capacity(file.joints.len());
    for (i, j) in file.joints.iter().enumerate() {
        let prismatic = j.kind == JointKind::Prismatic;
        let limits = match (prismatic, j.limits_deg, j.limits) {
            (false, Some([lo, hi]), None) => Some([lo.to_radians(), hi.to_radians()]),
            (true, None, Some(l)) => Some(l),
            (_, None, None) => None,
            (false, _, Some(_)) => {
                return Err(MechanismError::new(
                    format!("joints[{i}].limits"),
                    "a revolute joint's limits are `limits_deg`",
                ));
            }
            (true, Some(_), _) => {
                return Err(MechanismError::new(
                    format!("joints[{i}].limits_deg"),
                    "a prismatic joint's limits are `limits` in metres",
                ));
            }
        };
        rows.push(DhRow {
            name: j.name.clone(),
            kind: j.kind,
            a: j.a,
            alpha: j.alpha_deg.to_radians(),
            d: j.d,
            theta: j.theta_deg.to_radians(),
            offset: if prismatic {
                j.offset
            } else {
                j.offset_deg.to_radians()
            },
            limits,
        });
    }
    let base = file
        .base
        .as_ref()
        .map_or(Ok(Pose::identity()), |m| pose_from_matrix("base", m))?;
    let tool = file
        .tool
        .as_ref()
        .map_or(Ok(Pose::identity()), |m| pose_from_matrix("tool", m))?;
    chain(&file.name, file.convention, &rows, base, tool)
}

#[cfg(test)]
mod tests {
    use super::*;

    const CONTRACT: &str = CONTRACT_EXAMPLE;

    #[test]
    fn the_contract_example_loads() {
        let m = from_json(CONTRACT).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(m.dof(), 2);
        // q = (0, 0.2): up d₁, the x axis turned up by 90°, then 0.2 along the new z (−y).
        let p = m
            .pose(
                &[0.0, 0.2],
                &m.frame("tool").unwrap_or_else(|e| panic!("{e}")),
            )
            .unwrap_or_else(|e| panic!("{e}"));
        let v = p.translation.vector;
        assert!(
            v.x.abs() < 1e-12 && (v.y + 0.2).abs() < 1e-12 && (v.z - 0.6718).abs() < 1e-12,
            "{v}"
        );
    }

    #[test]
    fn bad_files_name_the_field() {
        let cases = [
            (
                CONTRACT.replace("\"alpha_deg\": 90", "\"alpha\": 90"),
                "joints[0]",
            ),
            (CONTRACT.replace("standard_dh", "sideways_dh"), "convention"),
            (
                CONTRACT.replace(
                    "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]\n}",
                    "[[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]\n}",
                ),
                "tool",
            ),
            (
                CONTRACT.replace("\"limits\": [0.0, 0.5]", "\"limits_deg\": [0, 5]"),
                "joints[1].limits_deg",
            ),
            (
                CONTRACT.replace("\"name\": \"q3\"", "\"name\": \"q1\""),
                "bodies[3].name",
            ),
        ];
        for (text, field) in cases {
            match from_json(&text) {
                Err(e) => assert!(e.field.starts_with(field), "{field}: got `{e}`"),
                Ok(_) => panic!("{field}: accepted"),
            }
        }
    }
}
