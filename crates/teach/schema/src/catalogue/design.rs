//! Widgets for software stability.

use crate::{Kind, WidgetSchema};

use super::param;

pub(crate) static WIDGETS: &[WidgetSchema] = &[
    WidgetSchema {
        name: "ant-beach",
        summary: "Simon's ant on a pebble beach: one rule, a winding path; grow the body and the path straightens",
        params: &[
            param(
                "size",
                Kind::Number {
                    min: 1.0,
                    max: 1000.0,
                },
                Some("1"),
                "the body's size, in ant lengths (1 = 4 mm, 1000 = 4 m)",
            ),
            param(
                "seed",
                Kind::Integer { min: 0, max: 9999 },
                Some("1"),
                "the beach (the same seed, the same pebbles)",
            ),
            param(
                "task",
                Kind::Choice {
                    options: &["nearly-straight"],
                },
                None,
                "a graded task: `nearly-straight` asks for a body size of at most 100 whose path is within 1 % of straight",
            ),
        ],
        rules: None,
    },
    WidgetSchema {
        name: "three-slots",
        summary: "a body, a behaviour set and a world, each swapped on its own; every combination run, the failures explained",
        params: &[
            param(
                "body",
                Kind::Choice {
                    options: &["differential", "car", "omni"],
                },
                Some("differential"),
                "the body to start with",
            ),
            param(
                "behaviours",
                Kind::Choice {
                    options: &["go-and-avoid", "wander-when-stuck"],
                },
                Some("go-and-avoid"),
                "the behaviour set to start with",
            ),
            param(
                "world",
                Kind::Choice {
                    options: &["open", "office", "maze", "beach"],
                },
                Some("open"),
                "the world to start with",
            ),
            param(
                "task",
                Kind::Choice {
                    options: &["fix-the-car"],
                },
                None,
                "a graded task: `fix-the-car` starts with the car failing in the maze and asks for one changed slot, the world kept, that reaches the goal",
            ),
        ],
        rules: None,
    },
    WidgetSchema {
        name: "technology-churn",
        summary: "one robot application designed stably and naively; replace an industrial object and count the classes to edit",
        params: &[param(
            "swap",
            Kind::Choice {
                options: &["SickLaser", "Pioneer3DX", "RosTopics"],
            },
            None,
            "the industrial object replaced at the start",
        )],
        rules: None,
    },
    WidgetSchema {
        name: "morphology-builder",
        summary: "the lab's mechanism model as the AnyMorphology pattern: elements, ports and pairs as a flat graph beside the hierarchy; dissolve a pair, see transforms through the ports, switch the plugged-in commands off",
        params: &[
            param(
                "mechanism",
                Kind::Choice {
                    options: &["planar-3r", "rover-arm", "hexapod"],
                },
                Some("planar-3r"),
                "the catalogue mechanism to read",
            ),
            param(
                "from",
                Kind::Integer { min: 0, max: 99 },
                Some("0"),
                "the element the transform starts from, by its number in the mechanism's list of bodies (0 = the base)",
            ),
            param(
                "to",
                Kind::Integer { min: 0, max: 99 },
                None,
                "the element the transform goes to, by its number in the list of bodies (the last when left out)",
            ),
            param(
                "dissolved",
                Kind::Numbers {
                    min_count: 1,
                    max_count: 64,
                    min: 0.0,
                    max: 99.0,
                },
                None,
                "pairs whose port is deleted, by their numbers in the mechanism's list of joints (none when left out)",
            ),
            param(
                "commands",
                Kind::YesNo,
                Some("yes"),
                "whether the plugged-in closed forms answer (`no`: the generic tree walk)",
            ),
        ],
        rules: None,
    },
];
