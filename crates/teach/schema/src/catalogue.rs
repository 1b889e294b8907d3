//! The catalogue: every widget a lesson may embed and its parameters.
//! The widgets themselves live in `kinolab-widgets`, one folder per domain;
//! each reads its parameters through [`crate::validate`].

use kinolab_control::{Gains, Segment};
use kinolab_mechanism::catalogue::mechanism;
use kinolab_wheels::Chassis;

use crate::{Catalogue, Kind, Param, Params, WidgetSchema};

const fn param(
    name: &'static str,
    kind: Kind,
    default: Option<&'static str>,
    help: &'static str,
) -> Param {
    Param {
        name,
        kind,
        default,
        help,
    }
}

const YES_NO: Kind = Kind::YesNo;

/// Three numbers (a pose `x, y, heading_deg`, or gains).
const fn triple(min: f64, max: f64) -> Kind {
    Kind::Numbers {
        min_count: 3,
        max_count: 3,
        min,
        max,
    }
}

const ROBOT: Param = param(
    "robot",
    Kind::Catalogue {
        of: Catalogue::Robots,
    },
    None,
    "a robot from the catalogue (default differential-drive); or give `layout`",
);

const LAYOUT: Param = param(
    "layout",
    Kind::Text {
        example: "f,90,0,0.25,0.1;f,-90,180,0.25,0.1;c,180,0,0.3,0.05,d=0.04",
        check: check_layout,
    },
    None,
    "wheels as a layout code: `kind,alpha_deg,beta_deg,l,radius` per wheel, `;` between wheels",
);

fn check_layout(text: &str) -> Result<(), String> {
    Chassis::from_compact("layout", text)
        .map(|_| ())
        .map_err(|e| format!("is not a wheel layout: {e}"))
}

fn check_plan(text: &str) -> Result<(), String> {
    Segment::parse_list(text)
        .map(|_| ())
        .map_err(|e| format!("is not a plan: {e}"))
}

/// A whole number of degrees of freedom, 0 to 3.
const fn degree(name: &'static str, help: &'static str) -> Param {
    param(name, Kind::Integer { min: 0, max: 3 }, None, help)
}

