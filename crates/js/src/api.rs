//! The JS API's computations on plain JSON values, so they can run (and be
//! compared with the command line) natively too. Every function returns
//! the same report the matching `kinolab` command prints, tidied the same
//! way; errors are the one-line messages the command line prints after the
//! file name.

use kinolab_common::FieldError;
use kinolab_common::display::tidy_report;
use serde::Serialize;
use serde::de::DeserializeOwned;
use serde_json::Value;

/// A report as JSON, or a one-line error.
pub type Reply = Result<Value, String>;

pub(crate) fn reply(report: &impl Serialize) -> Reply {
    tidy_report(report).map_err(text)
}

pub(crate) fn text(e: FieldError) -> String {
    e.to_string()
}

/// Read an argument of type `T`, naming it when it does not fit.
pub fn arg<T: DeserializeOwned>(name: &str, value: Value) -> Result<T, String> {
    serde_json::from_value(value).map_err(|e| format!("{name}: {e}"))
}

/// `kinolab leg-events`.
pub fn leg_events(legs: u32) -> Reply {
    reply(&kinolab_locomotion::report::leg_events(legs).map_err(text)?)
}

/// `kinolab stability`.
pub fn static_stability(com: [f64; 2], feet: &[[f64; 2]]) -> Reply {
    reply(&kinolab_locomotion::report::stability(com, feet).map_err(text)?)
}

/// The pick-and-place cell (no command-line twin).
pub fn pick_cell(placement: f64, tolerance: f64, sensor: f64, count: u32, seed: u32) -> Reply {
    let cell = kinolab_autonomy::PickCell::new(placement, tolerance, sensor).map_err(text)?;
    reply(&cell.report(count.min(100_000) as usize, u64::from(seed)))
}

/// Every embedded lesson's summary, in course order.
pub fn lessons() -> Reply {
    let course = kinolab_lessons::bundled::course().map_err(|e| e.to_string())?;
    let list: Vec<_> = course
        .summary()
        .into_iter()
        .flat_map(|u| u.lessons)
        .collect();
    reply(&list)
}

/// Every widget a lesson can embed: name, summary and parameters.
pub fn widgets() -> Reply {
    reply(&kinolab_schema::WIDGETS)
}

/// One lesson's Markdown checked, as the lesson checker would.
pub fn check_lesson(file: &str, markdown: &str) -> Reply {
    let (meta, blocks) =
        kinolab_lessons::parse_lesson(file, markdown).map_err(|e| e.to_string())?;
    let lesson = kinolab_lessons::Lesson {
        slug: String::new(),
        file: file.to_owned(),
        meta,
        blocks,
    };
    kinolab_schema::check_lesson(file, &lesson).map_err(|e| e.to_string())?;
    reply(&kinolab_lessons::summary::LessonSummary::of(
        file.to_owned(),
        &lesson,
    ))
}

// ---------------------------------------------------------------- wheels

/// A robot: a robot-file object, its JSON text, a compact layout code
/// (`f,90,0,0.25,0.1;…`), a catalogue id, or `catalogue:<id>`.
pub fn chassis(robot: Value) -> Result<kinolab_wheels::Chassis, String> {
    use kinolab_wheels::{Chassis, catalogue};
    let fail = |e: FieldError| format!("{}", e.within("robot"));
    match robot {
        Value::String(text) => {
            let text = text.trim();
            if text.starts_with('{') {
                Chassis::from_json(text).map_err(fail)
            } else if text.contains(',') {
                Chassis::from_compact("layout", text).map_err(fail)
            } else {
                catalogue::robot(text.strip_prefix("catalogue:").unwrap_or(text)).map_err(fail)
            }
        }
        other => Chassis::from_json(&other.to_string()).map_err(fail),
    }
}

/// The wheeled-robot catalogue: `[{ id, name, summary }]`.
pub fn robots() -> Reply {
    reply(&kinolab_wheels::catalogue::CATALOGUE)
}

/// A robot as a robot-file object.
pub fn robot_file(robot: Value) -> Reply {
    serde_json::from_str(&chassis(robot)?.to_json()).map_err(|e| format!("robot: {e}"))
}

/// `kinolab analyze`.
pub fn analyze_robot(robot: Value) -> Reply {
    reply(&kinolab_wheels::report::analysis(&chassis(robot)?))
}

/// `kinolab drive --twist`.
pub fn drive_twist(robot: Value, twist: [f64; 3], theta: Option<f64>) -> Reply {
    let chassis = chassis(robot)?;
    let [x, y, w] = twist;
    let v = kinolab_wheels::Vector3::new(x, y, w);
    reply(&kinolab_wheels::report::inverse(&chassis, v, theta).map_err(text)?)
}

/// `kinolab drive --wheels` (`None` where a spin is unknown).
pub fn drive_wheels(robot: Value, spins: &[Option<f64>], theta: Option<f64>) -> Reply {
    let chassis = chassis(robot)?;
    reply(&kinolab_wheels::report::forward(&chassis, spins, theta).map_err(text)?)
}

/// The differential drive's closed form: `{ v, omega, radius }`.
pub fn differential_drive(track: f64, v_left: f64, v_right: f64) -> Reply {
    reply(&kinolab_wheels::closed_form::differential_drive(track, v_left, v_right).map_err(text)?)
}

// ---------------------------------------------------------------- control

/// A run: a run-file object or its JSON text.
pub fn run_spec(run: Value) -> Result<kinolab_control::file::RunSpec, String> {
    let json = match run {
        Value::String(json) => json,
        other => other.to_string(),
    };
    kinolab_control::file::from_json(&json).map_err(text)
}

/// `kinolab simulate`.
pub fn simulate(run: Value) -> Reply {
    let spec = run_spec(run)?;
    let t = spec.run.simulate().map_err(text)?;
    reply(&kinolab_control::report::simulation(&spec, &t))
}

/// `kinolab batch --paths`.
pub fn batch_simulate(run: Value, radius: f64, count: usize, heading_deg: f64) -> Reply {
    let spec = run_spec(run)?;
    let report = kinolab_control::report::circle_batch(&spec, radius, count, heading_deg, true)
        .map_err(text)?;
    reply(&report)
}

/// `kinolab gains`.
pub fn controller_stability(k_rho: f64, k_alpha: f64, k_beta: f64) -> Reply {
    let gains = kinolab_control::Gains::new(k_rho, k_alpha, k_beta).map_err(text)?;
    reply(&kinolab_control::report::stability(&gains))
}
