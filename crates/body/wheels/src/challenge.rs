//! Graded exercises: a goal for a layout, checked by the same analysis the
//! lab shows, with feedback that says what is still missing.

use kinolab_common::Feedback;

use crate::analysis::Icr;
use crate::chassis::Chassis;

/// Something a learner is asked to build or set.
#[derive(Debug, Clone, PartialEq)]
pub enum Goal {
    /// δM equal to `target`, using at most `max_steer_inputs` steering inputs.
    Maneuverability {
        target: usize,
        max_steer_inputs: Option<usize>,
    },
    /// δm equal to `target`.
    Mobility { target: usize },
    /// DOF equal to `target`.
    Dof { target: usize },
    /// The layout's ICR at (x, y) in the robot frame, within `tolerance` metres.
    IcrAt { x: f64, y: f64, tolerance: f64 },
}

fn verdict(met: bool, message: String) -> Feedback {
    Feedback { met, message }
}

impl Goal {
    /// One line describing the task.
    pub fn describe(&self) -> String {
        match self {
            Goal::Maneuverability {
                target,
                max_steer_inputs: Some(k),
            } => format!(
                "Build a robot with δM = {target} using at most {k} steering input{}.",
                if *k == 1 { "" } else { "s" }
            ),
            Goal::Maneuverability { target, .. } => format!("Build a robot with δM = {target}."),
            Goal::Mobility { target } => format!("Reach a degree of mobility δm = {target}."),
            Goal::Dof { target } => format!("Build a robot that can reach DOF = {target}."),
            Goal::IcrAt { x, y, .. } => format!("Place the ICR at ({x}, {y})."),
        }
    }

    /// Does `chassis` meet the goal? The message explains either way.
    pub fn check(&self, chassis: &Chassis) -> Feedback {
        let a = chassis.analyze();
        match *self {
            Goal::Maneuverability {
                target,
                max_steer_inputs,
            } => {
                let inputs = a.steering_inputs;
                if let Some(limit) = max_steer_inputs.filter(|limit| inputs > *limit) {
                    return verdict(
                        false,
                        format!("{inputs} steering inputs: use at most {limit}."),
                    );
                }
                let met = a.maneuverability == target;
                verdict(
                    met,
                    format!(
                        "δM = δm + δs = {} + {} = {}{}",
                        a.mobility,
                        a.steerability,
                        a.maneuverability,
                        if met { ": done." } else { "." }
                    ),
                )
            }
            Goal::Mobility { target } => {
                let met = a.mobility == target;
                verdict(
                    met,
                    format!(
                        "rank C₁ = {}, so δm = {}{}",
                        a.rank_c1,
                        a.mobility,
                        if met { ": done." } else { "." }
                    ),
                )
            }
            Goal::Dof { target } => {
                let met = a.dof == target;
                verdict(
                    met,
                    format!("DOF = {}{}", a.dof, if met { ": done." } else { "." }),
                )
            }
            Goal::IcrAt { x, y, tolerance } => match a.icr {
                Icr::Point { x: px, y: py } => {
                    let miss = (px - x).hypot(py - y);
                    let met = miss <= tolerance;
                    verdict(
                        met,
                        format!(
                            "ICR at ({px:.2}, {py:.2}){}",
                            if met {
                                ": done.".to_owned()
                            } else {
                                format!(", {miss:.2} m away.")
                            }
                        ),
                    )
                }
                Icr::Infinity { .. } => verdict(
                    false,
                    "The ICR is at infinity: the robot drives straight.".into(),
                ),
                Icr::None => verdict(
                    false,
                    "The wheels disagree: this layout cannot move.".into(),
                ),
                Icr::Line { .. } | Icr::Anywhere => {
                    verdict(false, "The ICR is not pinned to one point yet.".into())
                }
            },
        }
    }
}

/// Check a learner's answer to "which wheels disagree?" for a stuck layout.
pub fn check_disagreeing(chassis: &Chassis, chosen: &[usize]) -> Feedback {
    let Some(d) = chassis.disagreement() else {
        return verdict(false, "This layout can move: no wheel disagrees.".into());
    };
    let mut expected: Vec<usize> = d.disagree.iter().map(|(i, _)| *i).collect();
    expected.sort_unstable();
    let mut chosen = chosen.to_vec();
    chosen.sort_unstable();
    chosen.dedup();
    let name = |v: &[usize]| {
        v.iter()
            .map(|i| format!("{}", i + 1))
            .collect::<Vec<_>>()
            .join(", ")
    };
    if chosen == expected {
        verdict(
            true,
            format!(
                "Right: wheel {} misses the point where the others' zero-motion lines meet.",
                name(&expected)
            ),
        )
    } else {
        let missing: Vec<usize> = expected
            .iter()
            .filter(|i| !chosen.contains(i))
            .copied()
            .collect();
        let extra: Vec<usize> = chosen
            .iter()
            .filter(|i| !expected.contains(i))
            .copied()
            .collect();
        let mut parts = Vec::new();
        if !extra.is_empty() {
            parts.push(format!("wheel {} agrees with the majority", name(&extra)));
        }
        if !missing.is_empty() {
            parts.push(format!("{} more wheel(s) to find", missing.len()));
        }
        verdict(false, format!("Not yet: {}.", parts.join("; ")))
    }
}
