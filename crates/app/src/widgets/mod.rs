//! The registry of live widgets that lessons embed by name.
//!
//! A lesson writes a fenced `widget` block whose first line is one of the
//! names in [`REGISTRY`]; its `key: value` lines are the parameters. Every
//! number a widget shows comes from a core crate, never from the UI.

mod chassis_view;
mod controller_field;
mod controller_params;
mod controller_playground;
mod dh_link;
mod frame_rotation;
mod leg_events;
mod mechanism_viewer;
mod scene3d;
mod scripted_vs_sensing;
mod speed_profile;
mod support_polygon;
mod wheel_drive;
mod wheel_workbench;

use kinolab_lessons::WidgetSpec;

/// A widget living inside a lesson.
pub trait LabWidget {
    fn ui(&mut self, ui: &mut egui::Ui);

    /// What a link must carry to reproduce this widget as the learner left
    /// it (URL-safe text), or `None` while it is as the lesson set it up.
    fn state(&self) -> Option<String> {
        None
    }

    /// Take back a [`LabWidget::state`] from a link; ignore what does not parse.
    fn restore(&mut self, _state: &str) {}
}

type Constructor = fn(&WidgetSpec) -> Result<Box<dyn LabWidget>, String>;

/// Every widget a lesson can name: name, constructor, one-line description.
pub const REGISTRY: &[(&str, Constructor, &str)] = &[
    (
        "leg-events",
        leg_events::create,
        "how many leg-event sequences a walker with k legs has",
    ),
    (
        "support-polygon",
        support_polygon::create,
        "drag feet and the centre of mass; see static stability",
    ),
    (
        "scripted-vs-sensing",
        scripted_vs_sensing::create,
        "a pick-and-place cell in a closed and an open world",
    ),
    (
        "wheel-workbench",
        wheel_workbench::create,
        "place wheels on a chassis; see C1, rank, the three degrees and the ICR",
    ),
    (
        "wheel-drive",
        wheel_drive::create,
        "drive a robot by wheel spins or by twist; trail, ICR, wheel velocities",
    ),
    (
        "frame-rotation",
        frame_rotation::create,
        "inertial and robot frames and the rotation R(theta) between them",
    ),
    (
        "speed-profile",
        speed_profile::create,
        "a trapezoidal speed profile: accelerate, cruise, brake over a distance",
    ),
    (
        "controller-playground",
        controller_playground::create,
        "the polar go-to-pose controller: runs, many starts, open vs closed loop, the gain region",
    ),
    (
        "mechanism-viewer",
        mechanism_viewer::create,
        "a mechanism in 3D or plan/side view: joint sliders, drag-to-IK, frames, bounding shapes, model tree",
    ),
    (
        "dh-link",
        dh_link::create,
        "one DH link built motion by motion, with its matrix; match a target frame",
    ),
];

/// Make the widget a lesson block names, or say why not.
pub fn create(spec: &WidgetSpec) -> Result<Box<dyn LabWidget>, String> {
    match REGISTRY.iter().find(|(name, _, _)| *name == spec.name) {
        Some((_, constructor, _)) => constructor(spec),
        None => {
            let known: Vec<&str> = REGISTRY.iter().map(|(name, _, _)| *name).collect();
            Err(format!(
                "There is no widget named `{}` (lesson line {}). Known widgets: {}.",
                spec.name,
                spec.line,
                known.join(", ")
            ))
        }
    }
}

/// A numeric parameter within `range`, or `default` when absent.
pub(crate) fn number_param(
    spec: &WidgetSpec,
    key: &str,
    default: f64,
    range: std::ops::RangeInclusive<f64>,
) -> Result<f64, String> {
    let Some(text) = spec.param(key) else {
        return Ok(default);
    };
    match text.parse::<f64>() {
        Ok(v) if range.contains(&v) => Ok(v),
        _ => Err(format!(
            "Parameter `{key}` must be a number from {} to {}, found `{text}`.",
            range.start(),
            range.end()
        )),
    }
}

/// A yes/no parameter, or `default` when absent.
pub(crate) fn yes_no_param(spec: &WidgetSpec, key: &str, default: bool) -> Result<bool, String> {
    match spec.param(key) {
        None => Ok(default),
        Some("yes") => Ok(true),
        Some("no") => Ok(false),
        Some(other) => Err(format!(
            "Parameter `{key}` must be yes or no, found `{other}`."
        )),
    }
}

/// Comma-separated numbers, or an error naming the parameter.
pub(crate) fn number_list(key: &str, text: &str) -> Result<Vec<f64>, String> {
    text.split(',')
        .map(|t| {
            t.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| {
                    format!(
                        "Parameter `{key}` needs numbers separated by commas, found `{}`.",
                        t.trim()
                    )
                })
        })
        .collect()
}

/// Reject parameters the widget does not know, so typos are visible.
pub(crate) fn known_params(spec: &WidgetSpec, known: &[&str]) -> Result<(), String> {
    for (key, _) in &spec.params {
        if !known.contains(&key.as_str()) {
            return Err(format!(
                "Widget `{}` has no parameter `{key}` (it takes: {}).",
                spec.name,
                known.join(", ")
            ));
        }
    }
    Ok(())
}

/// A widget block as a lesson would write it, for tests.
#[cfg(test)]
pub(crate) fn test_spec(name: &str, params: &[(&str, &str)]) -> WidgetSpec {
    WidgetSpec {
        name: name.into(),
        params: params
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect(),
        line: 1,
    }
}

/// A value for display: rounding noise smaller than `resolution` becomes 0,
/// so it never prints as "-0.00".
pub(crate) fn shown(x: f64, resolution: f64) -> f64 {
    if x.abs() < resolution { 0.0 } else { x }
}

/// Group digits in threes with thin spaces: 39 916 800.
pub(crate) fn group_digits(n: u128) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push('\u{2009}');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(name: &str, params: &[(&str, &str)]) -> WidgetSpec {
        WidgetSpec {
            name: name.into(),
            params: params
                .iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect(),
            line: 12,
        }
    }

    #[test]
    fn every_registered_widget_builds_with_defaults() {
        for (name, _, _) in REGISTRY {
            assert!(create(&spec(name, &[])).is_ok(), "{name}");
        }
    }

    #[test]
    fn unknown_names_and_bad_parameters_explain_themselves() {
        let Err(message) = create(&spec("flux-capacitor", &[])) else {
            panic!()
        };
        assert!(
            message.starts_with("There is no widget named `flux-capacitor` (lesson line 12)."),
            "{message}"
        );
        assert!(message.contains("support-polygon"));
        let Err(message) = create(&spec("leg-events", &[("legs", "many")])) else {
            panic!()
        };
        assert_eq!(
            message,
            "Parameter `legs` must be a number from 1 to 12, found `many`."
        );
        let Err(message) = create(&spec("support-polygon", &[("colour", "red")])) else {
            panic!()
        };
        assert!(message.contains("has no parameter `colour`"), "{message}");
    }

    #[test]
    fn digits_are_grouped() {
        assert_eq!(group_digits(39_916_800), "39\u{2009}916\u{2009}800");
        assert_eq!(group_digits(120), "120");
        assert_eq!(group_digits(5040), "5\u{2009}040");
    }
}
