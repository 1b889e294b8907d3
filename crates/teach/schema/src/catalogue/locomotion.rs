//! Widgets for legs: events, support, gaits, oscillators, a walking hexapod, balance.

use crate::{Kind, WidgetSchema};

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
];
