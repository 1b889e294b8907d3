//! Model files (`*.model.json`). The command-line contract's format — a
//! serial chain in standard or modified DH with optional base and tool
//! transforms — extended for everything else a mechanism can be:
//!
//! - `"convention": "transforms"`: each joint placed on its `parent` by an
//!   `origin` (`xyz`, `rpy_deg`) and turning about or sliding along `axis`,
//!   so trees are possible;
//! - `"convention": "zero_position"`: product of exponentials — each
//!   joint's `axis` and a `point` on it with every joint at zero, and the
//!   tool's pose at zero;
//! - `frames` (ports), `mounts` (another model, from a file or the
//!   catalogue, mounted at one of this model's frames under a name),
//!   `couplings`, `loops`, `shapes` (capsules) and `ignore` (body pairs).
//!
//! Angles are in degrees (`_deg`); errors name the JSON path.

use nalgebra::{Translation3, Unit, UnitQuaternion, Vector3};
use serde::Deserialize;

use crate::dh::{Convention, DhRow, chain_builder};
use crate::error::{FieldError, finite};
use crate::model::{JointKind, Model, ModelBuilder, Pose, WORLD};

/// How a file describes its joints.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
enum Description {
    /// Standard Denavit–Hartenberg rows (the contract's format).
    StandardDh,
    /// Modified (Craig) DH rows (the contract's format).
    ModifiedDh,
    /// Each joint placed on its parent by a plain transform, with an axis.
    Transforms,
    /// Zero-position (product of exponentials): each joint's axis and a
    /// point on it, in the world, with every joint at zero.
    ZeroPosition,
}

/// A pose written as a shift and roll–pitch–yaw angles (applied about x,
/// then y, then z of the parent frame).
#[derive(Debug, Clone, Copy, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct PoseFile {
    #[serde(default)]
    xyz: [f64; 3],
    #[serde(default)]
    rpy_deg: [f64; 3],
}

impl PoseFile {
    fn pose(&self, field: &str) -> Result<Pose, FieldError> {
        for v in self.xyz.iter().chain(&self.rpy_deg) {
            finite(field, *v)?;
        }
        let [r, p, y] = self.rpy_deg.map(f64::to_radians);
        Ok(Pose::from_parts(
            Translation3::from(Vector3::from(self.xyz)),
            UnitQuaternion::from_euler_angles(r, p, y),
        ))
    }
}

/// One joint. Which fields apply depends on the description; the others
/// must be left out.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct JointFile {
    name: String,
    #[serde(rename = "type")]
    kind: JointKind,
    // DH rows.
    a: Option<f64>,
    alpha_deg: Option<f64>,
    /// Revolute: the fixed offset d. Prismatic: unused.
    d: Option<f64>,
    /// Prismatic: the fixed angle θ. Revolute: unused.
    theta_deg: Option<f64>,
    // Transforms and zero position.
    /// The body this joint hangs from (a joint's name, `base` or
    /// `world`); the previous joint when left out.
    parent: Option<String>,
    /// The body the joint moves, when not named after the joint (a URDF
    /// link keeps its name).
    child: Option<String>,
    /// Transforms: where the joint sits on its parent.
    origin: Option<PoseFile>,
    /// The joint's axis (unit length not required).
    axis: Option<[f64; 3]>,
    /// Zero position: a point on the axis, in the world.
    point: Option<[f64; 3]>,
    /// Transforms: a fixed transform after the joint's motion.
    after: Option<PoseFile>,
    // All.
    /// Revolute: θ = q + offset.
    offset_deg: Option<f64>,
    /// Prismatic: d = q + offset.
    offset: Option<f64>,
    limits_deg: Option<[f64; 2]>,
    limits: Option<[f64; 2]>,
    /// The mass of the body the joint moves, in that body's frame.
    inertial: Option<InertialFile>,
}

/// A body's mass, its centre of mass (m) and its inertia tensor about the
/// centre of mass in the body's axes (kg·m², `[ixx, ixy, ixz, iyy, iyz,
/// izz]`, as URDF writes it).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct InertialFile {
    mass: f64,
    #[serde(default)]
    com: [f64; 3],
    #[serde(default)]
    inertia: [f64; 6],
}

/// A named frame on a body: a port where tools or other mechanisms attach.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct FrameFile {
    name: String,
    body: String,
    #[serde(default)]
    at: PoseFile,
}

