#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! One API, two hosts: for every operation and generated valid inputs (the
//! reliability suite's generators, without damage), the `kinolab` command
//! prints exactly the text the JavaScript function's JSON serialises to,
//! and the two refuse the same inputs.
//!
//! The JavaScript side runs natively: `kinolab_js::calls` is what the wasm
//! glue calls with the arguments converted to JSON.

use std::collections::BTreeMap;
use std::path::PathBuf;

use kinolab_fuzz::case::{Case, FileSpec};
use kinolab_fuzz::generate::{COMMANDS, valid_case};
use kinolab_fuzz::run::{Limits, run};
use kinolab_fuzz::seeds::Seeds;
use kinolab_js::calls::{self, Reply};
use serde_json::{Value, json};

/// Valid cases generated per command.
const CASES: u64 = 12;

/// A case's arguments after the command: positional ones, options with
/// their values (repeatable), and flags.
#[derive(Default)]
struct Args {
    positional: Vec<String>,
    options: Vec<(String, String)>,
    flags: Vec<String>,
}

const FLAGS: [&str; 3] = ["--minima", "--paths", "--csv"];

impl Args {
    fn of(case: &Case) -> Self {
        let mut args = Args::default();
        let mut rest = case.args[1..].iter();
        while let Some(a) = rest.next() {
            if FLAGS.contains(&a.as_str()) {
                args.flags.push(a.clone());
            } else if let Some(name) = a.strip_prefix("--") {
                args.options
                    .push((name.to_owned(), rest.next().cloned().unwrap_or_default()));
            } else {
                args.positional.push(a.clone());
            }
        }
        args
    }

    fn get(&self, name: &str) -> Option<&str> {
        self.options
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }

    fn all(&self, name: &str) -> Vec<String> {
        self.options
            .iter()
            .filter(|(n, _)| n == name)
            .map(|(_, v)| v.clone())
            .collect()
    }

    fn number(&self, name: &str) -> Option<f64> {
        self.get(name).map(|v| v.parse().unwrap())
    }

    fn numbers(&self, name: &str) -> Option<Vec<f64>> {
        self.get(name).map(numbers)
    }

    fn flag(&self, name: &str) -> bool {
        self.flags.iter().any(|f| f == name)
    }
}

fn numbers(text: &str) -> Vec<f64> {
    if text.trim().is_empty() {
        return Vec::new();
    }
    text.split(',').map(|v| v.trim().parse().unwrap()).collect()
}

fn points(text: &str) -> Value {
    let points: Vec<Vec<f64>> = text
        .split(';')
        .filter(|p| !p.trim().is_empty())
        .map(numbers)
        .collect();
    json!(points)
}

/// A file-like argument as JavaScript gets it: the file's text, or the
/// `catalogue:` name.
fn input(case: &Case, arg: &str) -> Value {
    case.files.iter().find(|(name, _)| name == arg).map_or_else(
        || Value::String(arg.to_owned()),
        |(_, spec)| match spec {
            FileSpec::Text(text) => Value::String(text.clone()),
            other => panic!("{arg}: {other:?} in a valid case"),
        },
    )
}

