#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! The command line, tested through its JSON and its error lines.

use std::process::Command;

use serde_json::Value;

fn kinolab(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_kinolab"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn json(args: &[&str]) -> Value {
    let (code, stdout, stderr) = kinolab(args);
    assert_eq!(code, 0, "stderr: {stderr}");
    serde_json::from_str(&stdout)
        .unwrap_or_else(|e| panic!("not one JSON document ({e}): {stdout}"))
}

#[test]
fn version_and_help() {
    let (code, stdout, _) = kinolab(&["--version"]);
    assert_eq!(code, 0);
    assert_eq!(
        stdout.trim(),
        format!("kinolab {}", env!("CARGO_PKG_VERSION"))
    );
    let (code, stdout, _) = kinolab(&["--help"]);
    assert_eq!(code, 0);
    assert!(
        stdout.contains("leg-events") && stdout.contains("stability") && stdout.contains("lessons")
    );
}

#[test]
fn leg_events_golden_values() {
    assert_eq!(json(&["leg-events", "2"])["events"], "6");
    assert_eq!(json(&["leg-events", "6"])["events"], "39916800");
}

#[test]
fn stability_of_a_square_stance() {
    let v = json(&[
        "stability",
        "--com",
        "0.5,0.2",
        "--feet",
        "1,1;-1,1;-1,-1;1,-1",
    ]);
    assert_eq!(v["stable"], true);
    assert!((v["margin"].as_f64().unwrap() - 0.5).abs() < 1e-12);
    let v = json(&[
        "stability",
        "--com",
        "-3,0",
        "--feet",
        "1,1;-1,1;-1,-1;1,-1",
    ]);
    assert_eq!(v["stable"], false);
    assert!((v["margin"].as_f64().unwrap() + 2.0).abs() < 1e-12);
}

#[test]
fn embedded_lessons_check_out() {
    let v = json(&["lessons"]);
    assert_eq!(v["ok"], true);
    assert_eq!(v["units"][0]["unit"], "automation");
    assert!(v["units"][0]["lessons"][0]["quizzes"].as_u64().unwrap() >= 3);
}

#[test]
fn a_broken_lesson_folder_names_file_and_line() {
    let dir = std::env::temp_dir().join(format!("kinolab-cli-test-{}", std::process::id()));
    let unit = dir.join("01-demo");
    std::fs::create_dir_all(&unit).unwrap();
    std::fs::write(unit.join("unit.md"), "---\ntitle: Demo\n---\n").unwrap();
    std::fs::write(unit.join("01-a.md"), "---\ntitle: A\nminutes: x\n---\n").unwrap();
    let (code, stdout, stderr) = kinolab(&["lessons", dir.to_str().unwrap()]);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(code, 2);
    assert!(stdout.is_empty());
    assert_eq!(
        stderr.trim(),
        "kinolab: 01-demo/01-a.md:3: `minutes` must be a whole number, found `x`"
    );
}

/// `kinolab lessons` on a one-lesson folder whose body is `body`: the exit
/// code and the error line.
fn check_lesson_body(tag: &str, body: &str, image: bool) -> (i32, String) {
    let dir = std::env::temp_dir().join(format!("kinolab-cli-{tag}-{}", std::process::id()));
    let unit = dir.join("01-demo");
    std::fs::create_dir_all(&unit).unwrap();
    std::fs::write(unit.join("unit.md"), "---\ntitle: Demo\n---\n").unwrap();
    let head = "---\ntitle: A\nminutes: 5\nobjectives:\n  - see\n---\n";
    std::fs::write(unit.join("01-a.md"), format!("{head}{body}")).unwrap();
    if image {
        std::fs::write(unit.join("wheel.png"), b"png").unwrap();
    }
    let (code, _, stderr) = kinolab(&["lessons", dir.to_str().unwrap()]);
    std::fs::remove_dir_all(&dir).ok();
    (code, stderr.trim().to_owned())
}

#[test]
fn the_checker_rejects_unknown_widgets_bad_parameters_and_missing_images() {
    let widget = |body: &str| format!("Text.\n\n```widget\n{body}\n```\n");
    let (code, err) = check_lesson_body("widget", &widget("flux-capacitor"), false);
    assert_eq!(code, 2);
    assert!(
        err.starts_with("kinolab: 01-demo/01-a.md:9: there is no widget named `flux-capacitor`"),
        "{err}"
    );
    let (_, err) = check_lesson_body("param", &widget("leg-events\nlegs: 40"), false);
    assert_eq!(
        err,
        "kinolab: 01-demo/01-a.md:9: parameter `legs` must be a whole number from 1 to 12, found `40`"
    );
    let (_, err) = check_lesson_body("key", &widget("support-polygon\ncolour: red"), false);
    assert!(
        err.contains("widget `support-polygon` has no parameter `colour`"),
        "{err}"
    );
    let (code, err) = check_lesson_body("image", "Text.\n\n![a wheel](tyre.png)\n", true);
    assert_eq!(code, 2);
    assert_eq!(
        err,
        "kinolab: 01-demo/01-a.md:9: there is no image `tyre.png` beside this lesson"
    );
    let (code, err) = check_lesson_body("ok", "Text.\n\n![a wheel](wheel.png)\n", true);
    assert_eq!((code, err.as_str()), (0, ""));
    // An exercise block names a graded exercise that exists.
    let exercise = |id: &str| format!("Text.\n\n```exercise\n{id}\n```\n");
    let (code, err) = check_lesson_body("exercise", &exercise("control-park"), false);
    assert_eq!((code, err.as_str()), (0, ""));
    let (code, err) = check_lesson_body("no-exercise", &exercise("control-parking"), false);
    assert_eq!(code, 2);
    assert!(
        err.starts_with("kinolab: 01-demo/01-a.md:9: parameter `exercise`")
            && err.contains("control-parking"),
        "{err}"
    );
    let (code, err) = check_lesson_body("two-words", &exercise("park the robot"), false);
    assert_eq!(code, 2);
    assert!(err.contains("the exercise's id alone"), "{err}");
}

