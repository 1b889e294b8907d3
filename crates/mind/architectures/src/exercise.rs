//! Graded tasks on architectures, checked by running the learner's choice.

use kinolab_common::Feedback;
use kinolab_world::catalogue::world;

use crate::FieldError;
use crate::arena::{Arena, ArenaSetup};
use crate::paradigm::Architecture;
use crate::routes::{SENSORS, Wiring};
use crate::surprise::Surprise;

/// The office world with one of its example surprises (by the widget's id).
pub fn office(surprise: Option<&str>) -> Result<ArenaSetup, FieldError> {
    let mut setup = ArenaSetup::new(world("office")?);
    if let Some(id) = surprise {
        let (_, spec) = crate::surprise::OFFICE
            .iter()
            .find(|(name, _)| *name == id)
            .ok_or_else(|| {
                FieldError::new("surprise", format!("no office surprise called `{id}`"))
            })?;
        setup.surprises.push(Surprise::parse("surprise", spec)?);
    }
    Ok(setup)
}

/// Run `kind` alone through `setup` to the end; whether it reached the
/// goal, and how many times it touched something.
fn outcome(setup: &ArenaSetup, kind: Architecture) -> Result<(bool, usize), FieldError> {
    let mut arena = Arena::new(setup, &[kind])?;
    while !arena.done() {
        arena.step();
    }
    let s = &arena.entrants[0].scores;
    Ok((s.reached, s.collisions))
}

/// "Set the planning cost so the hierarchical robot still survives the
/// person": it must reach the goal without touching anything.
pub fn survive_the_person(planning_cost_ms: f64) -> Result<Feedback, FieldError> {
    let mut setup = office(Some("person"))?;
    setup.planning_cost =
        kinolab_common::error::in_range("planning_cost", planning_cost_ms, 0.0, 1000.0)? / 1e3;
    let (reached, collisions) = outcome(&setup, Architecture::Hierarchical)?;
    Ok(match (reached, collisions) {
        (true, 0) => Feedback::met(format!(
            "At {planning_cost_ms} ms a cell the plans stay fresh enough: the hierarchical robot reaches the goal without touching the walker."
        )),
        (_, n) if n > 0 => Feedback::not_yet(format!(
            "At {planning_cost_ms} ms a cell the robot touched something {}: it drives plans made from sensing that is seconds old while the walker moves.",
            if n == 1 {
                "once".to_owned()
            } else {
                format!("{n} times")
            }
        )),
        _ => Feedback::not_yet("No collision, but the robot did not reach the goal in time."),
    })
}

/// A mission of the pick-an-architecture task.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mission {
    pub name: &'static str,
    /// The office surprise it is run with.
    pub surprise: Option<&'static str>,
    /// Whether touching something fails it (glass can only be found by touch).
    pub touch_fails: bool,
}

pub const MISSIONS: [Mission; 3] = [
    Mission {
        name: "an exact map, nothing moves",
        surprise: None,
        touch_fails: true,
    },
    Mission {
        name: "a person steps into the hall",
        surprise: Some("person"),
        touch_fails: true,
    },
    Mission {
        name: "the goal is behind a glass wall",
        surprise: Some("glass"),
        touch_fails: false,
    },
];

/// "Pick an architecture for each mission and defend it by running it":
/// each pick must reach the goal, without a collision where one can be
/// avoided.
pub fn pick_architecture(picks: [Architecture; 3]) -> Result<Feedback, FieldError> {
    let mut failed = Vec::new();
    for (m, kind) in MISSIONS.iter().zip(picks) {
        let mission = m.name;
        let (reached, collisions) = outcome(&office(m.surprise)?, kind)?;
        if !reached || (m.touch_fails && collisions > 0) {
            failed.push(format!(
                "{} on \"{mission}\" ({}, {collisions} collision(s))",
                kind.name(),
                if reached {
                    "reached the goal"
                } else {
                    "did not reach the goal"
                }
            ));
        }
    }
    Ok(if failed.is_empty() {
        Feedback::met("Every pick reached its goal, touching nothing it could have seen.")
    } else {
        Feedback::not_yet(format!("Not yet: {}.", failed.join("; ")))
    })
}

/// "Wire the sensors so the robot is hybrid, using every sensor."
pub fn wire_hybrid(wiring: &Wiring) -> Feedback {
    let report = wiring.report();
    let unused: Vec<&str> = SENSORS
        .iter()
        .zip(&report.routes)
        .filter(|(_, r)| matches!(r, crate::routes::Route::Unused))
        .map(|(s, _)| *s)
        .collect();
    match (report.paradigm, unused.is_empty()) {
        (Some(Architecture::Hybrid), true) => Feedback::met(
            "Hybrid: some sensors reach behaviours directly and some are fused into the world model.",
        ),
        (Some(Architecture::Hybrid), false) => {
            Feedback::not_yet(format!("Hybrid, but unused: {}.", unused.join(", ")))
        }
        (Some(kind), _) => Feedback::not_yet(format!(
            "This wiring is {}: a hybrid robot needs a local route into the behaviours and a global one into the model.",
            kind.name()
        )),
        (None, _) => Feedback::not_yet("Nothing is wired yet."),
    }
}
