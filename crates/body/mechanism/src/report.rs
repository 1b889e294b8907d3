//! The reports of `kinolab fk` and `kinolab ik` (field names as in the
//! command-line contract) and of the JS API's mechanism queries: typed
//! structs, printed through [`kinolab_common::display::tidy_report`].

use serde::Serialize;

use crate::file::matrix_of;
use crate::ik::Solution;
use crate::kinematics::Placement;
use crate::model::{JointKind, Model, Pose};
use crate::shapes::{Collisions, Part};

/// `kinolab fk`: the frame's name and its 4×4 matrix.
#[derive(Debug, Clone, Serialize)]
pub struct ForwardReport {
    pub frame: String,
    pub matrix: [[f64; 4]; 4],
}

pub fn forward(frame: &str, pose: &Pose) -> ForwardReport {
    ForwardReport {
        frame: frame.to_owned(),
        matrix: matrix_of(pose),
    }
}

/// `kinolab ik`: joint values and how well they meet the target.
#[derive(Debug, Clone, Serialize)]
pub struct InverseReport {
    pub q: Vec<f64>,
    pub converged: bool,
    pub position_error: f64,
    pub rotation_error: f64,
    pub iterations: usize,
}

pub fn inverse(s: &Solution) -> InverseReport {
    InverseReport {
        q: s.q.clone(),
        converged: s.converged,
        position_error: s.position_error,
        rotation_error: s.rotation_error,
        iterations: s.iterations,
    }
}

/// A mechanism's structure: joints and their roles, bodies, frames, the
/// sub-mechanism tree, couplings, loops and plugged-in solvers.
#[derive(Debug, Clone, Serialize)]
pub struct Description {
    pub name: String,
    pub dof: usize,
    pub variables: Vec<Variable>,
    pub joints: Vec<JointLink>,
    pub bodies: Vec<String>,
    pub frames: Vec<String>,
    pub groups: Vec<Group>,
    pub couplings: Vec<CouplingReport>,
    pub loops: Vec<String>,
    pub shapes: usize,
    pub solvers: Vec<String>,
}

/// One column of the state: its joint, limits (rad or m) and role.
#[derive(Debug, Clone, Serialize)]
pub struct Variable {
    pub name: String,
    #[serde(rename = "type")]
    pub kind: JointKind,
    pub limits: Option<[f64; 2]>,
    /// `driven`, `follows` (a coupling sets it) or `closes a loop`.
    pub role: &'static str,
}

#[derive(Debug, Clone, Serialize)]
pub struct JointLink {
    pub name: String,
    #[serde(rename = "type")]
    pub kind: JointKind,
    pub parent: String,
    pub child: String,
}

/// A sub-mechanism (a mount) and its bodies.
#[derive(Debug, Clone, Serialize)]
pub struct Group {
    pub name: String,
    pub parent: Option<String>,
    pub bodies: Vec<String>,
}

#[derive(Debug, Clone, Serialize)]
pub struct CouplingReport {
    pub follower: String,
    pub leader: String,
    pub ratio: f64,
    pub offset: f64,
}

