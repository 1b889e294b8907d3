//! The JSON of `kinolab fk` and `kinolab ik` (field names as in the
//! command-line contract), and of the JS API's mechanism queries.

use serde_json::{Value, json};

use crate::file::matrix_of;
use crate::ik::Solution;
use crate::kinematics::Placement;
use crate::model::{Model, Pose};
use crate::shapes::{Collisions, Part};

/// Rounding noise (|x| < 1e-12) written as 0.
fn tidy(x: f64) -> f64 {
    if x.abs() < 1e-12 { 0.0 } else { x }
}

/// `kinolab fk`: the frame's name and its 4×4 matrix.
pub fn forward(frame: &str, pose: &Pose) -> Value {
    let m = matrix_of(pose).map(|row| row.map(tidy));
    json!({ "frame": frame, "matrix": m })
}

/// `kinolab ik`: joint values and how well they meet the target.
pub fn inverse(s: &Solution) -> Value {
    json!({
        "q": s.q.iter().map(|v| tidy(*v)).collect::<Vec<_>>(),
        "converged": s.converged,
        "position_error": s.position_error,
        "rotation_error": s.rotation_error,
        "iterations": s.iterations,
    })
}

/// A mechanism's structure: joints and their roles, bodies, frames, the
/// sub-mechanism tree, couplings, loops and plugged-in solvers.
pub fn describe(model: &Model) -> Value {
    let variables: Vec<Value> = (0..model.dof())
        .filter_map(|v| {
            let j = model.variable_joint(v)?;
            let role = if model.is_follower(v) {
                "follows"
            } else if model.is_driven(v) {
                "driven"
            } else {
                "closes a loop"
            };
            Some(json!({
                "name": j.name,
                "type": j.kind,
                "limits": j.limits,
                "role": role,
            }))
        })
        .collect();
    let name_of = |b: usize| model.bodies().get(b).map_or("", |x| x.name.as_str());
    let joints: Vec<Value> = model
        .joints()
        .iter()
        .map(|j| json!({ "name": j.name, "type": j.kind, "parent": name_of(j.parent), "child": name_of(j.child) }))
        .collect();
    let groups: Vec<Value> = model
        .groups()
        .iter()
        .map(|g| {
            json!({
                "name": g.name,
                "parent": g.parent.and_then(|p| model.groups().get(p)).map(|p| p.name.clone()),
                "bodies": g.bodies.iter().map(|&b| name_of(b)).collect::<Vec<_>>(),
            })
        })
        .collect();
    let couplings: Vec<Value> = model
        .couplings()
        .iter()
        .map(|c| {
            let n = |v: usize| model.variable_joint(v).map_or("", |j| j.name.as_str());
            json!({ "follower": n(c.follower), "leader": n(c.leader), "ratio": c.ratio, "offset": c.offset })
        })
        .collect();
    json!({
        "name": model.name(),
        "dof": model.dof(),
        "variables": variables,
        "joints": joints,
        "bodies": model.bodies().iter().map(|b| b.name.clone()).collect::<Vec<_>>(),
        "frames": model.frames().iter().map(|f| f.name.clone()).collect::<Vec<_>>(),
        "groups": groups,
        "couplings": couplings,
        "loops": model.loops().iter().map(|l| l.name.clone()).collect::<Vec<_>>(),
        "shapes": model.shapes().len(),
        "solvers": model.command_names(),
    })
}

/// Every body's frame as a 4×4 matrix, by name.
pub fn placement(model: &Model, placed: &Placement) -> Value {
    let bodies: Vec<Value> = model
        .bodies()
        .iter()
        .zip(&placed.bodies)
        .map(|(b, p)| json!({ "name": b.name, "matrix": matrix_of(p).map(|r| r.map(tidy)) }))
        .collect();
    json!({ "bodies": bodies })
}

/// A 6 × n Jacobian as rows (vx, vy, vz, ωx, ωy, ωz).
pub fn jacobian(jac: &nalgebra::DMatrix<f64>) -> Value {
    let rows: Vec<Vec<f64>> = (0..jac.nrows())
        .map(|r| jac.row(r).iter().map(|v| tidy(*v)).collect())
        .collect();
    json!({ "rows": rows })
}

fn part(model: &Model, p: &Part) -> Value {
    match *p {
        Part::Body(b) => json!({ "body": model.bodies().get(b).map(|x| x.name.clone()) }),
        Part::Obstacle(i) => json!({ "obstacle": i }),
    }
}

/// Colliding pairs, the work the tree search did, and the smallest gap.
pub fn collisions(
    model: &Model,
    found: &Collisions,
    clearance: Option<(f64, Part, Part)>,
) -> Value {
    json!({
        "colliding": !found.pairs.is_empty(),
        "pairs": found.pairs.iter().map(|(a, b)| json!([part(model, a), part(model, b)])).collect::<Vec<_>>(),
        "coarse_tests": found.coarse_tests,
        "fine_tests": found.fine_tests,
        "clearance": clearance.map(|(d, a, b)| json!({ "distance": d, "between": [part(model, &a), part(model, &b)] })),
    })
}
