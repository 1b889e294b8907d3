//! The reports the command line prints and the JS API returns: typed
//! structs, in one place (field names as in the command-line contract;
//! `_deg` marks degrees). Print them through
//! [`kinolab_common::display::tidy_report`].

use kinolab_common::angle::{degrees, wrap};
use kinolab_wheels::{Chassis, Vector3};
use serde::Serialize;

use crate::batch::Outcome;
use crate::error::FieldError;
use crate::file::RunSpec;
use crate::polar::{Condition, Gains};
use crate::pose::Pose;
use crate::sim::{Driver, Trajectory};

/// A pose for people: metres and degrees, the heading wrapped.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct PoseReport {
    pub x: f64,
    pub y: f64,
    pub theta_deg: f64,
}

impl From<&Pose> for PoseReport {
    fn from(p: &Pose) -> Self {
        Self {
            x: p.x,
            y: p.y,
            theta_deg: degrees(wrap(p.theta)),
        }
    }
}

/// `kinolab gains`: the stability conditions, the linearised loop and its
/// eigenvalues.
#[derive(Debug, Clone, Serialize)]
pub struct StabilityReport {
    pub gains: GainsReport,
    pub locally_stable: bool,
    pub strongly_stable: bool,
    pub conditions: Vec<Condition>,
    pub eigenvalues: [[f64; 2]; 3],
    pub linearised: Vec<Vec<f64>>,
    pub explanation: String,
}

#[derive(Debug, Clone, Copy, Serialize)]
pub struct GainsReport {
    pub k_rho: f64,
    pub k_alpha: f64,
    pub k_beta: f64,
}

/// The gains' stability report.
pub fn stability(gains: &Gains) -> StabilityReport {
    let s = gains.stability();
    StabilityReport {
        gains: GainsReport {
            k_rho: gains.k_rho,
            k_alpha: gains.k_alpha,
            k_beta: gains.k_beta,
        },
        locally_stable: s.locally_stable,
        strongly_stable: s.strongly_stable,
        conditions: s.conditions,
        eigenvalues: s.eigenvalues,
        linearised: gains
            .linearised()
            .row_iter()
            .map(|r| r.iter().copied().collect())
            .collect(),
        explanation: s.explanation,
    }
}

/// `kinolab simulate`: samples, reached, time to goal, the final pose, and
/// the metrics.
#[derive(Debug, Clone, Serialize)]
pub struct SimulationReport {
    pub samples: Vec<SampleReport>,
    pub reached: bool,
    pub time_to_goal: Option<f64>,
    #[serde(rename = "final")]
    pub final_pose: PoseReport,
    pub goal: PoseReport,
    pub final_error: FinalError,
    pub path_length: f64,
    pub peak_wheel_speed: f64,
    pub robot: String,
    pub driven_wheels: Vec<usize>,
    pub direction: &'static str,
    /// True when the run was stopped because it ran away.
    pub diverged: bool,
    /// Why it was stopped (only when it diverged).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reason: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stability: Option<StabilityReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plan: Option<PlanReport>,
    /// A learner's law: how often it was called, and the error that
    /// stopped the run (`kind`, `message`, `line`, `column`, `t`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub law_calls: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<kinolab_script::ScriptError>,
}

/// One sample of a run, with the goal as the robot sees it and what each
/// wheel does.
#[derive(Debug, Clone, Serialize)]
pub struct SampleReport {
    #[serde(flatten)]
    pub motion: kinolab_common::trajectory::Sample,
    pub rho: f64,
    pub alpha_deg: f64,
    pub beta_deg: f64,
    /// `None` when the robot's wheels cannot make this motion.
    pub wheels: Option<Vec<WheelCommandReport>>,
}

#[derive(Debug, Clone, Copy, Serialize)]
pub struct WheelCommandReport {
    pub spin: f64,
    pub steer_deg: f64,
}

#[derive(Debug, Clone, Copy, Serialize)]
pub struct FinalError {
    pub position: f64,
    pub heading_deg: f64,
}

/// An open-loop plan's timing.
#[derive(Debug, Clone, Serialize)]
pub struct PlanReport {
    pub duration: f64,
    pub end: PoseReport,
    pub segments: Vec<SegmentReport>,
}

#[derive(Debug, Clone, Copy, Serialize)]
pub struct SegmentReport {
    pub t0: f64,
    pub duration: f64,
    pub peak: f64,
    pub ramp: f64,
    pub cruise: f64,
}

/// Each wheel's spin (rad/s) and steering (deg) for the commanded twist.
fn wheels(robot: &Chassis, v: f64, omega: f64) -> Option<Vec<WheelCommandReport>> {
    let solution = robot.inverse(Vector3::new(v, 0.0, omega)).ok()?;
    Some(
        solution
            .wheels
            .iter()
            .map(|w| WheelCommandReport {
                spin: w.spin,
                steer_deg: degrees(w.steer),
            })
            .collect(),
    )
}

