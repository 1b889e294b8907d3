//! Widgets for components that talk through patterns.

use crate::{Kind, WidgetSchema};

use super::param;

/// A need of "which pattern?" and the pattern chosen for it (none at first).
const fn pick(need: &'static str, help: &'static str) -> crate::Param {
    param(
        need,
        Kind::Choice {
            options: &[
                "send",
                "query",
                "push-newest",
                "push-timed",
                "event",
                "wiring",
            ],
        },
        None,
        help,
    )
}

pub(crate) static WIDGETS: &[WidgetSchema] = &[
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
            param(
                "latency",
                Kind::Number { min: 0.0, max: 0.5 },
                None,
                "every connection's fixed latency, s (the system's own when left out)",
            ),
            param(
                "jitter",
                Kind::Number { min: 0.0, max: 0.5 },
                None,
                "every connection's seeded jitter on top of the latency, s (the system's own when left out)",
            ),
            param(
                "loss",
                Kind::Number { min: 0.0, max: 0.5 },
                None,
                "the chance that a message is lost, 0 to 0.5 (the system's own when left out)",
            ),
            param(
                "period",
                Kind::Number {
                    min: 0.02,
                    max: 1.0,
                },
                Some("0.1"),
                "the period of the push-timed services and of the robot's base, s",
            ),
            param(
                "prescale",
                Kind::Integer { min: 1, max: 10 },
                Some("3"),
                "push-timed subscribers take every n-th update",
            ),
        ],
        rules: None,
    },
    WidgetSchema {
        name: "which-pattern",
        summary: "five needs of a robot system, each to be met with a communication pattern; every choice is run",
        params: &[
            param(
                "task",
                Kind::Choice {
                    options: &["match"],
                },
                None,
                "a graded task: `match` grades all five choices",
            ),
            pick(
                "bumper",
                "the pattern chosen to tell the behaviour when the bumper is hit",
            ),
            pick(
                "scan",
                "the pattern chosen for a laser scan for three consumers, 10 times a second",
            ),
            pick("path", "the pattern chosen for \"give me a path to X\""),
            pick(
                "velocity",
                "the pattern chosen for a velocity command to the base",
            ),
            pick(
                "source",
                "the pattern chosen to switch where the motion component takes its path from",
            ),
        ],
        rules: None,
    },
];