/// The JavaScript call that matches the command line's case, or `None`
/// for a call JavaScript has no twin of (`lessons DIR`: no files).
fn js(case: &Case) -> Option<Reply> {
    let a = Args::of(case);
    let first = || input(case, &a.positional[0]);
    Some(match case.command.as_str() {
        "leg-events" => calls::leg_events(a.positional[0].parse().unwrap()),
        "stability" => calls::static_stability(
            json!(numbers(a.get("com").unwrap())),
            points(a.get("feet").unwrap()),
        ),
        "analyze" => calls::analyze_robot(first()),
        "drive" => drive(&a, first()),
        "differential-drive" => calls::differential_drive(
            a.number("track").unwrap(),
            a.number("left").unwrap(),
            a.number("right").unwrap(),
        ),
        "robots" if a.positional.is_empty() => calls::robots(),
        "robots" => calls::robot_file(first()),
        "simulate" => calls::simulate(first()),
        "batch" => calls::batch_simulate(
            first(),
            a.number("radius").unwrap_or(1.0),
            a.number("count").map_or(16, |c| c as usize),
            a.number("heading-deg").unwrap_or(0.0),
            Some(a.flag("--paths")),
        ),
        "gains" => {
            let k = numbers(&a.positional[0]);
            calls::controller_stability(k[0], k[1], k[2])
        }
        "mechanisms" => calls::mechanisms(),
        "describe" | "home-state" | "fk" | "ik" | "place" | "jacobian" | "collide" => {
            mechanism(&case.command, &a, first())
        }
        "dynamics" | "statics" => forces(&case.command, &a, first()),
        "field" => field(&a, first()),
        "catalogues" => calls::catalogues(),
        "run" => calls::run_behaviours(first()),
        "lessons" if a.positional.is_empty() => calls::lessons(),
        "lessons" => return None,
        "check-lesson" => {
            let Value::String(text) = first() else {
                unreachable!()
            };
            calls::check_lesson(&a.positional[0], &text)
        }
        "widgets" => calls::widgets(),
        "pick-cell" => calls::pick_cell(
            a.number("placement-error").unwrap(),
            a.number("gripper-tolerance").unwrap(),
            a.number("sensor-error").unwrap(),
            a.number("count").map_or(100, |c| c as u32),
            a.number("seed").map_or(1, |c| c as u32),
        ),
        "gait" => calls::gait(
            first(),
            Some(a.number("samples").map_or(100, |s| s as usize)),
        ),
        "cpg" => calls::cpg(first()),
        "zmp" => calls::zmp(first()),
        "ant" => calls::ant_walk(first()),
        "walk" => calls::walk(
            first(),
            Some(a.number("lift").unwrap_or(0.03)),
            Some(a.number("samples").map_or(60, |s| s as usize)),
            a.number("stride"),
            None,
        ),
        "plan" => calls::plan(
            first(),
            json!(numbers(a.get("from").unwrap())),
            json!(numbers(a.get("to").unwrap())),
            a.number("cell").unwrap(),
            a.get("algorithm"),
        ),
        "arena" => calls::arena(
            first(),
            json!({
                "architecture": a.get("architecture").unwrap(),
                "perturb": a.all("perturb"),
                "planning_cost_ms": a.number("planning-cost").unwrap_or(2.0),
                "duration": a.number("duration").unwrap_or(120.0),
                "seed": a.number("seed").unwrap_or(0.0) as u64,
                "every": a.number("every").unwrap_or(1.0) as usize,
            }),
        ),
        "routes" => {
            let feeds: Vec<Vec<bool>> = a.positional[0]
                .split(';')
                .map(|row| row.chars().map(|c| c == '1').collect())
                .collect();
            calls::routes(json!(feeds))
        }
        "components" => calls::components(first(), a.number("until")),
        "script" => return script(case, &a),
        other => panic!("no JavaScript twin for `{other}`"),
    })
}

/// `script exercises`, `check` and `grade`; grading as CSV is the command
/// line's alone (see `cli.rs`).
fn script(case: &Case, a: &Args) -> Option<Reply> {
    let text = |name: &str| match input(case, name) {
        Value::String(text) => text,
        other => panic!("{other:?}"),
    };
    let exercise = a.get("exercise").unwrap_or_default().to_owned();
    Some(match a.positional[0].as_str() {
        "exercises" => calls::exercises(),
        "check" => calls::check_script(exercise, text(&a.positional[1]), None),
        "grade" if a.flag("--csv") => return None,
        "grade" => {
            let scripts: serde_json::Map<String, Value> = a.positional[1..]
                .iter()
                .map(|f| (f.clone(), Value::String(text(f))))
                .collect();
            calls::grade_scripts(exercise, Value::Object(scripts))
        }
        other => panic!("no `script {other}`"),
    })
}

fn drive(a: &Args, robot: Value) -> Reply {
    let theta = a.number("theta");
    match (a.get("twist"), a.get("wheels")) {
        (Some(t), None) => calls::drive_twist(robot, json!(numbers(t)), theta),
        (None, Some(w)) => {
            let spins: Vec<Option<f64>> = w
                .split(',')
                .filter(|s| !s.trim().is_empty())
                .map(|s| (s.trim() != "-").then(|| s.trim().parse().unwrap()))
                .collect();
            calls::drive_wheels(robot, json!(spins), theta)
        }
        _ => Err("neither".into()),
    }
}

fn mechanism(command: &str, a: &Args, model: Value) -> Reply {
    use kinolab_api::mechanism::{Describe, Fk, HomeState, Jacobian, Place};
    let model = calls::load_mechanism(model)?;
    let q = a.numbers("q").unwrap_or_default();
    let frame = a.get("frame").map(str::to_owned);
    match command {
        "describe" => calls::on(&model, &Describe),
        "home-state" => calls::on(&model, &HomeState),
        "fk" => calls::on(&model, &Fk { q, frame }),
        "place" => calls::on(&model, &Place { q }),
        "jacobian" => calls::on(&model, &Jacobian { q, frame }),
        "ik" => {
            let mut request = json!({ "position": a.numbers("position") });
            for (key, value) in [
                ("rotation", a.numbers("rotation").map(|r| json!(r))),
                ("seed", a.numbers("seed").map(|r| json!(r))),
                ("frame", frame.map(|f| json!(f))),
                (
                    "max_iterations",
                    a.number("max-iterations").map(|n| json!(n as usize)),
                ),
            ] {
                if let Some(value) = value {
                    request[key] = value;
                }
            }
            calls::ik(&model, request)
        }
        _ => {
            let obstacles: Vec<Value> = a
                .all("obstacle")
                .iter()
                .map(|o| {
                    let (kind, values) = o.split_once(':').unwrap();
                    json!({ kind: numbers(values) })
                })
                .collect();
            calls::collide(
                &model,
                q,
                a.get("plane").unwrap_or("side"),
                json!(obstacles),
            )
        }
    }
}

