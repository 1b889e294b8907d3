//! Widgets for closed and open worlds.

use crate::{Kind, WidgetSchema};

use super::param;

pub(crate) static WIDGETS: &[WidgetSchema] = &[WidgetSchema {
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
}];
