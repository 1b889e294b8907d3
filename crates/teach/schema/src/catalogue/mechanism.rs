//! Widgets for mechanisms.

use kinolab_mechanism::catalogue::mechanism;

use crate::{Catalogue, Kind, Params, WidgetSchema};

use super::{YES_NO, param};

pub(crate) static WIDGETS: &[WidgetSchema] = &[
    WidgetSchema {
        name: "mechanism-viewer",
        summary: "a mechanism in 3D or plan/side view: joint sliders, drag-to-IK, frames, bounding shapes, model tree",
        params: &[
            param(
                "model",
                Kind::Catalogue {
                    of: Catalogue::Mechanisms,
                },
                Some("planar-2r"),
                "the mechanism to show",
            ),
            param(
                "view",
                Kind::Choice {
                    options: &["3d", "plan", "side"],
                },
                None,
                "the camera (default: plan for planar arms, side for the rover, else 3d)",
            ),
            param(
                "q",
                Kind::Numbers {
                    min_count: 1,
                    max_count: 64,
                    min: -360.0,
                    max: 360.0,
                },
                None,
                "driven joint values to start from: degrees, or metres for sliding joints",
            ),
            param("frames", YES_NO, Some("yes"), "draw every joint's frame"),
            param(
                "shapes",
                YES_NO,
                Some("no"),
                "draw bounding capsules and collisions",
            ),
            param(
                "obstacles",
                Kind::Groups {
                    size: 3,
                    min_groups: 1,
                    min: -10.0,
                    max: 10.0,
                },
                None,
                "round obstacles `x, y, radius`, `;` between",
            ),
            param(
                "drag",
                YES_NO,
                Some("yes"),
                "drag the tool and let IK follow",
            ),
            param("tree", YES_NO, Some("no"), "open the model tree"),
            param(
                "task",
                Kind::Choice {
                    options: &["reach", "spot-singular"],
                },
                None,
                "a graded exercise",
            ),
            param(
                "target",
                Kind::Numbers {
                    min_count: 2,
                    max_count: 3,
                    min: -10.0,
                    max: 10.0,
                },
                None,
                "reach: the point `x, y` or `x, y, z` (m)",
            ),
            param(
                "tolerance",
                Kind::Number {
                    min: 0.0001,
                    max: 0.999,
                },
                Some("0.01"),
                "reach: how close counts, m",
            ),
            param(
                "sets",
                Kind::Groups {
                    size: 0,
                    min_groups: 2,
                    min: -360.0,
                    max: 360.0,
                },
                None,
                "spot-singular: joint values to judge, `;` between (one value per driven joint)",
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
                "spot-singular: the configurations marked singular so far, by number (1 is the first)",
            ),
        ],
        rules: Some(viewer_rules),
    },
    WidgetSchema {
        name: "dh-link",
        summary: "one DH link built motion by motion, with its matrix; match a target frame",
        params: &[
            param(
                "convention",
                Kind::Choice {
                    options: &["standard", "modified"],
                },
                Some("standard"),
                "standard DH, or modified (Craig)",
            ),
            param(
                "row",
                dh_row(),
                Some("0, 0, 0, 0"),
                "the link to start from: `a, alpha_deg, d, theta_deg`",
            ),
            param(
                "target",
                dh_row(),
                None,
                "exercise: the frame to match, as a DH row",
            ),
        ],
        rules: Some(dh_rules),
    },
    WidgetSchema {
        name: "arm-statics",
        summary: "an arm in a vertical plane held still: each joint's torque as a bar as you drag the pose, a payload at the tool, the pose that needs least torque, springy joints and the sag",
        params: &[
            param(
                "model",
                Kind::Choice {
                    options: &["vertical-2r", "vertical-3r"],
                },
                Some("vertical-3r"),
                "the arm: two or three links in a vertical plane",
            ),
            param(
                "q",
                Kind::Numbers {
                    min_count: 1,
                    max_count: 3,
                    min: -180.0,
                    max: 180.0,
                },
                None,
                "the joints to start from, degrees (0 is level, up is positive)",
            ),
            param(
                "payload",
                Kind::Number {
                    min: 0.0,
                    max: 10.0,
                },
                Some("1"),
                "the mass at the tool, kg",
            ),
            param(
                "stiffness",
                Kind::Number {
                    min: 100.0,
                    max: 50000.0,
                },
                None,
                "every joint's stiffness, N·m/rad (rigid joints when left out)",
            ),
            param(
                "exaggerate",
                YES_NO,
                Some("yes"),
                "draw the sag larger than it is (the true millimetres are printed)",
            ),
        ],
        rules: None,
    },
    WidgetSchema {
        name: "arm-fall",
        summary: "an arm let go under gravity: its forward dynamics played step by step, its energy plotted, damping, and how far the integrator's energy strays at two step sizes",
        params: &[
            param(
                "model",
                Kind::Choice {
                    options: &["double-pendulum", "vertical-2r", "vertical-3r"],
                },
                Some("double-pendulum"),
                "the arm that falls",
            ),
            param(
                "q",
                Kind::Numbers {
                    min_count: 1,
                    max_count: 3,
                    min: -180.0,
                    max: 180.0,
                },
                None,
                "where the joints start, degrees",
            ),
            param(
                "damping",
                Kind::Number { min: 0.0, max: 2.0 },
                Some("0"),
                "viscous damping at every joint, N·m·s/rad",
            ),
            param(
                "step",
                Kind::Number {
                    min: 0.5,
                    max: 50.0,
                },
                Some("10"),
                "the integration step, ms",
            ),
        ],
        rules: None,
    },
];

