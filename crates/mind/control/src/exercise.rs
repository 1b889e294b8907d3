//! Graded exercises on the controller, checked by simulating the learner's
//! gains, with feedback that says what to change.

use kinolab_common::Feedback;

use crate::error::FieldError;
use crate::polar::{Direction, Gains};
use crate::pose::Pose;
use crate::sim::{Driver, Run};

/// Something a learner is asked to achieve with their gains.
#[derive(Debug, Clone, PartialEq)]
pub enum Task {
    /// Reach `goal` from `start` within `time_limit` seconds, driving
    /// forward only when `forward_only`.
    ReachWithin {
        start: Pose,
        goal: Pose,
        time_limit: f64,
        forward_only: bool,
    },
    /// Mark exactly the gain sets that are not locally stable.
    SpotUnstable { sets: Vec<Gains> },
}

impl Task {
    /// One line describing the task.
    pub fn describe(&self) -> String {
        match self {
            Task::ReachWithin {
                time_limit,
                forward_only,
                ..
            } => format!(
                "Choose gains that reach the goal within {time_limit} s{}.",
                if *forward_only {
                    " without driving backward"
                } else {
                    ""
                }
            ),
            Task::SpotUnstable { .. } => {
                "Which of these gain sets are unstable? Mark all of them.".into()
            }
        }
    }

    /// Check gains against a [`Task::ReachWithin`] by simulating them.
    pub fn check_gains(&self, gains: Gains) -> Result<Feedback, FieldError> {
        let Task::ReachWithin {
            start,
            goal,
            time_limit,
            forward_only,
        } = self
        else {
            return Err(FieldError::new("task", "this task is not about gains"));
        };
        let mut run = Run::polar(*start, *goal, gains)?;
        run.duration = *time_limit;
        run.output_every = 1000;
        if *forward_only {
            run.driver = Driver::Polar {
                gains,
                direction: Direction::Forward,
            };
        }
        let t = run.simulate()?;
        let stability = gains.stability();
        Ok(match t.time_to_goal {
            Some(time) => Feedback {
                met: true,
                message: format!("Reached in {time:.2} s, within the {time_limit} s allowed."),
            },
            None if !stability.locally_stable => Feedback {
                met: false,
                message: format!("Not reached. {}", stability.explanation),
            },
            None => Feedback {
                met: false,
                message: format!(
                    "Not reached within {time_limit} s: still {:.3} m and {:.1}° off. {}",
                    t.final_position_error,
                    t.final_heading_error.to_degrees().abs(),
                    if t.final_position_error > 0.01 {
                        "A larger k_ρ closes the distance faster (keep k_α > k_ρ)."
                    } else {
                        "The heading settles last: a stronger (more negative) k_β helps, with k_α raised to keep strong stability."
                    }
                ),
            },
        })
    }

    /// Check a learner's marks against a [`Task::SpotUnstable`].
    pub fn check_marks(&self, marked: &[bool]) -> Result<Feedback, FieldError> {
        let Task::SpotUnstable { sets } = self else {
            return Err(FieldError::new(
                "task",
                "this task is not about marking gain sets",
            ));
        };
        if marked.len() != sets.len() {
            return Err(FieldError::new(
                "marked",
                format!("expected {} marks, got {}", sets.len(), marked.len()),
            ));
        }
        let mut wrong = Vec::new();
        for (i, (g, &m)) in sets.iter().zip(marked).enumerate() {
            let s = g.stability();
            if m == s.locally_stable {
                wrong.push(format!(
                    "set {} ({}, {}, {}) is {}: {}",
                    i + 1,
                    g.k_rho,
                    g.k_alpha,
                    g.k_beta,
                    if s.locally_stable {
                        "stable"
                    } else {
                        "unstable"
                    },
                    s.explanation
                ));
            }
        }
        Ok(if wrong.is_empty() {
            Feedback {
                met: true,
                message: "All correct: exactly the unstable sets are marked.".into(),
            }
        } else {
            Feedback {
                met: false,
                message: format!("Not yet — {}", wrong.join("; ")),
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::polar::TEXTBOOK_GAINS;

    fn reach(limit: f64) -> Task {
        Task::ReachWithin {
            start: Pose::new(-1.0, 0.5, 0.0),
            goal: Pose::default(),
            time_limit: limit,
            forward_only: true,
        }
    }

    #[test]
    fn reaching_in_time_is_checked_by_simulation() -> Result<(), FieldError> {
        // The textbook gains take about 5.8 s from this start.
        let slow = reach(3.0).check_gains(TEXTBOOK_GAINS)?;
        assert!(!slow.met, "{}", slow.message);
        let ok = reach(8.0).check_gains(TEXTBOOK_GAINS)?;
        assert!(
            ok.met && ok.message.starts_with("Reached in 5.8"),
            "{}",
            ok.message
        );
        let fast = reach(3.0).check_gains(Gains::new(4.0, 12.0, -4.0)?)?;
        assert!(fast.met, "{}", fast.message);
        let unstable = reach(3.0).check_gains(Gains::new(3.0, 8.0, 1.5)?)?;
        assert!(
            !unstable.met && unstable.message.contains("k_β > 0"),
            "{}",
            unstable.message
        );
        Ok(())
    }

    #[test]
    fn marks_are_compared_with_the_conditions() -> Result<(), FieldError> {
        let task = Task::SpotUnstable {
            sets: vec![
                TEXTBOOK_GAINS,
                Gains::new(3.0, 2.0, -1.5)?,
                Gains::new(1.0, 3.0, 0.5)?,
            ],
        };
        assert!(task.check_marks(&[false, true, true])?.met);
        let v = task.check_marks(&[false, true, false])?;
        assert!(!v.met && v.message.contains("set 3"), "{}", v.message);
        assert!(task.check_marks(&[true]).is_err());
        Ok(())
    }
}