pub static WIDGETS: &[WidgetSchema] = &[
    WidgetSchema {
        name: "leg-events",
        summary: "how many leg-event sequences a walker with k legs has",
        params: &[param(
            "legs",
            Kind::Integer { min: 1, max: 12 },
            Some("2"),
            "the number of legs k the widget starts with",
        )],
        rules: None,
    },
    WidgetSchema {
        name: "support-polygon",
        summary: "drag feet and the centre of mass; see static stability",
        params: &[param(
            "legs",
            Kind::Integer { min: 3, max: 8 },
            Some("4"),
            "how many feet to start with",
        )],
        rules: None,
    },
    WidgetSchema {
        name: "gait-studio",
        summary: "a walker's feet through one gait cycle: support polygon, stability margin, footfall diagram",
        params: &[
            param(
                "gait",
                Kind::Choice {
                    options: &kinolab_locomotion::NAMED_IDS,
                },
                Some("quadruped-crawl"),
                "the named gait to start from",
            ),
            param(
                "duty_factor",
                Kind::Number {
                    min: 0.05,
                    max: 0.95,
                },
                None,
                "the duty factor β to start with (the gait's own when left out)",
            ),
            param(
                "task",
                Kind::Choice {
                    options: &["static-phases"],
                },
                None,
                "a graded task: `static-phases` asks for lift-off phases that keep the walker statically stable at the given β (which is then fixed)",
            ),
        ],
        rules: None,
    },
    WidgetSchema {
        name: "cpg-lab",
        summary: "four coupled oscillators, one per leg, locking into a gait: dots on circles, editable weights, kicks",
        params: &[
            param(
                "gait",
                Kind::Choice {
                    options: &kinolab_locomotion::QUADRUPED_IDS,
                },
                Some("quadruped-trot"),
                "the gait whose phase offsets the coupling pulls towards",
            ),
            param(
                "speed",
                Kind::Number { min: 0.2, max: 5.0 },
                None,
                "start with the speed (m/s) choosing the gait through the Froude number, for legs and stride 0.5 m long",
            ),
            param(
                "weight",
                Kind::Number { min: 0.0, max: 5.0 },
                Some("1"),
                "every coupling weight w_ij to start with (1/s)",
            ),
            param(
                "model",
                Kind::Choice {
                    options: &["phase", "van-der-pol"],
                },
                Some("phase"),
                "phase oscillators or Van der Pol oscillators",
            ),
            param(
                "task",
                Kind::Choice {
                    options: &["lock-trot"],
                },
                None,
                "a graded task: `lock-trot` asks for weights and a gait that lock into a trot from eight starts",
            ),
        ],
        rules: None,
    },
    WidgetSchema {
        name: "hexapod-walker",
        summary: "the lab's hexapod walking a gait by per-leg inverse kinematics, with its support polygon and joint angles",
        params: &[
            param(
                "gait",
                Kind::Choice {
                    options: &kinolab_locomotion::HEXAPOD_IDS,
                },
                Some("hexapod-tripod"),
                "the gait to start with",
            ),
            param(
                "stride",
                Kind::Number { min: 0.0, max: 0.3 },
                Some("0.06"),
                "the stride L (m)",
            ),
        ],
        rules: None,
    },
    WidgetSchema {
        name: "zmp-cart-table",
        summary: "a body on a cart-table over one foot: push it and watch the zero moment point",
        params: &[
            param(
                "height",
                Kind::Number { min: 0.3, max: 1.5 },
                Some("0.8"),
                "the centre of mass's height z_c (m)",
            ),
            param(
                "push",
                Kind::Number { min: 0.0, max: 2.0 },
                Some("0.2"),
                "the speed a push gives the body (m/s)",
            ),
            param(
                "task",
                Kind::Choice {
                    options: &["largest-push"],
                },
                None,
                "a graded task: `largest-push` asks for the largest push the ankle can still catch, to within 5 %",
            ),
        ],
        rules: None,
    },
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
    WidgetSchema {
        name: "component-lab",
        summary: "components talking through send, query, push, event and wiring patterns on a simulated clock: boxes, wires, message tokens, a sequence diagram; drag a port onto a service to wire it",
        params: &[
            param(
                "system",
                Kind::Choice {
                    options: &["out-of-order", "newest-vs-timed", "events", "robot"],
                },
                Some("robot"),
                "the example system to run",
            ),
            param(
                "task",
                Kind::Choice {
                    options: &["wire-robot"],
                },
                None,
                "a graded task: `wire-robot` leaves three of the robot system's connections to the learner, and the core runs the result",
            ),
        ],
        rules: None,
    },
    WidgetSchema {
        name: "which-pattern",
        summary: "five needs of a robot system, each to be met with a communication pattern; every choice is run",
        params: &[param(
            "task",
            Kind::Choice {
                options: &["match"],
            },
            None,
            "a graded task: `match` grades all five choices",
        )],
        rules: None,
    },
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
                Kind::Number {
                    min: 0.0,
                    max: 9999.0,
                },
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
        params: &[param(
            "mechanism",
            Kind::Choice {
                options: &["planar-3r", "rover-arm", "hexapod"],
            },
            Some("planar-3r"),
            "the catalogue mechanism to read",
        )],
        rules: None,
    },
    WidgetSchema {
        name: "scripted-vs-sensing",
        summary: "a pick-and-place cell in a closed and an open world",
        params: &[param(
            "gripper_tolerance",
            Kind::Number {
                min: 0.001,
                max: 0.05,
            },
            Some("0.01"),
            "how far off (m) the gripper may be and still grasp",
        )],
        rules: None,
    },
    WidgetSchema {
        name: "wheel-workbench",
        summary: "place wheels on a chassis; see C1, rank, the three degrees and the ICR",
        params: &[
            ROBOT,
            LAYOUT,
            degree("goal-maneuverability", "challenge: reach this δM"),
            degree(
                "max-steer-inputs",
                "with goal-maneuverability: use at most this many steering inputs",
            ),
            param(
                "goal-icr",
                Kind::Numbers {
                    min_count: 2,
                    max_count: 2,
                    min: -5.0,
                    max: 5.0,
                },
                None,
                "challenge: put the layout's ICR at `x, y` (m, robot frame)",
            ),
            degree("goal-mobility", "challenge: reach this δm"),
            degree("goal-dof", "challenge: reach this DOF"),
            param(
                "find-disagreeing",
                YES_NO,
                Some("no"),
                "challenge: pick the wheels that keep a stuck layout from moving",
            ),
        ],
        rules: Some(workbench_rules),
    },
    WidgetSchema {
        name: "wheel-drive",
        summary: "drive a robot by wheel spins or by twist; trail, ICR, wheel velocities",
        params: &[
            ROBOT,
            LAYOUT,
            param(
                "mode",
                Kind::Choice {
                    options: &["twist", "wheels"],
                },
                Some("twist"),
                "what the learner sets: the chassis twist, or each wheel's spin",
            ),
        ],
        rules: Some(robot_rules),
    },
    WidgetSchema {
        name: "frame-rotation",
        summary: "inertial and robot frames and the rotation R(θ) between them",
        params: &[param(
            "theta-deg",
            Kind::Number {
                min: -180.0,
                max: 180.0,
            },
            Some("30"),
            "the robot's heading θ to start with, degrees",
        )],
        rules: None,
    },
    WidgetSchema {
        name: "speed-profile",
        summary: "a trapezoidal speed profile: accelerate, cruise, brake over a distance",
        params: &[
            param(
                "distance",
                Kind::Number {
                    min: 0.05,
                    max: 5.0,
                },
                Some("1"),
                "distance to cover, m",
            ),
            param(
                "max-speed",
                Kind::Number {
                    min: 0.05,
                    max: 2.0,
                },
                Some("0.5"),
                "speed limit, m/s",
            ),
            param(
                "max-accel",
                Kind::Number { min: 0.1, max: 5.0 },
                Some("1"),
                "acceleration limit, m/s²",
            ),
        ],
        rules: None,
    },
    WidgetSchema {
        name: "controller-playground",
        summary: "the polar go-to-pose controller: runs, many starts, open vs closed loop, the gain region",
        params: &[
            param(
                "view",
                Kind::Choice {
                    options: &["run", "many", "open-vs-closed", "gains"],
                },
                Some("run"),
                "the tab to open",
            ),
            param(
                "start",
                triple(-360.0, 360.0),
                Some("-1, 0.5, 0"),
                "start pose `x, y, heading_deg` (x, y within ±5 m)",
            ),
            param(
                "goal",
                triple(-360.0, 360.0),
                Some("0, 0, 0"),
                "goal pose `x, y, heading_deg` (x, y within ±5 m)",
            ),
            param(
                "gains",
                triple(-100.0, 100.0),
                Some("3, 8, -1.5"),
                "`k_rho, k_alpha, k_beta`",
            ),
            param(
                "direction",
                Kind::Choice {
                    options: &["auto", "forward", "backward"],
                },
                Some("auto"),
                "which way the controller may drive",
            ),
            param(
                "slip",
                Kind::Number { min: 0.0, max: 0.5 },
                Some("0"),
                "largest fraction of motion lost to slip",
            ),
            param(
                "push",
                Kind::Number { min: 0.0, max: 0.2 },
                Some("0"),
                "largest random push, m/s",
            ),
            param(
                "seed",
                Kind::Integer {
                    min: 0,
                    max: 1_000_000_000,
                },
                Some("1"),
                "seed of slip and pushes",
            ),
            param(
                "control-rate",
                Kind::Number {
                    min: 0.0,
                    max: 1000.0,
                },
                Some("0"),
                "controller rate, Hz (0: continuous)",
            ),
            param(
                "max-wheel-speed",
                Kind::Number {
                    min: 0.0,
                    max: 100.0,
                },
                Some("0"),
                "wheel-speed limit, rad/s (0: none)",
            ),
            param(
                "plan",
                Kind::Text {
                    example: "line 1; arc 0.5 90; turn -90",
                    check: check_plan,
                },
                Some("line 1; arc 0.5 90; line 0.5"),
                "the open-loop plan: `line METRES`, `arc RADIUS DEGREES`, `turn DEGREES`, `;` between",
            ),
            param(
                "task",
                Kind::Choice {
                    options: &["reach-within", "spot-unstable"],
                },
                None,
                "a graded exercise",
            ),
            param(
                "time-limit",
                Kind::Number {
                    min: 0.5,
                    max: 30.0,
                },
                Some("3"),
                "reach-within: seconds allowed",
            ),
            param(
                "forward-only",
                YES_NO,
                Some("no"),
                "reach-within: the robot may not reverse",
            ),
            param(
                "sets",
                Kind::Groups {
                    size: 3,
                    min_groups: 2,
                    min: -100.0,
                    max: 100.0,
                },
                Some("3, 8, -1.5; 3, 2, -1.5; 3, 8, 1.5; 2, 6, -1"),
                "spot-unstable: gain sets `k_rho, k_alpha, k_beta`, `;` between",
            ),
        ],
        rules: Some(playground_rules),
    },
    WidgetSchema {
        name: "mechanism-viewer",
        summary: "a mechanism in 3D or plan/side view: joint sliders, drag-to-IK, frames, bounding shapes, model tree",
        params: &[
            param(
                "model",
                Kind::Catalogue {
                    of: Catalogue::Mechanisms,
                },
                Some("planar-2r"),
                "the mechanism to show",
            ),
            param(
                "view",
                Kind::Choice {
                    options: &["3d", "plan", "side"],
                },
                None,
                "the camera (default: plan for planar arms, side for the rover, else 3d)",
            ),
            param(
                "q",
                Kind::Numbers {
                    min_count: 1,
                    max_count: 64,
                    min: -360.0,
                    max: 360.0,
                },
                None,
                "driven joint values to start from: degrees, or metres for sliding joints",
            ),
            param("frames", YES_NO, Some("yes"), "draw every joint's frame"),
            param(
                "shapes",
                YES_NO,
                Some("no"),
                "draw bounding capsules and collisions",
            ),
            param(
                "obstacles",
                Kind::Groups {
                    size: 3,
                    min_groups: 1,
                    min: -10.0,
                    max: 10.0,
                },
                None,
                "round obstacles `x, y, radius`, `;` between",
            ),
            param(
                "drag",
                YES_NO,
                Some("yes"),
                "drag the tool and let IK follow",
            ),
            param("tree", YES_NO, Some("no"), "open the model tree"),
            param(
                "task",
                Kind::Choice {
                    options: &["reach", "spot-singular"],
                },
                None,
                "a graded exercise",
            ),
            param(
                "target",
                Kind::Numbers {
                    min_count: 2,
                    max_count: 3,
                    min: -10.0,
                    max: 10.0,
                },
                None,
                "reach: the point `x, y` or `x, y, z` (m)",
            ),
            param(
                "tolerance",
                Kind::Number {
                    min: 0.0001,
                    max: 0.999,
                },
                Some("0.01"),
                "reach: how close counts, m",
            ),
            param(
                "sets",
                Kind::Groups {
                    size: 0,
                    min_groups: 2,
                    min: -360.0,
                    max: 360.0,
                },
                None,
                "spot-singular: joint values to judge, `;` between (one value per driven joint)",
            ),
        ],
        rules: Some(viewer_rules),
    },
    WidgetSchema {
        name: "dh-link",
        summary: "one DH link built motion by motion, with its matrix; match a target frame",
        params: &[
            param(
                "convention",
                Kind::Choice {
                    options: &["standard", "modified"],
                },
                Some("standard"),
                "standard DH, or modified (Craig)",
            ),
            param(
                "row",
                dh_row(),
                Some("0, 0, 0, 0"),
                "the link to start from: `a, alpha_deg, d, theta_deg`",
            ),
            param(
                "target",
                dh_row(),
                None,
                "exercise: the frame to match, as a DH row",
            ),
        ],
        rules: Some(dh_rules),
    },
    WidgetSchema {
        name: "field-sandbox",
        summary: "paint a potential field with the five primitives; find its minima; follow it; try the remedies",
        params: &[
            param(
                "preset",
                Kind::Catalogue {
                    of: Catalogue::Fields,
                },
                Some("goal-behind-a-rock"),
                "the field to start from",
            ),
            param("streamlines", YES_NO, Some("yes"), "draw streamlines"),
            param("shading", YES_NO, Some("yes"), "shade the field's strength"),
            param(
                "unicycle",
                YES_NO,
                Some("no"),
                "also drive a unicycle along the field",
            ),
            param(
                "remedies",
                YES_NO,
                Some("no"),
                "show the remedies and the steps each needs",
            ),
            param(
                "editable",
                YES_NO,
                Some("yes"),
                "let the learner add, remove and change primitives",
            ),
            param(
                "task",
                Kind::Choice {
                    options: &["vector-at", "escape", "stand-off"],
                },
                None,
                "an exercise: compute the vector at a point, add one field to escape, or set a wall's range and gain",
            ),
            param(
                "at",
                Kind::Numbers {
                    min_count: 2,
                    max_count: 2,
                    min: -100.0,
                    max: 100.0,
                },
                None,
                "the point of `task: vector-at` (x, y in m)",
            ),
            param(
                "clearance",
                Kind::Number {
                    min: 0.05,
                    max: 2.0,
                },
                None,
                "how far from the wall the robot must stop in `task: stand-off` (m)",
            ),
        ],
        rules: Some(sandbox_rules),
    },
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

