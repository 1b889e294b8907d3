//! The JSON the command line prints and the JS API returns, in one place
//! (field names as in the command-line contract; `_deg` marks degrees).

use kinolab_wheels::report::{degrees, tidy};
use kinolab_wheels::{Chassis, Vector3};
use serde_json::{Value, json};

use crate::batch::Outcome;
use crate::file::RunSpec;
use crate::polar::{Gains, Stability};
use crate::pose::{Pose, wrap};
use crate::sim::{Driver, Trajectory};

fn pose(p: &Pose) -> Value {
    json!({ "x": p.x, "y": p.y, "theta_deg": degrees(wrap(p.theta)) })
}

/// The gains' stability report.
pub fn stability(gains: &Gains) -> Value {
    let s: Stability = gains.stability();
    tidy(json!({
        "gains": { "k_rho": gains.k_rho, "k_alpha": gains.k_alpha, "k_beta": gains.k_beta },
        "locally_stable": s.locally_stable,
        "strongly_stable": s.strongly_stable,
        "conditions": s.conditions,
        "eigenvalues": s.eigenvalues,
        "linearised": gains.linearised().row_iter().map(|r| r.iter().copied().collect::<Vec<f64>>()).collect::<Vec<_>>(),
        "explanation": s.explanation,
    }))
}

/// Each wheel's spin (rad/s) and steering (deg) for the commanded twist.
fn wheels(robot: &Chassis, v: f64, omega: f64) -> Value {
    match robot.inverse(Vector3::new(v, 0.0, omega)) {
        Ok(solution) => Value::Array(
            solution
                .wheels
                .iter()
                .map(|w| json!({ "spin": w.spin, "steer_deg": degrees(w.steer) }))
                .collect(),
        ),
        Err(_) => Value::Null,
    }
}

/// `kinolab simulate`: samples, reached, time to goal, the final pose, and
/// the metrics.
pub fn simulation(spec: &RunSpec, t: &Trajectory) -> Value {
    let run = &spec.run;
    let samples: Vec<Value> = t
        .samples
        .iter()
        .map(|s| {
            json!({
                "t": s.t,
                "x": s.pose.x,
                "y": s.pose.y,
                "theta_deg": degrees(wrap(s.pose.theta)),
                "v": s.v,
                "omega": s.omega,
                "rho": s.polar.rho,
                "alpha_deg": degrees(s.polar.alpha),
                "beta_deg": degrees(s.polar.beta),
                "wheels": wheels(&spec.robot, s.v, s.omega),
            })
        })
        .collect();
    let mut out = json!({
        "samples": samples,
        "reached": t.reached,
        "time_to_goal": t.time_to_goal,
        "final": pose(&t.final_pose),
        "goal": pose(&run.goal),
        "final_error": {
            "position": t.final_position_error,
            "heading_deg": degrees(t.final_heading_error),
        },
        "path_length": t.path_length,
        "peak_wheel_speed": t.peak_wheel_speed,
        "robot": spec.robot.name(),
        "driven_wheels": run.drive.driven,
        "direction": if t.backward { "backward" } else { "forward" },
    });
    match &run.driver {
        Driver::Polar { gains, .. } => out["stability"] = stability(gains),
        Driver::OpenLoop(plan) => {
            out["plan"] = json!({
                "duration": plan.duration(),
                "end": pose(&plan.end()),
                "segments": plan.pieces.iter().map(|p| json!({
                    "t0": p.t0,
                    "duration": p.profile.duration(),
                    "peak": p.profile.peak,
                    "ramp": p.profile.ramp,
                    "cruise": p.profile.cruise,
                })).collect::<Vec<_>>(),
            });
        }
    }
    tidy(out)
}

/// `run` from `count` starts on a circle of `radius` around its goal, all
/// with heading `heading_deg`: the [`batch`] report, with each run's path
/// when `paths`. Errors name the argument (`radius`, `count`, `heading`).
pub fn circle_batch(
    spec: &RunSpec,
    radius: f64,
    count: usize,
    heading_deg: f64,
    paths: bool,
) -> Result<Value, crate::ControlError> {
    let starts =
        crate::batch::circle_starts(&spec.run.goal, radius, count, heading_deg.to_radians())?;
    let runs = crate::batch::batch(&spec.run, &starts)?;
    let outcomes: Vec<Outcome> = starts.iter().zip(&runs).map(Outcome::from).collect();
    Ok(batch(&outcomes, paths.then_some(runs.as_slice())))
}

/// A batch: one line per start, and whether all of them made it.
pub fn batch(outcomes: &[Outcome], paths: Option<&[Trajectory]>) -> Value {
    let runs: Vec<Value> = outcomes
        .iter()
        .enumerate()
        .map(|(i, o)| {
            let mut run = json!({
                "start": pose(&o.start),
                "reached": o.reached,
                "time_to_goal": o.time_to_goal,
                "final": pose(&o.final_pose),
                "final_position_error": o.final_position_error,
                "path_length": o.path_length,
                "direction": if o.backward { "backward" } else { "forward" },
            });
            if let Some(t) = paths.and_then(|p| p.get(i)) {
                run["path"] = t
                    .samples
                    .iter()
                    .map(|s| json!([s.pose.x, s.pose.y]))
                    .collect();
            }
            run
        })
        .collect();
    let slowest = outcomes
        .iter()
        .filter_map(|o| o.time_to_goal)
        .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.max(t))));
    tidy(json!({
        "runs": runs,
        "all_reached": outcomes.iter().all(|o| o.reached),
        "reached": outcomes.iter().filter(|o| o.reached).count(),
        "slowest_time_to_goal": slowest,
    }))
}
