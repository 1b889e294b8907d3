//! Kinolab for JavaScript.
//!
//! ```js
//! import init, * as kinolab from "./pkg/kinolab_js.js";
//! await init();
//! kinolab.legEvents(6).events;                           // "39916800"
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
//! This crate is glue: each function turns its JavaScript arguments into
//! JSON, hands them to [`calls`] (which builds the lab API's request and
//! asks it), and returns the report as plain objects, the same JSON as the
//! matching `kinolab` command. Bad input throws an `Error` whose message
//! names the argument and the field.

pub mod calls;
mod mechanism;

pub use mechanism::{Mechanism, mechanisms};
use serde::Serialize;
use serde_json::Value;
use wasm_bindgen::prelude::*;

use calls::Reply;

/// An error to throw: one line.
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

/// The package version.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_owned()
}

// ---------------------------------------------------------------- legs

/// What `kinolab leg-events` prints: `{ legs, events, events_f64 }`, N =
/// (2k − 1)! exactly as a decimal string (it outgrows JavaScript numbers).
#[wasm_bindgen(js_name = legEvents)]
pub fn leg_events(legs: u32) -> Result<JsValue, JsError> {
    to_js(calls::leg_events(legs))
}

/// Static stability, as `kinolab stability`: `com` is `[x, y]`, `feet` an
/// array of `[x, y]` (metres). Returns `{ stable, margin, support_polygon,
/// nearest_edge_point }`.
#[wasm_bindgen(js_name = staticStability)]
pub fn static_stability(com: JsValue, feet: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::static_stability(
        from_js("com", com)?,
        from_js("feet", feet)?,
    ))
}

/// What `kinolab gait` prints for a gait file (object or JSON text) or a
/// named gait (`catalogue:hexapod-tripod`): `{ samples: [{ tau, stance,
/// feet, margin }], min_margin, statically_stable }`. `samples` defaults to 100.
#[wasm_bindgen]
pub fn gait(file: JsValue, samples: Option<usize>) -> Result<JsValue, JsError> {
    to_js(calls::gait(from_js("gait", file)?, samples))
}

/// What `kinolab cpg` prints for a CPG file: `{ final_deg, lag, locked }`.
#[wasm_bindgen]
pub fn cpg(file: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::cpg(from_js("cpg", file)?))
}

/// What `kinolab zmp` prints for a push-recovery file (object or JSON
/// text): `{ samples: [{ t, x, xd, xdd, zmp, wanted, inside }], recovered,
/// left_foot_at }`.
#[wasm_bindgen]
pub fn zmp(run: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::zmp(from_js("run", run)?))
}

/// What `kinolab walk` prints: the hexapod walking a six-legged gait
/// (file or `"catalogue:<id>"`) through one cycle, `{ gait, stride, lift,
/// steps: [{ tau, q, targets, errors, unreachable, stance, margin }],
/// min_margin, progress }`; `lift` (m), `samples` and `stride` (m) may be
/// left out (0.03, 60, the gait's); `sequencer` is a learner's leg
/// sequencer's code (`foot(leg, phase)`).
#[wasm_bindgen]
pub fn walk(
    gait: JsValue,
    lift: Option<f64>,
    samples: Option<usize>,
    stride: Option<f64>,
    sequencer: Option<String>,
) -> Result<JsValue, JsError> {
    to_js(calls::walk(
        from_js("gait", gait)?,
        lift,
        samples,
        stride,
        sequencer,
    ))
}

// ---------------------------------------------------------------- wheels

/// The catalogue: `[{ id, name, summary }]`.
#[wasm_bindgen]
pub fn robots() -> Result<JsValue, JsError> {
    to_js(calls::robots())
}

/// A robot as a robot-file object (degrees, as people write them). The
/// robot may be an object, JSON text, a compact layout code, or a
/// catalogue id (`tricycle` or `catalogue:tricycle`).
#[wasm_bindgen(js_name = robotFile)]
pub fn robot_file(robot: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::robot_file(from_js("robot", robot)?))
}

/// What `kinolab analyze` prints: `{ rank_c1, degree_of_mobility,
/// degree_of_steerability, degree_of_maneuverability, dof, holonomic, icr, … }`.
#[wasm_bindgen(js_name = analyzeRobot)]
pub fn analyze_robot(robot: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::analyze_robot(from_js("robot", robot)?))
}

