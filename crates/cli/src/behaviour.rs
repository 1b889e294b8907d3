//! `kinolab field` (potential fields: vectors, minima, descent) and
//! `kinolab run` (behaviours in a world).

use std::path::Path;

use kinolab_fields::Field;
use kinolab_fields::descend::Steps;
use kinolab_fields::report;
use serde_json::Value;

use crate::{Failure, input, numbers, point, report as emit};

/// A field file, or `catalogue:<id>` for one of the classic fields.
fn load_field(path: &Path) -> Result<Field, Failure> {
    let shown = path.display().to_string();
    if let Some(id) = shown.strip_prefix("catalogue:") {
        let preset = kinolab_fields::catalogue::preset(id)
            .ok_or_else(|| Failure(format!("{shown}: no field called `{id}` in the catalogue")))?;
        return preset.field().map_err(|e| Failure(format!("{shown}: {e}")));
    }
    let text = input::read(path)?;
    Field::from_json(&text).map_err(|e| Failure(format!("{shown}: {e}")))
}

/// What `kinolab field` was asked.
pub(crate) struct FieldQuery<'a> {
    pub at: Option<&'a str>,
    pub minima: bool,
    pub area: Option<&'a str>,
    pub descend: Option<&'a str>,
    pub step: Option<f64>,
    pub max_steps: Option<usize>,
}

pub(crate) fn field(path: &Path, q: &FieldQuery<'_>) -> Result<Value, Failure> {
    let modes = [q.at.is_some(), q.minima, q.descend.is_some()]
        .iter()
        .filter(|m| **m)
        .count();
    if modes != 1 {
        return Err(Failure(
            "field: give exactly one of --at, --minima or --descend".into(),
        ));
    }
    let field = load_field(path)?;
    if let Some(at) = q.at {
        let points = at
            .split(';')
            .filter(|p| !p.trim().is_empty())
            .map(|p| point("at", p))
            .collect::<Result<Vec<_>, _>>()?;
        let r = report::vectors(&field, &points)
            .map_err(|e| Failure(format!("--{}: {}", e.field, e.message)))?;
        return emit("--at", &r);
    }
    if q.minima {
        let area = q
            .area
            .ok_or_else(|| Failure("--minima needs --box XMIN,YMIN,XMAX,YMAX".into()))?;
        let corners = match numbers("box", area)?.as_slice() {
            [a, b, c, d] => [*a, *b, *c, *d],
            other => {
                return Err(Failure(format!(
                    "--box: expected four numbers XMIN,YMIN,XMAX,YMAX, got {}",
                    other.len()
                )));
            }
        };
        let r = report::minima_in(&field, corners)
            .map_err(|e| Failure(format!("--box: {}", e.message)))?;
        return emit("--box", &r);
    }
    let start = point("descend", q.descend.unwrap_or_default())?;
    let defaults = Steps::default();
    let steps = Steps {
        step: q.step.unwrap_or(defaults.step),
        max_steps: q.max_steps.unwrap_or(defaults.max_steps),
    };
    let d = report::descent(&field, start, steps)
        .map_err(|e| Failure(format!("--{}: {}", e.field.replace('_', "-"), e.message)))?;
    emit("--descend", &d)
}

pub(crate) fn run(path: &Path) -> Result<Value, Failure> {
    let shown = path.display().to_string();
    let text = input::read(path)?;
    let setup = kinolab_behaviours::run::Setup::from_json(&text)
        .map_err(|e| Failure(format!("{shown}: {e}")))?;
    let r = kinolab_behaviours::run::run(&setup).map_err(|e| Failure(format!("{shown}: {e}")))?;
    emit(&shown, &r)
}
