//! What a page asks of whoever runs a learner's code, and the answer, as
//! plain data: in the browser the code runs in a worker of its own, so a
//! run that takes long, or takes the worker down, never takes the page
//! with it. The same [`answer`] runs natively, on a thread or at once.

use serde::{Deserialize, Serialize};

use crate::trace::Trace;
use crate::{Check, Exercise};

/// A learner's code and what to do with it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Job {
    pub exercise: String,
    pub source: String,
    pub task: Task,
}

/// What to do with the code.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Task {
    /// Run on the visible worlds, and record visible world `world`
    /// (counting from 0) for the stepper.
    Run { world: usize },
    /// Grade on every world, as a learner sees it (the held-back worlds
    /// only counted), and record the first visible world that failed, or
    /// visible world `world` when none did.
    Submit { world: usize },
    /// Record visible world `world` for the stepper.
    Trace { world: usize },
}

/// The answer: the check (after Run and Submit) and the recorded world.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Answer {
    pub check: Option<Check>,
    /// The world recorded (counting from 0) and its trace.
    pub trace: Option<(usize, Trace)>,
}

/// Do `job`. An unknown exercise, or a world that is not one the learner
/// may see, is refused with the reason.
pub fn answer(job: &Job) -> Result<Answer, String> {
    let exercise = crate::find(&job.exercise)
        .ok_or_else(|| format!("no exercise called `{}`", job.exercise))?;
    let source = job.source.as_str();
    Ok(match job.task {
        Task::Run { world } => {
            let (i, trace) = traced(&exercise, source, world)?;
            let known = Some((i, trace.outcome.clone()));
            Answer {
                check: Some(exercise.check_knowing(source, false, known)),
                trace: Some((i, trace)),
            }
        }
        Task::Submit { world } => {
            let check = exercise.check(source, true).for_learner();
            let failed = check
                .worlds
                .iter()
                .find(|w| !w.passed)
                .map(|w| w.name.clone());
            let worlds = (exercise.worlds)();
            let shown = failed
                .and_then(|name| worlds.iter().position(|w| w.name == name))
                .unwrap_or(world);
            Answer {
                check: Some(check),
                trace: Some(traced(&exercise, source, shown)?),
            }
        }
        Task::Trace { world } => Answer {
            check: None,
            trace: Some(traced(&exercise, source, world)?),
        },
    })
}

/// Visible world `i` of `exercise` run with `source`, recorded.
fn traced(exercise: &Exercise, source: &str, i: usize) -> Result<(usize, Trace), String> {
    let worlds = (exercise.worlds)();
    match worlds.get(i) {
        Some(w) if w.visible => Ok((i, exercise.trace(source, w))),
        Some(_) => Err(format!("world {} is held back", i + 1)),
        None => Err(format!(
            "the exercise has {} worlds, not {}",
            worlds.len(),
            i + 1
        )),
    }
}

/// [`answer`] from JSON to JSON: what a worker is handed and hands back
/// (`{"answer": …}` or `{"refused": "why"}`).
pub fn answer_json(job: &str) -> String {
    let reply = serde_json::from_str::<Job>(job)
        .map_err(|e| format!("not a job: {e}"))
        .and_then(|job| answer(&job));
    let value = match reply {
        Ok(answer) => serde_json::json!({ "answer": answer }),
        Err(why) => serde_json::json!({ "refused": why }),
    };
    value.to_string()
}

/// What [`answer_json`] handed back, read.
pub fn read_reply(text: &str) -> Result<Answer, String> {
    #[derive(Deserialize)]
    #[serde(rename_all = "snake_case")]
    enum Reply {
        Answer(Box<Answer>),
        Refused(String),
    }
    match serde_json::from_str::<Reply>(text) {
        Ok(Reply::Answer(answer)) => Ok(*answer),
        Ok(Reply::Refused(why)) => Err(why),
        Err(e) => Err(format!("the runner's answer could not be read: {e}")),
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn job(task: Task) -> Job {
        job_for("field-pull", task)
    }

    fn job_for(id: &str, task: Task) -> Job {
        let exercise = crate::find(id).unwrap();
        Job {
            exercise: exercise.id.into(),
            source: exercise.starter.into(),
            task,
        }
    }

    #[test]
    fn an_answer_crosses_as_json_and_comes_back_the_same() {
        for task in [
            Task::Run { world: 1 },
            Task::Submit { world: 1 },
            Task::Trace { world: 0 },
        ] {
            let direct = answer(&job(task)).unwrap();
            let wire = serde_json::to_string(&job(task)).unwrap();
            let crossed = read_reply(&answer_json(&wire)).unwrap();
            assert_eq!(crossed, direct, "{task:?}");
        }
        // Worlds cross as their world files.
        for id in [
            "behaviour-coordinate",
            "sequencer-replan",
            "legs-walk",
            "control-park",
        ] {
            let wire = serde_json::to_string(&job_for(id, Task::Trace { world: 0 })).unwrap();
            let crossed = read_reply(&answer_json(&wire)).unwrap();
            assert_eq!(
                crossed,
                answer(&job_for(id, Task::Trace { world: 0 })).unwrap(),
                "{id}"
            );
        }
    }

    #[test]
    fn a_held_back_world_is_never_recorded() {
        let held = (crate::find("field-pull").unwrap().worlds)()
            .iter()
            .position(|w| !w.visible)
            .unwrap();
        let refused = answer(&job(Task::Trace { world: held })).unwrap_err();
        assert!(refused.contains("held back"), "{refused}");
        assert!(read_reply(&answer_json("{}")).is_err());
    }

    #[test]
    fn a_submission_shows_only_how_many_held_back_worlds_passed() {
        let a = answer(&job(Task::Submit { world: 1 })).unwrap();
        let check = a.check.unwrap();
        assert!(check.worlds.iter().all(|w| w.visible));
        assert_eq!(check.held_back.map(|t| t.of), Some(3));
        // The starter fails a visible world: that one is recorded.
        assert_eq!(a.trace.map(|(i, _)| i), Some(0));
    }
}
