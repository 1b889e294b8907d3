//! Many starts at once: the textbook figure of trajectories from a circle of
//! start poses, all ending at the goal.

use kinolab_common::trig;
use serde::Serialize;

use crate::error::{FieldError, positive};
use crate::pose::Pose;
use crate::sim::{Run, Trajectory};

/// The "many starts" preview's integration step, s: RK4 at 20 ms is still
/// accurate to about 1e-5 m here, far below a pixel, and fast enough to
/// redraw a hundred runs while a slider moves.
pub const PREVIEW_DT: f64 = 0.02;
/// How long the preview simulates, s.
pub const PREVIEW_DURATION: f64 = 8.0;

/// `run` set up for the preview: coarse step, every step kept for drawing.
pub fn preview(run: &Run) -> Run {
    Run {
        dt: PREVIEW_DT,
        duration: PREVIEW_DURATION,
        output_every: 1,
        ..run.clone()
    }
}

/// Most starts one batch may have.
pub const MAX_STARTS: usize = 1000;
/// Most integration steps one batch may take, all starts together.
pub const MAX_BATCH_STEPS: usize = 20_000_000;
/// Most samples one batch may keep, all starts together.
pub const MAX_BATCH_SAMPLES: usize = 1_000_000;

/// `count` start poses evenly spaced on a circle of `radius` around the
/// goal, all with world heading `heading` (the first on the goal's left,
/// going counter-clockwise... from angle 0 of the goal frame).
pub fn circle_starts(
    goal: &Pose,
    radius: f64,
    count: usize,
    heading: f64,
) -> Result<Vec<Pose>, FieldError> {
    positive("radius", radius)?;
    crate::error::finite("radius", radius)?;
    crate::error::finite("heading", heading)?;
    if count == 0 || count > MAX_STARTS {
        return Err(FieldError::new(
            "count",
            format!("must be from 1 to {MAX_STARTS}, got {count}"),
        ));
    }
    Ok((0..count)
        .map(|i| {
            let phi = std::f64::consts::TAU * i as f64 / count as f64;
            let (s, c) = trig::sin_cos(phi);
            let mut p = Pose::new(radius * c, radius * s, 0.0).from_frame(goal);
            p.theta = heading;
            p
        })
        .collect())
}

/// One start's outcome, without its samples.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Outcome {
    pub start: Pose,
    pub reached: bool,
    pub time_to_goal: Option<f64>,
    pub final_pose: Pose,
    pub final_position_error: f64,
    pub path_length: f64,
    pub backward: bool,
    pub diverged: bool,
}

impl From<(&Pose, &Trajectory)> for Outcome {
    fn from((start, t): (&Pose, &Trajectory)) -> Self {
        Self {
            start: *start,
            reached: t.reached,
            time_to_goal: t.time_to_goal,
            final_pose: t.final_pose,
            final_position_error: t.final_position_error,
            path_length: t.path_length,
            backward: t.backward,
            diverged: t.diverged.is_some(),
        }
    }
}

/// Run `run` once from each of `starts` (its own start is ignored).
pub fn batch(run: &Run, starts: &[Pose]) -> Result<Vec<Trajectory>, FieldError> {
    if starts.len() > MAX_STARTS {
        return Err(FieldError::new(
            "starts",
            format!("at most {MAX_STARTS} starts, got {}", starts.len()),
        ));
    }
    let steps = run.check()?.saturating_mul(starts.len());
    if steps > MAX_BATCH_STEPS {
        return Err(FieldError::new(
            "count",
            format!(
                "{} starts × {} steps is {steps} steps; at most {MAX_BATCH_STEPS} in one batch \
                 (fewer starts, a larger dt or a shorter run)",
                starts.len(),
                steps / starts.len().max(1)
            ),
        ));
    }
    let samples = steps / run.output_every;
    if samples > MAX_BATCH_SAMPLES {
        return Err(FieldError::new(
            "count",
            format!(
                "the batch would keep {samples} samples; at most {MAX_BATCH_SAMPLES} \
                 (fewer starts, or a larger output_every)"
            ),
        ));
    }
    let mut one = run.clone();
    starts
        .iter()
        .enumerate()
        .map(|(i, start)| {
            one.start = *start;
            one.simulate().map_err(|e| {
                FieldError::new(
                    e.field.replacen("start", &format!("starts[{i}]"), 1),
                    e.message,
                )
            })
        })
        .collect()
}
