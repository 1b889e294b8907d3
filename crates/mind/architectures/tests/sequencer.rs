#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! A learner's sequencer drives the hybrid robot: one that replans when it
//! must reaches the goal past a closing door; one that never plans drives
//! at the goal like a reactive robot; an error stops the robot with the
//! learner's message.

use kinolab_architectures::exercise::office;
use kinolab_architectures::run::run;
use kinolab_architectures::{Architecture, ArenaSetup};

/// Replan with no plan, when the way is blocked or the goal moved; aim at
/// the next waypoint.
const CAREFUL: &str = r#"
fn next(state) {
    let moved = state.planned_for != () && state.goal != ()
        && (state.planned_for[0] - state.goal[0]).abs() + (state.planned_for[1] - state.goal[1]).abs() > 0.3;
    let replan = (state.plan.len() == 0 && !state.no_path) || state.blocked || moved;
    let target = if state.plan.len() > 0 { state.plan[0] } else { () };
    #{ replan: replan, target: target }
}"#;

fn with(setup: ArenaSetup, source: &str) -> ArenaSetup {
    ArenaSetup {
        sequencer: Some(source.to_owned()),
        ..setup
    }
}

#[test]
fn a_careful_sequencer_gets_past_a_closing_door() {
    let report = run(
        &with(office(Some("door")).unwrap(), CAREFUL),
        Architecture::Hybrid,
        10,
    )
    .unwrap();
    assert!(report.error.is_none(), "{:?}", report.error);
    assert!(report.metrics.reached, "{:?}", report.metrics);
    assert!(
        report.metrics.plans >= 2,
        "it replanned: {:?}",
        report.metrics
    );
}

#[test]
fn a_sequencer_that_never_plans_makes_no_plans() {
    let never = "fn next(state) { #{ replan: false } }";
    let report = run(
        &with(office(None).unwrap(), never),
        Architecture::Hybrid,
        10,
    )
    .unwrap();
    assert_eq!(report.metrics.plans, 0);
    assert!(report.error.is_none());
}

#[test]
fn a_failing_sequencer_stops_the_robot_with_its_message() {
    let broken = "fn next(state) { if state.t > 1.0 { return 42; } #{ replan: false } }";
    let report = run(
        &with(office(None).unwrap(), broken),
        Architecture::Hybrid,
        1,
    )
    .unwrap();
    let e = report.error.expect("42 is not a decision");
    assert!(e.message.contains("`next` must return #{ replan"), "{e}");
    let last = report.samples.last().unwrap().motion.t;
    assert!(last < 1.2, "stopped at {last}");
    let e = run(
        &with(office(None).unwrap(), "fn next(a, b) { () }"),
        Architecture::Hybrid,
        1,
    )
    .unwrap_err();
    assert_eq!(e.field, "sequencer");
}
