//! The behaviour sets the arena offers, each with a set-up for every
//! coordinator, so switching coordinator compares like with like.

use std::collections::BTreeMap;

use kinolab_behaviours::coordinate::sequencer::{Sequencer, State, Transition, Trigger};
use kinolab_behaviours::coordinate::subsumption::{Node, NodeKind, Subsumption};
use kinolab_behaviours::coordinate::{Coordinator, Voting};
use kinolab_behaviours::library::{Behaviour, Named, Side};

/// The coordinators, in the order of the arena's switch.
pub(super) const COORDINATORS: [&str; 4] = ["sum", "subsumption", "voting", "sequencer"];

fn gains(pairs: &[(&str, f64)]) -> BTreeMap<String, f64> {
    pairs.iter().map(|(k, v)| (k.to_string(), *v)).collect()
}

fn node(kind: NodeKind, by: &str, on: &str) -> Node {
    Node {
        node: kind,
        by: by.into(),
        on: on.into(),
        hold: 0.5,
    }
}

fn state(name: &str, behaviours: &[&str]) -> State {
    State {
        name: name.into(),
        behaviours: behaviours.iter().map(|b| b.to_string()).collect(),
    }
}

fn go(from: &str, to: &str, when: Trigger) -> Transition {
    Transition {
        from: from.into(),
        to: to.into(),
        when,
    }
}

/// The behaviours of set `set`.
pub(super) fn behaviours(set: &str) -> Vec<Named> {
    let avoid = Named::new(
        "avoid",
        Behaviour::Avoid {
            range: 0.7,
            gain: 0.4,
        },
    );
    let wander = Named::new(
        "wander",
        Behaviour::Wander {
            gain: 0.3,
            turn_deg: 60.0,
            every: 2.0,
            seed: 3,
        },
    );
    match set {
        "explore" => vec![
            wander,
            Named::new(
                "hug",
                Behaviour::FollowWall {
                    side: Side::Left,
                    distance: 0.45,
                    gain: 0.35,
                },
            ),
            avoid,
        ],
        "light" => vec![
            wander,
            Named::new(
                "seek",
                Behaviour::SeekLight {
                    gain: 0.35,
                    threshold: 0.05,
                },
            ),
            avoid,
        ],
        _ => vec![
            wander,
            Named::new(
                "go",
                Behaviour::GoToGoal {
                    gain: 0.4,
                    slow_within: 0.5,
                },
            ),
            avoid,
        ],
    }
}

/// The second behaviour of each set: the one with a purpose.
fn purpose(set: &str) -> &'static str {
    match set {
        "explore" => "hug",
        "light" => "seek",
        _ => "go",
    }
}

/// Coordinator `kind` for set `set`.
pub(super) fn coordinator(set: &str, kind: &str) -> Coordinator {
    let aim = purpose(set);
    match kind {
        "subsumption" => Coordinator::Subsumption(Subsumption {
            layers: vec!["wander".into(), aim.into(), "avoid".into()],
            nodes: vec![
                node(NodeKind::Suppress, aim, "wander"),
                node(NodeKind::Suppress, "avoid", aim),
            ],
        }),
        "voting" => Coordinator::Voting(Voting {
            weights: gains(&[("wander", 0.3), (aim, 1.0), ("avoid", 2.0)]),
            ..Voting::default()
        }),
        "sequencer" => Coordinator::Sequencer(sequencer(set)),
        _ => Coordinator::Sum {
            gains: gains(&[("wander", 0.3), (aim, 1.0), ("avoid", 1.5)]),
        },
    }
}

fn sequencer(set: &str) -> Sequencer {
    match set {
        "explore" => Sequencer {
            start: "roam".into(),
            states: vec![
                state("roam", &["wander", "avoid"]),
                state("follow", &["hug", "avoid"]),
            ],
            transitions: vec![
                go("roam", "follow", Trigger::ObstacleAhead { distance: 0.6 }),
                go("follow", "roam", Trigger::After { seconds: 8.0 }),
            ],
        },
        "light" => Sequencer {
            start: "search".into(),
            states: vec![
                state("search", &["wander", "avoid"]),
                state("approach", &["seek", "avoid"]),
            ],
            transitions: vec![
                go("search", "approach", Trigger::LightAbove { level: 0.6 }),
                go("approach", "search", Trigger::LightBelow { level: 0.3 }),
            ],
        },
        _ => Sequencer {
            start: "travel".into(),
            states: vec![
                state("travel", &["go", "avoid"]),
                state("escape", &["wander", "avoid"]),
            ],
            transitions: vec![
                go("travel", "escape", Trigger::Bump),
                go("escape", "travel", Trigger::After { seconds: 3.0 }),
            ],
        },
    }
}