#[test]
fn bad_input_is_one_line_naming_the_field() {
    for (args, expected) in [
        (
            vec!["leg-events", "0"],
            "kinolab: legs: a walker needs at least one leg",
        ),
        (
            vec!["stability", "--com", "0,nan", "--feet", "1,1"],
            "kinolab: --com: `nan` is not a finite number",
        ),
        (
            vec!["stability", "--com", "0", "--feet", "1,1"],
            "kinolab: --com: expected two numbers X,Y, got 1",
        ),
        (
            vec!["stability", "--com", "0,0", "--feet", ""],
            "kinolab: --feet: no foot is on the ground",
        ),
    ] {
        let (code, stdout, stderr) = kinolab(&args);
        assert_eq!(code, 2, "{args:?}");
        assert!(stdout.is_empty());
        assert_eq!(stderr.trim(), expected);
        assert_eq!(stderr.lines().count(), 1);
    }
    let (code, _, stderr) = kinolab(&["no-such-command"]);
    assert_eq!(code, 2);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(!stderr.contains("panicked"));
}

/// The call exits 0 with one JSON document and nothing on stderr.
fn ok(args: &[&str]) -> serde_json::Value {
    let (code, stdout, stderr) = kinolab(args);
    assert_eq!(code, 0, "{args:?}: {stderr}");
    assert!(stderr.is_empty(), "{stderr}");
    serde_json::from_str(&stdout).unwrap()
}

/// The call exits 2 with one stderr line containing `want`, and no stdout.
fn fails_with(args: &[&str], want: &str) {
    let (code, stdout, stderr) = kinolab(args);
    assert_eq!(code, 2, "{args:?}");
    assert!(stdout.is_empty());
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.contains(want), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"));
}

/// Write `text` to a fresh file under the system temp folder.
fn robot_file(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("kinolab-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// The robot-file example of the command-line contract, verbatim.
const EVERY_WHEEL_KIND: &str = kinolab_wheels::catalogue::EVERY_WHEEL_KIND;

#[test]
fn analyze_the_contract_example() {
    let path = robot_file("every.robot.json", EVERY_WHEEL_KIND);
    let out = json(&["analyze", &path]);
    // Rear axle plus a straight steered front wheel: translation only now,
    // one steering input to turn with.
    assert_eq!(out["rank_c1"], 2);
    assert_eq!(out["degree_of_mobility"], 1);
    assert_eq!(out["degree_of_steerability"], 1);
    assert_eq!(out["degree_of_maneuverability"], 2);
    assert_eq!(out["dof"], 3);
    assert_eq!(out["holonomic"], false);
    assert_eq!(out["icr"]["kind"], "infinity");
    assert_eq!(out["icr"]["direction"], serde_json::json!([1.0, 0.0]));
}

#[test]
fn analyze_reports_each_icr_kind() {
    let kind = |id: &str| json(&["analyze", &format!("catalogue:{id}")])["icr"].clone();
    assert_eq!(kind("three-swedish")["kind"], "anywhere");
    let line = kind("differential-drive");
    assert_eq!(line["kind"], "line");
    assert_eq!(line["point"], serde_json::json!([0.0, 0.0]));
    assert_eq!(line["direction"], serde_json::json!([0.0, 1.0]));
    let point = kind("ackermann-car");
    assert_eq!(point["kind"], "point");
    assert!((point["x"].as_f64().unwrap()).abs() < 1e-9);
    assert!((point["y"].as_f64().unwrap() - 2.5).abs() < 1e-9);
    let stuck = robot_file(
        "stuck.robot.json",
        r#"{"wheels":[
            {"kind":"fixed","alpha_deg":90,"beta_deg":0,"l":0.3,"radius":0.1},
            {"kind":"fixed","alpha_deg":210,"beta_deg":0,"l":0.3,"radius":0.1},
            {"kind":"fixed","alpha_deg":330,"beta_deg":0,"l":0.3,"radius":0.1},
            {"kind":"fixed","alpha_deg":0,"beta_deg":60,"l":0.5,"radius":0.1}]}"#,
    );
    let out = json(&["analyze", &stuck]);
    assert_eq!(out["icr"]["kind"], "none");
    assert_eq!(out["degree_of_mobility"], 0);
    assert_eq!(out["disagreement"]["disagree"][0]["wheel"], 3);
}

#[test]
fn drive_inverse_and_forward() {
    // Siegwart: r = l = 1, right wheel first.
    let path = robot_file(
        "siegwart.robot.json",
        r#"{"name":"siegwart","wheels":[
            {"kind":"fixed","alpha_deg":-90,"beta_deg":180,"l":1,"radius":1},
            {"kind":"fixed","alpha_deg":90,"beta_deg":0,"l":1,"radius":1}]}"#,
    );
    let out = json(&[
        "drive",
        &path,
        "--wheels",
        "4,2",
        "--theta",
        "1.5707963267948966",
    ]);
    let close = |v: &Value, want: [f64; 3]| {
        (0..3).all(|i| (v[i].as_f64().unwrap() - want[i]).abs() < 1e-12)
    };
    assert!(close(&out["twist"], [3.0, 0.0, 1.0]), "{out}");
    assert!(close(&out["twist_inertial"], [0.0, 3.0, 1.0]), "{out}");
    assert_eq!(out["residual"], 0.0);
    assert_eq!(out["consistent"], true);
    let out = json(&["drive", &path, "--twist", "3,0,1"]);
    assert_eq!(out["feasible"], true);
    assert_eq!(out["wheels"][0]["spin"], 4.0);
    assert_eq!(out["wheels"][1]["spin"], 2.0);
    // Sideways is what a differential drive cannot do.
    let out = json(&["drive", &path, "--twist", "0,1,0"]);
    assert_eq!(out["feasible"], false);
    assert_eq!(out["violations"].as_array().unwrap().len(), 2);
    assert_eq!(out["violations"][0]["wheel"], 0);
    assert_eq!(out["violations"][0]["residual"], 1.0);
    // One known spin cannot pin down the turn rate.
    let out = json(&["drive", &path, "--wheels", "4,-"]);
    assert_eq!(out["consistent"], true);
    assert_eq!(out["determined"], false);
}

