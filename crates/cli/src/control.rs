//! `kinolab simulate`, `kinolab batch` and `kinolab gains`: the polar
//! controller and open-loop plans on run files (`*.run.json`, see the
//! contract).

use std::path::Path;

use kinolab_control::file::{RunSpec, from_json};
use kinolab_control::{Gains, report};
use serde_json::Value;

use crate::{Failure, input, numbers, report as emit};

fn load(path: &Path) -> Result<RunSpec, Failure> {
    let shown = path.display().to_string();
    let text = input::read(path)?;
    from_json(&text).map_err(|e| Failure(format!("{shown}: {e}")))
}

pub(crate) fn simulate(path: &Path) -> Result<Value, Failure> {
    let spec = load(path)?;
    let trajectory = spec
        .run
        .simulate()
        .map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    emit(
        &path.display().to_string(),
        &report::simulation(&spec, &trajectory),
    )
}

pub(crate) fn batch_run(
    path: &Path,
    radius: f64,
    count: usize,
    heading_deg: f64,
    paths: bool,
) -> Result<Value, Failure> {
    let spec = load(path)?;
    let batch =
        report::circle_batch(&spec, radius, count, heading_deg, paths).map_err(|e| {
            match e.field.as_str() {
                "radius" | "count" | "heading" | "paths" => {
                    Failure(format!("--{}: {}", e.field, e.message))
                }
                _ => Failure(format!("{}: {e}", path.display())),
            }
        })?;
    emit(&path.display().to_string(), &batch)
}

pub(crate) fn gains(text: &str) -> Result<Value, Failure> {
    match numbers("gains", text)?.as_slice() {
        [r, a, b] => {
            let g = Gains::new(*r, *a, *b).map_err(|e| Failure(format!("gains: {e}")))?;
            emit("gains", &report::stability(&g))
        }
        other => Err(Failure(format!(
            "gains: expected three numbers K_RHO,K_ALPHA,K_BETA, got {}",
            other.len()
        ))),
    }
}
