//! Widgets for potential fields.

use crate::{Catalogue, Kind, Params, WidgetSchema};

use super::{YES_NO, param};

pub(crate) static WIDGETS: &[WidgetSchema] = &[WidgetSchema {
    name: "field-sandbox",
    summary: "paint a potential field with the five primitives; find its minima; follow it; try the remedies",
    params: &[
        param(
            "preset",
            Kind::Catalogue {
                of: Catalogue::Fields,
            },
            Some("goal-behind-a-rock"),
            "the field to start from",
        ),
        param("streamlines", YES_NO, Some("yes"), "draw streamlines"),
        param("shading", YES_NO, Some("yes"), "shade the field's strength"),
        param(
            "unicycle",
            YES_NO,
            Some("no"),
            "also drive a unicycle along the field",
        ),
        param(
            "remedies",
            YES_NO,
            Some("no"),
            "show the remedies and the steps each needs",
        ),
        param(
            "editable",
            YES_NO,
            Some("yes"),
            "let the learner add, remove and change primitives",
        ),
        param(
            "task",
            Kind::Choice {
                options: &["vector-at", "escape", "stand-off"],
            },
            None,
            "an exercise: compute the vector at a point, add one field to escape, or set a wall's range and gain",
        ),
        param(
            "at",
            Kind::Numbers {
                min_count: 2,
                max_count: 2,
                min: -100.0,
                max: 100.0,
            },
            None,
            "the point of `task: vector-at` (x, y in m)",
        ),
        param(
            "clearance",
            Kind::Number {
                min: 0.05,
                max: 2.0,
            },
            None,
            "how far from the wall the robot must stop in `task: stand-off` (m)",
        ),
    ],
    rules: Some(sandbox_rules),
}];

fn sandbox_rules(p: &Params) -> Result<(), String> {
    let task = p.choice("task");
    if task == Some("vector-at") && p.numbers("at").is_none() {
        return Err("`task: vector-at` needs `at: x, y`".into());
    }
    if p.given("at") && task != Some("vector-at") {
        return Err("`at` goes with `task: vector-at`".into());
    }
    if p.given("clearance") && task != Some("stand-off") {
        return Err("`clearance` goes with `task: stand-off`".into());
    }
    let preset = p.choice("preset").unwrap_or("goal-behind-a-rock");
    let field = kinolab_fields::catalogue::preset(preset)
        .ok_or_else(|| format!("no field preset `{preset}`"))?
        .field()
        .map_err(|e| e.to_string())?;
    if task == Some("stand-off")
        && !field
            .primitives
            .iter()
            .any(|q| matches!(q.source, kinolab_fields::Source::Perpendicular { .. }))
    {
        return Err(format!(
            "`task: stand-off` needs a preset with a wall; `{preset}` has none"
        ));
    }
    if matches!(task, Some("escape" | "stand-off")) && field.goal.is_none() {
        return Err(format!(
            "`task` needs a preset with a goal; `{preset}` has none"
        ));
    }
    Ok(())
}