#[test]
fn drive_steers_to_the_nearest_angle() {
    let path = robot_file("every2.robot.json", EVERY_WHEEL_KIND);
    // Turning left about (0, 2.5): the front wheel steers by atan(0.6/2.5).
    let out = json(&["drive", &path, "--twist", "0.5,0,0.2"]);
    assert_eq!(out["feasible"], true);
    let steer = out["wheels"][2]["steer_deg"].as_f64().unwrap();
    assert!((steer - (90.0 + (0.6f64 / 2.5).atan().to_degrees())).abs() < 1e-6);
    let spin = out["wheels"][2]["spin"].as_f64().unwrap();
    assert!((spin * 0.1 - 0.2 * 0.6f64.hypot(2.5)).abs() < 1e-9);
    let castor_rate = out["wheels"][3]["steer_rate_deg"].as_f64().unwrap();
    assert!(castor_rate.abs() > 1.0, "a sideways castor swings round");
    assert_eq!(out["wheels"].as_array().unwrap().len(), 6);
}

#[test]
fn bad_robot_input_is_one_line_naming_file_and_field() {
    let check = fails_with;
    let negative = robot_file(
        "negative.robot.json",
        r#"{"wheels":[{"kind":"fixed","alpha_deg":0,"beta_deg":0,"l":0.2,"radius":-0.1}]}"#,
    );
    check(
        &["analyze", &negative],
        "negative.robot.json: wheels[0].radius: must be greater than 0, got -0.1",
    );
    let unknown = robot_file(
        "unknown.robot.json",
        r#"{"wheels":[{"kind":"fixed","alpha_deg":0,"beta_deg":0,"l":0.2,"radius":0.1,"color":"red"}]}"#,
    );
    check(
        &["analyze", &unknown],
        "unknown.robot.json: wheels[0].color: unknown field `color`",
    );
    let malformed = robot_file("malformed.robot.json", "{\"wheels\": [");
    check(&["analyze", &malformed], "malformed.robot.json:");
    check(
        &["analyze", "/no/such/robot.json"],
        "/no/such/robot.json: cannot read",
    );
    let good = robot_file("good.robot.json", EVERY_WHEEL_KIND);
    check(
        &["drive", &good, "--twist", "1,NaN,0"],
        "--twist: `NaN` is not a finite number",
    );
    check(
        &["drive", &good, "--twist", "1,0"],
        "--twist: expected three numbers",
    );
    check(
        &["drive", &good, "--wheels", "1,2"],
        "--wheels: expected 6 spins",
    );
    check(&["drive", &good], "give --twist");
    check(
        &[
            "drive",
            &good,
            "--twist",
            "1,0,0",
            "--wheels",
            "1,2,3,4,5,6",
        ],
        "not both",
    );
    check(
        &["analyze", "catalogue:hovercraft"],
        "no catalogue robot \"hovercraft\"",
    );
}

#[test]
fn robots_lists_the_catalogue_and_prints_files() {
    let out = json(&["robots"]);
    let ids: Vec<&str> = out
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["id"].as_str().unwrap())
        .collect();
    assert!(ids.contains(&"synchro-drive") && ids.contains(&"rocker-bogie"));
    let file = json(&["robots", "ackermann-car"]);
    assert_eq!(file["wheels"][2]["steer_group"], "linkage");
    let path = robot_file("car.robot.json", &file.to_string());
    assert_eq!(json(&["analyze", &path])["degree_of_maneuverability"], 2);
}

/// The run-file example of the command-line contract, verbatim.
const CONTRACT_RUN: &str = kinolab_control::file::CONTRACT_EXAMPLE;

#[test]
fn simulate_the_contract_example() {
    let path = robot_file("contract.run.json", CONTRACT_RUN);
    let out = json(&["simulate", &path]);
    let samples = out["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 101);
    let first = &samples[0];
    assert_eq!(first["t"], 0.0);
    assert_eq!(
        (first["x"].as_f64(), first["y"].as_f64()),
        (Some(-1.0), Some(0.5))
    );
    assert_eq!(first["theta_deg"], 0.0);
    // v = k_ρ ρ = 3 √1.25 ≈ 3.354; ω = (k_α − k_β) α with α = atan2(−0.5, 1).
    let v = first["v"].as_f64().unwrap();
    assert!((v - 3.0 * 1.25f64.sqrt()).abs() < 1e-12, "{v}");
    let omega = first["omega"].as_f64().unwrap();
    assert!(
        (omega - 9.5 * (-0.5f64).atan2(1.0)).abs() < 1e-12,
        "{omega}"
    );
    for key in ["t", "x", "y", "theta_deg", "v", "omega"] {
        assert!(samples.iter().all(|s| s[key].is_number()), "{key}");
    }
    assert_eq!(out["reached"], true);
    let t = out["time_to_goal"].as_f64().unwrap();
    assert!((5.0..7.0).contains(&t), "{t}");
    let last = &samples[100];
    assert_eq!(last["t"], 10.0);
    for key in ["x", "y", "theta_deg"] {
        let f = out["final"][key].as_f64().unwrap();
        assert!(f.abs() < 1e-3, "{key} = {f}");
        assert_eq!(out["final"][key], last[key]);
    }
    assert_eq!(out["stability"]["strongly_stable"], true);
}

#[test]
fn simulate_batch_and_gains() {
    let path = robot_file("circle.run.json", CONTRACT_RUN);
    let out = json(&["batch", &path, "--radius", "1", "--count", "24"]);
    assert_eq!(out["runs"].as_array().unwrap().len(), 24);
    assert_eq!(out["all_reached"], true);
    assert_eq!(out["reached"], 24);
    // Starts in front of the goal drive rear first.
    assert_eq!(out["runs"][0]["direction"], "backward");
    assert_eq!(out["runs"][12]["direction"], "forward");

    let g = json(&["gains", "3,8,-1.5"]);
    assert_eq!(g["strongly_stable"], true);
    let eig: Vec<f64> = g["eigenvalues"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| e[0].as_f64().unwrap())
        .collect();
    assert!((eig[0] + 3.0).abs() < 1e-12);
    // λ² + 5λ + 4.5 = 0 → λ = (−5 ± √7)/2
    let mut rest = [eig[1], eig[2]];
    rest.sort_by(f64::total_cmp);
    assert!((rest[0] - (-5.0 - 7f64.sqrt()) / 2.0).abs() < 1e-12);
    assert!((rest[1] - (-5.0 + 7f64.sqrt()) / 2.0).abs() < 1e-12);
    let g = json(&["gains", "3,2,-1.5"]);
    assert_eq!(g["locally_stable"], false);
    assert_eq!(g["conditions"][2]["holds"], false);

    // An open-loop plan reaches its own end when nothing slips.
    let plan = robot_file(
        "plan.run.json",
        r#"{"controller":{"kind":"open_loop","segments":[{"kind":"line","length":1},{"kind":"turn","angle_deg":90}]},
            "start":{"x":0,"y":0,"theta_deg":0},"duration":5}"#,
    );
    let out = json(&["simulate", &plan]);
    assert_eq!(out["reached"], true);
    assert!((out["final"]["x"].as_f64().unwrap() - 1.0).abs() < 1e-6);
    assert!((out["final"]["theta_deg"].as_f64().unwrap() - 90.0).abs() < 1e-6);
    assert!((out["plan"]["duration"].as_f64().unwrap() - 4.0).abs() < 1e-9);
    assert_eq!(out["samples"][10]["wheels"].as_array().unwrap().len(), 3);
}