/// `kinolab simulate`.
pub fn simulation(spec: &RunSpec, t: &Trajectory) -> SimulationReport {
    let run = &spec.run;
    let samples = t
        .samples
        .iter()
        .map(|s| SampleReport {
            motion: kinolab_common::trajectory::Sample::new(
                s.t,
                [s.pose.x, s.pose.y, wrap(s.pose.theta)],
                s.v,
                s.omega,
            ),
            rho: s.polar.rho,
            alpha_deg: degrees(s.polar.alpha),
            beta_deg: degrees(s.polar.beta),
            wheels: wheels(&spec.robot, s.v, s.omega),
        })
        .collect();
    let (stability, plan) = match &run.driver {
        Driver::Polar { gains, .. } => (Some(stability(gains)), None),
        Driver::Script(_) => (None, None),
        Driver::OpenLoop(plan) => (
            None,
            Some(PlanReport {
                duration: plan.duration(),
                end: PoseReport::from(&plan.end()),
                segments: plan
                    .pieces
                    .iter()
                    .map(|p| SegmentReport {
                        t0: p.t0,
                        duration: p.profile.duration(),
                        peak: p.profile.peak,
                        ramp: p.profile.ramp,
                        cruise: p.profile.cruise,
                    })
                    .collect(),
            }),
        ),
    };
    SimulationReport {
        samples,
        reached: t.reached,
        time_to_goal: t.time_to_goal,
        final_pose: PoseReport::from(&t.final_pose),
        goal: PoseReport::from(&run.goal),
        final_error: FinalError {
            position: t.final_position_error,
            heading_deg: degrees(t.final_heading_error),
        },
        path_length: t.path_length,
        peak_wheel_speed: t.peak_wheel_speed,
        robot: spec.robot.name().to_owned(),
        driven_wheels: run.drive.driven.clone(),
        direction: direction(t.backward),
        diverged: t.diverged.is_some(),
        reason: t.diverged.as_ref().map(|d| d.reason.clone()),
        stability,
        plan,
        law_calls: matches!(run.driver, Driver::Script(_)).then_some(t.calls.len()),
        error: t.error.clone(),
    }
}

fn direction(backward: bool) -> &'static str {
    if backward { "backward" } else { "forward" }
}

/// `kinolab batch`: one line per start, and whether all of them made it.
#[derive(Debug, Clone, Serialize)]
pub struct BatchReport {
    pub runs: Vec<RunReport>,
    pub all_reached: bool,
    pub reached: usize,
    pub slowest_time_to_goal: Option<f64>,
}

/// One run of a batch.
#[derive(Debug, Clone, Serialize)]
pub struct RunReport {
    pub start: PoseReport,
    pub reached: bool,
    pub time_to_goal: Option<f64>,
    #[serde(rename = "final")]
    pub final_pose: PoseReport,
    pub final_position_error: f64,
    pub path_length: f64,
    pub direction: &'static str,
    /// True when this run was stopped because it ran away.
    pub diverged: bool,
    /// The sampled path, when asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub path: Option<Vec<[f64; 2]>>,
}

/// `run` from `count` starts on a circle of `radius` around its goal, all
/// with heading `heading_deg`: the [`batch`] report, with each run's path
/// when `paths`. Errors name the argument (`radius`, `count`, `heading`).
/// Bounded like every command: at most [`crate::batch::MAX_BATCH_STEPS`]
/// steps and [`crate::batch::MAX_BATCH_SAMPLES`] samples in all.
pub fn circle_batch(
    spec: &RunSpec,
    radius: f64,
    count: usize,
    heading_deg: f64,
    paths: bool,
) -> Result<BatchReport, FieldError> {
    let starts =
        crate::batch::circle_starts(&spec.run.goal, radius, count, heading_deg.to_radians())?;
    let runs = crate::batch::batch(&spec.run, &starts)?;
    let outcomes: Vec<Outcome> = starts.iter().zip(&runs).map(Outcome::from).collect();
    Ok(batch(&outcomes, paths.then_some(runs.as_slice())))
}

/// A batch report from the runs' outcomes (and their paths, if given).
pub fn batch(outcomes: &[Outcome], paths: Option<&[Trajectory]>) -> BatchReport {
    let runs = outcomes
        .iter()
        .enumerate()
        .map(|(i, o)| RunReport {
            start: PoseReport::from(&o.start),
            reached: o.reached,
            time_to_goal: o.time_to_goal,
            final_pose: PoseReport::from(&o.final_pose),
            final_position_error: o.final_position_error,
            path_length: o.path_length,
            direction: direction(o.backward),
            diverged: o.diverged,
            path: paths
                .and_then(|p| p.get(i))
                .map(|t| t.samples.iter().map(|s| [s.pose.x, s.pose.y]).collect()),
        })
        .collect();
    let slowest = outcomes
        .iter()
        .filter_map(|o| o.time_to_goal)
        .fold(None, |m: Option<f64>, t| Some(m.map_or(t, |m| m.max(t))));
    BatchReport {
        runs,
        all_reached: outcomes.iter().all(|o| o.reached),
        reached: outcomes.iter().filter(|o| o.reached).count(),
        slowest_time_to_goal: slowest,
    }
}
