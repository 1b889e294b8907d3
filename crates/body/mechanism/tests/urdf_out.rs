//! URDF out: every catalogue model, and models written in DH, as
//! transforms with offsets and as products of exponentials, written as URDF
//! and read back, place every body and named frame where the model does
//! (to 1e-12), with the same limits and the couplings as `mimic`.
// The helpers below are test code too: a failed read is a failed test.
#![allow(clippy::expect_used)]

use kinolab_mechanism::catalogue::{CATALOGUE, mechanism};
use kinolab_mechanism::file::from_json;
use kinolab_mechanism::{JointKind, Model, Pose, urdf};
use serde_json::json;

mod support;

fn same(a: &Pose, b: &Pose) -> bool {
    (a.translation.vector - b.translation.vector).norm() < 1e-12
        && a.rotation.angle_to(&b.rotation) < 1e-12
}

/// Write `model`, read it back, and compare every body and frame in 40
/// seeded states. Returns what the writer said it left out.
fn round_trip(model: &Model) -> Vec<String> {
    let written = urdf::write(model);
    let robot = urdf::read(&written.text)
        .unwrap_or_else(|e| panic!("{}: {e}\n{}", model.name(), written.text));
    let back = &robot.model;
    for q in support::sample(&support::states(model), 40) {
        let set: Vec<(String, f64)> = robot
            .driven()
            .map(|name| {
                let v = model.variable(name).expect("a driven joint of the model");
                (name.to_owned(), q[v])
            })
            .collect();
        let q_back = robot.state_named(&set).expect("inside the limits");
        let placed = model.place(&q).expect("place");
        let placed_back = back.place(&q_back).expect("place back");
        let at = |name: &str| {
            let f = back.frame(name).expect("a link of the file");
            placed_back.bodies[f.body] * f.offset
        };
        for (body, pose) in model.bodies().iter().zip(&placed.bodies) {
            assert!(
                same(pose, &at(&body.name)),
                "{} {}",
                model.name(),
                body.name
            );
        }
        for (frame, (name, link)) in model.frames().iter().zip(&written.frame_links) {
            assert_eq!(&frame.name, name);
            let pose = placed.bodies[frame.body] * frame.offset;
            assert!(same(&pose, &at(link)), "{} frame {name}", model.name());
        }
    }
    same_joints(model, back);
    written.notices
}

/// Every moving joint keeps its limits (a revolute joint without limits
/// comes back continuous) and every coupling its leader, ratio and offset.
fn same_joints(model: &Model, back: &Model) {
    for joint in model.joints().iter().filter(|j| j.kind.moves()) {
        let v = back.variable(&joint.name).expect("the joint is back");
        let other = back.variable_joint(v).expect("its joint");
        assert_eq!(joint.limits, other.limits, "{}", joint.name);
        let kind = match (joint.kind, joint.limits) {
            (JointKind::Revolute, None) => JointKind::Continuous,
            (kind, _) => kind,
        };
        assert_eq!(kind, other.kind, "{}", joint.name);
    }
    assert_eq!(
        named_couplings(model),
        named_couplings(back),
        "{}",
        model.name()
    );
}

/// Each coupling by its joints' names: follower, leader, ratio, offset.
fn named_couplings(m: &Model) -> Vec<(String, String, f64, f64)> {
    let name = |v: usize| {
        m.variable_joint(v)
            .map(|j| j.name.clone())
            .unwrap_or_default()
    };
    let mut couplings: Vec<_> = m
        .couplings()
        .iter()
        .map(|c| (name(c.follower), name(c.leader), c.ratio, c.offset))
        .collect();
    couplings.sort_by(|a, b| a.0.cmp(&b.0));
    couplings
}

#[test]
fn every_catalogue_model_reads_back_to_the_same_frames() {
    for (id, _, _) in CATALOGUE {
        let model = mechanism(id).expect("catalogue model");
        let notices = round_trip(&model);
        if model.loops().is_empty() {
            assert!(notices.is_empty(), "{id}: {notices:?}");
        } else {
            assert_eq!(notices.len(), model.loops().len(), "{id}: {notices:?}");
            assert!(notices[0].contains("left open"), "{notices:?}");
        }
    }
}

