//! URDF in: real robots' files against Pinocchio's forward kinematics
//! (`tests/urdf/goldens.py` made the goldens), the joints a user sets, and
//! hostile files that must fail fast with one line naming the element.
// The helpers below are test code too: a failed read is a failed test.
#![allow(clippy::expect_used)]

use std::time::Instant;

use kinolab_mechanism::urdf;
use serde_json::Value;

fn robot_file(name: &str) -> String {
    let path = format!("{}/robots/{name}.urdf", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn golden(name: &str) -> Value {
    let path = format!(
        "{}/tests/urdf/{name}.golden.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Every link's pose matches Pinocchio's to 1e-9 in every configuration.
fn matches_pinocchio(name: &str) {
    let robot = urdf::read(&robot_file(name)).expect("reads");
    let model = &robot.model;
    let mut compared = 0;
    for config in golden(name)["configs"].as_array().expect("configs") {
        let set: Vec<(String, f64)> = config["set"]
            .as_object()
            .expect("set")
            .iter()
            .map(|(k, v)| (k.clone(), v.as_f64().expect("number")))
            .collect();
        let q = robot.state_named(&set).expect("state");
        let placed = model.place(&q).expect("place");
        for (link, m) in config["frames"].as_object().expect("frames") {
            let f = model.frame(link).expect("link is a frame");
            let pose = placed.bodies[f.body] * f.offset;
            let h = pose.to_homogeneous();
            for r in 0..4 {
                for c in 0..4 {
                    let want = m[r][c].as_f64().expect("number");
                    assert!(
                        (h[(r, c)] - want).abs() < 1e-9,
                        "{name} {link} [{r}][{c}]: {} vs Pinocchio {want}",
                        h[(r, c)]
                    );
                }
            }
            compared += 1;
        }
    }
    assert!(
        compared >= 6 * model.bodies().len(),
        "{name}: compared {compared} frames"
    );
}

#[test]
fn the_panda_arm_matches_pinocchio() {
    matches_pinocchio("panda");
}

#[test]
fn the_ur5_arm_matches_pinocchio() {
    matches_pinocchio("ur5");
}

#[test]
fn the_solo12_quadruped_matches_pinocchio() {
    matches_pinocchio("solo12");
}

#[test]
fn the_driven_joints_are_the_moving_non_mimic_joints_in_file_order() {
    let panda = urdf::read(&robot_file("panda")).expect("reads");
    let names: Vec<&str> = panda.driven().collect();
    let mut want: Vec<String> = (1..=7).map(|i| format!("panda_joint{i}")).collect();
    want.push("panda_finger_joint1".into());
    assert_eq!(names, want);
    // The second finger mimics the first.
    let q = panda
        .state(&[0.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0, 0.03])
        .expect("state");
    let second = panda
        .model
        .variable("panda_finger_joint2")
        .expect("variable");
    assert_eq!(q[second], 0.03);
    assert!(
        panda.notices.iter().any(|n| n.contains("mesh")),
        "{:?}",
        panda.notices
    );
    // The quadruped's legs keep the file's order (leg by leg), not the
    // model's depth order.
    let solo = urdf::read(&robot_file("solo12")).expect("reads");
    let names: Vec<&str> = solo.driven().collect();
    assert_eq!(&names[..4], ["FL_HAA", "FL_HFE", "FL_KFE", "FR_HAA"]);
}

#[test]
fn values_outside_a_limit_are_computed_and_named_unknown_names_refused() {
    let panda = urdf::read(&robot_file("panda")).expect("reads");
    let far = panda
        .state(&[0.0, 3.0, 0.0, -1.0, 0.0, 1.0, 0.0, 0.0])
        .expect("FK is geometry: any finite value");
    let outside = panda.model.outside_limits(&far);
    assert_eq!(outside.len(), 1, "{outside:?}");
    assert_eq!(outside[0].joint, "panda_joint2");
    assert_eq!(
        (outside[0].value, outside[0].limits),
        (3.0, [-1.7628, 1.7628])
    );
    // The zero pose: only the elbow's range leaves 0 out.
    let zero = panda.state_named(&[]).expect("zeros");
    assert!(zero.iter().all(|&v| v == 0.0), "{zero:?}");
    let names: Vec<String> = panda
        .model
        .outside_limits(&zero)
        .into_iter()
        .map(|o| o.joint)
        .collect();
    assert_eq!(names, ["panda_joint4"]);
    // On a limit, or past it by rounding only, is inside.
    let on = panda
        .state(&[0.0, 1.7628 + 1e-12, 0.0, -1.0, 0.0, 1.0, 0.0, 0.0])
        .expect("on");
    assert!(panda.model.outside_limits(&on).is_empty());
    let e = panda
        .state_named(&[("panda_finger_joint2".into(), 0.01)])
        .expect_err("a mimic joint is not set directly");
    assert!(e.message.contains("not a movable joint"), "{e}");
    assert!(panda.state(&[0.0; 3]).is_err());
    let e = panda.state(&[f64::NAN; 8]).expect_err("not a number");
    assert_eq!(e.field, "panda_joint1", "{e}");
}

/// A chain of `n` revolute links in URDF.
fn chain(n: usize) -> String {
    let mut s = String::from("<robot name=\"chain\">\n<link name=\"l0\"/>\n");
    for i in 1..=n {
        s += &format!(
            "<link name=\"l{i}\"/><joint name=\"j{i}\" type=\"revolute\"><parent link=\"l{}\"/><child link=\"l{i}\"/><origin xyz=\"0 0 0.1\" rpy=\"0 0.1 0\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n",
            i - 1
        );
    }
    s + "</robot>"
}

/// `text` fails in well under a second with one line mentioning `needle`.
fn refused(text: &str, needle: &str) {
    let start = Instant::now();
    let e = urdf::read(text).expect_err("a hostile file is refused");
    let line = e.to_string();
    assert!(
        start.elapsed().as_secs_f64() < 2.0,
        "took {:?}",
        start.elapsed()
    );
    assert!(!line.contains('\n'), "one line: {line}");
    assert!(line.contains(needle), "`{line}` should mention `{needle}`");
}

#[test]
fn hostile_files_give_one_line_naming_the_element() {
    let laughs = r#"<?xml version="1.0"?>
<!DOCTYPE lolz [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
<!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">]>
<robot name="&lol3;"><link name="a"/></robot>"#;
    refused(laughs, "line");
    refused(&chain(100_000), "at most 4194304 are read");
    let links: String = (0..100_000)
        .map(|i| format!("<link name=\"l{i}\"/>"))
        .collect();
    refused(
        &format!("<robot name=\"r\">{links}</robot>"),
        "at most 512 joints",
    );
    let deep = format!(
        "<robot name=\"r\">{}{}</robot>",
        "<a>".repeat(5000),
        "</a>".repeat(5000)
    );
    assert!(urdf::read(&deep).is_err());
    let own_parent = chain(2).replace(
        "<parent link=\"l1\"/><child link=\"l2\"/>",
        "<parent link=\"l2\"/><child link=\"l2\"/>",
    );
    refused(
        &own_parent,
        "<joint name=\"j2\"> (line 4): joins link `l2` to itself",
    );
    // One change to a good chain each, and what the message must say.
    let edits = [
        ("xyz=\"0 0 0.1\"", "xyz=\"0 NaN 0.1\"", "(line 3)"),
        (
            "<axis xyz=\"0 0 1\"/>",
            "<axis xyz=\"0 0 0\"/>",
            "zero length",
        ),
        (
            "<parent link=\"l1\"/>",
            "<parent link=\"ghost\"/>",
            "`ghost` is not in the file",
        ),
        (
            "<link name=\"l1\"/>",
            "<link name=\"l0\"/>",
            "used twice (first on line 2)",
        ),
        ("<parent link=\"l0\"/>", "<parent link=\"l2\"/>", "loop"),
    ];
    for (from, to, needle) in edits {
        refused(&chain(2).replace(from, to), needle);
    }
    refused(
        &format!(
            "{}<link name=\"extra\"/></robot>",
            chain(2).trim_end_matches("</robot>")
        ),
        "no one root",
    );
    refused("<robot name=\"r\"><link name=\"a\">", "not valid XML");
    refused("{\"name\": 1}", "not valid XML");
}

#[test]
fn a_long_chain_reads_and_places_like_its_product_of_transforms() {
    let robot = urdf::read(&chain(50)).expect("reads");
    assert_eq!(robot.model.dof(), 50);
    assert_eq!(robot.tip(), "l50");
    let q: Vec<f64> = (0..50).map(|i| 0.02 * i as f64 - 0.5).collect();
    let state = robot.state(&q).expect("state");
    let placed = robot.model.place(&state).expect("place");
    let mut want = nalgebra::Isometry3::identity();
    for qi in &q {
        let origin = nalgebra::Isometry3::new(
            nalgebra::Vector3::new(0.0, 0.0, 0.1),
            nalgebra::Vector3::new(0.0, 0.1, 0.0),
        );
        want = want * origin * nalgebra::Isometry3::rotation(nalgebra::Vector3::z() * *qi);
    }
    let tip = robot.model.frame("l50").expect("tip");
    let got = placed.bodies[tip.body];
    assert!((got.to_homogeneous() - want.to_homogeneous()).abs().max() < 1e-12);
}

#[test]
fn collision_solids_become_bounding_capsules_and_free_joints_stay_put() {
    let text = r#"<robot name="r">
  <link name="base"><collision><origin xyz="0 0 0.5"/><geometry><box size="0.2 0.4 1.0"/></geometry></collision></link>
  <link name="ball"><collision><geometry><sphere radius="0.1"/></geometry></collision>
    <collision><geometry><mesh filename="x.stl"/></geometry></collision></link>
  <joint name="float" type="floating"><parent link="base"/><child link="ball"/><origin xyz="1 0 0"/></joint>
</robot>"#;
    let robot = urdf::read(text).expect("reads");
    assert_eq!(robot.model.dof(), 0);
    let shapes = robot.model.shapes();
    assert_eq!(shapes.len(), 2);
    let bar = &shapes[0];
    assert_eq!((bar.a.z, bar.b.z), (0.0, 1.0));
    assert!((bar.radius - (0.1f64.powi(2) + 0.2f64.powi(2)).sqrt()).abs() < 1e-15);
    assert_eq!(shapes[1].radius, 0.1);
    assert_eq!(robot.notices.len(), 2, "{:?}", robot.notices);
    let placed = robot.model.place(&[]).expect("place");
    let ball = robot.model.frame("ball").expect("ball");
    assert_eq!(placed.bodies[ball.body].translation.vector.x, 1.0);
}

#[test]
fn the_panda_from_urdf_agrees_with_the_catalogue_panda_in_modified_dh() {
    let urdf = urdf::read(&robot_file("panda")).expect("reads");
    let flange = urdf.model.frame("panda_link8").expect("flange");
    let dh = kinolab_mechanism::catalogue::mechanism("panda").expect("catalogue");
    let tool = dh.frame("tool").expect("tool");
    let mut s = 11u64;
    for _ in 0..200 {
        let q: Vec<f64> = (0..7)
            .map(|i| {
                s = s.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
                let [lo, hi] = dh.variable_joint(i).and_then(|j| j.limits).expect("limits");
                lo + (s >> 11) as f64 / (1u64 << 53) as f64 * (hi - lo)
            })
            .collect();
        let mut all = q.clone();
        all.push(0.0);
        let a = dh.pose(&q, &tool).expect("dh");
        let b = urdf
            .model
            .pose(&urdf.state(&all).expect("state"), &flange)
            .expect("urdf");
        let gap = (a.to_homogeneous() - b.to_homogeneous()).abs().max();
        assert!(gap < 1e-12, "q = {q:?}: the two models differ by {gap}");
    }
}

#[test]
fn a_cut_or_garbled_real_file_is_an_error_never_a_panic() {
    let text = robot_file("solo12");
    let mut refused = 0;
    for cut in (0..text.len()).step_by(211) {
        let head = &text[..text.floor_char_boundary(cut)];
        refused += usize::from(urdf::read(head).is_err());
    }
    // Swap one character for a troublesome one at many places.
    for (i, at) in (0..text.len()).step_by(389).enumerate() {
        let at = text.floor_char_boundary(at);
        let bad = ["\"", "<", "-", "e9", "nan", " 0", "&"][i % 7];
        let garbled = format!(
            "{}{bad}{}",
            &text[..at],
            &text[text.ceil_char_boundary(at + 1)..]
        );
        let _ = urdf::read(&garbled);
    }
    assert!(refused > 100, "only {refused} cut files refused");
}

/// The model's own joint order is the file's (parents still first), so a
/// viewer's sliders and a saved model file list Solo's joints leg by leg,
/// as the file does, not hip joints first.
#[test]
fn the_models_variables_follow_the_file_order() {
    let robot = urdf::read(&robot_file("solo12")).expect("reads");
    let model = &robot.model;
    let variables: Vec<&str> = (0..model.dof())
        .filter_map(|v| model.variable_joint(v).map(|j| j.name.as_str()))
        .collect();
    let driven: Vec<&str> = robot.driven().collect();
    assert_eq!(variables, driven);
    assert_eq!(&variables[..4], ["FL_HAA", "FL_HFE", "FL_KFE", "FR_HAA"]);
    // A child listed before its parent still comes after it.
    let text = "<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>\
        <joint name=\"late\" type=\"continuous\"><parent link=\"b\"/><child link=\"c\"/></joint>\
        <joint name=\"early\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/></joint></robot>";
    let r = urdf::read(text).expect("reads");
    let names: Vec<&str> = r.model.joints().iter().map(|j| j.name.as_str()).collect();
    assert_eq!(names, ["early", "late"]);
    assert_eq!(r.driven().collect::<Vec<_>>(), ["late", "early"]);
}

#[test]
fn the_catalogue_unpacks_the_very_files_shipped() {
    for (id, file) in [
        ("ur5", "ur5"),
        ("panda-urdf", "panda"),
        ("solo12", "solo12"),
    ] {
        let on_disk = urdf::read(&robot_file(file)).expect("a shipped file reads");
        let built_in = kinolab_mechanism::catalogue::mechanism(id).expect("the catalogue reads");
        assert_eq!(built_in, on_disk.model, "{id}");
    }
}

#[test]
fn the_hand_is_where_the_most_independent_turns_end() {
    let hand = |name: &str| {
        let robot = urdf::read(&robot_file(name)).expect("reads");
        robot.model.hand().to_owned()
    };
    // Not the fingers, which slide (and one of which mimics the other).
    assert_eq!(hand("panda"), "panda_link7");
    // Not ee_link or tool0, bolted on beyond the last wrist joint.
    assert_eq!(hand("ur5"), "wrist_3_link");
    // A quadruped's first leg, at the knee's link (the foot is bolted on).
    assert_eq!(hand("solo12"), "FL_LOWER_LEG");
}