/// `a, alpha_deg, d, theta_deg`, with a and d within ±2 m (angles are
/// checked to ±360°, lengths more tightly by the rule below).
const fn dh_row() -> Kind {
    Kind::Numbers {
        min_count: 4,
        max_count: 4,
        min: -360.0,
        max: 360.0,
    }
}

fn dh_rules(p: &Params) -> Result<(), String> {
    for key in ["row", "target"] {
        if let Some([a, _, d, _]) = p.numbers(key)
            && (a.abs() > 2.0 || d.abs() > 2.0)
        {
            return Err(format!("parameter `{key}`: a and d must be within ±2 m"));
        }
    }
    Ok(())
}

/// Not both `robot` and `layout`.
fn robot_rules(p: &Params) -> Result<(), String> {
    if p.given("robot") && p.given("layout") {
        return Err("give either `robot` or `layout`, not both".into());
    }
    Ok(())
}

/// The robot, from `robot`, `layout` or the default.
pub fn robot_of(p: &Params) -> Result<Chassis, String> {
    match (p.text("layout"), p.choice("robot")) {
        (Some(code), _) => Chassis::from_compact("Layout", code).map_err(|e| e.to_string()),
        (None, id) => kinolab_wheels::catalogue::robot(id.unwrap_or("differential-drive"))
            .map_err(|e| e.to_string()),
    }
}

