//! Potential fields and behaviour runs for JavaScript, on plain JSON values
//! (so they run natively too, against the command line).

use kinolab_fields::Field;
use kinolab_fields::descend::Steps;
use serde_json::Value;

use crate::api::{Reply, reply, text};

/// A field: a field-file object, its JSON text, or `catalogue:<id>`.
pub fn field(source: Value) -> Result<Field, String> {
    match source {
        Value::String(s) => match s.strip_prefix("catalogue:") {
            Some(id) => kinolab_fields::catalogue::preset(id)
                .ok_or_else(|| format!("no field called `{id}` in the catalogue"))?
                .field()
                .map_err(text),
            None => Field::from_json(&s).map_err(text),
        },
        other => Field::from_json(&other.to_string()).map_err(text),
    }
}

/// `kinolab field --at`.
pub fn field_vectors(source: Value, at: &[[f64; 2]]) -> Reply {
    reply(&kinolab_fields::report::vectors(&field(source)?, at).map_err(text)?)
}

/// `kinolab field --minima --box`.
pub fn field_minima(source: Value, area: [f64; 4]) -> Reply {
    reply(&kinolab_fields::report::minima_in(&field(source)?, area).map_err(text)?)
}

/// `kinolab field --descend`.
pub fn field_descend(
    source: Value,
    start: [f64; 2],
    step: Option<f64>,
    max_steps: Option<usize>,
) -> Reply {
    let defaults = Steps::default();
    let steps = Steps {
        step: step.unwrap_or(defaults.step),
        max_steps: max_steps.unwrap_or(defaults.max_steps),
    };
    reply(&kinolab_fields::report::descent(&field(source)?, start, steps).map_err(text)?)
}

/// `kinolab run`: a behaviour run file (object or JSON text).
pub fn run_behaviours(run: Value) -> Reply {
    let json = match run {
        Value::String(json) => json,
        other => other.to_string(),
    };
    let setup = kinolab_behaviours::run::Setup::from_json(&json).map_err(text)?;
    reply(&kinolab_behaviours::run::run(&setup).map_err(text)?)
}

/// The example worlds' ids and the classic fields' ids and titles.
pub fn catalogues() -> Reply {
    let worlds: Vec<&str> = kinolab_world::catalogue::WORLDS
        .iter()
        .map(|(id, _)| *id)
        .collect();
    let fields: Vec<Value> = kinolab_fields::catalogue::PRESETS
        .iter()
        .map(|p| serde_json::json!({ "id": p.id, "title": p.title, "shows": p.shows }))
        .collect();
    Ok(serde_json::json!({ "worlds": worlds, "fields": fields }))
}
