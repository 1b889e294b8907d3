//! Widgets for closed and open worlds.

use crate::{Kind, WidgetSchema};

use super::param;

pub(crate) static WIDGETS: &[WidgetSchema] = &[WidgetSchema {
    name: "scripted-vs-sensing",
    summary: "a pick-and-place cell in a closed and an open world",
    params: &[
        param(
            "gripper_tolerance",
            Kind::Number {
                min: 0.001,
                max: 0.05,
            },
            Some("0.01"),
            "how far off (m) the gripper may be and still grasp",
        ),
        param(
            "placement_error",
            Kind::Number {
                min: 0.0,
                max: 0.05,
            },
            Some("0.015"),
            "how far (m) the parts stray from their nominal spot",
        ),
        param(
            "sensor_error",
            Kind::Number {
                min: 0.0,
                max: 0.03,
            },
            Some("0.002"),
            "how far off (m) the sensing robot's measurement of a part may be",
        ),
        param(
            "seed",
            Kind::Integer {
                min: 0,
                max: 1_000_000,
            },
            Some("1"),
            "the batch of parts (\"New batch of parts\" counts it up)",
        ),
    ],
    rules: None,
}];
