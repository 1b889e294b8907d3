#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! The command line and the JS API give the same numbers for the same
//! input: each case runs `kinolab` and the JS API's computation (natively,
//! the same code the wasm package runs) and compares the JSON.

use std::process::Command;

use kinolab_js::api;
use kinolab_js::mechanism_api::MechanismApi;
use serde_json::{Value, json};

/// The same JSON, numbers equal to 1e-12 relative: the two sides compute
/// the same way, but a test build and the binary may use differently
/// built maths routines, which differ in the last bit.
fn same(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
            (x - y).abs() <= 1e-12 * x.abs().max(y.abs()).max(1.0)
        }
        (Value::Array(x), Value::Array(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(x, y)| same(x, y))
        }
        (Value::Object(x), Value::Object(y)) => {
            x.len() == y.len() && x.iter().all(|(k, v)| y.get(k).is_some_and(|w| same(v, w)))
        }
        _ => a == b,
    }
}

macro_rules! assert_same {
    ($a:expr, $b:expr $(, $what:expr)?) => {{
        let (a, b) = (&$a, &$b);
        assert!(same(a, b), "{}\n  cli: {a}\n  js:  {b}", { let _w = ""; $( let _w = $what; )? _w });
    }};
}

fn cli(args: &[&str]) -> Value {
    let out = Command::new(env!("CARGO_BIN_EXE_kinolab"))
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// A file in a fresh temporary folder, for the command line to read.
fn file(name: &str, value: &Value) -> String {
    let dir = std::env::temp_dir().join(format!("kinolab-parity-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, value.to_string()).unwrap();
    path.display().to_string()
}

#[test]
fn wheels_reports_match() {
    for id in [
        "tricycle",
        "ackermann-car",
        "synchro-drive",
        "uranus-mecanum",
    ] {
        let robot = format!("catalogue:{id}");
        assert_same!(
            cli(&["analyze", &robot]),
            api::analyze_robot(json!(robot)).unwrap(),
            "{id}"
        );
        assert_same!(
            cli(&["drive", &robot, "--twist", "0.5,0,0.2", "--theta", "0.3"]),
            api::drive_twist(json!(robot), [0.5, 0.0, 0.2], Some(0.3)).unwrap(),
            "{id}"
        );
    }
    let file = file(
        "two.robot.json",
        &api::robot_file(json!("differential-drive")).unwrap(),
    );
    assert_same!(
        cli(&["drive", &file, "--wheels", "4,2,-"]),
        api::drive_wheels(
            json!("differential-drive"),
            &[Some(4.0), Some(2.0), None],
            None
        )
        .unwrap()
    );
}

#[test]
fn control_reports_match() {
    let run = json!({
        "controller": { "kind": "polar", "k_rho": 3.0, "k_alpha": 8.0, "k_beta": -1.5 },
        "start": { "x": -1.0, "y": 0.5, "theta_deg": 0 },
        "goal": { "x": 0.0, "y": 0.0, "theta_deg": 0 },
        "dt": 0.001, "duration": 10.0, "output_every": 500,
        "noise": { "seed": 7, "slip": 0.1, "push_speed": 0.02, "push_turn_deg": 2 }
    });
    let path = file("go.run.json", &run);
    assert_same!(
        cli(&["simulate", &path]),
        api::simulate(run.clone()).unwrap()
    );
    assert_same!(
        cli(&[
            "batch",
            &path,
            "--radius",
            "0.8",
            "--count",
            "6",
            "--heading-deg",
            "30",
            "--paths"
        ]),
        api::batch_simulate(run, 0.8, 6, 30.0).unwrap()
    );
    assert_same!(
        cli(&["gains", "3,8,-1.5"]),
        api::controller_stability(3.0, 8.0, -1.5).unwrap()
    );
}

#[test]
fn mechanism_reports_match_for_chains_couplings_and_loops() {
    for (id, q, frame) in [
        ("puma560", "0.1,0.8,-0.6,0.3,0.5,-0.2", "tool"),
        ("four-bar", "0.7,0,0", "coupler-point"),
        ("rocker-bogie", "0.1,-0.2,0.05,0.3", "left-front-wheel"),
    ] {
        let model = format!("catalogue:{id}");
        let js = MechanismApi::load(json!(model)).unwrap();
        let values: Vec<f64> = q.split(',').map(|v| v.parse().unwrap()).collect();
        assert_eq!(values.len(), js.model.dof(), "{id}");
        assert_same!(
            cli(&["fk", &model, "--q", q, "--frame", frame]),
            js.fk(values.clone(), Some(frame)).unwrap(),
            id
        );
    }
    // IK starts from the same home state on both sides, loops closed.
    for (id, target, frame) in [
        ("puma560", [0.5, -0.15, 1.0], "tool"),
        ("planar-2r", [1.2, 0.6, 0.0], "tool"),
        ("four-bar", [0.5, 0.5, 0.0], "coupler-point"),
    ] {
        let model = format!("catalogue:{id}");
        let js = MechanismApi::load(json!(model)).unwrap();
        let position = format!("{},{},{}", target[0], target[1], target[2]);
        assert_same!(
            cli(&["ik", &model, "--position", &position, "--frame", frame]),
            js.ik(json!({ "position": target, "frame": frame }))
                .unwrap(),
            id
        );
    }
}

#[test]
fn locomotion_and_lesson_reports_match() {
    assert_same!(cli(&["leg-events", "6"]), api::leg_events(6).unwrap());
    assert_same!(
        cli(&[
            "stability",
            "--com",
            "0.05,0.02",
            "--feet",
            "0.3,0.2;-0.3,0.2;0,-0.25"
        ]),
        api::static_stability([0.05, 0.02], &[[0.3, 0.2], [-0.3, 0.2], [0.0, -0.25]]).unwrap()
    );
    let flat: Vec<Value> = cli(&["lessons"])["units"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|u| u["lessons"].as_array().unwrap().clone())
        .collect();
    assert_same!(Value::Array(flat), api::lessons().unwrap());
}

#[test]
fn field_and_behaviour_reports_match() {
    let field_file = include_str!("../../fields/presets/goal-behind-a-rock.field.json");
    let path = file(
        "rock.field.json",
        &serde_json::from_str::<Value>(field_file).unwrap(),
    );
    let f = || Value::String(field_file.to_owned());
    assert_same!(
        cli(&["field", &path, "--at", "1,0.5;-0.2,3;2,0"]),
        api_ok(kinolab_js::behaviour_api::field_vectors(
            f(),
            &[[1.0, 0.5], [-0.2, 3.0], [2.0, 0.0]]
        )),
        "field --at"
    );
    assert_same!(
        cli(&[
            "field",
            "catalogue:u-shaped-wall",
            "--minima",
            "--box",
            "0,-2.5,7,2.5"
        ]),
        api_ok(kinolab_js::behaviour_api::field_minima(
            Value::String("catalogue:u-shaped-wall".into()),
            [0.0, -2.5, 7.0, 2.5]
        )),
        "field --minima"
    );
    assert_same!(
        cli(&["field", &path, "--descend=0.3,0.2", "--step", "0.02"]),
        api_ok(kinolab_js::behaviour_api::field_descend(
            f(),
            [0.3, 0.2],
            Some(0.02),
            None
        )),
        "field --descend"
    );
    let run_file = include_str!("../../behaviours/runs/voting.run.json");
    let run_path = file(
        "voting.run.json",
        &serde_json::from_str::<Value>(run_file).unwrap(),
    );
    assert_same!(
        cli(&["run", &run_path]),
        api_ok(kinolab_js::behaviour_api::run_behaviours(Value::String(
            run_file.to_owned()
        ))),
        "run"
    );
}

/// The contract's examples of the legged and planning commands.
const GAIT: &str = r#"{ "name": "quadruped-crawl", "duty_factor": 0.75, "stride": 0.2, "com": [0.0, 0.0],
  "legs": [ { "name": "LF", "x": 0.3, "y": 0.2, "phase": 0.25 }, { "name": "RF", "x": 0.3, "y": -0.2, "phase": 0.75 },
            { "name": "LH", "x": -0.3, "y": 0.2, "phase": 0.0 }, { "name": "RH", "x": -0.3, "y": -0.2, "phase": 0.5 } ] }"#;
const CPG: &str = r#"{ "frequency": 1.0, "legs": ["LF", "RF", "LH", "RH"], "target_phases": [0.25, 0.75, 0.0, 0.5],
  "weight": 2.0, "initial_deg": [0, 10, 20, 30], "dt": 0.001, "duration": 10.0 }"#;
const WORLD: &str = r#"{ "name": "two-rooms", "bounds": [0.0, 0.0, 10.0, 6.0], "robot_radius": 0.2,
  "obstacles": [ { "kind": "circle", "x": 3.0, "y": 3.0, "radius": 0.5 },
                 { "kind": "polygon", "points": [[5, 0], [5.2, 0], [5.2, 4], [5, 4]] },
                 { "kind": "wall", "from": [7, 2], "to": [7, 6], "thickness": 0.1 } ] }"#;

