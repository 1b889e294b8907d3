//! Every JavaScript function on JSON values, as the wasm glue passes them
//! in: each builds the API's request from its arguments and returns the
//! API's report. They run natively too, so tests hold them to the command
//! line byte for byte.

use kinolab_api::mechanism::{self, Query};
use kinolab_api::{NoFiles, Operation, Source, behaviours, components, control, fields, legs};
use kinolab_api::{forces, plans, teach, wheels};
use kinolab_mechanism::Model;
use serde::de::DeserializeOwned;
use serde_json::Value;

/// A report as JSON, or the one-line error the function throws.
pub type Reply = Result<Value, String>;

/// Ask the API.
fn ask(operation: &impl Operation) -> Reply {
    kinolab_api::answer(operation, &mut NoFiles).map_err(|e| e.to_string())
}

/// Read an argument of type `T`, naming it when it does not fit.
pub fn arg<T: DeserializeOwned>(name: &str, value: Value) -> Result<T, String> {
    serde_json::from_value(value).map_err(|e| format!("{name}: {e}"))
}

/// A file-like argument: an object, JSON text or XML text (a URDF file) is
/// the file's text; any other string is a name (`catalogue:<id>`, an id, a
/// layout code).
pub fn source(value: Value) -> Source {
    match value {
        Value::String(text) if text.trim_start().starts_with(['{', '<']) => Source::Text(text),
        Value::String(name) => Source::Named(name),
        other => Source::Text(other.to_string()),
    }
}

pub fn leg_events(legs: u32) -> Reply {
    ask(&legs::LegEvents { legs })
}

pub fn static_stability(com: Value, feet: Value) -> Reply {
    ask(&legs::Stability {
        com: arg("com", com)?,
        feet: arg("feet", feet)?,
    })
}

pub fn gait(file: Value, samples: Option<usize>) -> Reply {
    ask(&legs::GaitCycle {
        gait: source(file),
        samples: samples.unwrap_or(100),
    })
}

pub fn cpg(file: Value) -> Reply {
    ask(&legs::Oscillators { cpg: source(file) })
}

pub fn zmp(run: Value) -> Reply {
    ask(&legs::Zmp { run: source(run) })
}

pub fn walk(
    gait: Value,
    lift: Option<f64>,
    samples: Option<usize>,
    stride: Option<f64>,
    sequencer: Option<String>,
) -> Reply {
    ask(&legs::Walk {
        gait: source(gait),
        lift: lift.unwrap_or(0.03),
        samples: samples.unwrap_or(60),
        stride,
        sequencer,
    })
}

pub fn ant_walk(beach: Value) -> Reply {
    ask(&teach::AntWalk {
        beach: source(beach),
    })
}

pub fn robots() -> Reply {
    ask(&wheels::Robots)
}

pub fn robot_file(robot: Value) -> Reply {
    ask(&wheels::RobotFile {
        robot: source(robot),
    })
}

pub fn analyze_robot(robot: Value) -> Reply {
    ask(&wheels::Analyze {
        robot: source(robot),
    })
}

pub fn drive_twist(robot: Value, twist: Value, theta: Option<f64>) -> Reply {
    ask(&wheels::DriveTwist {
        robot: source(robot),
        twist: arg("twist", twist)?,
        theta,
    })
}

pub fn drive_wheels(robot: Value, spins: Value, theta: Option<f64>) -> Reply {
    ask(&wheels::DriveWheels {
        robot: source(robot),
        spins: arg("spins", spins)?,
        theta,
    })
}

pub fn differential_drive(track: f64, v_left: f64, v_right: f64) -> Reply {
    ask(&wheels::DifferentialDrive {
        track,
        v_left,
        v_right,
    })
}

pub fn simulate(run: Value) -> Reply {
    ask(&control::Simulate { run: source(run) })
}

