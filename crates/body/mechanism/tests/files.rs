//! Model files in every description agree with each other and with the
//! catalogue; bad files say which field is wrong.

use std::f64::consts::PI;

use kinolab_mechanism::catalogue::mechanism;
use kinolab_mechanism::file::{from_json, from_json_with};
use kinolab_mechanism::{FieldError, Model, Pose};
use serde_json::json;

fn tool_pose(m: &Model, q: &[f64]) -> Pose {
    let f = m.frame("tool").unwrap_or_else(|e| panic!("{e}"));
    m.pose(q, &f).unwrap_or_else(|e| panic!("{e}"))
}

fn same(a: &Pose, b: &Pose) -> bool {
    (a.translation.vector - b.translation.vector).norm() < 1e-12
        && a.rotation.angle_to(&b.rotation) < 1e-12
}

mod support;

/// `count` seeded joint states of `m`, within its limits.
fn states(m: &Model, count: usize) -> Vec<Vec<f64>> {
    support::sample(&support::states(m), count)
}

/// The Puma written by hand as a product of exponentials: each joint's
/// axis and a point on it with every joint at zero, read off the standard
/// DH table (joint i turns about z_{i−1} through o_{i−1}), and the tool at
/// (0.4521, −0.15005, 1.1036) with the base's orientation. It must move
/// exactly like the catalogue's DH Puma.
#[test]
fn zero_position_puma_matches_the_dh_puma() -> Result<(), FieldError> {
    let (d1, a2, a3, d3, d4) = (0.6718, 0.4318, 0.0203, 0.15005, 0.4318);
    let axis = |name: &str, axis: [f64; 3], point: [f64; 3]| json!({ "name": name, "type": "revolute", "axis": axis, "point": point });
    let file = json!({
        "name": "Puma by screws",
        "convention": "zero_position",
        "joints": [
            axis("q1", [0.0, 0.0, 1.0], [0.0, 0.0, 0.0]),
            axis("q2", [0.0, -1.0, 0.0], [0.0, 0.0, d1]),
            axis("q3", [0.0, -1.0, 0.0], [a2, 0.0, d1]),
            axis("q4", [0.0, 0.0, 1.0], [a2 + a3, -d3, d1]),
            axis("q5", [0.0, -1.0, 0.0], [a2 + a3, -d3, d1 + d4]),
            axis("q6", [0.0, 0.0, 1.0], [a2 + a3, -d3, d1 + d4]),
        ],
        "tool": [[1, 0, 0, a2 + a3], [0, 1, 0, -d3], [0, 0, 1, d1 + d4], [0, 0, 0, 1]],
    });
    let poe = from_json(&file.to_string())?;
    let puma = mechanism("puma560")?;
    for q in states(&puma, 200) {
        assert!(same(&tool_pose(&poe, &q), &tool_pose(&puma, &q)), "{q:?}");
    }
    Ok(())
}

#[test]
fn a_transforms_tree_matches_the_dh_chain() -> Result<(), FieldError> {
    let file = json!({
        "name": "2R by transforms",
        "convention": "transforms",
        "joints": [
            { "name": "q1", "type": "revolute", "limits_deg": [-170, 170] },
            { "name": "q2", "type": "revolute", "origin": { "xyz": [1.0, 0, 0] } },
            { "name": "hand", "type": "fixed", "origin": { "xyz": [0.8, 0, 0] } }
        ],
    });
    let tree = from_json(&file.to_string())?;
    let dh = mechanism("planar-2r")?;
    for q in states(&dh, 50) {
        let a = tool_pose(&tree, &q).translation.vector;
        let b = tool_pose(&dh, &q).translation.vector;
        assert!((a - b).norm() < 1e-12, "{a} {b}");
    }
    Ok(())
}

/// A hexapod assembled from two files — a torso with six mount points and
/// one leg — is the catalogue's hexapod.
#[test]
fn a_hexapod_from_one_leg_file() -> Result<(), FieldError> {
    let leg = json!({
        "name": "Leg",
        "convention": "transforms",
        "joints": [
            { "name": "coxa", "type": "revolute", "parent": "world", "limits_deg": [-45, 45] },
            { "name": "femur", "type": "revolute", "origin": { "xyz": [0.05, 0, 0] }, "axis": [0, -1, 0], "limits_deg": [-90, 90] },
            { "name": "tibia", "type": "revolute", "origin": { "xyz": [0.1, 0, 0] }, "axis": [0, -1, 0], "offset_deg": -90, "limits_deg": [-120, 120] }
        ],
        "frames": [ { "name": "foot", "body": "tibia", "at": { "xyz": [0.15, 0, 0] } } ]
    });
    let mounts = [
        ("left-front", 0.12, 0.06, 45.0),
        ("left-middle", 0.0, 0.08, 90.0),
        ("left-rear", -0.12, 0.06, 135.0),
        ("right-rear", -0.12, -0.06, -135.0),
        ("right-middle", 0.0, -0.08, -90.0),
        ("right-front", 0.12, -0.06, -45.0),
    ];
    let torso = json!({
        "name": "Hexapod",
        "convention": "transforms",
        "joints": [ { "name": "torso", "type": "fixed", "parent": "world", "origin": { "xyz": [0, 0, 0.15] } } ],
        "frames": mounts.iter().map(|(n, x, y, h)| json!({ "name": format!("{n}-mount"), "body": "torso", "at": { "xyz": [x, y, 0], "rpy_deg": [0, 0, h] } })).collect::<Vec<_>>(),
        "mounts": mounts.iter().map(|(n, _, _, _)| json!({ "name": n, "model": "leg.model.json", "at": format!("{n}-mount") })).collect::<Vec<_>>(),
    });
    let mut opened = Vec::new();
    let built = from_json_with(&torso.to_string(), &mut |name: &str| {
        opened.push(name.to_string());
        from_json(&leg.to_string())
    })?;
    assert_eq!(opened.len(), 6);
    let reference = mechanism("hexapod")?;
    assert_eq!(built.dof(), reference.dof());
    for q in states(&reference, 30) {
        for (n, _, _, _) in mounts {
            let name = format!("{n}/foot");
            let a = built.pose(&q, &built.frame(&name)?)?;
            let b = reference.pose(&q, &reference.frame(&name)?)?;
            assert!(same(&a, &b), "{name}");
        }
    }
    Ok(())
}

