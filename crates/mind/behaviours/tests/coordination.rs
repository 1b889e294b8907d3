#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Coordination semantics: subsumption's suppress and inhibit with their
//! hold times, voting totals, sequencer transitions.

use std::collections::BTreeMap;

use kinolab_behaviours::coordinate::sequencer::{
    Sequencer, SequencerState, State, Transition, Trigger,
};
use kinolab_behaviours::coordinate::subsumption::{Node, NodeKind, Subsumption, SubsumptionState};
use kinolab_behaviours::coordinate::{Coordinator, Responses, Trace, Voting};
use kinolab_behaviours::library::{Behaviour, Named};
use kinolab_behaviours::run::{Runner, Setup};
use kinolab_behaviours::{Drive, Response, Vec2};
use kinolab_world::sensors::{GoalPercept, Percepts};
use kinolab_world::{Body, Rect, World};

fn named(names: &[&str]) -> Vec<Named> {
    names
        .iter()
        .map(|n| {
            Named::new(
                *n,
                Behaviour::GoToGoal {
                    gain: 1.0,
                    slow_within: 1.0,
                },
            )
        })
        .collect()
}

fn msg(x: f64) -> Option<Response> {
    Some(Response::Vector(Vec2::new(x, 0.0)))
}

/// The message on the lowest wire over a sequence of steps, where the
/// upper layer `b` speaks only on the steps marked `true`.
fn lowest_wire(kind: NodeKind, upper_speaks: &[bool]) -> Vec<Option<f64>> {
    let behaviours = named(&["a", "b"]);
    let s = Subsumption {
        layers: vec!["a".into(), "b".into()],
        nodes: vec![Node {
            node: kind,
            by: "b".into(),
            on: "a".into(),
            hold: 0.3,
        }],
    };
    let mut state = SubsumptionState::new(&s);
    upper_speaks
        .iter()
        .map(|&speaks| {
            let responses = [msg(1.0), if speaks { msg(2.0) } else { None }];
            let r = Responses {
                behaviours: &behaviours,
                responses: &responses,
            };
            let (wires, _) = s.wires(&mut state, &r, 0.1);
            wires[0].map(|(r, _)| match r {
                Response::Vector(v) => v.x,
                _ => f64::NAN,
            })
        })
        .collect()
}

#[test]
fn suppress_replaces_for_the_hold_time() {
    // b speaks on steps 2 and 3; the hold of 0.3 s at 0.1 s a step keeps
    // its message on a's wire for three more steps.
    let speaks = [false, false, true, true, false, false, false, false, false];
    let wire = lowest_wire(NodeKind::Suppress, &speaks);
    let want = [1.0, 1.0, 2.0, 2.0, 2.0, 2.0, 2.0, 1.0, 1.0];
    assert_eq!(wire, want.map(Some).to_vec());
}

#[test]
fn inhibit_silences_for_the_hold_time() {
    let speaks = [false, true, false, false, false, false];
    let wire = lowest_wire(NodeKind::Inhibit, &speaks);
    assert_eq!(wire, vec![Some(1.0), None, None, None, None, Some(1.0)]);
}

#[test]
fn nodes_chain_down_the_layers() {
    // c suppresses b's wire, and b's wire (now carrying c) suppresses a's.
    let behaviours = named(&["a", "b", "c"]);
    let s = Subsumption {
        layers: vec!["a".into(), "b".into(), "c".into()],
        nodes: vec![
            Node {
                node: NodeKind::Suppress,
                by: "b".into(),
                on: "a".into(),
                hold: 0.0,
            },
            Node {
                node: NodeKind::Suppress,
                by: "c".into(),
                on: "b".into(),
                hold: 0.0,
            },
        ],
    };
    let mut state = SubsumptionState::new(&s);
    let responses = [msg(1.0), None, msg(3.0)];
    let (wires, acting) = s.wires(
        &mut state,
        &Responses {
            behaviours: &behaviours,
            responses: &responses,
        },
        0.1,
    );
    assert!(matches!(wires[0], Some((Response::Vector(v), 2)) if v.x == 3.0));
    assert_eq!(acting, vec![true, true]);
}

#[test]
fn a_node_must_come_from_above() {
    let s = Coordinator::Subsumption(Subsumption {
        layers: vec!["a".into(), "b".into()],
        nodes: vec![Node {
            node: NodeKind::Suppress,
            by: "a".into(),
            on: "b".into(),
            hold: 0.5,
        }],
    });
    let e = s.check(&["a".into(), "b".into()]).unwrap_err();
    assert_eq!(e.field, "nodes[0].by");
}

fn open_room() -> World {
    let mut w = World::empty("open", Rect::from([0.0, 0.0, 10.0, 10.0]));
    w.start = kinolab_world::Pose::new(2.0, 5.0, 0.0);
    w.goal = Some(Vec2::new(8.0, 5.0));
    w
}

