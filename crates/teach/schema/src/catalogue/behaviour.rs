//! Widgets for behaviours and their coordination.

use crate::{Catalogue, Kind, Params, WidgetSchema};

use super::param;

/// A point in m, anywhere a world reaches.
const POINT: Kind = Kind::Numbers {
    min_count: 2,
    max_count: 2,
    min: -100.0,
    max: 100.0,
};

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
                "top-node",
                Kind::Choice {
                    options: &["suppress", "inhibit"],
                },
                Some("suppress"),
                "with `coordinator: subsumption`: what avoid, the top layer, does to the layer below it: replace its message (suppress) or silence its wire (inhibit)",
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
            param(
                "moved",
                Kind::Groups {
                    size: 3,
                    min_groups: 0,
                    min: -100.0,
                    max: 100.0,
                },
                Some(""),
                "obstacles moved from where the world has them: each its number (from 0), then x, y (m), separated by `;`",
            ),
            param(
                "goal",
                POINT,
                None,
                "where the goal is moved to (x, y in m); the world's own goal when left out",
            ),
            param(
                "layers",
                Kind::Text {
                    example: "go, avoid, wander",
                    check: check_layers,
                },
                None,
                "for `task: layers`: the layers, level 0 first; the exercise's starting order when left out",
            ),
            param(
                "node",
                Kind::Text {
                    example: "avoid suppresses go",
                    check: check_node,
                },
                None,
                "for `task: layers`: the one node, `BY suppresses ON` or `BY inhibits ON`; no node when left out",
            ),
            param(
                "hold",
                Kind::Number { min: 0.0, max: 2.0 },
                Some("0.5"),
                "for `task: layers`: how long the node keeps acting after its last message, s",
            ),
            param(
                "task-world",
                Kind::Integer { min: 1, max: 3 },
                Some("1"),
                "for `task: layers`: which of the exercise's three worlds is shown",
            ),
        ],
        rules: Some(arena_rules),
    },
    WidgetSchema {
        name: "braitenberg",
        summary: "Braitenberg vehicles and lights: wire each vehicle and watch its character",
        params: &[
            param(
                "vehicles",
                Kind::Text {
                    example: "love, aggression",
                    check: check_vehicles,
                },
                Some("love, fear"),
                "the vehicles, by character (fear, aggression, love, explorer), comma-separated, at most four",
            ),
            param(
                "gains",
                Kind::Numbers {
                    min_count: 1,
                    max_count: 4,
                    min: 0.0,
                    max: 6.0,
                },
                None,
                "each vehicle's gain w (wheel speed per unit of light, rad/s), in order; each character's own when left out",
            ),
            param(
                "bases",
                Kind::Numbers {
                    min_count: 1,
                    max_count: 4,
                    min: 0.0,
                    max: 10.0,
                },
                None,
                "each vehicle's base wheel speed with no light (rad/s), in order; each character's own when left out",
            ),
            param(
                "lights",
                Kind::Groups {
                    size: 2,
                    min_groups: 1,
                    min: 0.2,
                    max: 7.8,
                },
                Some("5.5, 4; 4.5, 1.5"),
                "where the lights are in the 8 m × 6 m room: x, y (m) each, separated by `;`, at most four",
            ),
        ],
        rules: Some(braitenberg_rules),
    },
    WidgetSchema {
        name: "blend-or-choose",
        summary: "a frog and two flies: blending the two pulls misses both, choosing one catches it",
        params: &[param(
            "flies",
            Kind::Groups {
                size: 2,
                min_groups: 2,
                min: -0.5,
                max: 0.62,
            },
            Some("-0.3, 0.4; 0.32, 0.42"),
            "where the two flies are over the pond: x (−0.5 to 0.5 m), y (0.1 to 0.62 m) each, separated by `;`",
        )],
        rules: Some(frog_rules),
    },
];

fn arena_rules(p: &Params) -> Result<(), String> {
    let layers = p.choice("task") == Some("layers");
    if layers && p.choice("coordinator").unwrap_or("sum") != "subsumption" {
        return Err("`task: layers` needs `coordinator: subsumption`".into());
    }
    for name in ["layers", "node"] {
        if p.given(name) && !layers {
            return Err(format!("`{name}` goes with `task: layers`"));
        }
    }
    if p.given("top-node") && layers {
        return Err(
            "`top-node` is for the arena's own stacks; `task: layers` sets its node with `node`"
                .into(),
        );
    }
    for group in p.groups("moved").unwrap_or_default() {
        if group[0] < 0.0 || group[0].fract() != 0.0 {
            return Err(format!(
                "`moved` starts each group with an obstacle's number (0, 1, 2 …), found `{}`",
                group[0]
            ));
        }
    }
    Ok(())
}

fn check_layers(text: &str) -> Result<(), String> {
    kinolab_behaviours::exercise::layers_from_text(text).map(|_| ())
}

fn check_node(text: &str) -> Result<(), String> {
    kinolab_behaviours::exercise::node_from_text(text, 0.5).map(|_| ())
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

fn braitenberg_rules(p: &Params) -> Result<(), String> {
    let vehicles = p.text("vehicles").map_or(0, |v| v.split(',').count());
    for name in ["gains", "bases"] {
        if let Some(values) = p.numbers(name)
            && values.len() != vehicles
        {
            return Err(format!(
                "`{name}` gives {} numbers for {vehicles} vehicles",
                values.len()
            ));
        }
    }
    let lights = p.groups("lights").unwrap_or_default();
    if lights.len() > 4 {
        return Err(format!("`lights` has {}; give one to four", lights.len()));
    }
    if lights.iter().any(|l| l[1] > 5.8) {
        return Err("`lights` must lie in the room: y from 0.2 to 5.8 m".into());
    }
    Ok(())
}

fn frog_rules(p: &Params) -> Result<(), String> {
    let flies = p.groups("flies").unwrap_or_default();
    if flies.len() != 2 {
        return Err(format!("`flies` has {}; give two", flies.len()));
    }
    if flies.iter().any(|f| f[0] > 0.5 || f[1] < 0.1) {
        return Err(
            "`flies` must be over the pond: x from −0.5 to 0.5 m, y from 0.1 to 0.62 m".into(),
        );
    }
    Ok(())
}
