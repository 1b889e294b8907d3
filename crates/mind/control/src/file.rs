//! Run files (`*.run.json`): the command line's and the JS API's input,
//! in the contract's format, with angles in degrees (`_deg`).
//!
//! Beyond the contract's fields a run may name a `robot` (a catalogue id or
//! an inline robot file), a `max_wheel_speed`, a `control_rate`, `noise`, a
//! `tolerance`, and an `open_loop` controller made of segments.

use kinolab_wheels::Chassis;
use serde::Deserialize;

use crate::error::FieldError;
use crate::noise::Noise;
use crate::plan::{Limits, Plan, Segment};
use crate::polar::{Direction, Gains};
use crate::pose::Pose;
use crate::sim::{DriveModel, Driver, Run, Tolerance};

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct PoseFile {
    x: f64,
    y: f64,
    theta_deg: f64,
}

impl From<&PoseFile> for Pose {
    fn from(p: &PoseFile) -> Self {
        Pose::new(p.x, p.y, p.theta_deg.to_radians())
    }
}

#[derive(Debug, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
enum ControllerFile {
    Polar {
        k_rho: f64,
        k_alpha: f64,
        k_beta: f64,
        #[serde(default)]
        direction: Direction,
    },
    OpenLoop {
        segments: Vec<SegmentFile>,
        #[serde(default)]
        limits: Option<LimitsFile>,
    },
    /// A learner's law: `control(rho, alpha, beta)` → `[v, omega]`, run at
    /// the control rate (100 Hz when the run gives none). A command line
    /// may give `path` (a file beside the run file) instead of `source`.
    Script {
        source: String,
        #[serde(default)]
        direction: Direction,
    },
}

#[derive(Debug, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase", deny_unknown_fields)]
enum SegmentFile {
    Line { length: f64 },
    Arc { radius: f64, angle_deg: f64 },
    Turn { angle_deg: f64 },
}