#[test]
fn bad_run_input_is_one_line_naming_file_and_field() {
    let check = fails_with;
    let bad = |name: &str, from: &str, to: &str| robot_file(name, &CONTRACT_RUN.replace(from, to));
    check(
        &["simulate", &bad("a.run.json", "\"k_beta\"", "\"k_b\"")],
        "a.run.json: controller: unknown field `k_b`",
    );
    check(
        &[
            "simulate",
            &bad("b.run.json", "\"dt\": 0.001", "\"dt\": -1"),
        ],
        "b.run.json: dt: must be greater than 0, got -1",
    );
    check(
        &[
            "simulate",
            &bad("c.run.json", "\"x\": -1.0", "\"x\": \"far\""),
        ],
        "c.run.json: start.x: invalid type",
    );
    check(
        &[
            "simulate",
            &bad("d.run.json", "\"dt\": 0.001", "\"dt\": 1e-9"),
        ],
        "d.run.json: dt: duration / dt",
    );
    check(
        &["simulate", "/no/such.run.json"],
        "/no/such.run.json: cannot read",
    );
    check(
        &["batch", &bad("e.run.json", "", ""), "--count", "0"],
        "--count: must be from 1",
    );
    check(&["gains", "3,8"], "gains: expected three numbers");
}

#[test]
fn fk_and_ik_on_the_puma() {
    // The issue's golden pose: q = (0, π/2, −π/2, 0, 0, 0).
    let q = format!(
        "0,{},{},0,0,0",
        std::f64::consts::FRAC_PI_2,
        -std::f64::consts::FRAC_PI_2
    );
    let out = json(&["fk", "catalogue:puma560", "--q", &q]);
    assert_eq!(out["frame"], "tool");
    let m = &out["matrix"];
    let at = |i: usize, j: usize| m[i][j].as_f64().unwrap();
    assert!((at(0, 3) - 0.0203).abs() < 1e-12);
    assert!((at(1, 3) + 0.15005).abs() < 1e-12);
    assert!((at(2, 3) - (0.8636 + 0.6718)).abs() < 1e-12);
    assert_eq!(m[3], serde_json::json!([0.0, 0.0, 0.0, 1.0]));
    let elbow = json(&["fk", "catalogue:puma560", "--q", &q, "--frame", "q2"]);
    assert!((elbow["matrix"][0][3].as_f64().unwrap()).abs() < 1e-12);

    // IK back to a full pose from a nearby seed.
    let target = json(&[
        "fk",
        "catalogue:puma560",
        "--q",
        "0.3,-0.6,0.9,0.2,0.7,-0.4",
    ]);
    let t = &target["matrix"];
    let position = format!("{},{},{}", t[0][3], t[1][3], t[2][3]);
    let rotation: Vec<String> = (0..3)
        .flat_map(|i| (0..3).map(move |j| (i, j)))
        .map(|(i, j)| t[i][j].to_string())
        .collect();
    let out = json(&[
        "ik",
        "catalogue:puma560",
        "--position",
        &position,
        "--rotation",
        &rotation.join(","),
        "--seed",
        "0.2,-0.5,0.8,0,0.5,0",
    ]);
    assert_eq!(out["converged"], true, "{out}");
    assert!(out["position_error"].as_f64().unwrap() < 1e-6);
    assert!(out["rotation_error"].as_f64().unwrap() < 1e-6);
    assert_eq!(out["q"].as_array().unwrap().len(), 6);

    // Out of reach: not converged, the closest pose, exit 0.
    let out = json(&["ik", "catalogue:planar-2r", "--position", "3,0,0"]);
    assert_eq!(out["converged"], false);
    assert!((out["position_error"].as_f64().unwrap() - 1.2).abs() < 1e-4);
}