#[test]
fn lower_layers_keep_running_while_suppressed() {
    // Wander at level 0, suppressed all the time by go-to-goal. Its
    // responses step by step match those of wander running alone with the
    // same odometry: it kept its own clock and state underneath.
    let wander = Named::new(
        "wander",
        Behaviour::Wander {
            gain: 0.3,
            turn_deg: 90.0,
            every: 0.5,
            seed: 9,
        },
    );
    let go = Named::new(
        "go",
        Behaviour::GoToGoal {
            gain: 0.3,
            slow_within: 0.5,
        },
    );
    let layered = Setup::new(
        open_room(),
        vec![wander.clone(), go.clone()],
        Coordinator::Subsumption(Subsumption {
            layers: vec!["wander".into(), "go".into()],
            nodes: vec![Node {
                node: NodeKind::Suppress,
                by: "go".into(),
                on: "wander".into(),
                hold: 0.5,
            }],
        }),
    );
    let mut runner = Runner::new(&layered).unwrap();
    let mut alone = wander.clone();
    for _ in 0..100 {
        let frame = runner.step();
        assert_eq!(frame.decision.in_control, Some(1), "go has control");
        assert_eq!(
            frame.responses[0],
            alone.respond(&frame.percepts),
            "wander ran underneath"
        );
    }
    // Remove the upper layer: the lower one still drives the robot.
    let lower_only = Setup::new(
        open_room(),
        vec![go],
        Coordinator::Subsumption(Subsumption {
            layers: vec!["go".into()],
            nodes: vec![],
        }),
    );
    let report = kinolab_behaviours::run::run(&lower_only).unwrap();
    assert!(report.metrics.reached);
}

fn percepts_with(goal: Option<(f64, f64)>, light: [f64; 2], time: f64) -> Percepts {
    Percepts {
        time,
        goal: goal.map(|(bearing, distance)| GoalPercept { bearing, distance }),
        light,
        ..Percepts::default()
    }
}

fn drive() -> Drive {
    Drive {
        body: Body::default(),
        heading_gain: 3.0,
    }
}

#[test]
fn votes_are_weighted_and_summed() {
    // "ahead" wants to go straight on, "left" at 90°. Each arc's chord
    // points κ·L/2 off the nose (L = 1 m), so arc k's total is
    // 1·cos(κ_k/2) + 2·cos(κ_k/2 − 90°).
    let behaviours = vec![
        Named::new(
            "ahead",
            Behaviour::GoToGoal {
                gain: 0.4,
                slow_within: 0.5,
            },
        ),
        Named::new(
            "left",
            Behaviour::GoToGoal {
                gain: 0.4,
                slow_within: 0.5,
            },
        ),
    ];
    let responses = [
        Some(Response::Vector(Vec2::new(0.4, 0.0))),
        Some(Response::Vector(Vec2::new(0.0, 0.4))),
    ];
    let voting = Voting {
        weights: BTreeMap::from([("left".into(), 2.0)]),
        ..Voting::default()
    };
    let d = voting.decide(
        &Responses {
            behaviours: &behaviours,
            responses: &responses,
        },
        &Percepts::default(),
        &drive(),
    );
    let Trace::Voting {
        curvatures,
        totals,
        winner,
    } = d.trace
    else {
        panic!("a voting trace")
    };
    assert_eq!(curvatures.len(), 21);
    for (k, t) in curvatures.iter().zip(&totals) {
        let want = (k / 2.0).cos() + 2.0 * (k / 2.0 - std::f64::consts::FRAC_PI_2).cos();
        assert!((t - want).abs() < 1e-12, "κ = {k}: {t} vs {want}");
    }
    // cos a + 2 sin a peaks at a = atan 2 = 63°, beyond the sharpest left
    // arc's chord (1 rad = 57°), so that arc wins.
    assert_eq!(winner, Some(20));
    assert_eq!(d.in_control, Some(1));
}

#[test]
fn the_sequencer_moves_on_perceptual_events() {
    let behaviours = named(&["explore", "home", "dock"]);
    let seq = Sequencer {
        start: "exploring".into(),
        states: vec![
            State {
                name: "exploring".into(),
                behaviours: vec!["explore".into()],
            },
            State {
                name: "homing".into(),
                behaviours: vec!["home".into()],
            },
            State {
                name: "docking".into(),
                behaviours: vec!["dock".into()],
            },
        ],
        transitions: vec![
            Transition {
                from: "exploring".into(),
                to: "homing".into(),
                when: Trigger::LightAbove { level: 0.5 },
            },
            Transition {
                from: "homing".into(),
                to: "docking".into(),
                when: Trigger::GoalWithin { distance: 0.4 },
            },
            Transition {
                from: "docking".into(),
                to: "exploring".into(),
                when: Trigger::After { seconds: 1.0 },
            },
        ],
    };
    Coordinator::Sequencer(seq.clone())
        .check(&["explore".into(), "home".into(), "dock".into()])
        .unwrap();
    let mut st = SequencerState::new(&seq);
    let responses = [msg(1.0), msg(1.0), msg(1.0)];
    let r = Responses {
        behaviours: &behaviours,
        responses: &responses,
    };
    let mut step = |p: Percepts| match seq.decide(&mut st, &r, &p, &drive(), 0.25).trace {
        Trace::Sequencer { state } => state,
        _ => unreachable!(),
    };
    assert_eq!(
        step(percepts_with(Some((0.0, 3.0)), [0.1, 0.2], 0.0)),
        "exploring"
    );
    assert_eq!(
        step(percepts_with(Some((0.0, 3.0)), [0.6, 0.2], 0.25)),
        "homing"
    );
    assert_eq!(
        step(percepts_with(Some((0.0, 1.0)), [0.6, 0.2], 0.5)),
        "homing"
    );
    assert_eq!(
        step(percepts_with(Some((0.0, 0.3)), [0.6, 0.2], 0.75)),
        "docking"
    );
    // One second in "docking" (four steps of 0.25 s), then back to exploring.
    for _ in 0..4 {
        assert_eq!(
            step(percepts_with(Some((0.0, 0.3)), [0.0, 0.0], 1.0)),
            "docking"
        );
    }
    assert_eq!(
        step(percepts_with(Some((0.0, 0.3)), [0.0, 0.0], 2.0)),
        "exploring"
    );
}