#[test]
fn gait_cpg_and_plan_reports_match() {
    let parse = |t: &str| serde_json::from_str::<Value>(t).unwrap();
    let gait = file("crawl.gait.json", &parse(GAIT));
    assert_same!(
        cli(&["gait", &gait, "--samples", "40"]),
        api_ok(kinolab_js::legs_api::gait(parse(GAIT), 40)),
        "gait"
    );
    let cpg = file("crawl.cpg.json", &parse(CPG));
    assert_same!(
        cli(&["cpg", &cpg]),
        api_ok(kinolab_js::legs_api::cpg(parse(CPG))),
        "cpg"
    );
    let world = file("two-rooms.world.json", &parse(WORLD));
    assert_same!(
        cli(&[
            "plan", &world, "--from", "1,1", "--to=9,5", "--cell", "0.25"
        ]),
        api_ok(kinolab_js::legs_api::plan(
            parse(WORLD),
            [1.0, 1.0],
            [9.0, 5.0],
            0.25
        )),
        "plan"
    );
    assert_same!(
        cli(&[
            "arena",
            "catalogue:office",
            "--architecture",
            "hybrid",
            "--perturb",
            "person:6.3,5.6,6.3,2.0@0.6",
            "--perturb",
            "noise:0.1",
            "--planning-cost",
            "3",
            "--seed",
            "4",
            "--every",
            "20"
        ]),
        api_ok(kinolab_js::architecture_api::arena(
            Value::String("catalogue:office".into()),
            serde_json::json!({ "architecture": "hybrid", "perturb": ["person:6.3,5.6,6.3,2.0@0.6", "noise:0.1"],
                                "planning_cost_ms": 3, "seed": 4, "every": 20 })
        )),
        "arena"
    );
    assert_same!(
        cli(&["components", "example:events", "--until", "2.5"]),
        api_ok(kinolab_js::architecture_api::components(
            Value::String("example:events".into()),
            Some(2.5)
        )),
        "components"
    );
}

fn api_ok(reply: api::Reply) -> Value {
    reply.unwrap()
}
