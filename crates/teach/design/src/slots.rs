//! Three slots, filled independently: a body (embodiment), a behaviour set
//! (intelligence) and a world (situatedness). Any combination can run,
//! because each slot is reached only through its stable face; some
//! combinations fail, and the matrix of all of them says which and why.

use kinolab_behaviours::coordinate::Coordinator;
use kinolab_behaviours::coordinate::sequencer::{Sequencer, State, Transition, Trigger};
use kinolab_behaviours::coordinate::subsumption::{Node, NodeKind, Subsumption};
use kinolab_behaviours::run::{RunReport, Setup, run};
use kinolab_behaviours::{Behaviour, Named};
use kinolab_world::{Body, DiffDrive, Obstacle, PointRobot, Pose, Rect, Shape, Vec2, World};
use serde::Serialize;

use crate::FieldError;

pub const BODIES: [&str; 3] = ["differential", "car", "omni"];
pub const BEHAVIOURS: [&str; 2] = ["go-and-avoid", "wander-when-stuck"];
pub const WORLDS: [&str; 4] = ["open", "office", "maze", "beach"];

/// The car's tightest turn, m.
pub const CAR_TURN: f64 = 1.2;
/// Seconds each run may take.
pub const DURATION: f64 = 90.0;

/// A body by name.
pub fn body(name: &str) -> Result<Body, FieldError> {
    let diff = || DiffDrive::new(0.3, 0.05, 10.0, 0.18);
    Ok(match name {
        "differential" => Body::Differential(diff()?),
        "car" => Body::Differential(diff()?.car_like(CAR_TURN)?),
        "omni" => Body::Point(PointRobot {
            max_speed: 0.5,
            max_turn: 4.0,
            radius: 0.18,
        }),
        other => return Err(FieldError::new("body", format!("no body `{other}`"))),
    })
}

/// A behaviour set by name: its behaviours and how they are coordinated.
fn behaviours(name: &str) -> Result<(Vec<Named>, Coordinator), FieldError> {
    let go = Named::new(
        "go",
        Behaviour::GoToGoal {
            gain: 0.4,
            slow_within: 0.5,
        },
    );
    let avoid = Named::new(
        "avoid",
        Behaviour::Avoid {
            range: 0.6,
            gain: 0.4,
        },
    );
    let names = |list: &[&str]| list.iter().map(|s| (*s).to_owned()).collect::<Vec<_>>();
    Ok(match name {
        "go-and-avoid" => (
            vec![go, avoid],
            Coordinator::Subsumption(Subsumption {
                layers: names(&["go", "avoid"]),
                nodes: vec![Node {
                    node: NodeKind::Suppress,
                    by: "avoid".into(),
                    on: "go".into(),
                    hold: 0.5,
                }],
            }),
        ),
        "wander-when-stuck" => {
            let wander = Named::new(
                "wander",
                Behaviour::Wander {
                    gain: 0.3,
                    turn_deg: 60.0,
                    every: 1.5,
                    seed: 4,
                },
            );
            let dock = Named::new(
                "dock",
                Behaviour::Dock {
                    within: 0.5,
                    speed: 0.15,
                },
            );
            let state = |n: &str, b: &[&str]| State {
                name: n.into(),
                behaviours: names(b),
            };
            let go_to = |from: &str, to: &str, when| Transition {
                from: from.into(),
                to: to.into(),
                when,
            };
            (
                vec![go, avoid, wander, dock],
                Coordinator::Sequencer(Sequencer {
                    start: "travel".into(),
                    states: vec![
                        state("travel", &["go", "avoid"]),
                        state("escape", &["wander", "avoid"]),
                        state("dock", &["dock"]),
                    ],
                    transitions: vec![
                        go_to("travel", "dock", Trigger::GoalWithin { distance: 0.5 }),
                        go_to("travel", "escape", Trigger::Bump),
                        go_to("travel", "escape", Trigger::After { seconds: 12.0 }),
                        go_to("escape", "travel", Trigger::After { seconds: 6.0 }),
                    ],
                }),
            )
        }
        other => {
            return Err(FieldError::new(
                "behaviours",
                format!("no behaviour set `{other}`"),
            ));
        }
    })
}

