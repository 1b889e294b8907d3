//! Widgets for legs: events, support, gaits, oscillators, a walking hexapod, balance.

use crate::{Kind, Params, WidgetSchema};

use super::param;

pub(crate) static WIDGETS: &[WidgetSchema] = &[
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
        params: &[
            param(
                "legs",
                Kind::Integer { min: 3, max: 8 },
                Some("4"),
                "how many feet to start with",
            ),
            param(
                "feet",
                Kind::Groups {
                    size: 2,
                    min_groups: 3,
                    min: -GROUND_X,
                    max: GROUND_X,
                },
                None,
                "where the feet stand, `x, y` in metres (x forwards, y to the left, within ±0.5 and ±0.32 m), one per leg separated by `;` (spread evenly around the body when left out)",
            ),
            param(
                "lifted",
                Kind::Numbers {
                    min_count: 1,
                    max_count: 8,
                    min: 1.0,
                    max: 8.0,
                },
                None,
                "the numbers of the feet lifted off the ground (every foot stands when left out)",
            ),
            param(
                "com",
                Kind::Numbers {
                    min_count: 2,
                    max_count: 2,
                    min: -GROUND_X,
                    max: GROUND_X,
                },
                Some("0, 0"),
                "the centre of mass seen from above, `x, y` in metres (within ±0.5 and ±0.32 m)",
            ),
        ],
        rules: Some(support_rules),
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
                "stride",
                Kind::Number { min: 0.0, max: 0.4 },
                None,
                "the stride L (m) to start with (the gait's own when left out)",
            ),
            param(
                "com",
                Kind::Numbers {
                    min_count: 2,
                    max_count: 2,
                    min: -0.2,
                    max: 0.2,
                },
                Some("0, 0"),
                "the centre of mass in the body frame, `x, y` in metres (x forwards, y to the left)",
            ),
            param(
                "phases",
                Kind::Numbers {
                    min_count: 1,
                    max_count: 8,
                    min: 0.0,
                    max: 0.999,
                },
                None,
                "each leg's lift-off phase φ, in the gait's leg order (the gait's own when left out; all 0 with the task)",
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
        rules: Some(studio_rules),
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
                "weights",
                Kind::Groups {
                    size: 4,
                    min_groups: 4,
                    min: 0.0,
                    max: 5.0,
                },
                None,
                "each coupling weight w_ij (1/s): four rows LF, RF, LH, RH of four, row i pulled by column j, separated by `;` (the diagonal is ignored; every weight `weight` when left out)",
            ),
            param(
                "frequency",
                Kind::Number { min: 0.2, max: 3.0 },
                Some("1"),
                "the oscillators' frequency f (Hz) when no speed chooses it",
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
        rules: Some(cpg_rules),
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
            param(
                "lift",
                Kind::Number {
                    min: 0.0,
                    max: 0.06,
                },
                Some("0.03"),
                "how high a swinging foot is lifted (m)",
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
];

/// The ground the support-polygon widget shows: ±x by ±y metres.
const GROUND_X: f64 = 0.5;
const GROUND_Y: f64 = 0.32;

/// One foot per leg, lifted feet named by number, everything on the ground shown.
fn support_rules(p: &Params) -> Result<(), String> {
    let legs = p.integer("legs").unwrap_or(0);
    let feet = p.groups("feet");
    if let Some(feet) = feet
        && feet.len() as i64 != legs
    {
        return Err(format!(
            "parameter `feet` needs one foot per leg ({legs}), found {}",
            feet.len()
        ));
    }
    let points = feet.into_iter().flatten().map(Vec::as_slice);
    if points
        .chain(p.numbers("com"))
        .any(|xy| xy.get(1).is_some_and(|y| y.abs() > GROUND_Y))
    {
        return Err(format!(
            "parameter `feet` and `com`: y must be within ±{GROUND_Y} m"
        ));
    }
    for &n in p.numbers("lifted").unwrap_or_default() {
        if n.fract() != 0.0 || n < 1.0 || n > legs as f64 {
            return Err(format!(
                "parameter `lifted` names feet by number, 1 to {legs}, found `{n}`"
            ));
        }
    }
    Ok(())
}

/// A lift-off phase for each of the gait's legs.
fn studio_rules(p: &Params) -> Result<(), String> {
    let legs = p
        .choice("gait")
        .and_then(kinolab_locomotion::named)
        .map_or(0, |g| g.legs.len());
    match p.numbers("phases") {
        Some(phases) if phases.len() != legs => Err(format!(
            "parameter `phases` needs one phase per leg of the gait ({legs}), found {}",
            phases.len()
        )),
        _ => Ok(()),
    }
}

/// Four rows of weights.
fn cpg_rules(p: &Params) -> Result<(), String> {
    match p.groups("weights") {
        Some(rows) if rows.len() != 4 => Err(format!(
            "parameter `weights` needs four rows of four, found {} rows",
            rows.len()
        )),
        _ => Ok(()),
    }
}
