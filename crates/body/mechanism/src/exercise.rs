//! Graded exercises on mechanisms, checked by the core with feedback that
//! says what is still wrong.

use nalgebra::{DMatrix, Vector3};

use crate::dh::{Convention, link};
use kinolab_common::Feedback;

use crate::error::FieldError;
use crate::model::{FrameRef, Model};

/// The Jacobian rows that matter for a mechanism's task: the rows that
/// move at all (at a generic state), positions first, at most one per
/// joint. A planar 2R keeps ẋ and ẏ; a planar 3R adds the turn; a
/// six-joint arm keeps all six.
pub fn task_rows(model: &Model, frame: &FrameRef) -> Result<Vec<usize>, FieldError> {
    let mut q = model.zero_state();
    for (i, v) in q.iter_mut().enumerate() {
        *v += 0.3 + 0.1 * i as f64;
    }
    model.clamp(&mut q);
    model.apply_couplings(&mut q);
    let jac = model.jacobian(&q, frame)?;
    let moving: Vec<usize> = (0..6)
        .filter(|&r| jac.row(r).iter().any(|v| v.abs() > 1e-9))
        .collect();
    Ok(moving.into_iter().take(model.dof().max(1)).collect())
}

/// How close `q` is to a singularity: the smallest singular value of the
/// task rows of the Jacobian divided by the largest (0 when singular).
pub fn conditioning(model: &Model, q: &[f64], frame: &FrameRef) -> Result<f64, FieldError> {
    let rows = task_rows(model, frame)?;
    let full = model.jacobian(q, frame)?;
    let jac = DMatrix::from_fn(rows.len(), full.ncols(), |r, c| full[(rows[r], c)]);
    let sv = jac.singular_values();
    let largest = sv.iter().cloned().fold(0.0, f64::max);
    let smallest = sv.iter().cloned().fold(f64::INFINITY, f64::min);
    // Fewer singular values than task rows counts as losing a direction.
    let lost = sv.len() < rows.len();
    Ok(if largest <= 0.0 || lost {
        0.0
    } else {
        smallest / largest
    })
}

/// Below this conditioning a configuration counts as singular.
pub const SINGULAR: f64 = 1e-6;

/// Something a learner is asked to do with a mechanism.
#[derive(Debug, Clone, PartialEq)]
pub enum Task {
    /// Bring `frame` to `target` (m) within `tolerance`.
    Reach {
        frame: String,
        target: Vector3<f64>,
        tolerance: f64,
    },
    /// Tick exactly the singular configurations.
    SpotSingular { frame: String, sets: Vec<Vec<f64>> },
    /// Give a DH row (a, α, d, θ; radians) whose link lands where the
    /// target row's does.
    DhRow {
        convention: Convention,
        target: [f64; 4],
    },
}

impl Task {
    /// One line describing the task.
    pub fn describe(&self) -> String {
        match self {
            Task::Reach { target, .. } => format!(
                "Move the joints until the tool is at ({:.2}, {:.2}, {:.2}).",
                target.x, target.y, target.z
            ),
            Task::SpotSingular { .. } => {
                "Tick every configuration in which the arm is singular, then press Check.".into()
            }
            Task::DhRow { .. } => {
                "Set a, α, d and θ so that frame i lands on the dashed target frame.".into()
            }
        }
    }

    /// Check a state against a `Reach` task.
    pub fn check_state(&self, model: &Model, q: &[f64]) -> Result<Feedback, FieldError> {
        let Task::Reach {
            frame,
            target,
            tolerance,
        } = self
        else {
            return Err(FieldError::new(
                "task",
                "this task is not checked on a state",
            ));
        };
        let at = model.pose(q, &model.frame(frame)?)?.translation.vector;
        let off = (at - target).norm();
        Ok(if off <= *tolerance {
            Feedback {
                met: true,
                message: format!(
                    "Reached: the tool is {:.1} mm from the target.",
                    off * 1000.0
                ),
            }
        } else {
            let d = target - at;
            Feedback {
                met: false,
                message: format!(
                    "Not yet: {:.0} mm away (still to go: x {:+.2}, y {:+.2}, z {:+.2} m).",
                    off * 1000.0,
                    d.x,
                    d.y,
                    d.z
                ),
            }
        })
    }

    /// Check the ticks of a `SpotSingular` task.
    pub fn check_marks(&self, model: &Model, marks: &[bool]) -> Result<Feedback, FieldError> {
        let Task::SpotSingular { frame, sets } = self else {
            return Err(FieldError::new("task", "this task has no ticks"));
        };
        if marks.len() != sets.len() {
            return Err(FieldError::new(
                "marks",
                format!(
                    "expected {} ticks, one per set, got {}",
                    sets.len(),
                    marks.len()
                ),
            ));
        }
        let f = model.frame(frame)?;
        let mut wrong = Vec::new();
        for (i, (q, &marked)) in sets.iter().zip(marks).enumerate() {
            let singular = conditioning(model, q, &f)? < SINGULAR;
            if marked != singular {
                wrong.push((i + 1, singular));
            }
        }
        Ok(if wrong.is_empty() {
            Feedback {
                met: true,
                message: "Right: exactly those configurations lose a direction of motion.".into(),
            }
        } else {
            let list: Vec<String> = wrong
                .iter()
                .map(|(i, singular)| {
                    if *singular {
                        format!("{i} is singular")
                    } else {
                        format!("{i} is not")
                    }
                })
                .collect();
            Feedback {
                met: false,
                message: format!(
                    "Not quite: {}. Look for joints lined up so that two of them move the tool the same way.",
                    list.join(", ")
                ),
            }
        })
    }

    /// Check a DH row against a `DhRow` task: the transforms must match
    /// (any row giving the same frame counts).
    pub fn check_row(&self, row: [f64; 4]) -> Result<Feedback, FieldError> {
        let Task::DhRow { convention, target } = self else {
            return Err(FieldError::new(
                "task",
                "this task is not checked on a DH row",
            ));
        };
        let want = link(*convention, target[0], target[1], target[2], target[3]);
        let got = link(*convention, row[0], row[1], row[2], row[3]);
        let shift = (want.translation.vector - got.translation.vector).norm();
        let turn = want.rotation.angle_to(&got.rotation);
        Ok(if shift < 5e-3 && turn < 0.5f64.to_radians() {
            Feedback {
                met: true,
                message: "Right: your row puts frame i exactly on the target.".into(),
            }
        } else {
            let mut parts = Vec::new();
            if shift >= 5e-3 {
                parts.push(format!("the origin is {:.0} mm off", shift * 1000.0));
            }
            if turn >= 0.5f64.to_radians() {
                parts.push(format!(
                    "the axes are turned {:.0}° too far",
                    turn.to_degrees()
                ));
            }
            Feedback {
                met: false,
                message: format!("Not yet: {}.", parts.join(" and ")),
            }
        })
    }
}