#[test]
fn couplings_loops_and_shapes_load_from_a_file() -> Result<(), FieldError> {
    let file = json!({
        "name": "Screw",
        "convention": "transforms",
        "joints": [
            { "name": "turn", "type": "continuous" },
            { "name": "travel", "type": "prismatic", "limits": [-1, 1] }
        ],
        "couplings": [ { "follower": "travel", "leader": "turn", "ratio": 0.002 } ],
        "shapes": [ { "body": "travel", "a": [0, 0, 0], "b": [0, 0, 0.1], "radius": 0.01 } ]
    });
    let screw = from_json(&file.to_string())?;
    let mut q = vec![2.0 * PI, 0.0];
    screw.apply_couplings(&mut q);
    // 2 mm of travel per radian: one turn advances the nut 2π · 2 mm.
    assert!((q[1] - 2.0 * PI * 0.002).abs() < 1e-15);
    assert!((tool_pose(&screw, &q).translation.z - q[1]).abs() < 1e-15);
    assert_eq!(screw.shapes().len(), 1);
    Ok(())
}

#[test]
fn bad_extended_files_name_the_field() {
    let cases = [
        (
            json!({ "name": "x", "convention": "transforms", "joints": [ { "name": "a", "type": "revolute", "alpha_deg": 3 } ] }),
            "joints[0].alpha_deg",
        ),
        (
            json!({ "name": "x", "convention": "standard_dh", "joints": [ { "name": "a", "type": "revolute", "axis": [0, 0, 1] } ] }),
            "joints[0].axis",
        ),
        (
            json!({ "name": "x", "convention": "transforms", "joints": [ { "name": "a", "type": "revolute", "axis": [0, 0, 0] } ] }),
            "joints[0].axis",
        ),
        (
            json!({ "name": "x", "convention": "transforms", "joints": [ { "name": "a", "type": "revolute", "parent": "ghost" } ] }),
            "joints[0].parent",
        ),
        (
            json!({ "name": "x", "convention": "transforms", "joints": [ { "name": "a", "type": "revolute" } ], "mounts": [ { "name": "m", "model": "catalogue:planar-2r", "at": "nowhere" } ] }),
            "mounts[0].at",
        ),
        (
            json!({ "name": "x", "convention": "transforms", "joints": [ { "name": "a", "type": "revolute" } ], "mounts": [ { "name": "m", "model": "catalogue:warp-drive", "at": "tool" } ] }),
            "mounts[0].model",
        ),
        (
            json!({ "name": "x", "convention": "transforms", "joints": [ { "name": "a", "type": "revolute" } ], "couplings": [ { "follower": "a", "leader": "b" } ] }),
            "couplings[0].leader",
        ),
        (
            json!({ "name": "x", "convention": "transforms", "joints": [ { "name": "a", "type": "revolute" } ], "shapes": [ { "body": "a", "a": [0, 0, 0], "b": [1, 0, 0], "radius": -1 } ] }),
            "shapes[0].radius",
        ),
        (
            json!({ "name": "x", "convention": "transforms", "joints": [ { "name": "a", "type": "revolute" } ], "loops": [ { "name": "l", "a": "tool", "b": "nothing", "passive": ["a"] } ] }),
            "loops[0].b",
        ),
        (
            json!({ "name": "x", "convention": "zero_position", "joints": [ { "name": "a", "type": "revolute", "origin": {} } ] }),
            "joints[0].origin",
        ),
    ];
    for (file, field) in cases {
        match from_json(&file.to_string()) {
            Err(e) => assert!(e.field.starts_with(field), "{field}: got `{e}`"),
            Ok(_) => panic!("{field}: accepted"),
        }
    }
}

/// Every catalogue mechanism written as a file and read back moves the
/// same: every body's frame, couplings, loops and shapes survive.
#[test]
fn saved_models_load_back_the_same() -> Result<(), FieldError> {
    for (id, _, _) in kinolab_mechanism::catalogue::CATALOGUE {
        let model = mechanism(id)?;
        let text = kinolab_mechanism::file::to_json(&model);
        let back = from_json(&text).map_err(|e| FieldError::new(*id, e.to_string()))?;
        assert_eq!(back.dof(), model.dof(), "{id}");
        assert_eq!(back.couplings().len(), model.couplings().len(), "{id}");
        assert_eq!(back.loops().len(), model.loops().len(), "{id}");
        assert_eq!(back.shapes().len(), model.shapes().len(), "{id}");
        for q in states(&model, 10) {
            let a = model.place(&q)?;
            let b = back.place(&q)?;
            for (name, pose) in model.bodies().iter().zip(&a.bodies) {
                let i = back
                    .bodies()
                    .iter()
                    .position(|x| x.name == name.name)
                    .unwrap_or(usize::MAX);
                assert!(same(pose, &b.bodies[i]), "{id}: {}", name.name);
            }
        }
    }
    Ok(())
}
