//! Widgets for behaviours and their coordination.

use crate::{Catalogue, Kind, Params, WidgetSchema};

use super::param;

pub(crate) static WIDGETS: &[WidgetSchema] = &[
    WidgetSchema {
        name: "behaviour-arena",
        summary: "a robot, its behaviours and a coordinator in a world: watch who has control, step and scrub",
        params: &[
            param(
                "world",
                Kind::Catalogue {
                    of: Catalogue::Worlds,
                },
                Some("scattered"),
                "the world to start in",
            ),
            param(
                "set",
                Kind::Choice {
                    options: &["goal-and-avoid", "explore", "light"],
                },
                Some("goal-and-avoid"),
                "which behaviours the robot has",
            ),
            param(
                "coordinator",
                Kind::Choice {
                    options: &["sum", "subsumption", "voting", "sequencer"],
                },
                Some("sum"),
                "how the behaviours are coordinated at first",
            ),
            param(
                "seed",
                Kind::Integer {
                    min: 0,
                    max: 1_000_000,
                },
                Some("1"),
                "the run's seed",
            ),
            param(
                "task",
                Kind::Choice {
                    options: &["layers"],
                },
                None,
                "an exercise: order the layers and place one node so the robot reaches the goal without a collision on three worlds",
            ),
        ],
        rules: Some(arena_rules),
    },
    WidgetSchema {
        name: "braitenberg",
        summary: "Braitenberg vehicles and lights: wire each vehicle and watch its character",
        params: &[param(
            "vehicles",
            Kind::Text {
                example: "love, aggression",
                check: check_vehicles,
            },
            Some("love, fear"),
            "the vehicles, by character (fear, aggression, love, explorer), comma-separated, at most four",
        )],
        rules: None,
    },
    WidgetSchema {
        name: "blend-or-choose",
        summary: "a frog and two flies: blending the two pulls misses both, choosing one catches it",
        params: &[],
        rules: None,
    },
];

fn arena_rules(p: &Params) -> Result<(), String> {
    if p.choice("task") == Some("layers")
        && p.choice("coordinator").unwrap_or("sum") != "subsumption"
    {
        return Err("`task: layers` needs `coordinator: subsumption`".into());
    }
    Ok(())
}

fn check_vehicles(text: &str) -> Result<(), String> {
    let names: Vec<&str> = text.split(',').map(str::trim).collect();
    if names.is_empty() || names.len() > 4 {
        return Err(format!("lists {} vehicles; give one to four", names.len()));
    }
    for n in names {
        if !["fear", "aggression", "love", "explorer"].contains(&n) {
            return Err(format!(
                "has `{n}`: the characters are fear, aggression, love and explorer"
            ));
        }
    }
    Ok(())
}
