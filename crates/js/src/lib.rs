//! Kinolab for JavaScript.
//!
//! ```js
//! import init, * as kinolab from "./pkg/kinolab_js.js";
//! await init();
//! kinolab.legEvents(6);                                  // "39916800"
//! kinolab.staticStability([0, 0], [[1, 1], [-1, 1], [0, -1]]);
//! kinolab.analyzeRobot("tricycle").degree_of_maneuverability; // 2
//! kinolab.driveWheels("f,-90,180,1,1;f,90,0,1,1", [4, 2]).twist; // [3, 0, 1]
//! kinolab.simulate({ controller: { kind: "polar", k_rho: 3, k_alpha: 8, k_beta: -1.5 },
//!   start: { x: -1, y: 0.5, theta_deg: 0 }, goal: { x: 0, y: 0, theta_deg: 0 } }).reached; // true
//! const arm = kinolab.Mechanism.load("catalogue:planar-2r");
//! arm.ik({ position: [1.2, 0.6, 0] }).converged;        // true
//! kinolab.fieldMinima("catalogue:u-shaped-wall", [0, -2.5, 7, 2.5]).minima.length; // 2
//! ```
//!
//! Every function computes with the same core crates as the lab and the
//! command line, through [`api`], and returns the same JSON (snake_case
//! fields) as the matching `kinolab` command. Bad input throws an `Error`
//! whose message names the field.

pub mod api;
pub mod architecture_api;
pub mod behaviour_api;
pub mod legs_api;
mod mechanism;
pub mod mechanism_api;

pub use mechanism::{Mechanism, mechanisms};
use serde::Serialize;
use serde_json::Value;
use wasm_bindgen::prelude::*;

use api::Reply;

/// An error to throw: the command line's one-line message.
fn thrown(message: &str) -> JsError {
    JsError::new(&kinolab_common::error::one_line(message))
}

/// A reply as a JavaScript value (plain objects, `null` for none).
fn to_js(reply: Reply) -> Result<JsValue, JsError> {
    let value = reply.map_err(|e| thrown(&e))?;
    value
        .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| thrown(&format!("result: {e}")))
}

/// A JavaScript argument as JSON, naming the argument if it cannot be.
fn from_js(name: &str, value: JsValue) -> Result<Value, JsError> {
    if value.is_undefined() {
        return Ok(Value::Null);
    }
    serde_wasm_bindgen::from_value(value).map_err(|e| thrown(&format!("{name}: {e}")))
}

/// A typed JavaScript argument.
fn typed<T: serde::de::DeserializeOwned>(name: &str, value: JsValue) -> Result<T, JsError> {
    api::arg(name, from_js(name, value)?).map_err(|e| thrown(&e))
}

/// The package version.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_owned()
}

/// N = (2k − 1)!, as a decimal string (it outgrows JavaScript numbers).
#[wasm_bindgen(js_name = legEvents)]
pub fn leg_events(legs: u32) -> Result<String, JsError> {
    let report = api::leg_events(legs).map_err(|e| thrown(&e))?;
    Ok(report["events"].as_str().unwrap_or_default().to_owned())
}

/// Static stability, as `kinolab stability`: `com` is `[x, y]`, `feet` an
/// array of `[x, y]` (metres). Returns `{ stable, margin, support_polygon,
/// nearest_edge_point }`.
#[wasm_bindgen(js_name = staticStability)]
pub fn static_stability(com: JsValue, feet: JsValue) -> Result<JsValue, JsError> {
    let com: [f64; 2] = typed("com", com)?;
    let feet: Vec<[f64; 2]> = typed("feet", feet)?;
    to_js(api::static_stability(com, &feet))
}

/// The pick-and-place cell: lengths in metres, `count` parts from `seed`.
/// Returns `{ scripted_success, sensing_success, scripted_grasped,
/// sensing_grasped, parts }`.
#[wasm_bindgen(js_name = pickCell)]
pub fn pick_cell(
    placement_error: f64,
    gripper_tolerance: f64,
    sensor_error: f64,
    count: u32,
    seed: u32,
) -> Result<JsValue, JsError> {
    to_js(api::pick_cell(
        placement_error,
        gripper_tolerance,
        sensor_error,
        count,
        seed,
    ))
}

/// Every embedded lesson: `[{ address, title, minutes, objectives, quizzes, widgets }]`.
#[wasm_bindgen]
pub fn lessons() -> Result<JsValue, JsError> {
    to_js(api::lessons())
}