#[test]
fn fk_reads_the_contract_model_file() {
    let path = robot_file(
        "contract.model.json",
        kinolab_mechanism::file::CONTRACT_EXAMPLE,
    );
    let out = json(&["fk", &path, "--q", "0,0.2"]);
    assert_eq!(out["matrix"][1][3], -0.2);
    assert_eq!(out["matrix"][2][3], 0.6718);
    fails_with(
        &["fk", &path, "--q", "0,0.2,1"],
        "--q: `puma560` has 2 joints, got 3 values",
    );
    fails_with(
        &["fk", &path, "--q", "0,0.2", "--frame", "hand"],
        "--frame: no frame named `hand`",
    );
    fails_with(
        &["ik", &path, "--position", "1,2"],
        "--position: expected three numbers X,Y,Z",
    );
    fails_with(
        &[
            "ik",
            &path,
            "--position",
            "0,0,1",
            "--rotation",
            "2,0,0,0,1,0,0,0,1",
        ],
        "rotation: must be a rigid transform",
    );
    let broken = robot_file(
        "broken.model.json",
        r#"{"name":"x","convention":"standard_dh","joints":[{"name":"q1","type":"hinge"}]}"#,
    );
    fails_with(
        &["fk", &broken, "--q", "0"],
        "broken.model.json: joints[0].type: unknown variant `hinge`",
    );
}

#[test]
fn a_model_file_mounts_another_file_next_to_it() {
    robot_file(
        "finger.model.json",
        r#"{"name":"finger","convention":"transforms","joints":[
            {"name":"knuckle","type":"revolute","parent":"world"},
            {"name":"tip","type":"fixed","origin":{"xyz":[0.1,0,0]}}]}"#,
    );
    let hand = robot_file(
        "hand.model.json",
        r#"{"name":"hand","convention":"transforms",
            "joints":[{"name":"palm","type":"fixed","origin":{"xyz":[0,0,1]}}],
            "frames":[{"name":"left","body":"palm","at":{"xyz":[0,0.05,0]}},
                      {"name":"right","body":"palm","at":{"xyz":[0,-0.05,0],"rpy_deg":[0,0,180]}}],
            "mounts":[{"name":"l","model":"finger.model.json","at":"left"},
                      {"name":"r","model":"finger.model.json","at":"right"}],
            "couplings":[{"follower":"r/knuckle","leader":"l/knuckle"}]}"#,
    );
    // Both fingers turn together; the right one is mounted facing back, so
    // the same turn mirrors the left finger.
    let left = json(&[
        "fk",
        &hand,
        "--q",
        "1.5707963267948966,0",
        "--frame",
        "l/tip",
    ]);
    let right = json(&[
        "fk",
        &hand,
        "--q",
        "1.5707963267948966,0",
        "--frame",
        "r/tip",
    ]);
    let at = |v: &Value, i: usize| v["matrix"][i][3].as_f64().unwrap();
    assert!(at(&left, 0).abs() < 1e-12 && (at(&left, 1) - 0.15).abs() < 1e-12);
    assert!(at(&right, 0).abs() < 1e-12 && (at(&right, 1) + 0.15).abs() < 1e-12);
    assert!((at(&right, 2) - 1.0).abs() < 1e-12);
    let missing = robot_file(
        "lonely.model.json",
        r#"{"name":"x","convention":"transforms","joints":[{"name":"a","type":"fixed"}],
            "mounts":[{"name":"m","model":"nowhere.model.json","at":"tool"}]}"#,
    );
    fails_with(&["fk", &missing], "mounts[0].model: ");
    fails_with(&["fk", &missing], "nowhere.model.json: cannot read");
}

#[test]
fn field_follows_the_contract() {
    let dir = std::env::temp_dir().join(format!("kinolab-cli-field-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // One attractive pull of gain 2 towards (4, 0), constant profile, and
    // a wall at x = 2 pushing back 3 (1 − d/1): they balance at d = 1/3.
    let field = dir.join("wall.field.json");
    std::fs::write(
        &field,
        r#"{ "name": "wall", "goal": { "x": 4, "y": 0 }, "fields": [
            { "kind": "attractive", "x": 4, "y": 0, "gain": 2, "profile": "constant" },
            { "kind": "perpendicular", "from": [2, -5], "to": [2, 5], "gain": 3, "profile": "linear", "range": 1, "sense": "away" } ] }"#,
    )
    .unwrap();
    let f = field.to_str().unwrap();
    let v = json(&["field", f, "--at", "0,0;-1,0"]);
    let got: Vec<Vec<f64>> = serde_json::from_value(v["vectors"].clone()).unwrap();
    assert_eq!(got, vec![vec![2.0, 0.0], vec![2.0, 0.0]]);
    let v = json(&["field", f, "--minima", "--box", "-1,-2,5,2"]);
    let m = &v["minima"][0];
    assert!(
        (m["x"].as_f64().unwrap() - (2.0 - 1.0 / 3.0)).abs() < 1e-6,
        "{v}"
    );
    assert_eq!(m["goal"], false);
    let v = json(&["field", f, "--descend", "0,0"]);
    assert_eq!(v["outcome"], "trapped");
    let first: Vec<f64> = serde_json::from_value(v["path"][0].clone()).unwrap();
    assert_eq!(first, vec![0.0, 0.0]);
    let (code, _, stderr) = kinolab(&["field", f, "--minima"]);
    assert_eq!(code, 2);
    assert!(stderr.contains("--box"), "{stderr}");
    let (code, _, stderr) = kinolab(&["field", f, "--descend", "0,0", "--step", "-1"]);
    assert_eq!(code, 2);
    assert!(stderr.contains("--step"), "{stderr}");
    std::fs::write(
        &field,
        r#"{ "fields": [ { "kind": "repulsive", "x": 0, "y": 0, "profile": "linear" } ] }"#,
    )
    .unwrap();
    let (code, stdout, stderr) = kinolab(&["field", f, "--at", "1,1"]);
    assert_eq!((code, stdout.as_str()), (2, ""));
    assert!(
        stderr.contains("wall.field.json") && stderr.contains("fields[0].range"),
        "{stderr}"
    );
}

#[test]
fn run_reports_a_behaviour_run() {
    let examples = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../mind/behaviours/runs/subsumption.run.json"
    );
    let v = json(&["run", examples]);
    assert_eq!(v["metrics"]["reached"], true);
    assert_eq!(v["metrics"]["collisions"], 0);
    let names: Vec<&str> = v["control"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|s| s["behaviour"].as_str())
        .collect();
    assert!(
        names.contains(&"go") && names.contains(&"avoid"),
        "{names:?}"
    );
}

