//! Widgets for plans and architectures.

use crate::{Kind, WidgetSchema};

use super::param;

pub(crate) static WIDGETS: &[WidgetSchema] = &[
    WidgetSchema {
        name: "grid-planner",
        summary: "a world as an occupancy grid; Dijkstra and A* expanding it cell by cell",
        params: &[
            param(
                "world",
                Kind::Choice {
                    options: &[
                        "two-rooms",
                        "scattered",
                        "u-trap",
                        "corridor",
                        "lights",
                        "crossing",
                    ],
                },
                Some("two-rooms"),
                "one of the lab's example worlds",
            ),
            param(
                "cell",
                Kind::Number { min: 0.1, max: 1.0 },
                Some("0.25"),
                "the cell side s to start with (m)",
            ),
        ],
        rules: None,
    },
    WidgetSchema {
        name: "architecture-arena",
        summary: "hierarchical, reactive and hybrid robots on one clock in copies of one world, with surprises",
        params: &[
            param(
                "world",
                Kind::Choice {
                    options: &["office", "two-rooms", "u-trap", "crossing"],
                },
                Some("office"),
                "one of the lab's example worlds",
            ),
            param(
                "surprise",
                Kind::Choice {
                    options: &[
                        "none",
                        "door",
                        "person",
                        "wrong-map",
                        "noise",
                        "moved-goal",
                        "glass",
                    ],
                },
                Some("none"),
                "the surprise scripted into the run: a door that closes, a person who walks across, a map missing an obstacle, noisy range sensors, a goal that moves, or the goal behind glass",
            ),
            param(
                "planning_cost",
                Kind::Number {
                    min: 0.0,
                    max: 20.0,
                },
                Some("2"),
                "simulated planning time per expanded cell (ms)",
            ),
            param(
                "task",
                Kind::Choice {
                    options: &["survive-the-person", "pick-architecture"],
                },
                None,
                "a graded task: `survive-the-person` asks for a planning cost at which the hierarchical robot reaches the goal without touching the walker; `pick-architecture` asks for an architecture per mission, checked by running it",
            ),
        ],
        rules: None,
    },
    WidgetSchema {
        name: "sensing-routes",
        summary: "wire sensors to the functions they feed; the core names each sensor's route and the paradigm",
        params: &[
            param(
                "preset",
                Kind::Choice {
                    options: &["empty", "hierarchical", "reactive", "hybrid"],
                },
                Some("empty"),
                "the wiring to start from",
            ),
            param(
                "task",
                Kind::Choice {
                    options: &["wire-hybrid"],
                },
                None,
                "a graded task: `wire-hybrid` asks for a wiring the core classifies as hybrid, with every sensor used",
            ),
        ],
        rules: None,
    },
];
