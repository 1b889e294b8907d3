//! The behaviour sets the arena offers, each with a set-up for every
//! coordinator, so switching coordinator compares like with like.

use std::collections::BTreeMap;

use kinolab_behaviours::coordinate::sequencer::{Sequencer, State, Transition, Trigger};
use kinolab_behaviours::coordinate::subsumption::{Node, NodeKind, Subsumption};
use kinolab_behaviours::coordinate::{Coordinator, Voting};
use kinolab_behaviours::library::{Behaviour, Named, Side};
use serde::{Deserialize, Serialize};

/// The behaviour sets the arena offers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub(super) enum Set {
    GoalAndAvoid,
    Explore,
    Light,
}

/// The coordinators, as the schema names them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub(super) enum CoordinatorKind {
    Sum,
    Subsumption,
    Voting,
    Sequencer,
}

impl CoordinatorKind {
    pub fn name(self) -> &'static str {
        match self {
            CoordinatorKind::Sum => "sum",
            CoordinatorKind::Subsumption => "subsumption",
            CoordinatorKind::Voting => "voting",
            CoordinatorKind::Sequencer => "sequencer",
        }
    }
}

/// The coordinators, in the order of the arena's switch.
pub(super) const COORDINATORS: [CoordinatorKind; 4] = [
    CoordinatorKind::Sum,
    CoordinatorKind::Subsumption,
    CoordinatorKind::Voting,
    CoordinatorKind::Sequencer,
];

fn gains(pairs: &[(&str, f64)]) -> BTreeMap<String, f64> {
    let mut gains = BTreeMap::new();
    for (k, v) in pairs {
        gains.insert((*k).to_owned(), *v);
    }
    gains
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
pub(super) fn behaviours(set: Set) -> Vec<Named> {
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
        Set::Explore => vec![
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
        Set::Light => vec![
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
        Set::GoalAndAvoid => vec![
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
fn purpose(set: Set) -> &'static str {
    match set {
        Set::Explore => "hug",
        Set::Light => "seek",
        Set::GoalAndAvoid => "go",
    }
}

/// Coordinator `kind` for set `set`; in the subsumption stack, avoid's
/// node on the layer below is of kind `top`.
pub(super) fn coordinator(set: Set, kind: CoordinatorKind, top: NodeKind) -> Coordinator {
    let aim = purpose(set);
    match kind {
        CoordinatorKind::Subsumption => Coordinator::Subsumption(Subsumption {
            layers: vec!["wander".into(), aim.into(), "avoid".into()],
            nodes: vec![
                node(NodeKind::Suppress, aim, "wander"),
                node(top, "avoid", aim),
            ],
        }),
        CoordinatorKind::Voting => Coordinator::Voting(Voting {
            weights: gains(&[("wander", 0.3), (aim, 1.0), ("avoid", 2.0)]),
            ..Voting::default()
        }),
        CoordinatorKind::Sequencer => Coordinator::Sequencer(sequencer(set)),
        CoordinatorKind::Sum => Coordinator::Sum {
            gains: gains(&[("wander", 0.3), (aim, 1.0), ("avoid", 1.5)]),
        },
    }
}

fn sequencer(set: Set) -> Sequencer {
    match set {
        Set::Explore => Sequencer {
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
        Set::Light => Sequencer {
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
        Set::GoalAndAvoid => Sequencer {
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