/// The contract's gait example: at τ = 0.005 the hind-left leg swings and
/// the others stand, each foot where the stance line puts it.
#[test]
fn gait_follows_the_contract() {
    let path = robot_file(
        "crawl.gait.json",
        r#"{ "name": "quadruped-crawl", "duty_factor": 0.75, "stride": 0.2, "com": [0.0, 0.0],
  "legs": [ { "name": "LF", "x": 0.3, "y": 0.2, "phase": 0.25 }, { "name": "RF", "x": 0.3, "y": -0.2, "phase": 0.75 },
            { "name": "LH", "x": -0.3, "y": 0.2, "phase": 0.0 }, { "name": "RH", "x": -0.3, "y": -0.2, "phase": 0.5 } ] }"#,
    );
    let v = ok(&["gait", &path]);
    let samples = v["samples"].as_array().unwrap();
    assert_eq!(samples.len(), 100);
    let first = &samples[0];
    assert_eq!(first["tau"], 0.005);
    assert_eq!(first["stance"], serde_json::json!(["LF", "RF", "RH"]));
    // x = x_i + L/2 − L (σ − (1 − β))/β with σ = (τ − φ) mod 1.
    let lf = 0.3 + 0.1 - 0.2 * ((0.005 - 0.25 + 1.0) - 0.25) / 0.75;
    let rh = -0.3 + 0.1 - 0.2 * ((0.005 - 0.5 + 1.0) - 0.25) / 0.75;
    let feet = first["feet"].as_array().unwrap();
    assert!((feet[0][0].as_f64().unwrap() - lf).abs() < 1e-12);
    assert!((feet[2][0].as_f64().unwrap() - rh).abs() < 1e-12);
    assert_eq!(feet[1][1], -0.2);
    let min = v["min_margin"].as_f64().unwrap();
    let smallest = samples
        .iter()
        .map(|s| s["margin"].as_f64().unwrap())
        .fold(f64::INFINITY, f64::min);
    assert_eq!(min, smallest);
    assert_eq!(v["statically_stable"], min > 0.0);
    assert!(min > 0.0, "the crawl with the CoM at the centre is static");
    let bad = robot_file(
        "bad.gait.json",
        r#"{ "duty_factor": 1.0, "stride": 0.2, "legs": [ { "name": "LF", "x": 0.3, "y": 0.2, "phase": 0.25 } ] }"#,
    );
    fails_with(&["gait", &bad], "bad.gait.json: duty_factor:");
    fails_with(&["gait", &path, "--samples", "0"], "--samples:");
}

#[test]
fn cpg_follows_the_contract() {
    let path = robot_file(
        "crawl.cpg.json",
        r#"{ "frequency": 1.0, "legs": ["LF", "RF", "LH", "RH"], "target_phases": [0.25, 0.75, 0.0, 0.5],
  "weight": 2.0, "initial_deg": [0, 10, 20, 30], "dt": 0.001, "duration": 10.0 }"#,
    );
    let v = ok(&["cpg", &path]);
    assert_eq!(v["locked"], true);
    let lag: Vec<f64> = serde_json::from_value(v["lag"].clone()).unwrap();
    for (got, want) in lag.iter().zip([0.0, 0.5, 0.75, 0.25]) {
        let d = (got - want).rem_euclid(1.0);
        assert!(d.min(1.0 - d) < 1e-6, "{got} vs {want}");
    }
    // Ten cycles at 1 Hz: θ₀ has turned 3600° give or take what locking
    // took, and the final phases differ by the lags.
    let final_deg: Vec<f64> = serde_json::from_value(v["final_deg"].clone()).unwrap();
    assert!((final_deg[0] - 3600.0).abs() < 180.0, "{final_deg:?}");
    for (theta, lag) in final_deg.iter().zip(&lag) {
        let turns = (final_deg[0] - theta) / 360.0 - lag;
        assert!((turns - turns.round()).abs() < 1e-9, "{theta} {lag}");
    }
}

#[test]
fn plan_follows_the_contract() {
    let path = robot_file(
        "two-rooms.world.json",
        r#"{ "name": "two-rooms", "bounds": [0.0, 0.0, 10.0, 6.0], "robot_radius": 0.2,
  "obstacles": [ { "kind": "circle", "x": 3.0, "y": 3.0, "radius": 0.5 },
                 { "kind": "polygon", "points": [[5, 0], [5.2, 0], [5.2, 4], [5, 4]] },
                 { "kind": "wall", "from": [7, 2], "to": [7, 6], "thickness": 0.1 } ] }"#,
    );
    let v = ok(&[
        "plan", &path, "--from", "1,1", "--to", "9,5", "--cell", "0.5",
    ]);
    let cells = v["cells"].as_array().unwrap();
    assert_eq!(cells.first().unwrap(), &serde_json::json!([2, 2]));
    assert_eq!(cells.last().unwrap(), &serde_json::json!([18, 10]));
    // The cost is the summed step lengths of the cells given.
    let mut cost = 0.0;
    for w in cells.windows(2) {
        let di = (w[1][0].as_i64().unwrap() - w[0][0].as_i64().unwrap()).abs();
        let dj = (w[1][1].as_i64().unwrap() - w[0][1].as_i64().unwrap()).abs();
        assert!(di <= 1 && dj <= 1 && di + dj > 0);
        cost += if di + dj == 2 { 0.5 * 2f64.sqrt() } else { 0.5 };
    }
    assert!((v["cost"].as_f64().unwrap() - cost).abs() < 1e-9);
    assert_eq!(v["points"][0], serde_json::json!([1.25, 1.25]));
    // Dijkstra finds the same cost with more work.
    let d = ok(&[
        "plan",
        &path,
        "--from",
        "1,1",
        "--to",
        "9,5",
        "--cell",
        "0.5",
        "--algorithm",
        "dijkstra",
    ]);
    assert!((d["cost"].as_f64().unwrap() - v["cost"].as_f64().unwrap()).abs() < 1e-12);
    assert!(d["expanded"].as_u64().unwrap() > v["expanded"].as_u64().unwrap());
    // Walled in: no path, exit 0 and a null cost.
    let boxed = robot_file(
        "boxed.world.json",
        r#"{ "bounds": [0, 0, 4, 4], "robot_radius": 0.1,
  "obstacles": [ { "kind": "wall", "from": [2, 0], "to": [2, 4], "thickness": 0.2 } ] }"#,
    );
    let v = ok(&[
        "plan", &boxed, "--from", "1,1", "--to", "3,3", "--cell", "0.25",
    ]);
    assert!(v["cost"].is_null() && v["cells"].as_array().unwrap().is_empty());
    fails_with(
        &[
            "plan", &path, "--from", "3,3", "--to", "9,5", "--cell", "0.5",
        ],
        "--from:",
    );
    fails_with(
        &[
            "plan", &path, "--from", "1,1", "--to", "11,5", "--cell", "0.5",
        ],
        "--to:",
    );
    fails_with(
        &[
            "plan", &path, "--from", "1,1", "--to", "9,5", "--cell", "-1",
        ],
        "--cell:",
    );
}

