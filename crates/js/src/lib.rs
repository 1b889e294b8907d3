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
//! ```
//!
//! Every function computes with the same core crates as the lab and the
//! command line. Bad input throws an `Error` whose message names the field.

mod mechanism;

pub use mechanism::{Mechanism, mechanisms};
use serde::Serialize;
use wasm_bindgen::prelude::*;

fn to_js<T: Serialize>(value: &T) -> Result<JsValue, JsError> {
    serde_wasm_bindgen::to_value(value).map_err(|e| JsError::new(&format!("result: {e}")))
}

fn from_js<T: serde::de::DeserializeOwned>(field: &str, value: JsValue) -> Result<T, JsError> {
    serde_wasm_bindgen::from_value(value).map_err(|e| JsError::new(&format!("{field}: {e}")))
}

/// The package version.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_owned()
}

/// N = (2k − 1)!, as a decimal string (it outgrows JavaScript numbers).
#[wasm_bindgen(js_name = legEvents)]
pub fn leg_events(legs: u32) -> Result<String, JsError> {
    kinolab_locomotion::leg_events(legs)
        .map(|n| n.to_string())
        .map_err(|e| JsError::new(&e.to_string()))
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct StabilityJs {
    stable: bool,
    margin: f64,
    support_polygon: Vec<[f64; 2]>,
    nearest_edge_point: [f64; 2],
}

/// Static stability: `com` is `[x, y]`, `feet` an array of `[x, y]` (metres).
/// Returns `{ stable, margin, supportPolygon, nearestEdgePoint }`.
#[wasm_bindgen(js_name = staticStability)]
pub fn static_stability(com: JsValue, feet: JsValue) -> Result<JsValue, JsError> {
    let com: [f64; 2] = from_js("com", com)?;
    let feet: Vec<[f64; 2]> = from_js("feet", feet)?;
    let s = kinolab_locomotion::static_stability(com, &feet)
        .map_err(|e| JsError::new(&e.to_string()))?;
    to_js(&StabilityJs {
        stable: s.stable,
        margin: s.margin,
        support_polygon: s.polygon,
        nearest_edge_point: s.nearest,
    })
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct PickRunJs {
    scripted_success: f64,
    sensing_success: f64,
    scripted_grasped: usize,
    sensing_grasped: usize,
    parts: Vec<[f64; 2]>,
}

/// The pick-and-place cell: lengths in metres, `count` parts from `seed`.
#[wasm_bindgen(js_name = pickCell)]
pub fn pick_cell(
    placement_error: f64,
    gripper_tolerance: f64,
    sensor_error: f64,
    count: u32,
    seed: u32,
) -> Result<JsValue, JsError> {
    let cell = kinolab_autonomy::PickCell::new(placement_error, gripper_tolerance, sensor_error)
        .map_err(|e| JsError::new(&e.to_string()))?;
    let trials = cell.run(count.min(100_000) as usize, u64::from(seed));
    to_js(&PickRunJs {
        scripted_success: cell.scripted_success(),
        sensing_success: cell.sensing_success(),
        scripted_grasped: trials.iter().filter(|t| t.scripted_grasped).count(),
        sensing_grasped: trials.iter().filter(|t| t.sensing_grasped).count(),
        parts: trials.iter().map(|t| t.part).collect(),
    })
}

#[derive(Serialize)]
struct LessonJs {
    address: String,
    title: String,
    minutes: u32,
    objectives: Vec<String>,
    quizzes: usize,
    widgets: Vec<String>,
}

fn describe(address: String, lesson: &kinolab_lessons::Lesson) -> LessonJs {
    use kinolab_lessons::Block;
    LessonJs {
        address,
        title: lesson.meta.title.clone(),
        minutes: lesson.meta.minutes,
        objectives: lesson.meta.objectives.clone(),
        quizzes: lesson
            .blocks
            .iter()
            .filter(|b| matches!(b, Block::Quiz(_)))
            .count(),
        widgets: lesson
            .blocks
            .iter()
            .filter_map(|b| match b {
                Block::Widget(w) => Some(w.name.clone()),
                _ => None,
            })
            .collect(),
    }
}

/// Every embedded lesson: `[{ address, title, minutes, objectives, quizzes, widgets }]`.
#[wasm_bindgen]
pub fn lessons() -> Result<JsValue, JsError> {
    let course = kinolab_lessons::bundled::course().map_err(|e| JsError::new(&e.to_string()))?;
    let list: Vec<LessonJs> = course
        .units
        .iter()
        .flat_map(|u| {
            u.lessons
                .iter()
                .map(move |l| describe(format!("{}/{}", u.slug, l.slug), l))
        })
        .collect();
    to_js(&list)
}

/// Parse a lesson's Markdown (for authors' tools): returns its description,
/// or throws an error naming `file` and the line.
#[wasm_bindgen(js_name = checkLesson)]
pub fn check_lesson(file: &str, markdown: &str) -> Result<JsValue, JsError> {
    let (meta, blocks) =
        kinolab_lessons::parse_lesson(file, markdown).map_err(|e| JsError::new(&e.to_string()))?;
    let lesson = kinolab_lessons::Lesson {
        slug: String::new(),
        meta,
        blocks,
    };
    to_js(&describe(file.to_owned(), &lesson))
}

// ---------------------------------------------------------------- wheels

/// A robot from JavaScript: a robot-file object, a robot file as JSON text,
/// a compact layout code (`f,90,0,0.25,0.1;...`) or a catalogue id.
fn chassis(robot: JsValue) -> Result<kinolab_wheels::Chassis, JsError> {
    use kinolab_wheels::{Chassis, catalogue};
    let fail = |e: kinolab_wheels::WheelsError| JsError::new(&format!("robot: {e}"));
    if let Some(text) = robot.as_string() {
        let text = text.trim();
        return if text.starts_with('{') {
            Chassis::from_json(text).map_err(fail)
        } else if text.contains(',') {
            Chassis::from_compact("layout", text).map_err(fail)
        } else {
            catalogue::robot(text).map_err(fail)
        };
    }
    let value: serde_json::Value = from_js("robot", robot)?;
    Chassis::from_json(&value.to_string()).map_err(fail)
}

fn json_to_js(value: &serde_json::Value) -> Result<JsValue, JsError> {
    value
        .serialize(&serde_wasm_bindgen::Serializer::json_compatible())
        .map_err(|e| JsError::new(&format!("result: {e}")))
}

/// The catalogue: `[{ id, name, summary }]`.
#[wasm_bindgen]
pub fn robots() -> Result<JsValue, JsError> {
    let list: Vec<serde_json::Value> = kinolab_wheels::catalogue::CATALOGUE
        .iter()
        .map(|e| serde_json::json!({ "id": e.id, "name": e.name, "summary": e.summary }))
        .collect();
    json_to_js(&serde_json::Value::Array(list))
}

/// A catalogue robot as a robot-file object (degrees, as people write them).
#[wasm_bindgen(js_name = robotFile)]
pub fn robot_file(robot: JsValue) -> Result<JsValue, JsError> {
    let text = chassis(robot)?.to_json();
    let value: serde_json::Value =
        serde_json::from_str(&text).map_err(|e| JsError::new(&format!("robot: {e}")))?;
    json_to_js(&value)
}

/// What `kinolab analyze` prints: `{ rank_c1, degree_of_mobility,
/// degree_of_steerability, degree_of_maneuverability, dof, holonomic, icr, … }`.
#[wasm_bindgen(js_name = analyzeRobot)]
pub fn analyze_robot(robot: JsValue) -> Result<JsValue, JsError> {
    json_to_js(&kinolab_wheels::report::analysis(&chassis(robot)?))
}

/// Inverse kinematics, as `kinolab drive --twist`: `twist` is
/// `[vx, vy, omega]` in the robot frame; `theta` (optional, rad) adds the
/// inertial motion.
#[wasm_bindgen(js_name = driveTwist)]
pub fn drive_twist(robot: JsValue, twist: JsValue, theta: Option<f64>) -> Result<JsValue, JsError> {
    let chassis = chassis(robot)?;
    let [x, y, w]: [f64; 3] = from_js("twist", twist)?;
    let report =
        kinolab_wheels::report::inverse(&chassis, kinolab_wheels::Vector3::new(x, y, w), theta)
            .map_err(|e| JsError::new(&e.to_string()))?;
    json_to_js(&report)
}

/// Forward kinematics, as `kinolab drive --wheels`: one spin per wheel
/// (rad/s), `null` where unknown.
#[wasm_bindgen(js_name = driveWheels)]
pub fn drive_wheels(
    robot: JsValue,
    spins: JsValue,
    theta: Option<f64>,
) -> Result<JsValue, JsError> {
    let chassis = chassis(robot)?;
    let spins: Vec<Option<f64>> = from_js("spins", spins)?;
    let report = kinolab_wheels::report::forward(&chassis, &spins, theta)
        .map_err(|e| JsError::new(&e.to_string()))?;
    json_to_js(&report)
}

/// Differential drive closed form: `{ v, omega, radius }` (radius `null`
/// when driving straight) from the wheel separation and ground speeds.
#[wasm_bindgen(js_name = differentialDrive)]
pub fn differential_drive(track: f64, v_left: f64, v_right: f64) -> Result<JsValue, JsError> {
    let m = kinolab_wheels::closed_form::differential_drive(track, v_left, v_right)
        .map_err(|e| JsError::new(&e.to_string()))?;
    json_to_js(&serde_json::json!({ "v": m.v, "omega": m.omega, "radius": m.radius }))
}

/// A run given as a run-file object or as JSON text.
fn run_spec(run: JsValue) -> Result<kinolab_control::file::RunSpec, JsError> {
    let text = match run.as_string() {
        Some(text) => text,
        None => {
            let value: serde_json::Value = from_js("run", run)?;
            value.to_string()
        }
    };
    kinolab_control::file::from_json(&text).map_err(|e| JsError::new(&e.to_string()))
}

/// What `kinolab simulate` prints, for a run-file object (or its JSON
/// text): `{ samples: [{ t, x, y, theta_deg, v, omega, … }], reached,
/// time_to_goal, final, … }`.
#[wasm_bindgen]
pub fn simulate(run: JsValue) -> Result<JsValue, JsError> {
    let spec = run_spec(run)?;
    let t = spec
        .run
        .simulate()
        .map_err(|e| JsError::new(&e.to_string()))?;
    json_to_js(&kinolab_control::report::simulation(&spec, &t))
}

/// The run from `count` starts on a circle of `radius` around its goal,
/// all with heading `headingDeg`: `{ runs: [{ start, reached, time_to_goal,
/// final, path }], all_reached, reached, slowest_time_to_goal }`.
#[wasm_bindgen(js_name = batchSimulate)]
pub fn batch_simulate(
    run: JsValue,
    radius: f64,
    count: usize,
    heading_deg: f64,
) -> Result<JsValue, JsError> {
    let spec = run_spec(run)?;
    let report = kinolab_control::report::circle_batch(&spec, radius, count, heading_deg, true)
        .map_err(|e| JsError::new(&e.to_string()))?;
    json_to_js(&report)
}

/// What `kinolab gains` prints: `{ locally_stable, strongly_stable,
/// conditions, eigenvalues, linearised, explanation }`.
#[wasm_bindgen(js_name = controllerStability)]
pub fn controller_stability(k_rho: f64, k_alpha: f64, k_beta: f64) -> Result<JsValue, JsError> {
    let gains = kinolab_control::Gains::new(k_rho, k_alpha, k_beta)
        .map_err(|e| JsError::new(&e.to_string()))?;
    json_to_js(&kinolab_control::report::stability(&gains))
}
