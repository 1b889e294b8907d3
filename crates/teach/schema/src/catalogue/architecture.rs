//! Widgets for plans and architectures.

use crate::{Kind, Params, WidgetSchema};

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
            param(
                "radius",
                Kind::Number { min: 0.0, max: 0.6 },
                None,
                "the robot's radius the obstacles are grown by (m); the world's own when left out",
            ),
            param(
                "start",
                POINT,
                None,
                "where the search starts (x, y in m); the world's start when left out",
            ),
            param(
                "goal",
                POINT,
                None,
                "where the search goes (x, y in m); the world's goal when left out",
            ),
            param(
                "algorithm",
                Kind::Choice {
                    options: &["astar", "dijkstra"],
                },
                Some("astar"),
                "the search shown: `astar` (A* with the octile heuristic) or `dijkstra`",
            ),
        ],
        rules: Some(planner_rules),
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
            param(
                "focus",
                Kind::Choice {
                    options: &["hierarchical", "reactive", "hybrid"],
                },
                Some("hierarchical"),
                "the robot whose beliefs are drawn, and whose run \"Save run\" writes for `kinolab arena`",
            ),
            param(
                "picks",
                Kind::Text {
                    example: "hierarchical, reactive, hybrid",
                    check: check_picks,
                },
                Some("reactive, reactive, reactive"),
                "the pick-architecture task's choice for each of its three missions, in order, comma-separated",
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
            param(
                "wiring",
                Kind::Text {
                    example: "10010;10000;10000;00100;01001;01001",
                    check: check_wiring,
                },
                None,
                "the wiring drawn, in place of the preset's: six rows (range rays, sonar, bumpers, light sensors, goal bearing, odometry) of five 0/1 marks (avoid, go to goal, seek light, follow wall, world model), `;` between rows, as `kinolab routes` takes it",
            ),
        ],
        rules: None,
    },
];

/// A point in a world, x, y in m.
const POINT: Kind = Kind::Numbers {
    min_count: 2,
    max_count: 2,
    min: -100.0,
    max: 100.0,
};

/// The start and the goal lie in the chosen world.
fn planner_rules(p: &Params) -> Result<(), String> {
    let id = p.choice("world").unwrap_or("two-rooms");
    let world = kinolab_world::catalogue::world(id).map_err(|e| e.to_string())?;
    let b = world.bounds;
    for name in ["start", "goal"] {
        if let Some([x, y]) = p.numbers(name).map(|v| [v[0], v[1]])
            && !b.contains(x, y)
        {
            return Err(format!(
                "`{name}: {x}, {y}` lies outside the world `{id}` ({} to {} by {} to {} m)",
                b.x_min, b.x_max, b.y_min, b.y_max
            ));
        }
    }
    Ok(())
}

/// The architectures, as the task names them.
const ARCHITECTURES: [&str; 3] = ["hierarchical", "reactive", "hybrid"];

fn check_picks(text: &str) -> Result<(), String> {
    let picks: Vec<&str> = text.split(',').map(str::trim).collect();
    if picks.len() != 3 {
        return Err(format!(
            "lists {} picks; give three, one per mission",
            picks.len()
        ));
    }
    match picks.iter().find(|p| !ARCHITECTURES.contains(p)) {
        Some(p) => Err(format!(
            "has `{p}`: the architectures are hierarchical, reactive and hybrid"
        )),
        None => Ok(()),
    }
}

fn check_wiring(text: &str) -> Result<(), String> {
    let rows: Vec<String> = text
        .split(';')
        .map(|r| {
            r.chars()
                .filter(|c| !c.is_whitespace() && *c != ',')
                .collect()
        })
        .collect();
    let marks = |r: &String| r.len() == 5 && r.chars().all(|c| c == '0' || c == '1');
    if rows.len() == 6 && rows.iter().all(marks) {
        Ok(())
    } else {
        Err("is not six rows of five 0/1 marks separated by `;` (`10010;10000;10000;00100;01001;01001`)".into())
    }
}