#[test]
fn the_rocker_bogie_differential_is_written_as_mimic() {
    let model = mechanism("rocker-bogie").expect("catalogue model");
    let text = urdf::write(&model).text;
    assert!(
        text.contains("<mimic joint=\"left-rocker\" multiplier=\"-1\" offset=\"0\"/>"),
        "{text}"
    );
}

/// A transforms file with joint offsets, a tilted axis, a post-less tree
/// with a branch, a revolute joint without limits and a named frame.
#[test]
fn offsets_tilted_axes_and_branches_survive() {
    let file = json!({
        "name": "Odd tree",
        "convention": "transforms",
        "joints": [
            { "name": "a", "type": "revolute", "offset_deg": 30, "axis": [1, 1, 0], "origin": { "xyz": [0.1, 0.2, 0.3], "rpy_deg": [10, 89.9999, -20] } },
            { "name": "b", "type": "prismatic", "parent": "a", "axis": [0, 0.6, 0.8], "offset": 0.05, "limits": [-0.2, 0.3] },
            { "name": "c", "type": "continuous", "parent": "a", "origin": { "xyz": [0, 0, 0.5], "rpy_deg": [0, -90, 0] } },
            { "name": "d", "type": "revolute", "parent": "c", "origin": { "xyz": [0.2, 0, 0], "rpy_deg": [180, 0, 90] }, "limits_deg": [-10, 150] }
        ],
        "frames": [ { "name": "grip", "body": "d", "at": { "xyz": [0.1, 0, 0], "rpy_deg": [0, 90, 0] } } ]
    });
    let model = from_json(&file.to_string()).expect("the file reads");
    round_trip(&model);
    let written = urdf::write(&model);
    assert!(
        written
            .frame_links
            .contains(&("grip".to_owned(), "grip".to_owned())),
        "{:?}",
        written.frame_links
    );
}

/// Standard DH puts the link transform after the motion: each joint is
/// written with a `-moving` link and a fixed `-post` joint.
#[test]
fn dh_rows_are_written_with_a_moving_link_and_a_post_joint() {
    let model = mechanism("puma560").expect("catalogue model");
    let text = urdf::write(&model).text;
    assert!(text.contains("<link name=\"q2-moving\"/>"), "{text}");
    assert!(
        text.contains("<joint name=\"q2-post\" type=\"fixed\">"),
        "{text}"
    );
}

#[test]
fn a_product_of_exponentials_model_reads_back() {
    let axis = |name: &str, axis: [f64; 3], point: [f64; 3]| json!({ "name": name, "type": "revolute", "axis": axis, "point": point, "limits_deg": [-120, 120] });
    let file = json!({
        "name": "Screws",
        "convention": "zero_position",
        "joints": [
            axis("q1", [0.0, 0.0, 1.0], [0.0, 0.0, 0.0]),
            axis("q2", [0.0, -1.0, 0.0], [0.0, 0.0, 0.5]),
            axis("q3", [0.6, 0.0, 0.8], [0.4, 0.1, 0.5]),
        ],
        "tool": [[0, 0, 1, 0.7], [0, 1, 0, 0.1], [-1, 0, 0, 0.4], [0, 0, 0, 1]],
    });
    let model = from_json(&file.to_string()).expect("the file reads");
    assert!(round_trip(&model).is_empty());
}

#[test]
fn names_with_markup_characters_are_escaped() {
    let file = json!({
        "name": "A <\"tricky\"> & odd -- robot",
        "convention": "transforms",
        "joints": [ { "name": "j<1>&\"2\"", "type": "revolute", "limits_deg": [-60, 60] } ]
    });
    let model = from_json(&file.to_string()).expect("the file reads");
    round_trip(&model);
}