fn workbench_rules(p: &Params) -> Result<(), String> {
    robot_rules(p)?;
    let challenges = [
        "goal-maneuverability",
        "goal-icr",
        "goal-mobility",
        "goal-dof",
    ]
    .iter()
    .filter(|c| p.given(c))
    .count()
        + usize::from(p.yes("find-disagreeing"));
    if challenges > 1 {
        return Err("a workbench takes at most one challenge".into());
    }
    if p.given("max-steer-inputs") && !p.given("goal-maneuverability") {
        return Err("`max-steer-inputs` goes with `goal-maneuverability`".into());
    }
    if p.yes("find-disagreeing") && robot_of(p)?.disagreement().is_none() {
        return Err("`find-disagreeing` needs a layout that cannot move".into());
    }
    Ok(())
}

fn playground_rules(p: &Params) -> Result<(), String> {
    for key in ["start", "goal"] {
        if let Some([x, y, _]) = p.numbers(key)
            && (x.abs() > 5.0 || y.abs() > 5.0)
        {
            return Err(format!("parameter `{key}`: x and y must be within ±5 m"));
        }
    }
    let gains = p.numbers("gains").unwrap_or_default();
    if let [r, a, b] = gains {
        Gains::new(*r, *a, *b).map_err(|e| format!("parameter `gains`: {e}"))?;
    }
    let task = p.choice("task");
    for key in ["time-limit", "forward-only"] {
        if p.given(key) && task != Some("reach-within") {
            return Err(format!("`{key}` goes with `task: reach-within`"));
        }
    }
    if p.given("sets") && task != Some("spot-unstable") {
        return Err("`sets` goes with `task: spot-unstable`".into());
    }
    Ok(())
}