/// Inverse kinematics, as `kinolab drive --twist`: `twist` is
/// `[vx, vy, omega]` in the robot frame; `theta` (optional, rad) adds the
/// inertial motion.
#[wasm_bindgen(js_name = driveTwist)]
pub fn drive_twist(robot: JsValue, twist: JsValue, theta: Option<f64>) -> Result<JsValue, JsError> {
    to_js(calls::drive_twist(
        from_js("robot", robot)?,
        from_js("twist", twist)?,
        theta,
    ))
}

/// Forward kinematics, as `kinolab drive --wheels`: one spin per wheel
/// (rad/s), `null` where unknown.
#[wasm_bindgen(js_name = driveWheels)]
pub fn drive_wheels(
    robot: JsValue,
    spins: JsValue,
    theta: Option<f64>,
) -> Result<JsValue, JsError> {
    to_js(calls::drive_wheels(
        from_js("robot", robot)?,
        from_js("spins", spins)?,
        theta,
    ))
}

/// What `kinolab differential-drive` prints: `{ v, omega, radius }`
/// (radius `null` when driving straight) from the wheel separation and
/// the wheels' ground speeds.
#[wasm_bindgen(js_name = differentialDrive)]
pub fn differential_drive(track: f64, v_left: f64, v_right: f64) -> Result<JsValue, JsError> {
    to_js(calls::differential_drive(track, v_left, v_right))
}

// ---------------------------------------------------------------- control

/// What `kinolab simulate` prints, for a run-file object (or its JSON
/// text): `{ samples: [{ t, x, y, theta_deg, v, omega, … }], reached,
/// time_to_goal, final, … }`.
#[wasm_bindgen]
pub fn simulate(run: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::simulate(from_js("run", run)?))
}

/// What `kinolab batch` prints: the run from `count` starts on a circle of
/// `radius` around its goal, all with heading `heading_deg`; each run's
/// path unless `paths` is false.
#[wasm_bindgen(js_name = batchSimulate)]
pub fn batch_simulate(
    run: JsValue,
    radius: f64,
    count: usize,
    heading_deg: f64,
    paths: Option<bool>,
) -> Result<JsValue, JsError> {
    to_js(calls::batch_simulate(
        from_js("run", run)?,
        radius,
        count,
        heading_deg,
        paths,
    ))
}

/// What `kinolab gains` prints: `{ locally_stable, strongly_stable,
/// conditions, eigenvalues, linearised, explanation }`.
#[wasm_bindgen(js_name = controllerStability)]
pub fn controller_stability(k_rho: f64, k_alpha: f64, k_beta: f64) -> Result<JsValue, JsError> {
    to_js(calls::controller_stability(k_rho, k_alpha, k_beta))
}

// ---------------------------------------------------------------- fields and behaviours

/// What `kinolab field --at` prints: `{ vectors: [[fx, fy], …] }`, one per
/// point, for a field-file object, its JSON text, or `"catalogue:<id>"`.
#[wasm_bindgen(js_name = fieldVectors)]
pub fn field_vectors(field: JsValue, at: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::field_vectors(
        from_js("field", field)?,
        from_js("at", at)?,
    ))
}

/// What `kinolab field --minima --box` prints: `{ minima: [{ x, y, goal }] }`.
#[wasm_bindgen(js_name = fieldMinima)]
pub fn field_minima(field: JsValue, area: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::field_minima(
        from_js("field", field)?,
        from_js("box", area)?,
    ))
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
    to_js(calls::field_descend(
        from_js("field", field)?,
        from_js("start", start)?,
        step,
        max_steps,
    ))
}

/// What `kinolab catalogues` prints: the example worlds' ids and the
/// classic fields, `{ worlds, fields: [{ id, title, shows }] }`.
#[wasm_bindgen]
pub fn catalogues() -> Result<JsValue, JsError> {
    to_js(calls::catalogues())
}

/// What `kinolab run` prints for a behaviour run file (object or JSON
/// text): `{ samples, control, events, metrics }`.
#[wasm_bindgen(js_name = runBehaviours)]
pub fn run_behaviours(run: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::run_behaviours(from_js("run", run)?))
}

// ---------------------------------------------------------------- plans, architectures, components

/// What `kinolab plan` prints: `{ cost, cells, points, expanded }` (`cost`
/// null when no path), for a world file (object, JSON text, or
/// `"catalogue:<id>"`); `algorithm` is `"astar"` (default) or `"dijkstra"`.
#[wasm_bindgen]
pub fn plan(
    world: JsValue,
    from: JsValue,
    to: JsValue,
    cell: f64,
    algorithm: Option<String>,
) -> Result<JsValue, JsError> {
    to_js(calls::plan(
        from_js("world", world)?,
        from_js("from", from)?,
        from_js("to", to)?,
        cell,
        algorithm.as_deref(),
    ))
}

