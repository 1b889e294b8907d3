//! Widgets for components that talk through patterns.

use crate::{Kind, WidgetSchema};

use super::param;

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
];
