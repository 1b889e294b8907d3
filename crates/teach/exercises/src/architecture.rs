//! Architectures: the learner's sequencer `next(state)` for the hybrid
//! robot decides when to replan and where the skills aim, graded on worlds
//! where something changes under the robot.

use kinolab_architectures::placing::Placed;
use kinolab_architectures::run::{ArenaReport, run as simulate};
use kinolab_architectures::{Architecture, ArenaSetup, FieldError};
use kinolab_common::display::fixed;
use kinolab_world::{EventKind, Vec2};

use crate::{Exercise, Hook, Outcome, World};

/// One run: the arena with its surprises, and how many plans a sequencer
/// that replans only when it must needs there at most.
#[derive(Debug, Clone, PartialEq)]
pub struct Trial {
    pub setup: ArenaSetup,
    pub max_plans: usize,
}

/// Plans allowed: the first, one for each surprise, and two to spare.
fn plan_budget(setup: &ArenaSetup) -> usize {
    3 + setup.surprises.len()
}

const STARTER: &str = r#"// state.t, state.at ([x, y]), state.goal ([x, y] or ()),
// state.plan (the waypoints still ahead), state.planned_for (the goal the
// plan was made for), state.planning, state.no_path, state.blocked.
// Answer #{ replan: true or false, target: [x, y] or () } (() aims at the goal).
fn next(state) {
    let replan = state.plan.len() == 0 && state.planned_for == ();
    let target = if state.plan.len() > 0 { state.plan[0] } else { () };
    #{ replan: replan, target: target }
}
"#;

pub const EXERCISES: [Exercise; 1] = [Exercise {
    id: "sequencer-replan",
    unit: "architectures",
    lesson: "architectures/hybrid-architectures",
    hook: Hook::Sequencer,
    signature: kinolab_architectures::paradigm::scripted::SIGNATURE,
    title: "Replan when the world changes",
    task: "The starter plans once and follows the plan. Make the sequencer replan when it must, and only then, so the hybrid robot reaches the goal without touching anything when a door closes on its way or the goal moves. Planning costs time: a world with one surprise allows four plans at most.",
    starter: STARTER,
    hints: &[
        "The map tells you when the way ahead is blocked: `state.blocked`.",
        "When the goal moves, the plan was made for somewhere else: compare `state.planned_for` with `state.goal` (an unchanged goal is handed back exactly as it was).",
        "Planning takes time: while `state.planning` is true, a replan request is ignored and the old plan still holds.",
    ],
    worlds: replan,
}];

fn world(name: &str, visible: bool, setup: ArenaSetup) -> World {
    World {
        name: name.into(),
        visible,
        trial: crate::Trial::Arena(Trial {
            max_plans: plan_budget(&setup),
            setup,
        }),
    }
}

/// `world` with a `kind` surprise placed at `t` s from the robot's start.
fn placed(id: &str, kind: Placed, t: f64) -> Result<ArenaSetup, FieldError> {
    let w = kinolab_world::catalogue::world(id)?;
    let start = Vec2::new(w.start.x, w.start.y);
    let surprise = kind.place(&w, start, t)?;
    let mut setup = ArenaSetup::new(w);
    setup.surprises.push(surprise);
    Ok(setup)
}

fn office(surprise: Option<&str>) -> Result<ArenaSetup, FieldError> {
    kinolab_architectures::exercise::office(surprise)
}

fn replan() -> Vec<World> {
    let worlds = [
        ("office: a door closes", true, office(Some("door"))),
        ("office: the goal moves", true, office(Some("moved-goal"))),
        ("office: nothing happens", false, office(None)),
        (
            "scattered: a door closes",
            false,
            placed("scattered", Placed::Door, 3.0),
        ),
        (
            "U-trap: a door closes",
            false,
            placed("u-trap", Placed::Door, 3.0),
        ),
        (
            "corridor: the goal moves",
            false,
            placed("corridor", Placed::MovedGoal, 3.0),
        ),
    ];
    // Every set-up is fixed; one that cannot be made is a defect the tests
    // catch (the exercise would have fewer worlds).
    worlds
        .into_iter()
        .filter_map(|(name, visible, setup)| setup.ok().map(|s| world(name, visible, s)))
        .collect()
}

pub(crate) fn run(source: &str, world: &World, t: &Trial) -> Outcome {
    let setup = setup(source, t);
    judge(world, t, simulate(&setup, Architecture::Hybrid, EVERY))
}

/// Samples kept: one in this many steps.
pub(crate) const EVERY: usize = 10;

/// The trial's arena with the learner's sequencer in the hybrid robot.
pub(crate) fn setup(source: &str, t: &Trial) -> ArenaSetup {
    ArenaSetup {
        sequencer: Some(source.to_owned()),
        ..t.setup.clone()
    }
}

/// The outcome of a run (or of one that could not start).
pub(crate) fn judge(world: &World, t: &Trial, report: Result<ArenaReport, FieldError>) -> Outcome {
    let mut out = Outcome::new(world);
    let report = match report {
        Ok(r) => r,
        Err(e) => return out.judged(Some(format!("the run could not start: {e}"))),
    };
    let m = &report.metrics;
    out.error = report.error.clone();
    out.time = report.samples.last().map(|s| s.motion.t);
    out = out
        .metric("path_length", m.path_length)
        .metric("plans", m.plans as f64)
        .metric("collisions", m.collisions as f64);
    let bump = report
        .events
        .iter()
        .find(|e| matches!(e.kind, EventKind::Bump { .. }));
    let reason = if let Some(b) = bump {
        out.time = Some(b.t);
        Some(format!("touched something at {} s", fixed(b.t, 1)))
    } else if !m.reached {
        Some(format!(
            "not at the goal after {} s",
            fixed(t.setup.duration, 0)
        ))
    } else if m.plans > t.max_plans {
        Some(format!(
            "planned {} times: replanning only when the world changes needs at most {} plans here",
            m.plans, t.max_plans
        ))
    } else {
        None
    };
    out.judged(reason)
}
