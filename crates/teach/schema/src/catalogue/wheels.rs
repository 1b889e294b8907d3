//! Widgets for wheeled robots.

use kinolab_wheels::Chassis;

use crate::{Catalogue, Kind, Param, Params, WidgetSchema};

use super::{YES_NO, degree, param};

pub(crate) static WIDGETS: &[WidgetSchema] = &[
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
            param(
                "chosen",
                Kind::Numbers {
                    min_count: 1,
                    max_count: kinolab_wheels::MAX_WHEELS,
                    min: 1.0,
                    max: kinolab_wheels::MAX_WHEELS as f64,
                },
                None,
                "find-disagreeing: the wheels picked so far, by number (1 is the first wheel)",
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
            param(
                "forward",
                Kind::Number {
                    min: -1.0,
                    max: 1.0,
                },
                Some("0.3"),
                "twist: the speed forward, m/s",
            ),
            param(
                "sideways",
                Kind::Number {
                    min: -1.0,
                    max: 1.0,
                },
                Some("0"),
                "twist: the speed to the left, m/s",
            ),
            param(
                "turn",
                Kind::Number {
                    min: -2.0,
                    max: 2.0,
                },
                Some("0.4"),
                "twist: the turn rate, rad/s (anticlockwise)",
            ),
            param(
                "spins",
                Kind::Numbers {
                    min_count: 1,
                    max_count: kinolab_wheels::MAX_WHEELS,
                    min: -20.0,
                    max: 20.0,
                },
                None,
                "wheels: each wheel's spin, rad/s, one per wheel in order (a passive wheel's is ignored; default: the spins that make the twist)",
            ),
        ],
        rules: Some(drive_rules),
    },
    WidgetSchema {
        name: "frame-rotation",
        summary: "inertial and robot frames and the rotation R(θ) between them",
        params: &[
            param(
                "theta-deg",
                Kind::Number {
                    min: -180.0,
                    max: 180.0,
                },
                Some("30"),
                "the robot's heading θ to start with, degrees",
            ),
            param(
                "motion",
                Kind::Numbers {
                    min_count: 3,
                    max_count: 3,
                    min: -1.0,
                    max: 1.0,
                },
                Some("1, 0, 0"),
                "the motion in the world frame to start with: `x speed, y speed, turn rate` (m/s, m/s, rad/s)",
            ),
        ],
        rules: None,
    },
];

/// Not both `robot` and `layout`.
fn robot_rules(p: &Params) -> Result<(), String> {
    if p.given("robot") && p.given("layout") {
        return Err("give either `robot` or `layout`, not both".into());
    }
    Ok(())
}

/// One spin per wheel, and only with `mode: wheels`.
fn drive_rules(p: &Params) -> Result<(), String> {
    robot_rules(p)?;
    if let Some(spins) = p.numbers("spins") {
        if p.choice("mode") != Some("wheels") {
            return Err("`spins` goes with `mode: wheels`".into());
        }
        let wheels = robot_of(p)?.wheels().len();
        if spins.len() != wheels {
            return Err(format!(
                "`spins` needs {wheels} values (one per wheel), got {}",
                spins.len()
            ));
        }
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
    if let Some(chosen) = p.numbers("chosen") {
        if !p.yes("find-disagreeing") {
            return Err("`chosen` goes with `find-disagreeing: yes`".into());
        }
        let wheels = robot_of(p)?.wheels().len();
        if let Some(bad) = chosen
            .iter()
            .find(|n| n.fract() != 0.0 || **n > wheels as f64)
        {
            return Err(format!(
                "`chosen`: {bad} is not a wheel's number (1 to {wheels})"
            ));
        }
    }
    Ok(())
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
