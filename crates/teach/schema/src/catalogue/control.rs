//! Widgets for motion control.

use kinolab_control::{Gains, Segment};

use crate::{Kind, Params, WidgetSchema};

use super::{YES_NO, param, triple};

pub(crate) static WIDGETS: &[WidgetSchema] = &[
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
                "starts",
                Kind::Integer { min: 4, max: 100 },
                Some("24"),
                "many: how many starts on the 1 m circle around the goal",
            ),
            param(
                "start-heading",
                Kind::Number {
                    min: -180.0,
                    max: 180.0,
                },
                Some("0"),
                "many: the heading every start faces, degrees",
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
            param(
                "marked",
                Kind::Numbers {
                    min_count: 1,
                    max_count: 64,
                    min: 1.0,
                    max: 64.0,
                },
                None,
                "spot-unstable: the gain sets marked unstable so far, by number (1 is the first)",
            ),
        ],
        rules: Some(playground_rules),
    },
];

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
    if let Some(marked) = p.numbers("marked") {
        if task != Some("spot-unstable") {
            return Err("`marked` goes with `task: spot-unstable`".into());
        }
        let sets = p.groups("sets").map_or(0, <[_]>::len);
        if let Some(bad) = marked
            .iter()
            .find(|n| n.fract() != 0.0 || **n > sets as f64)
        {
            return Err(format!(
                "`marked`: {bad} is not a gain set's number (1 to {sets})"
            ));
        }
    }
    Ok(())
}

fn check_plan(text: &str) -> Result<(), String> {
    Segment::parse_list(text)
        .map(|_| ())
        .map_err(|e| format!("is not a plan: {e}"))
}