pub fn batch_simulate(
    run: Value,
    radius: f64,
    count: usize,
    heading_deg: f64,
    paths: Option<bool>,
) -> Reply {
    ask(&control::Batch {
        run: source(run),
        radius,
        count,
        heading_deg,
        paths: paths.unwrap_or(true),
    })
}

pub fn controller_stability(k_rho: f64, k_alpha: f64, k_beta: f64) -> Reply {
    ask(&control::ControllerStability {
        k_rho,
        k_alpha,
        k_beta,
    })
}

pub fn mechanisms() -> Reply {
    ask(&mechanism::Mechanisms)
}

/// A model loaded once, for the `Mechanism` class.
pub fn load_mechanism(model: Value) -> Result<Model, String> {
    mechanism::model(&source(model), &mut NoFiles).map_err(|e| e.to_string())
}

/// A question about a loaded model.
pub fn on(model: &Model, query: &impl Query) -> Reply {
    mechanism::answer_on(model, query).map_err(|e| e.to_string())
}

pub fn ik(model: &Model, request: Value) -> Reply {
    on(model, &arg::<mechanism::Ik>("request", request)?)
}

pub fn collide(model: &Model, q: Vec<f64>, plane: &str, obstacles: Value) -> Reply {
    let obstacles = match obstacles {
        Value::Null => Vec::new(),
        list => arg("obstacles", list)?,
    };
    on(
        model,
        &mechanism::Collide {
            q,
            plane: plane.to_owned(),
            obstacles,
        },
    )
}

pub fn field_vectors(field: Value, at: Value) -> Reply {
    ask(&fields::FieldVectors {
        field: source(field),
        at: arg("at", at)?,
    })
}

pub fn field_minima(field: Value, area: Value) -> Reply {
    ask(&fields::FieldMinima {
        field: source(field),
        area: arg("box", area)?,
    })
}

pub fn field_descend(
    field: Value,
    start: Value,
    step: Option<f64>,
    max_steps: Option<usize>,
) -> Reply {
    ask(&fields::FieldDescend {
        field: source(field),
        start: arg("start", start)?,
        step,
        max_steps,
    })
}

pub fn catalogues() -> Reply {
    ask(&fields::Catalogues)
}

pub fn run_behaviours(run: Value) -> Reply {
    ask(&behaviours::RunBehaviours { run: source(run) })
}

pub fn plan(world: Value, from: Value, to: Value, cell: f64, algorithm: Option<&str>) -> Reply {
    let algorithm = match algorithm.unwrap_or("astar") {
        "astar" => kinolab_world::search::Algorithm::AStar,
        "dijkstra" => kinolab_world::search::Algorithm::Dijkstra,
        other => return Err(format!("algorithm: `{other}` is not `astar` or `dijkstra`")),
    };
    ask(&plans::Plan {
        world: source(world),
        from: arg("from", from)?,
        to: arg("to", to)?,
        cell,
        algorithm,
    })
}

pub fn arena(world: Value, options: Value) -> Reply {
    let request = kinolab_common::error::from_json(&options.to_string())
        .map_err(|e| format!("options: {e}"))?;
    ask(&plans::Arena {
        world: source(world),
        request,
    })
}

pub fn routes(feeds: Value) -> Reply {
    ask(&plans::Routes {
        feeds: arg("feeds", feeds)?,
    })
}

pub fn components(system: Value, until: Option<f64>) -> Reply {
    ask(&components::Components {
        system: source(system),
        until,
    })
}

pub fn lessons() -> Reply {
    ask(&teach::Lessons::default())
}

pub fn check_lesson(file: &str, markdown: &str) -> Reply {
    ask(&teach::CheckLesson {
        file: file.to_owned(),
        markdown: markdown.to_owned(),
    })
}

pub fn widgets() -> Reply {
    ask(&teach::Widgets)
}

pub fn pick_cell(
    placement_error: f64,
    gripper_tolerance: f64,
    sensor_error: f64,
    count: u32,
    seed: u32,
) -> Reply {
    ask(&teach::PickCell {
        placement_error,
        gripper_tolerance,
        sensor_error,
        count,
        seed,
    })
}