/// A world by name: an open floor, the office, a maze with a sharp
/// corner into a narrow passage, or a beach of scattered stones.
pub fn world(name: &str) -> Result<World, FieldError> {
    let built = |bounds: [f64; 4], shapes: Vec<Shape>, start: [f64; 2], goal: [f64; 2]| {
        let mut w = World::empty(name, Rect::from(bounds));
        w.obstacles = shapes.into_iter().map(Obstacle::new).collect();
        w.start = Pose::new(start[0], start[1], 0.0);
        w.goal = Some(Vec2::new(goal[0], goal[1]));
        w
    };
    Ok(match name {
        "open" => built([0.0, 0.0, 8.0, 5.0], Vec::new(), [1.0, 2.5], [7.0, 2.5]),
        "office" => kinolab_world::catalogue::world("office")?,
        "maze" => {
            let corner = [[0.0, 1.0], [4.4, 1.0], [4.4, 4.0], [0.0, 4.0]];
            let points = corner.iter().map(|p| Vec2::new(p[0], p[1])).collect();
            built(
                [0.0, 0.0, 5.0, 4.0],
                vec![Shape::Polygon { points }],
                [0.6, 0.5],
                [4.7, 3.4],
            )
        }
        "beach" => kinolab_world::catalogue::world("scattered")?,
        other => return Err(FieldError::new("world", format!("no world `{other}`"))),
    })
}

/// The run set-up for one combination.
pub fn setup(body_name: &str, behaviour_set: &str, world_name: &str) -> Result<Setup, FieldError> {
    let (behaviours, coordinator) = behaviours(behaviour_set)?;
    let mut setup = Setup::new(world(world_name)?, behaviours, coordinator);
    setup.body = body(body_name)?;
    setup.duration = DURATION;
    setup.seed = 1;
    setup.output_every = 10;
    setup.check()?;
    Ok(setup)
}

/// One cell of the matrix.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Outcome {
    pub body: &'static str,
    pub behaviours: &'static str,
    pub world: &'static str,
    pub reached: bool,
    pub time: Option<f64>,
    pub collisions: usize,
    /// Why it failed, in a sentence (empty when it reached the goal).
    pub why: String,
}

/// Run one combination.
pub fn outcome(
    b: &'static str,
    s: &'static str,
    w: &'static str,
) -> Result<(Outcome, RunReport), FieldError> {
    let setup = setup(b, s, w)?;
    let report = run(&setup)?;
    let m = &report.metrics;
    let travelled = m.path_length;
    let why = if m.reached {
        String::new()
    } else if b == "car" {
        format!(
            "a car cannot turn tighter than {CAR_TURN} m, and this world has turns tighter than that"
        )
    } else if travelled < 1.0 {
        "it barely moved: every behaviour's pull cancelled out (a trap)".to_owned()
    } else if m.collisions > 5 {
        format!("it kept bumping into things ({} times)", m.collisions)
    } else {
        format!("still wandering after {DURATION} s ({travelled:.1} m driven)")
    };
    Ok((
        Outcome {
            body: b,
            behaviours: s,
            world: w,
            reached: m.reached,
            time: m.time,
            collisions: m.collisions,
            why,
        },
        report,
    ))
}

/// Every combination, in the order bodies × behaviours × worlds.
pub fn matrix() -> Result<Vec<Outcome>, FieldError> {
    let mut out = Vec::new();
    for b in BODIES {
        for s in BEHAVIOURS {
            for w in WORLDS {
                out.push(outcome(b, s, w)?.0);
            }
        }
    }
    Ok(out)
}

/// The participants of each analysis pattern, and which slot feeds it.
pub const PATTERNS: [(&str, &str, &[&str]); 3] = [
    (
        "Embodiment",
        "body",
        &["AnyBody", "AnyMorphology", "AnyKinoDynamics"],
    ),
    (
        "Intelligence",
        "behaviours",
        &["AnyAction", "AnyBehavior", "AnyControl"],
    ),
    (
        "Situatedness",
        "world",
        &[
            "AnyRobot",
            "AnyEnvironment",
            "AnyPlace",
            "AnyTime",
            "AnyInteraction",
        ],
    ),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_matrix_is_the_same_every_time_and_its_failures_are_the_documented_ones() {
        let m = matrix().unwrap();
        assert_eq!(m.len(), 24);
        assert_eq!(m, matrix().unwrap());
        let cell = |b: &str, s: &str, w: &str| {
            m.iter()
                .find(|o| o.body == b && o.behaviours == s && o.world == w)
                .unwrap()
        };
        // The car cannot make the maze's corner with either behaviour set,
        // and says why.
        for s in BEHAVIOURS {
            let car = cell("car", s, "maze");
            assert!(
                !car.reached && car.why.contains("cannot turn tighter"),
                "{car:?}"
            );
        }
        // The differential drive turns on the spot: it gets everywhere.
        assert!(
            m.iter()
                .filter(|o| o.body == "differential")
                .all(|o| o.reached)
        );
        // On open floor every combination works.
        assert!(m.iter().filter(|o| o.world == "open").all(|o| o.reached));
        assert!(m.iter().all(|o| o.reached == o.why.is_empty()));
        assert_eq!(body("hovercraft").unwrap_err().field, "body");
    }
}