/// What `kinolab arena` prints: `{ architecture, surprises, samples, events,
/// metrics }` for a world (object, JSON text, or `"catalogue:<id>"`) and
/// `{ architecture, perturb?, planning_cost_ms?, duration?, seed?, every? }`.
#[wasm_bindgen]
pub fn arena(world: JsValue, options: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::arena(
        from_js("world", world)?,
        from_js("options", options)?,
    ))
}

/// What `kinolab routes` prints: `{ routes, paradigm }` for
/// `feeds[sensor][function]` (6 × 5 booleans).
#[wasm_bindgen]
pub fn routes(feeds: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::routes(from_js("feeds", feeds)?))
}

/// What `kinolab components` prints: `{ name, seed, until, trace,
/// components, counts, quiet_ports, robot?, complete }` for a system file
/// (object, JSON text, or `"example:<id>"`), run until `until` seconds (the
/// file's `until` when undefined).
#[wasm_bindgen]
pub fn components(system: JsValue, until: Option<f64>) -> Result<JsValue, JsError> {
    to_js(calls::components(from_js("system", system)?, until))
}

// ---------------------------------------------------------------- lessons, widgets, automation

/// What `kinolab lessons` prints: `{ ok, units: [{ unit, title, lessons:
/// [{ address, title, minutes, objectives, quizzes, widgets }] }] }`.
#[wasm_bindgen]
pub fn lessons() -> Result<JsValue, JsError> {
    to_js(calls::lessons())
}

/// What `kinolab check-lesson` prints: a lesson's Markdown checked as the
/// lesson checker does (widgets and their parameters included), its
/// summary, or an error naming `file` and the line.
#[wasm_bindgen(js_name = checkLesson)]
pub fn check_lesson(file: &str, markdown: &str) -> Result<JsValue, JsError> {
    to_js(calls::check_lesson(file, markdown))
}

/// What `kinolab widgets` prints: every widget a lesson can embed (and the
/// gallery at `#/gallery/<name>` shows alone), `[{ name, summary, params:
/// [{ name, kind, default, help }] }]`.
#[wasm_bindgen]
pub fn widgets() -> Result<JsValue, JsError> {
    to_js(calls::widgets())
}

/// What `kinolab ant` prints for an ant's walk file (object or JSON text):
/// `{ size, path, length, tortuosity, turns, reached, obstacles }`.
#[wasm_bindgen(js_name = antWalk)]
pub fn ant_walk(beach: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::ant_walk(from_js("beach", beach)?))
}

/// What `kinolab pick-cell` prints: the pick-and-place cell with lengths in
/// metres, `count` parts from `seed`: `{ scripted_success,
/// sensing_success, scripted_grasped, sensing_grasped, parts }`.
#[wasm_bindgen(js_name = pickCell)]
pub fn pick_cell(
    placement_error: f64,
    gripper_tolerance: f64,
    sensor_error: f64,
    count: u32,
    seed: u32,
) -> Result<JsValue, JsError> {
    to_js(calls::pick_cell(
        placement_error,
        gripper_tolerance,
        sensor_error,
        count,
        seed,
    ))
}

// ---------------------------------------------------------------- code exercises

/// What `kinolab script exercises` prints: every graded code exercise,
/// `[{ id, unit, lesson, hook, signature, returns, title, task, starter,
/// hints, visible, held_back }]`.
#[wasm_bindgen]
pub fn exercises() -> Result<JsValue, JsError> {
    to_js(calls::exercises())
}

/// What `kinolab script check` prints for a learner's `source`: `{
/// exercise, passed, worlds: [{ name, visible, passed, reason, time,
/// metrics, error }], held_back: { passed, of }, error }`, the visible
/// worlds in full. With `all` true (`--all`), every world in full.
#[wasm_bindgen(js_name = checkScript)]
pub fn check_script(
    exercise: String,
    source: String,
    all: Option<bool>,
) -> Result<JsValue, JsError> {
    to_js(calls::check_script(exercise, source, all))
}

/// What `kinolab script grade` prints: one row per script of `scripts`
/// (an object of sources by name), `[{ file, passed, visible: [P, N],
/// held_back: [P, N], error_kind, first_failure }]`.
#[wasm_bindgen(js_name = gradeScripts)]
pub fn grade_scripts(exercise: String, scripts: JsValue) -> Result<JsValue, JsError> {
    to_js(calls::grade_scripts(exercise, from_js("scripts", scripts)?))
}