/// Every widget a lesson can embed (and the gallery at `#/gallery/<name>`
/// shows alone): `[{ name, summary, params: [{ name, kind, default, help }] }]`.
#[wasm_bindgen]
pub fn widgets() -> Result<JsValue, JsError> {
    to_js(api::widgets())
}

/// Check a lesson's Markdown as the lesson checker does (widgets and their
/// parameters included): its summary, or an error naming `file` and line.
#[wasm_bindgen(js_name = checkLesson)]
pub fn check_lesson(file: &str, markdown: &str) -> Result<JsValue, JsError> {
    to_js(api::check_lesson(file, markdown))
}

// ---------------------------------------------------------------- wheels

/// The catalogue: `[{ id, name, summary }]`.
#[wasm_bindgen]
pub fn robots() -> Result<JsValue, JsError> {
    to_js(api::robots())
}

/// A robot as a robot-file object (degrees, as people write them). The
/// robot may be an object, JSON text, a compact layout code, or a
/// catalogue id (`tricycle` or `catalogue:tricycle`).
#[wasm_bindgen(js_name = robotFile)]
pub fn robot_file(robot: JsValue) -> Result<JsValue, JsError> {
    to_js(api::robot_file(from_js("robot", robot)?))
}

/// What `kinolab analyze` prints: `{ rank_c1, degree_of_mobility,
/// degree_of_steerability, degree_of_maneuverability, dof, holonomic, icr, … }`.
#[wasm_bindgen(js_name = analyzeRobot)]
pub fn analyze_robot(robot: JsValue) -> Result<JsValue, JsError> {
    to_js(api::analyze_robot(from_js("robot", robot)?))
}

/// Inverse kinematics, as `kinolab drive --twist`: `twist` is
/// `[vx, vy, omega]` in the robot frame; `theta` (optional, rad) adds the
/// inertial motion.
#[wasm_bindgen(js_name = driveTwist)]
pub fn drive_twist(robot: JsValue, twist: JsValue, theta: Option<f64>) -> Result<JsValue, JsError> {
    let twist: [f64; 3] = typed("twist", twist)?;
    to_js(api::drive_twist(from_js("robot", robot)?, twist, theta))
}

/// Forward kinematics, as `kinolab drive --wheels`: one spin per wheel
/// (rad/s), `null` where unknown.
#[wasm_bindgen(js_name = driveWheels)]
pub fn drive_wheels(
    robot: JsValue,
    spins: JsValue,
    theta: Option<f64>,
) -> Result<JsValue, JsError> {
    let spins: Vec<Option<f64>> = typed("spins", spins)?;
    to_js(api::drive_wheels(from_js("robot", robot)?, &spins, theta))
}

/// Differential drive closed form: `{ v, omega, radius }` (radius `null`
/// when driving straight) from the wheel separation and ground speeds.
#[wasm_bindgen(js_name = differentialDrive)]
pub fn differential_drive(track: f64, v_left: f64, v_right: f64) -> Result<JsValue, JsError> {
    to_js(api::differential_drive(track, v_left, v_right))
}

// ---------------------------------------------------------------- control

/// What `kinolab simulate` prints, for a run-file object (or its JSON
/// text): `{ samples: [{ t, x, y, theta_deg, v, omega, … }], reached,
/// time_to_goal, final, … }`.
#[wasm_bindgen]
pub fn simulate(run: JsValue) -> Result<JsValue, JsError> {
    to_js(api::simulate(from_js("run", run)?))
}

/// What `kinolab batch --paths` prints: the run from `count` starts on a
/// circle of `radius` around its goal, all with heading `heading_deg`.
#[wasm_bindgen(js_name = batchSimulate)]
pub fn batch_simulate(
    run: JsValue,
    radius: f64,
    count: usize,
    heading_deg: f64,
) -> Result<JsValue, JsError> {
    to_js(api::batch_simulate(
        from_js("run", run)?,
        radius,
        count,
        heading_deg,
    ))
}

/// What `kinolab gains` prints: `{ locally_stable, strongly_stable,
/// conditions, eigenvalues, linearised, explanation }`.
#[wasm_bindgen(js_name = controllerStability)]
pub fn controller_stability(k_rho: f64, k_alpha: f64, k_beta: f64) -> Result<JsValue, JsError> {
    to_js(api::controller_stability(k_rho, k_alpha, k_beta))
}

// ---------------------------------------------------------------- behaviours