#[test]
fn arena_runs_each_architecture_and_scores_it() {
    let base = ["arena", "catalogue:office", "--every", "10"];
    let mut scores = Vec::new();
    for kind in ["hierarchical", "reactive", "hybrid"] {
        let mut args = base.to_vec();
        args.extend(["--architecture", kind, "--perturb", "glass:8.2,0,8.2,3.2"]);
        let v = ok(&args);
        assert_eq!(v["architecture"], kind);
        assert_eq!(v["surprises"][0]["kind"], "glass");
        let samples = v["samples"].as_array().unwrap();
        assert_eq!(samples[0]["x"], 1.0);
        // Samples every 10 steps of 50 ms.
        assert!((samples[1]["t"].as_f64().unwrap() - 0.5).abs() < 1e-9);
        let m = &v["metrics"];
        // Every bump is an event and a collision.
        let bumps = v["events"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|e| e["kind"] == "bump")
            .count();
        assert_eq!(m["collisions"].as_u64().unwrap() as usize, bumps);
        scores.push((
            m["reached"].as_bool().unwrap(),
            m["replans"].as_u64().unwrap(),
        ));
    }
    // The window: the robots with a model get round the glass, the reactive one does not.
    assert_eq!(
        scores.iter().map(|s| s.0).collect::<Vec<_>>(),
        [true, false, true]
    );
    assert_eq!(scores[1].1, 0);
    fails_with(
        &[
            "arena",
            "catalogue:office",
            "--architecture",
            "deliberative",
        ],
        "--architecture",
    );
    fails_with(
        &[
            "arena",
            "catalogue:office",
            "--architecture",
            "hybrid",
            "--perturb",
            "door:1,1@2",
        ],
        "--perturb[0]",
    );
    fails_with(
        &[
            "arena",
            "catalogue:office",
            "--architecture",
            "hybrid",
            "--planning-cost",
            "nan",
        ],
        "--planning-cost",
    );
    fails_with(
        &[
            "arena",
            "catalogue:office",
            "--architecture",
            "hybrid",
            "--duration",
            "1e9",
        ],
        "--duration",
    );
}

/// A value outside an option's range hears that option's own range, however
/// far outside it is; a seed says what a seed must be.
#[test]
fn arena_options_name_their_own_ranges() {
    let arena = |extra: &[&str], want: &str| {
        let mut args = vec!["arena", "catalogue:office", "--architecture", "hybrid"];
        args.extend_from_slice(extra);
        fails_with(&args, want);
    };
    arena(
        &["--duration", "1e308"],
        "--duration: must be from 0 to 600, got 1e308",
    );
    arena(
        &["--duration", "-5"],
        "--duration: must be from 0 to 600, got -5",
    );
    arena(
        &["--planning-cost", "1e9"],
        "--planning-cost: must be from 0 to 1000, got 1e9",
    );
    arena(
        &["--perturb", "noise:1e9"],
        "--perturb[0]: must be from 0 to 1, got 1e9",
    );
    arena(
        &["--perturb", "door:5,1,5,2@1e300"],
        "--perturb[0]: must be from 0 to 3600, got 1e300",
    );
    for seed in ["-1", "1.5", "many"] {
        arena(
            &["--seed", seed],
            "a seed is a whole number from 0 to 18446744073709551615",
        );
    }
}

#[test]
fn components_prints_the_trace_and_the_final_state() {
    let path = robot_file(
        "out-of-order.system.json",
        include_str!("../../../talk/components/systems/out-of-order.system.json"),
    );
    let v = ok(&["components", &path]);
    let trace = v["trace"].as_array().unwrap();
    // Two requests, then their answers the other way round.
    let answers: Vec<&str> = trace
        .iter()
        .filter(|r| r["kind"] == "answer")
        .map(|r| r["summary"].as_str().unwrap())
        .collect();
    assert_eq!(answers, ["Number 16.0", "Number 9.0", "Number 25.0"]);
    let first = &trace.iter().find(|r| r["kind"] == "request").unwrap();
    assert_eq!(first["port"], "client.ask");
    assert_eq!(first["service"], "solver.compute");
    assert_eq!(first["pattern"], "query");
    assert!(
        (first["delivered"].as_f64().unwrap() - first["sent"].as_f64().unwrap() - 0.02).abs()
            < 1e-9
    );
    assert_eq!(v["counts"]["messages"], 6);
    assert_eq!(v["complete"], true);
    // `--until` cuts the run: at 0.2 s the answers are still being worked on.
    let short = ok(&["components", &path, "--until", "0.2"]);
    assert_eq!(short["counts"]["delivered"], 2);
    let robot = ok(&["components", "example:robot", "--until", "3"]);
    assert_eq!(robot["robot"][0], 1.0);
    fails_with(&["components", &path, "--until", "-1"], "--until");
    fails_with(&["components", "example:nowhere"], "no example system");
    let bad = robot_file(
        "bad.system.json",
        r#"{"components": [{"name": "s", "kind": "server", "params": {"work": []}}]}"#,
    );
    fails_with(&["components", &bad], "components[0].params.work");
}