pub fn describe(model: &Model) -> Description {
    let name_of = |b: usize| {
        model
            .bodies()
            .get(b)
            .map_or("", |x| x.name.as_str())
            .to_owned()
    };
    let variable_name = |v: usize| {
        model
            .variable_joint(v)
            .map_or("", |j| j.name.as_str())
            .to_owned()
    };
    Description {
        name: model.name().to_owned(),
        dof: model.dof(),
        variables: (0..model.dof())
            .filter_map(|v| {
                let j = model.variable_joint(v)?;
                Some(Variable {
                    name: j.name.clone(),
                    kind: j.kind,
                    limits: j.limits,
                    role: role(model, v),
                })
            })
            .collect(),
        joints: model
            .joints()
            .iter()
            .map(|j| JointLink {
                name: j.name.clone(),
                kind: j.kind,
                parent: name_of(j.parent),
                child: name_of(j.child),
            })
            .collect(),
        bodies: model.bodies().iter().map(|b| b.name.clone()).collect(),
        frames: model.frames().iter().map(|f| f.name.clone()).collect(),
        groups: model
            .groups()
            .iter()
            .map(|g| Group {
                name: g.name.clone(),
                parent: g
                    .parent
                    .and_then(|p| model.groups().get(p))
                    .map(|p| p.name.clone()),
                bodies: g.bodies.iter().map(|&b| name_of(b)).collect(),
            })
            .collect(),
        couplings: model
            .couplings()
            .iter()
            .map(|c| CouplingReport {
                follower: variable_name(c.follower),
                leader: variable_name(c.leader),
                ratio: c.ratio,
                offset: c.offset,
            })
            .collect(),
        loops: model.loops().iter().map(|l| l.name.clone()).collect(),
        shapes: model.shapes().len(),
        solvers: model
            .command_names()
            .into_iter()
            .map(String::from)
            .collect(),
    }
}

/// Who sets variable `v`.
fn role(model: &Model, v: usize) -> &'static str {
    if model.is_follower(v) {
        "follows"
    } else if model.is_driven(v) {
        "driven"
    } else {
        "closes a loop"
    }
}

/// Every body's frame as a 4×4 matrix, by name.
#[derive(Debug, Clone, Serialize)]
pub struct PlacementReport {
    pub bodies: Vec<BodyPose>,
}

#[derive(Debug, Clone, Serialize)]
pub struct BodyPose {
    pub name: String,
    pub matrix: [[f64; 4]; 4],
}

pub fn placement(model: &Model, placed: &Placement) -> PlacementReport {
    PlacementReport {
        bodies: model
            .bodies()
            .iter()
            .zip(&placed.bodies)
            .map(|(b, p)| BodyPose {
                name: b.name.clone(),
                matrix: matrix_of(p),
            })
            .collect(),
    }
}

/// A 6 × n Jacobian as rows (vx, vy, vz, ωx, ωy, ωz).
#[derive(Debug, Clone, Serialize)]
pub struct JacobianReport {
    pub rows: Vec<Vec<f64>>,
}

pub fn jacobian(jac: &nalgebra::DMatrix<f64>) -> JacobianReport {
    JacobianReport {
        rows: (0..jac.nrows())
            .map(|r| jac.row(r).iter().copied().collect())
            .collect(),
    }
}

/// One side of a colliding pair: a body by name, or an obstacle by index.
#[derive(Debug, Clone, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PartReport {
    Body(String),
    Obstacle(usize),
}

fn part(model: &Model, p: &Part) -> PartReport {
    match *p {
        Part::Body(b) => PartReport::Body(
            model
                .bodies()
                .get(b)
                .map(|x| x.name.clone())
                .unwrap_or_default(),
        ),
        Part::Obstacle(i) => PartReport::Obstacle(i),
    }
}

/// Colliding pairs, the work the tree search did, and the smallest gap.
#[derive(Debug, Clone, Serialize)]
pub struct CollisionReport {
    pub colliding: bool,
    pub pairs: Vec<[PartReport; 2]>,
    pub coarse_tests: usize,
    pub fine_tests: usize,
    pub clearance: Option<Clearance>,
}

#[derive(Debug, Clone, Serialize)]
pub struct Clearance {
    pub distance: f64,
    pub between: [PartReport; 2],
}

pub fn collisions(
    model: &Model,
    found: &Collisions,
    clearance: Option<(f64, Part, Part)>,
) -> CollisionReport {
    CollisionReport {
        colliding: !found.pairs.is_empty(),
        pairs: found
            .pairs
            .iter()
            .map(|(a, b)| [part(model, a), part(model, b)])
            .collect(),
        coarse_tests: found.coarse_tests,
        fine_tests: found.fine_tests,
        clearance: clearance.map(|(distance, a, b)| Clearance {
            distance,
            between: [part(model, &a), part(model, &b)],
        }),
    }
}
