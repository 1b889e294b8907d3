//! Widgets for potential fields.

use crate::{Catalogue, Kind, Params, WidgetSchema};

use super::{YES_NO, param};

/// A point in m.
const POINT: Kind = Kind::Numbers {
    min_count: 2,
    max_count: 2,
    min: -100.0,
    max: 100.0,
};

/// The remedies whose paths the sandbox can draw, in its order.
pub const PATHS: [&str; 5] = [
    "noise",
    "avoid-past",
    "templates",
    "wall-following",
    "wavefront",
];

fn check_fields(text: &str) -> Result<(), String> {
    kinolab_fields::file::from_line(text).map(|_| ())
}

fn check_paths(text: &str) -> Result<(), String> {
    for word in text.split(',').map(str::trim) {
        if !PATHS.contains(&word) {
            return Err(format!("has `{word}`: the paths are {}", PATHS.join(", ")));
        }
    }
    Ok(())
}

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
            Some("0.3"),
            "how far from the wall the robot must stop in `task: stand-off` (m)",
        ),
        param(
            "fields",
            Kind::Text {
                example: "attractive x 4 y 0 gain 1 profile linear range 1; repulsive x 2 y 0 radius 0.3 gain 2 profile linear range 1",
                check: check_fields,
            },
            None,
            "the primitives, `;`-separated, each its kind and then a field file's keys and values (`from` and `to` as `x,y`); the preset's when left out",
        ),
        param(
            "goal",
            POINT,
            None,
            "where the goal is (x, y in m); the preset's when left out",
        ),
        param(
            "start",
            POINT,
            None,
            "where the robot starts (x, y in m); the preset's start when left out",
        ),
        param(
            "paths",
            Kind::Text {
                example: "noise, wavefront",
                check: check_paths,
            },
            None,
            "which remedies' paths are drawn, comma-separated: noise, avoid-past, templates, wall-following, wavefront; none when left out",
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
    let mut field = kinolab_fields::catalogue::preset(preset)
        .ok_or_else(|| format!("no field preset `{preset}`"))?
        .field()
        .map_err(|e| e.to_string())?;
    if let Some(text) = p.text("fields") {
        field.primitives = kinolab_fields::file::from_line(text)?
            .iter()
            .map(|e| e.primitive().map_err(|e| e.to_string()))
            .collect::<Result<_, _>>()?;
    }
    if p.given("goal") {
        field.goal = p
            .numbers("goal")
            .map(|g| kinolab_fields::Vec2::new(g[0], g[1]));
    }
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