impl From<&SegmentFile> for Segment {
    fn from(s: &SegmentFile) -> Self {
        match *s {
            SegmentFile::Line { length } => Segment::Line { length },
            SegmentFile::Arc { radius, angle_deg } => Segment::Arc {
                radius,
                angle: angle_deg.to_radians(),
            },
            SegmentFile::Turn { angle_deg } => Segment::Turn {
                angle: angle_deg.to_radians(),
            },
        }
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct LimitsFile {
    max_speed: f64,
    max_accel: f64,
    max_turn_rate_deg: f64,
    max_turn_accel_deg: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct NoiseFile {
    seed: u64,
    #[serde(default)]
    slip: f64,
    #[serde(default)]
    push_speed: f64,
    #[serde(default)]
    push_turn_deg: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ToleranceFile {
    position: f64,
    heading_deg: f64,
}

#[derive(Debug, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a run file (an object with `controller` and `start`)"
)]
struct RunFile {
    controller: ControllerFile,
    start: PoseFile,
    goal: Option<PoseFile>,
    #[serde(default = "kinolab_common::defaults::reciprocal::<1000>")]
    dt: f64,
    #[serde(default = "kinolab_common::defaults::whole::<10>")]
    duration: f64,
    #[serde(default = "default_output_every")]
    output_every: usize,
    robot: Option<serde_json::Value>,
    max_wheel_speed: Option<f64>,
    control_rate: Option<f64>,
    noise: Option<NoiseFile>,
    tolerance: Option<ToleranceFile>,
}

fn default_output_every() -> usize {
    100
}

/// The run-file example of the command-line contract, verbatim.
pub const CONTRACT_EXAMPLE: &str = r#"{
  "controller": { "kind": "polar", "k_rho": 3.0, "k_alpha": 8.0, "k_beta": -1.5 },
  "start": { "x": -1.0, "y": 0.5, "theta_deg": 0 },
  "goal":  { "x": 0.0,  "y": 0.0, "theta_deg": 0 },
  "dt": 0.001,
  "duration": 10.0,
  "output_every": 100
}"#;

/// A parsed run and the robot it drives.
#[derive(Debug, Clone)]
pub struct RunSpec {
    pub run: Run,
    pub robot: Chassis,
}

/// The robot a run names: a catalogue id, or an inline robot file.
fn robot(value: Option<&serde_json::Value>) -> Result<Chassis, FieldError> {
    let wheels_error = |e: kinolab_common::FieldError| {
        FieldError::new(
            format!("robot.{}", e.field).trim_end_matches('.'),
            e.message,
        )
    };
    match value {
        None => kinolab_wheels::catalogue::robot("differential-drive").map_err(wheels_error),
        Some(serde_json::Value::String(id)) => {
            // `catalogue:<id>` as on the command line, or the bare id.
            let id = id.strip_prefix("catalogue:").unwrap_or(id);
            kinolab_wheels::catalogue::robot(id).map_err(|e| FieldError::new("robot", e.message))
        }
        Some(object @ serde_json::Value::Object(_)) => {
            Chassis::from_json(&object.to_string()).map_err(wheels_error)
        }
        Some(_) => Err(FieldError::new(
            "robot",
            "must be a catalogue id such as \"differential-drive\" or a robot object",
        )),
    }
}

/// Parse a run file. Errors name the JSON path of the bad field.
pub fn from_json(text: &str) -> Result<RunSpec, FieldError> {
    let file: RunFile = kinolab_common::error::from_json(text)?;
    from_file(&file)
}

fn from_file(file: &RunFile) -> Result<RunSpec, FieldError> {
    let robot = robot(file.robot.as_ref())?;
    let drive = DriveModel::new(&robot)?;
    let start = Pose::from(&file.start);
    let mut run = match &file.controller {
        ControllerFile::Polar {
            k_rho,
            k_alpha,
            k_beta,
            direction,
        } => {
            let gains = Gains::new(*k_rho, *k_alpha, *k_beta)
                .map_err(|e| FieldError::new(format!("controller.{}", e.field), e.message))?;
            let Some(goal) = &file.goal else {
                return Err(FieldError::new(
                    "goal",
                    "missing field (the polar controller needs a goal)",
                ));
            };
            let mut run = Run::polar(start, goal.into(), gains)?;
            run.driver = Driver::Polar {
                gains,
                direction: *direction,
            };
            run
        }
        ControllerFile::OpenLoop { segments, limits } => {
            check_degrees(segments, limits.as_ref())?;
            let segments: Vec<Segment> = segments.iter().map(Segment::from).collect();
            let limits = limits.as_ref().map_or_else(Limits::default, |l| Limits {
                max_speed: l.max_speed,
                max_accel: l.max_accel,
                max_turn_rate: l.max_turn_rate_deg.to_radians(),
                max_turn_accel: l.max_turn_accel_deg.to_radians(),
            });
            let plan = Plan::new(start, &segments, limits).map_err(|e| {
                let field = if e.field.starts_with("start") {
                    e.field
                } else {
                    format!("controller.{}", in_degrees(&e.field))
                };
                FieldError::new(field, e.message)
            })?;
            let mut run = Run::open_loop(plan)?;
            if let Some(goal) = &file.goal {
                run.goal = goal.into();
            }
            run
        }
        ControllerFile::Script { source, direction } => {
            let law = crate::law::Law::new(source, *direction)
                .map_err(|e| FieldError::new("controller.source", e.to_string()))?;
            let Some(goal) = &file.goal else {
                return Err(FieldError::new(
                    "goal",
                    "missing field (a control law drives to a goal)",
                ));
            };
            let mut run = Run::polar(start, goal.into(), crate::polar::TEXTBOOK_GAINS)?;
            run.driver = Driver::Script(law);
            run
        }
    };
    run.dt = file.dt;
    run.duration = file.duration;
    run.output_every = file.output_every;
    run.drive = drive;
    run.max_wheel_speed = file.max_wheel_speed;
    run.control_rate = file.control_rate;
    run.noise = file.noise.as_ref().map(|n| Noise {
        seed: n.seed,
        slip: n.slip,
        push_speed: n.push_speed,
        push_turn: n.push_turn_deg.to_radians(),
    });
    if let Some(t) = &file.tolerance {
        run.tolerance = Tolerance {
            position: crate::error::positive("tolerance.position", t.position)?,
            heading: crate::error::positive("tolerance.heading_deg", t.heading_deg)?.to_radians(),
        };
    }
    Ok(RunSpec { run, robot })
}

/// The plan's angles checked in degrees, as the file gives them, so a
/// message repeats the number the author wrote.
fn check_degrees(segments: &[SegmentFile], limits: Option<&LimitsFile>) -> Result<(), FieldError> {
    for (i, s) in segments.iter().enumerate() {
        if let SegmentFile::Arc { angle_deg, .. } | SegmentFile::Turn { angle_deg } = s {
            crate::error::finite_at(*angle_deg, || format!("controller.segments[{i}].angle_deg"))?;
        }
    }
    if let Some(l) = limits {
        crate::error::positive("controller.limits.max_turn_rate_deg", l.max_turn_rate_deg)?;
        crate::error::positive("controller.limits.max_turn_accel_deg", l.max_turn_accel_deg)?;
    }
    Ok(())
}

/// A plan's field named as the file spells it: its angles are in degrees.
fn in_degrees(field: &str) -> String {
    for name in ["angle", "max_turn_rate", "max_turn_accel"] {
        if field.ends_with(&format!(".{name}")) {
            return format!("{field}_deg");
        }
    }
    field.to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    const CONTRACT: &str = CONTRACT_EXAMPLE;

    #[test]
    fn the_contract_example_parses() {
        let spec = from_json(CONTRACT).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(spec.run.start, Pose::new(-1.0, 0.5, 0.0));
        assert_eq!(spec.run.output_every, 100);
        assert_eq!(spec.robot.name(), "Differential drive");
        assert!(
            matches!(spec.run.driver, Driver::Polar { gains, .. } if gains == crate::TEXTBOOK_GAINS)
        );
    }

    #[test]
    fn bad_fields_are_named() {
        let cases = [
            (CONTRACT.replace("\"k_beta\"", "\"k_gamma\""), "controller"),
            (
                CONTRACT.replacen("\"theta_deg\": 0", "\"theta\": 0", 1),
                "start",
            ),
            (CONTRACT.replace("0.001", "-0.001"), "dt"),
            (
                CONTRACT.replace("\"dt\"", "\"robot\": \"tricycle\", \"dt\""),
                "robot.wheels[2]",
            ),
            (
                CONTRACT.replace("\"dt\"", "\"robot\": \"hovercraft\", \"dt\""),
                "robot",
            ),
            (
                CONTRACT.replace("\"dt\"", "\"noise\": {\"seed\": 1, \"slip\": 2}, \"dt\""),
                "noise.slip",
            ),
            (CONTRACT.replace("\"polar\"", "\"pid\""), "controller"),
        ];
        for (text, field) in cases {
            let result = from_json(&text).and_then(|s| s.run.simulate().map(|_| ()));
            match result {
                Err(e) => assert!(e.field.starts_with(field), "{field}: got `{e}`"),
                Ok(()) => panic!("{field}: accepted"),
            }
        }
    }
}