/// `dynamics` and `statics` as `Mechanism.dynamics` and `.statics` get them.
fn forces(command: &str, a: &Args, model: Value) -> Reply {
    let model = calls::load_mechanism(model)?;
    let mut request = json!({ "q": a.numbers("q").unwrap_or_default() });
    for key in ["qd", "qdd", "tau", "gravity"] {
        if let Some(v) = a.numbers(key) {
            request[key] = json!(v);
        }
    }
    if command == "dynamics" {
        return calls::dynamics(&model, request);
    }
    let loads: Vec<Value> = a
        .all("load")
        .iter()
        .map(|l| {
            let (frame, values) = l.rsplit_once(':').unwrap();
            let v = numbers(values);
            let moment = if v.len() == 6 {
                v[3..].to_vec()
            } else {
                vec![0.0; 3]
            };
            json!({ "frame": frame, "force": v[..3], "moment": moment })
        })
        .collect();
    request["loads"] = json!(loads);
    if let Some(k) = a.number("stiffness") {
        request["stiffness"] = json!(k);
    }
    if let Some(frame) = a.get("frame") {
        request["frame"] = json!(frame);
    }
    calls::statics(&model, request)
}

fn field(a: &Args, field: Value) -> Reply {
    if let Some(at) = a.get("at") {
        calls::field_vectors(field, points(at))
    } else if let Some(start) = a.get("descend") {
        calls::field_descend(
            field,
            json!(numbers(start)),
            a.number("step"),
            a.number("max-steps").map(|n| n as usize),
        )
    } else {
        calls::field_minima(field, json!(numbers(a.get("box").unwrap())))
    }
}

fn folder(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("kinolab-parity-{}-{name}", std::process::id()))
}

#[test]
fn every_command_prints_what_its_javascript_twin_returns() {
    let seeds = Seeds::load();
    let binary = PathBuf::from(env!("CARGO_BIN_EXE_kinolab"));
    let limits = Limits {
        time: std::time::Duration::from_secs(120),
        ..Limits::default()
    };
    let mut answered: BTreeMap<&str, u64> = BTreeMap::new();
    for (command, _) in COMMANDS.iter().filter(|(c, _)| *c != "usage") {
        for index in 0..CASES {
            let case = valid_case(&seeds, command, 2026, index);
            let out = run(&binary, &case, &folder(command), &limits).unwrap();
            let Some(js) = js(&case) else { continue };
            let cli = String::from_utf8_lossy(&out.stdout);
            match (out.status, js) {
                (Some(0), Ok(value)) => {
                    assert_eq!(
                        cli.trim_end(),
                        value.to_string(),
                        "{:?} and its JavaScript twin differ",
                        case.args
                    );
                    *answered.entry(command).or_default() += 1;
                }
                (Some(2), Err(_)) => {}
                (status, js) => panic!(
                    "{:?}: the command exited {status:?} ({}), JavaScript gave {js:?}",
                    case.args,
                    String::from_utf8_lossy(&out.stderr).trim()
                ),
            }
        }
        let _ = std::fs::remove_dir_all(folder(command));
    }
    for (command, _) in COMMANDS.iter().filter(|(c, _)| *c != "usage") {
        let n = answered.get(command).copied().unwrap_or(0);
        assert!(
            n >= 3,
            "`{command}` answered only {n} of {CASES} valid cases: {answered:?}"
        );
    }
}

#[test]
fn every_operation_has_a_command_and_a_javascript_function() {
    let readme =
        std::fs::read_to_string(kinolab_fuzz::seeds::workspace().join("README.md")).unwrap();
    let generated: Vec<&str> = COMMANDS.iter().map(|(c, _)| *c).collect();
    for op in kinolab_api::OPERATIONS {
        let command = op.command.split(' ').next().unwrap();
        assert!(
            generated.contains(&command),
            "the generators never call `{command}`"
        );
        let function = op.js.rsplit('.').next().unwrap();
        assert!(
            readme.contains(&format!("{function}(")),
            "the README does not show `{}`",
            op.js
        );
        assert!(
            readme.contains(&format!("kinolab {command}"))
                || readme.contains(&format!("-- {command}")),
            "the README does not show `kinolab {command}`"
        );
    }
}