pub fn exercises() -> Reply {
    ask(&kinolab_api::script::Exercises)
}

pub fn check_script(exercise: String, source: String, all: Option<bool>) -> Reply {
    ask(&kinolab_api::script::CheckScript {
        exercise,
        source,
        all: all.unwrap_or(false),
    })
}

/// `scripts`: an object of learners' scripts by name (`{ "ana.rhai": "fn …" }`).
pub fn grade_scripts(exercise: String, scripts: Value) -> Reply {
    let scripts: std::collections::BTreeMap<String, String> = arg("scripts", scripts)?;
    ask(&kinolab_api::script::Grade {
        exercise,
        scripts: scripts
            .into_iter()
            .map(|(file, text)| kinolab_api::script::Submission::text(file, text))
            .collect(),
    })
}

/// `{ q?, set?, … }`: every joint in order, or some by name.
fn posed(
    q: Option<Vec<f64>>,
    set: Option<std::collections::BTreeMap<String, f64>>,
) -> Result<forces::Joints, String> {
    match (q, set) {
        (Some(_), Some(_)) => Err("give `q` or `set`, not both".into()),
        (_, Some(set)) => Ok(forces::Joints::Named(set.into_iter().collect())),
        (q, None) => Ok(forces::Joints::All(q.unwrap_or_default())),
    }
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct DynamicsRequest {
    q: Option<Vec<f64>>,
    set: Option<std::collections::BTreeMap<String, f64>>,
    qd: Option<Vec<f64>>,
    qdd: Option<Vec<f64>>,
    tau: Option<Vec<f64>>,
    gravity: Option<[f64; 3]>,
}

/// `kinolab dynamics` for `{ q | set, qd?, qdd | tau, gravity? }`.
pub fn dynamics(model: &Model, request: Value) -> Reply {
    let r: DynamicsRequest = arg("request", request)?;
    let asked = match (r.qdd, r.tau) {
        (Some(qdd), None) => forces::Asked::Inverse { qdd },
        (None, Some(tau)) => forces::Asked::Forward { tau },
        _ => {
            return Err(
                "request: give `qdd` (inverse dynamics) or `tau` (forward), one of them".into(),
            );
        }
    };
    on(
        model,
        &forces::Dynamics {
            joints: posed(r.q, r.set)?,
            qd: r.qd,
            asked,
            gravity: r.gravity,
        },
    )
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct LoadRequest {
    frame: String,
    force: [f64; 3],
    #[serde(default)]
    moment: [f64; 3],
}

#[derive(serde::Deserialize)]
#[serde(untagged)]
enum StiffnessRequest {
    All(f64),
    Named(std::collections::BTreeMap<String, f64>),
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct StaticsRequest {
    q: Option<Vec<f64>>,
    set: Option<std::collections::BTreeMap<String, f64>>,
    #[serde(default)]
    loads: Vec<LoadRequest>,
    stiffness: Option<StiffnessRequest>,
    frame: Option<String>,
    gravity: Option<[f64; 3]>,
}

/// `kinolab statics` for `{ q | set, loads?: [{ frame, force, moment? }],
/// stiffness?: K | { NAME: K }, frame?, gravity? }`.
pub fn statics(model: &Model, request: Value) -> Reply {
    let r: StaticsRequest = arg("request", request)?;
    on(
        model,
        &forces::Statics {
            joints: posed(r.q, r.set)?,
            loads: r
                .loads
                .into_iter()
                .map(|l| forces::LoadSpec {
                    frame: l.frame,
                    force: l.force,
                    moment: l.moment,
                })
                .collect(),
            stiffness: r.stiffness.map(|k| match k {
                StiffnessRequest::All(k) => forces::Stiffness::All(k),
                StiffnessRequest::Named(set) => forces::Stiffness::Named(set.into_iter().collect()),
            }),
            frame: r.frame,
            gravity: r.gravity,
        },
    )
}