/// What `kinolab field --at` prints: `{ vectors: [[fx, fy], …] }`, one per
/// point, for a field-file object, its JSON text, or `"catalogue:<id>"`.
#[wasm_bindgen(js_name = fieldVectors)]
pub fn field_vectors(field: JsValue, at: JsValue) -> Result<JsValue, JsError> {
    let at: Vec<[f64; 2]> = typed("at", at)?;
    to_js(behaviour_api::field_vectors(from_js("field", field)?, &at))
}

/// What `kinolab field --minima --box` prints: `{ minima: [{ x, y, goal }] }`.
#[wasm_bindgen(js_name = fieldMinima)]
pub fn field_minima(field: JsValue, area: JsValue) -> Result<JsValue, JsError> {
    let area: [f64; 4] = typed("box", area)?;
    to_js(behaviour_api::field_minima(from_js("field", field)?, area))
}

/// What `kinolab field --descend` prints: `{ path, outcome, end }`.
/// `step` (m) and `maxSteps` may be left out (0.01 m, 10 000 steps).
#[wasm_bindgen(js_name = fieldDescend)]
pub fn field_descend(
    field: JsValue,
    start: JsValue,
    step: Option<f64>,
    max_steps: Option<usize>,
) -> Result<JsValue, JsError> {
    let start: [f64; 2] = typed("start", start)?;
    to_js(behaviour_api::field_descend(
        from_js("field", field)?,
        start,
        step,
        max_steps,
    ))
}

/// What `kinolab run` prints for a behaviour run file (object or JSON
/// text): `{ samples, control, events, metrics }`.
#[wasm_bindgen(js_name = runBehaviours)]
pub fn run_behaviours(run: JsValue) -> Result<JsValue, JsError> {
    to_js(behaviour_api::run_behaviours(from_js("run", run)?))
}

/// The example worlds' ids and the classic fields: `{ worlds, fields }`.
#[wasm_bindgen]
pub fn catalogues() -> Result<JsValue, JsError> {
    to_js(behaviour_api::catalogues())
}

// ---------------------------------------------------------------- legs and plans

/// What `kinolab gait` prints for a gait file (object or JSON text):
/// `{ samples: [{ tau, stance, feet, margin }], min_margin, statically_stable }`.
/// `samples` defaults to 100.
#[wasm_bindgen]
pub fn gait(file: JsValue, samples: Option<usize>) -> Result<JsValue, JsError> {
    to_js(legs_api::gait(
        from_js("gait", file)?,
        samples.unwrap_or(100),
    ))
}

/// What `kinolab cpg` prints for a CPG file: `{ final_deg, lag, locked }`.
#[wasm_bindgen]
pub fn cpg(file: JsValue) -> Result<JsValue, JsError> {
    to_js(legs_api::cpg(from_js("cpg", file)?))
}

/// What `kinolab plan` prints: `{ cost, cells, points }` (`cost` null when
/// no path), for a world file (object, JSON text, or `"catalogue:<id>"`).
#[wasm_bindgen]
pub fn plan(world: JsValue, from: JsValue, to: JsValue, cell: f64) -> Result<JsValue, JsError> {
    let from: [f64; 2] = typed("from", from)?;
    let to: [f64; 2] = typed("to", to)?;
    to_js(legs_api::plan(from_js("world", world)?, from, to, cell))
}

// ---------------------------------------------------------------- architectures

/// What `kinolab arena` prints: `{ architecture, surprises, samples, events,
/// metrics }` for a world (object, JSON text, or `"catalogue:<id>"`) and
/// `{ architecture, perturb?, planning_cost_ms?, duration?, seed?, every? }`.
#[wasm_bindgen]
pub fn arena(world: JsValue, options: JsValue) -> Result<JsValue, JsError> {
    to_js(architecture_api::arena(
        from_js("world", world)?,
        from_js("options", options)?,
    ))
}

/// What `kinolab components` prints: `{ name, seed, until, trace,
/// components, counts, quiet_ports, robot?, complete }` for a system file
/// (object, JSON text, or `"example:<id>"`), run until `until` seconds (the
/// file's `until` when undefined).
#[wasm_bindgen]
pub fn components(system: JsValue, until: Option<f64>) -> Result<JsValue, JsError> {
    to_js(architecture_api::components(
        from_js("system", system)?,
        until,
    ))
}

/// Sensing routes: `{ routes, paradigm }` for `feeds[sensor][function]`.
#[wasm_bindgen]
pub fn routes(feeds: JsValue) -> Result<JsValue, JsError> {
    to_js(architecture_api::routes(from_js("feeds", feeds)?))
}