/// Another mechanism mounted at one of this model's frames.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct MountFile {
    /// The prefix of everything mounted (`left-front/coxa`).
    name: String,
    /// The sub-mechanism: a file name the loader resolves, or
    /// `catalogue:<id>`.
    model: String,
    /// The mount point: a frame of this model.
    at: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct CouplingFile {
    follower: String,
    leader: String,
    #[serde(default = "kinolab_common::defaults::one")]
    ratio: f64,
    #[serde(default)]
    offset: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct LoopFile {
    name: String,
    a: String,
    b: String,
    #[serde(default)]
    whole_pose: bool,
    passive: Vec<String>,
}

/// A bounding capsule on a body, ends in the body's frame.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ShapeFile {
    body: String,
    a: [f64; 3],
    b: [f64; 3],
    radius: f64,
}

#[derive(Debug, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a model file (an object with `name`, `convention` and `joints`)"
)]
struct ModelFile {
    name: String,
    convention: Description,
    joints: Vec<JointFile>,
    base: Option<[[f64; 4]; 4]>,
    /// The name of the body everything hangs from (default `world`): a
    /// robot read from URDF keeps its root link's name.
    root: Option<String>,
    /// The tool frame on the last joint's body; for the zero-position
    /// description, the tool's pose in the world with every joint at zero.
    tool: Option<[[f64; 4]; 4]>,
    #[serde(default)]
    frames: Vec<FrameFile>,
    #[serde(default)]
    mounts: Vec<MountFile>,
    #[serde(default)]
    couplings: Vec<CouplingFile>,
    #[serde(default)]
    loops: Vec<LoopFile>,
    #[serde(default)]
    shapes: Vec<ShapeFile>,
    #[serde(default)]
    ignore: Vec<[String; 2]>,
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
pub fn pose_from_matrix(field: &str, m: &[[f64; 4]; 4]) -> Result<Pose, FieldError> {
    use nalgebra::{Matrix3, Rotation3, Translation3, UnitQuaternion};
    for v in m.iter().flatten() {
        finite(field, *v)?;
    }
    let r = Matrix3::from_fn(|i, j| m[i][j]);
    let orthogonal =
        (r.transpose() * r - Matrix3::identity()).norm() < 1e-6 && r.determinant() > 0.0;
    if !orthogonal || m[3] != [0.0, 0.0, 0.0, 1.0] {
        return Err(FieldError::new(
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

fn parse(text: &str) -> Result<ModelFile, FieldError> {
    let file: ModelFile = kinolab_common::error::from_json(text)?;
    crate::model::check_size("joints", file.joints.len())?;
    Ok(file)
}

/// Parse a model file. Mounted sub-mechanisms may only come from the
/// catalogue (`catalogue:<id>`); see [`from_json_with`] for files.
pub fn from_json(text: &str) -> Result<Model, FieldError> {
    from_json_with(text, &mut |name: &str| {
        Err(FieldError::new(
            "",
            format!("cannot open `{name}` here; use `catalogue:<id>`"),
        ))
    })
}

/// Parse a model file; `resolve` turns a mount's `model` name into a model
/// (the command line reads the file next to this one). `catalogue:<id>`
/// always works.
pub fn from_json_with(
    text: &str,
    resolve: &mut dyn FnMut(&str) -> Result<Model, FieldError>,
) -> Result<Model, FieldError> {
    let file = parse(text)?;
    if file.joints.is_empty() && file.mounts.is_empty() {
        return Err(FieldError::new(
            "joints",
            "a model needs at least one joint or mount",
        ));
    }
    let base = file
        .base
        .as_ref()
        .map_or(Ok(Pose::identity()), |m| pose_from_matrix("base", m))?;
    let mut b = match file.convention {
        Description::StandardDh | Description::ModifiedDh => {
            let convention = if file.convention == Description::StandardDh {
                Convention::StandardDh
            } else {
                Convention::ModifiedDh
            };
            let tool = file
                .tool
                .as_ref()
                .map_or(Ok(Pose::identity()), |m| pose_from_matrix("tool", m))?;
            let mut b = chain_builder(&file.name, convention, &dh_rows(&file.joints)?, base, tool)?;
            b.bodies[0].name = root_name(&file);
            b
        }
        Description::Transforms | Description::ZeroPosition => tree(&file, base)?,
    };
    for (i, j) in file.joints.iter().enumerate() {
        let Some(m) = &j.inertial else { continue };
        let name = j.child.as_deref().unwrap_or(&j.name);
        let body = body_index(&b, name, &format!("joints[{i}].inertial"))?;
        let place = format!("joints[{i}].inertial (body `{name}`)");
        b.bodies[body].inertial = Some(crate::Inertial::new(&place, m.mass, m.com, m.inertia)?);
    }
    for (i, f) in file.frames.iter().enumerate() {
        let field = format!("frames[{i}]");
        let body = body_index(&b, &f.body, &format!("{field}.body"))?;
        b.frame(f.name.clone(), body, f.at.pose(&format!("{field}.at"))?);
    }
    for (i, m) in file.mounts.iter().enumerate() {
        let field = format!("mounts[{i}]");
        let sub = match m.model.strip_prefix("catalogue:") {
            Some(id) => crate::catalogue::mechanism(id),
            None => resolve(&m.model),
        }
        .map_err(|e| FieldError::new(format!("{field}.model"), e.to_string()))?;
        crate::model::check_size(&field, b.joints.len() + sub.joints().len())?;
        let Some(port) = b.frames.iter().find(|f| f.name == m.at) else {
            return Err(FieldError::new(
                format!("{field}.at"),
                format!("no frame named `{}` to mount on", m.at),
            ));
        };
        let (on, at) = (port.body, port.offset);
        b.mount(&sub, on, at, &m.name, None);
    }
    for c in &file.couplings {
        b.couple(&c.follower, &c.leader, c.ratio, c.offset);
    }
    for l in &file.loops {
        let passive: Vec<&str> = l.passive.iter().map(String::as_str).collect();
        b.close_loop(&l.name, &l.a, &l.b, l.whole_pose, &passive);
    }
    for (i, sh) in file.shapes.iter().enumerate() {
        let body = body_index(&b, &sh.body, &format!("shapes[{i}].body"))?;
        b.shape(body, sh.a, sh.b, sh.radius);
    }
    for (i, [x, y]) in file.ignore.iter().enumerate() {
        let x = body_index(&b, x, &format!("ignore[{i}]"))?;
        let y = body_index(&b, y, &format!("ignore[{i}]"))?;
        b.ignore_pair(x, y);
    }
    b.build()
}

fn body_index(b: &ModelBuilder, name: &str, field: &str) -> Result<usize, FieldError> {
    b.bodies
        .iter()
        .position(|x| x.name == name)
        .ok_or_else(|| FieldError::new(field, format!("no body named `{name}`")))
}

/// A joint's limits in radians or metres, checked in the file's own units.
fn limits(i: usize, j: &JointFile) -> Result<Option<[f64; 2]>, FieldError> {
    let prismatic = j.kind == JointKind::Prismatic;
    let ordered = |name: &str, [lo, hi]: [f64; 2]| {
        let field = format!("joints[{i}].{name}");
        finite(field.as_str(), lo)?;
        finite(field.as_str(), hi)?;
        if lo > hi {
            return Err(FieldError::new(
                field,
                format!("the lower limit {lo} is above the upper limit {hi}"),
            ));
        }
        Ok([lo, hi])
    };
    match (prismatic, j.limits_deg, j.limits) {
        (false, Some(l), None) => Ok(Some(ordered("limits_deg", l)?.map(f64::to_radians))),
        (true, None, Some(l)) => Ok(Some(ordered("limits", l)?)),
        (_, None, None) => Ok(None),
        (false, _, Some(_)) => Err(FieldError::new(
            format!("joints[{i}].limits"),
            "a revolute joint's limits are `limits_deg`",
        )),
        (true, Some(_), _) => Err(FieldError::new(
            format!("joints[{i}].limits_deg"),
            "a prismatic joint's limits are `limits` in metres",
        )),
    }
}

fn offset(j: &JointFile) -> f64 {
    if j.kind == JointKind::Prismatic {
        j.offset.unwrap_or(0.0)
    } else {
        j.offset_deg.unwrap_or(0.0).to_radians()
    }
}

/// Refuse a field that the description does not use.
fn unused(i: usize, present: &[(&str, bool)], description: &str) -> Result<(), FieldError> {
    match present.iter().find(|(_, here)| *here) {
        Some((name, _)) => Err(FieldError::new(
            format!("joints[{i}].{name}"),
            format!("not part of a {description} description"),
        )),
        None => Ok(()),
    }
}

fn dh_rows(joints: &[JointFile]) -> Result<Vec<DhRow>, FieldError> {
    let mut rows = Vec::with_capacity(joints.len());
    for (i, j) in joints.iter().enumerate() {
        unused(
            i,
            &[
                ("parent", j.parent.is_some()),
                ("child", j.child.is_some()),
                ("origin", j.origin.is_some()),
                ("axis", j.axis.is_some()),
                ("point", j.point.is_some()),
            ],
            "DH",
        )?;
        rows.push(DhRow {
            name: j.name.clone(),
            kind: j.kind,
            a: j.a.unwrap_or(0.0),
            alpha: j.alpha_deg.unwrap_or(0.0).to_radians(),
            d: j.d.unwrap_or(0.0),
            theta: j.theta_deg.unwrap_or(0.0).to_radians(),
            offset: offset(j),
            limits: limits(i, j)?,
        });
    }
    Ok(rows)
}

fn unit_axis(field: &str, v: [f64; 3]) -> Result<Unit<Vector3<f64>>, FieldError> {
    for x in v {
        finite(field, x)?;
    }
    Unit::try_new(Vector3::from(v), 1e-9)
        .ok_or_else(|| FieldError::new(field, "an axis cannot be zero (or shorter than 1e-9)"))
}

fn root_name(file: &ModelFile) -> String {
    file.root.clone().unwrap_or_else(|| WORLD.to_owned())
}

/// Transforms and zero-position descriptions: a tree hung from `base`.
fn tree(file: &ModelFile, base: Pose) -> Result<ModelBuilder, FieldError> {
    let zero_position = file.convention == Description::ZeroPosition;
    let mut b = ModelBuilder::new(file.name.clone());
    b.bodies[0].name = root_name(file);
    // The joints keep the order the file gives them (parents first), as a
    // URDF file's do; a file that mounts others is ordered by depth, like
    // the catalogue's assemblies, so a hexapod file and the catalogue's
    // hexapod take their joint values in the same order.
    b.keep_order = file.mounts.is_empty();
    // A `base` body only when the file places one.
    let mut previous = match file.base {
        Some(_) => b.fixed_base(base),
        None => 0,
    };
    // Zero position: where each body's frame sits, relative to the base,
    // with every joint at zero (its joint's point, axes as the base's).
    let mut home: Vec<Vector3<f64>> = vec![Vector3::zeros(); b.bodies.len()];
    for (i, j) in file.joints.iter().enumerate() {
        let field = |f: &str| format!("joints[{i}].{f}");
        let dh_fields = [
            ("a", j.a.is_some()),
            ("alpha_deg", j.alpha_deg.is_some()),
            ("d", j.d.is_some()),
            ("theta_deg", j.theta_deg.is_some()),
        ];
        let parent = match &j.parent {
            Some(p) => body_index(&b, p, &field("parent"))?,
            None => previous,
        };
        let axis = unit_axis(&field("axis"), j.axis.unwrap_or([0.0, 0.0, 1.0]))?;
        let origin = if zero_position {
            unused(i, &dh_fields, "zero-position")?;
            unused(
                i,
                &[("origin", j.origin.is_some()), ("after", j.after.is_some())],
                "zero-position",
            )?;
            let point = match j.point {
                Some(p) => {
                    for v in p {
                        finite(field("point"), v)?;
                    }
                    Vector3::from(p)
                }
                None => home.get(parent).copied().unwrap_or_default(),
            };
            let from = home.get(parent).copied().unwrap_or_default();
            home.push(point);
            Pose::translation(point.x - from.x, point.y - from.y, point.z - from.z)
        } else {
            unused(i, &dh_fields, "transforms")?;
            unused(i, &[("point", j.point.is_some())], "transforms")?;
            j.origin.unwrap_or_default().pose(&field("origin"))?
        };
        let after = match &j.after {
            Some(a) => a.pose(&field("after"))?,
            None => Pose::identity(),
        };
        previous = b.joint(
            j.name.clone(),
            j.kind,
            parent,
            origin,
            axis,
            offset(j),
            after,
            limits(i, j)?,
        );
        if let Some(child) = &j.child {
            b.bodies[previous].name = child.clone();
        }
    }
    let tool = match &file.tool {
        None => Pose::identity(),
        Some(m) => {
            let t = pose_from_matrix("tool", m)?;
            if zero_position {
                // M is the tool in the base frame at zero; the last body's
                // frame then sits at its joint's point, unrotated.
                let at = home.get(previous).copied().unwrap_or_default();
                Pose::translation(-at.x, -at.y, -at.z) * t
            } else {
                t
            }
        }
    };
    if !file.frames.iter().any(|f| f.name == "tool") {
        b.frame("tool", previous, tool);
    }
    Ok(b)
}

fn pose_json(p: &Pose) -> serde_json::Value {
    let [r, pi, y] = crate::model::rpy(&p.rotation);
    let t = p.translation.vector;
    serde_json::json!({ "xyz": [t.x, t.y, t.z], "rpy_deg": [r.to_degrees(), pi.to_degrees(), y.to_degrees()] })
}

/// A model as a file in the transforms description: every joint with its
/// parent, origin, axis and the transform after its motion, with frames,
/// couplings, loops, shapes and ignored pairs. Mounted sub-mechanisms are
/// written out flat (their names keep the mount prefix).
pub fn to_json(model: &Model) -> String {
    use serde_json::json;
    let body = |b: usize| {
        model
            .bodies()
            .get(b)
            .map_or(String::new(), |x| x.name.clone())
    };
    let joints: Vec<serde_json::Value> = model
        .joints()
        .iter()
        .map(|j| {
            let mut v = json!({
                "name": j.name,
                "type": j.kind,
                "parent": body(j.parent),
                "origin": pose_json(&j.origin),
                "axis": [j.axis.x, j.axis.y, j.axis.z],
            });
            if j.post != Pose::identity() {
                v["after"] = pose_json(&j.post);
            }
            if body(j.child) != j.name {
                v["child"] = json!(body(j.child));
            }
            let prismatic = j.kind == JointKind::Prismatic;
            if j.offset != 0.0 {
                if prismatic {
                    v["offset"] = json!(j.offset);
                } else {
                    v["offset_deg"] = json!(j.offset.to_degrees());
                }
            }
            if let Some([lo, hi]) = j.limits {
                if prismatic {
                    v["limits"] = json!([lo, hi]);
                } else {
                    v["limits_deg"] = json!([lo.to_degrees(), hi.to_degrees()]);
                }
            }
            if let Some(i) = model.bodies().get(j.child).and_then(|b| b.inertial) {
                v["inertial"] = json!({
                    "mass": i.mass,
                    "com": [i.com.x, i.com.y, i.com.z],
                    "inertia": i.entries(),
                });
            }
            v
        })
        .collect();
    let frame_name = |f: &crate::FrameRef| -> String {
        model
            .frames()
            .iter()
            .find(|x| x.body == f.body && x.offset == f.offset)
            .map_or_else(|| body(f.body), |x| x.name.clone())
    };
    let variable = |v: usize| {
        model
            .variable_joint(v)
            .map_or(String::new(), |j| j.name.clone())
    };
    let mut file = json!({
        "name": model.name(),
        "convention": "transforms",
        "joints": joints,
        "frames": model.frames().iter().map(|f| json!({ "name": f.name, "body": body(f.body), "at": pose_json(&f.offset) })).collect::<Vec<_>>(),
        "couplings": model.couplings().iter().map(|c| json!({ "follower": variable(c.follower), "leader": variable(c.leader), "ratio": c.ratio, "offset": c.offset })).collect::<Vec<_>>(),
        "loops": model.loops().iter().map(|l| json!({ "name": l.name, "a": frame_name(&l.a), "b": frame_name(&l.b), "whole_pose": l.whole_pose, "passive": l.passive.iter().map(|&v| variable(v)).collect::<Vec<_>>() })).collect::<Vec<_>>(),
        "shapes": model.shapes().iter().map(|s| json!({ "body": body(s.body), "a": [s.a.x, s.a.y, s.a.z], "b": [s.b.x, s.b.y, s.b.z], "radius": s.radius })).collect::<Vec<_>>(),
        "ignore": model.ignored_pairs().iter().map(|&(a, b)| json!([body(a), body(b)])).collect::<Vec<_>>(),
    });
    if let Some(root) = model.bodies().first().filter(|b| b.name != WORLD) {
        file["root"] = json!(root.name);
    }
    serde_json::to_string_pretty(&file).unwrap_or_default()
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