/// The Panda arm's URDF as shipped with the lab.
fn panda_urdf() -> String {
    format!(
        "{}/../../body/mechanism/robots/panda.urdf",
        env!("CARGO_MANIFEST_DIR")
    )
}

#[test]
fn fk_reads_a_urdf_file_by_joint_order_or_name() {
    let panda = panda_urdf();
    let described = json(&["describe", &panda]);
    let movable = described["movable"].as_array().expect("movable");
    assert_eq!(movable.len(), 8);
    assert_eq!(movable[0], "panda_joint1");
    let tip = described["tip"].as_str().expect("tip").to_owned();
    // The same pose from all joints in order and from two of them by name.
    let q = "0.3,0,0,-1.2,0,1.4,0,0";
    let by_order = json(&["fk", &panda, "--q", q]);
    assert_eq!(by_order["frame"], tip.as_str());
    let by_name = json(&[
        "fk",
        &panda,
        "--set",
        "panda_joint1=0.3,panda_joint4=-1.2,panda_joint6=1.4",
    ]);
    assert_eq!(by_order, by_name);
    // Link 1 turns about the base's z axis by joint 1 and sits 0.333 m up.
    let link1 = json(&["fk", &panda, "--q", q, "--frame", "panda_link1"]);
    assert!((link1["matrix"][0][0].as_f64().unwrap() - 0.3f64.cos()).abs() < 1e-12);
    assert_eq!(link1["matrix"][2][3], 0.333);
    let all = json(&["fk", &panda, "--q", q, "--all-frames"]);
    assert_eq!(all["frames"]["panda_link1"], link1["matrix"]);
    assert_eq!(all["frames"][&tip], by_order["matrix"]);
    assert!(by_order.get("outside_limits").is_none(), "{by_order}");
    // FK is geometry: a pose past a limit is computed, and the limit named.
    let past = json(&["fk", &panda, "--q", "0,3,0,-1.2,0,1.4,0,0"]);
    assert!(past["matrix"][0][3].is_f64(), "{past}");
    let outside = past["outside_limits"].as_array().expect("outside_limits");
    assert_eq!(outside.len(), 1, "{past}");
    assert_eq!(outside[0]["joint"], "panda_joint2");
    assert_eq!(outside[0]["value"], 3.0);
    assert_eq!(outside[0]["limits"][1], 1.7628);
    // The zero pose, where the elbow's range [-3.0718, -0.0698] leaves out 0.
    let zero = json(&["fk", &panda, "--set", "panda_joint1=0"]);
    assert_eq!(zero["outside_limits"][0]["joint"], "panda_joint4", "{zero}");
    assert_eq!(zero["outside_limits"][0]["value"], 0.0);
    fails_with(
        &["fk", &panda, "--set", "elbow=1"],
        "panda.urdf: --set: `elbow` is not a movable joint",
    );
    let broken = robot_file(
        "broken.urdf",
        "<robot name=\"r\">\n<link name=\"a\"/>\n<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>\n</robot>",
    );
    fails_with(
        &["fk", &broken, "--q", ""],
        "broken.urdf: <joint name=\"j\"> (line 3): its child link `b` is not in the file",
    );
}

/// IK on a URDF answers in `--q` order and puts the tip where it was asked:
/// FK of the answer lands on the target.
#[test]
fn ik_on_a_urdf_answers_in_q_order() {
    let panda = panda_urdf();
    let target = [0.4, 0.1, 0.5];
    let answer = json(&["ik", &panda, "--position", "0.4,0.1,0.5"]);
    assert_eq!(answer["converged"], true);
    let q: Vec<String> = answer["q"]
        .as_array()
        .expect("q")
        .iter()
        .map(|v| v.as_f64().expect("number").to_string())
        .collect();
    assert_eq!(q.len(), 8, "the Panda's eight movable joints");
    let placed = json(&["fk", &panda, "--q", &q.join(",")]);
    for (i, want) in target.iter().enumerate() {
        let got = placed["matrix"][i][3].as_f64().expect("number");
        assert!((got - want).abs() < 1e-6, "{i}: {got} vs {want}");
    }
    fails_with(
        &["ik", &panda, "--position", "0.4,0.1,0.5", "--seed", "1,2"],
        "panda.urdf: --seed: `panda` has 8 movable joints",
    );
}

/// A catalogue model goes out as URDF and comes back with the same tool
/// pose; a loop that URDF cannot close is a note on stderr.
#[test]
fn export_urdf_writes_a_file_fk_reads_back() {
    let (code, urdf, stderr) = kinolab(&["export-urdf", "catalogue:puma560"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stderr.is_empty(), "{stderr}");
    assert!(urdf.starts_with("<?xml"), "{urdf}");
    let path = robot_file("puma.urdf", &urdf);
    let q = "0.1,-0.4,0.3,0.8,-0.5,1.1";
    let back = json(&["fk", &path, "--q", q, "--frame", "tool"]);
    let model = json(&["fk", "catalogue:puma560", "--q", q]);
    for r in 0..3 {
        for c in 0..4 {
            let (a, b) = (
                back["matrix"][r][c].as_f64(),
                model["matrix"][r][c].as_f64(),
            );
            assert!((a.unwrap() - b.unwrap()).abs() < 1e-12, "[{r}][{c}]");
        }
    }
    let (code, _, stderr) = kinolab(&["export-urdf", "catalogue:four-bar"]);
    assert_eq!(code, 0);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(
        stderr.contains("note: loop `four-bar loop` is left open"),
        "{stderr}"
    );
    fails_with(
        &["export-urdf", "catalogue:nope"],
        "no built-in mechanism `nope`",
    );
}