/// `a, alpha_deg, d, theta_deg`, with a and d within ±2 m (angles are
/// checked to ±360°, lengths more tightly by the rule below).
const fn dh_row() -> Kind {
    Kind::Numbers {
        min_count: 4,
        max_count: 4,
        min: -360.0,
        max: 360.0,
    }
}

fn dh_rules(p: &Params) -> Result<(), String> {
    for key in ["row", "target"] {
        if let Some([a, _, d, _]) = p.numbers(key)
            && (a.abs() > 2.0 || d.abs() > 2.0)
        {
            return Err(format!("parameter `{key}`: a and d must be within ±2 m"));
        }
    }
    Ok(())
}

fn viewer_rules(p: &Params) -> Result<(), String> {
    let model = mechanism(p.choice("model").unwrap_or("planar-2r")).map_err(|e| e.to_string())?;
    let driven = (0..model.dof()).filter(|&v| model.is_driven(v)).count();
    if let Some(q) = p.numbers("q")
        && q.len() != driven
    {
        return Err(format!(
            "`q` needs {driven} values (one per driven joint of `{}`), got {}",
            model.name(),
            q.len()
        ));
    }
    marked_rule(p)?;
    match p.choice("task") {
        Some("reach") if p.numbers("target").is_none() => {
            Err("`task: reach` needs `target: x, y` or `target: x, y, z`".into())
        }
        Some("spot-singular") => match p.groups("sets") {
            None => Err("`task: spot-singular` needs `sets: q1, q2; q1, q2; …`".into()),
            Some(sets) if sets.iter().any(|s| s.len() != driven) => Err(format!(
                "each group in `sets` needs {driven} values, one per driven joint"
            )),
            Some(_) => Ok(()),
        },
        _ => Ok(()),
    }
}

/// `marked` numbers some of the `sets` of a spot-singular task.
fn marked_rule(p: &Params) -> Result<(), String> {
    let Some(marked) = p.numbers("marked") else {
        return Ok(());
    };
    if p.choice("task") != Some("spot-singular") {
        return Err("`marked` goes with `task: spot-singular`".into());
    }
    let sets = p.groups("sets").map_or(0, <[_]>::len);
    match marked
        .iter()
        .find(|n| n.fract() != 0.0 || **n > sets as f64)
    {
        Some(bad) => Err(format!(
            "`marked`: {bad} is not a configuration's number (1 to {sets})"
        )),
        None => Ok(()),
    }
}
