//! The registry: which constructor builds each widget a lesson can name.
//!
//! Names, parameters and their checks live in the widget schema
//! (`kinolab-schema`), shared with the lesson checker, the command line and
//! the JS API; this list only pairs each schema entry with the code that
//! draws it.

use kinolab_lessons::WidgetSpec;

use crate::widget::{Constructor, LabWidget};
use crate::{
    architecture, autonomy, behaviour, code, components, control, design, fields, locomotion,
    mechanism, wheels,
};

/// Every widget's constructor, by its schema name.
pub const CONSTRUCTORS: &[(&str, Constructor)] = &[
    ("leg-events", locomotion::leg_events::create),
    ("support-polygon", locomotion::support_polygon::create),
    ("gait-studio", locomotion::gait_studio::create),
    ("cpg-lab", locomotion::cpg_lab::create),
    ("hexapod-walker", locomotion::walker::create),
    ("zmp-cart-table", locomotion::zmp::create),
    ("grid-planner", architecture::grid_planner::create),
    ("architecture-arena", architecture::arena::create),
    ("sensing-routes", architecture::routes::create),
    ("component-lab", components::lab::create),
    ("which-pattern", components::which_pattern::create),
    ("ant-beach", design::ant_beach::create),
    ("three-slots", design::three_slots::create),
    ("technology-churn", design::churn::create),
    ("morphology-builder", design::morphology::create),
    ("scripted-vs-sensing", autonomy::scripted_vs_sensing::create),
    ("wheel-workbench", wheels::workbench::create),
    ("wheel-drive", wheels::drive::create),
    ("frame-rotation", wheels::frame_rotation::create),
    ("speed-profile", control::speed_profile::create),
    ("controller-playground", control::playground::create),
    ("mechanism-viewer", mechanism::viewer::create),
    ("dh-link", mechanism::dh_link::create),
    ("arm-statics", mechanism::holding::create),
    ("arm-fall", mechanism::falling::create),
    ("field-sandbox", fields::sandbox::create),
    ("behaviour-arena", behaviour::arena::create),
    ("braitenberg", behaviour::braitenberg::create),
    ("blend-or-choose", behaviour::frog::create),
    ("code", code::create),
];

/// The widgets that simulate something over time: each has the one
/// player, links that carry its instant, and a run the command line
/// reproduces ("Save run").
pub const SIMULATING: &[&str] = &[
    "controller-playground",
    "behaviour-arena",
    "braitenberg",
    "field-sandbox",
    "grid-planner",
    "architecture-arena",
    "component-lab",
    "gait-studio",
    "hexapod-walker",
    "cpg-lab",
    "zmp-cart-table",
    "ant-beach",
];

/// Make the widget a lesson block names, or say why not (the same message
/// the lesson checker gives, with the block's line).
pub fn create(spec: &WidgetSpec) -> Result<Box<dyn LabWidget>, String> {
    let params = kinolab_schema::validate(spec).map_err(|e| format!("line {}: {e}", spec.line))?;
    let (_, constructor) = CONSTRUCTORS
        .iter()
        .find(|(name, _)| *name == spec.name)
        .ok_or_else(|| format!("widget `{}` has a schema but no constructor", spec.name))?;
    constructor(&params)
}

/// A widget block as a lesson would write it (for tests, and for hosts that
/// build a widget without a lesson).
pub fn spec(name: &str, params: &[(&str, &str)]) -> WidgetSpec {
    WidgetSpec {
        name: name.into(),
        params: params
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect(),
        line: 1,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn schema_and_registry_list_the_same_widgets() {
        let schema: Vec<&str> = kinolab_schema::widgets().map(|w| w.name).collect();
        let built: Vec<&str> = CONSTRUCTORS.iter().map(|(n, _)| *n).collect();
        assert_eq!(schema, built);
    }

    #[test]
    fn every_widget_builds_with_its_defaults() {
        for (name, _) in CONSTRUCTORS {
            if let Err(e) = create(&spec(name, &[])) {
                panic!("{name}: {e}");
            }
        }
    }

    #[test]
    fn bad_blocks_say_what_and_where() {
        let Err(message) = create(&spec("flux-capacitor", &[])) else {
            panic!("an unknown widget was built")
        };
        assert!(
            message.starts_with("line 1: there is no widget named `flux-capacitor`"),
            "{message}"
        );
        let Err(message) = create(&spec("leg-events", &[("legs", "many")])) else {
            panic!("a bad parameter was accepted")
        };
        assert_eq!(
            message,
            "line 1: parameter `legs` must be a whole number from 1 to 12, found `many`"
        );
    }
}