fn viewer_rules(p: &Params) -> Result<(), String> {
    let model = mechanism(p.choice("model").unwrap_or("planar-2r")).map_err(|e| e.to_string())?;
    let driven = (0..model.dof()).filter(|&v| model.is_driven(v)).count();
    if let Some(q) = p.numbers("q")
        && q.len() != driven
    {
        return Err(format!(
            "`q` needs {driven} values (one per driven joint of `{}`), got {}",
            model.name(),
            q.len()
        ));
    }
    match p.choice("task") {
        Some("reach") if p.numbers("target").is_none() => {
            Err("`task: reach` needs `target: x, y` or `target: x, y, z`".into())
        }
        Some("spot-singular") => match p.groups("sets") {
            None => Err("`task: spot-singular` needs `sets: q1, q2; q1, q2; …`".into()),
            Some(sets) if sets.iter().any(|s| s.len() != driven) => Err(format!(
                "each group in `sets` needs {driven} values, one per driven joint"
            )),
            Some(_) => Ok(()),
        },
        _ => Ok(()),
    }
}

fn sandbox_rules(p: &Params) -> Result<(), String> {
    let task = p.choice("task");
    if task == Some("vector-at") && p.numbers("at").is_none() {
        return Err("`task: vector-at` needs `at: x, y`".into());
    }
    if p.given("at") && task != Some("vector-at") {
        return Err("`at` goes with `task: vector-at`".into());
    }
    if p.given("clearance") && task != Some("stand-off") {
        return Err("`clearance` goes with `task: stand-off`".into());
    }
    let preset = p.choice("preset").unwrap_or("goal-behind-a-rock");
    let field = kinolab_fields::catalogue::preset(preset)
        .ok_or_else(|| format!("no field preset `{preset}`"))?
        .field()
        .map_err(|e| e.to_string())?;
    if task == Some("stand-off")
        && !field
            .primitives
            .iter()
            .any(|q| matches!(q.source, kinolab_fields::Source::Perpendicular { .. }))
    {
        return Err(format!(
            "`task: stand-off` needs a preset with a wall; `{preset}` has none"
        ));
    }
    if matches!(task, Some("escape" | "stand-off")) && field.goal.is_none() {
        return Err(format!(
            "`task` needs a preset with a goal; `{preset}` has none"
        ));
    }
    Ok(())
}

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
