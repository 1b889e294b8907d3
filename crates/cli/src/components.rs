//! `kinolab components`: a system of components run on the simulated clock;
//! the trace of every message and the final state.

use std::path::Path;

use kinolab_components::System;
use serde_json::Value;

use crate::{Failure, input, report as emit};

/// A system file, or `example:<id>` for one the lab ships.
fn load(path: &Path) -> Result<System, Failure> {
    let shown = path.display().to_string();
    match shown.strip_prefix("example:") {
        Some(id) => kinolab_components::system::example(id),
        None => System::from_json(&input::read(path)?),
    }
    .map_err(|e| Failure(format!("{shown}: {e}")))
}

pub(crate) fn components(path: &Path, until: Option<f64>) -> Result<Value, Failure> {
    let shown = path.display().to_string();
    let system = load(path)?;
    let report = system.run(until).map_err(|e| match e.field.as_str() {
        "until" if until.is_some() => Failure(format!("--until: {}", e.message)),
        _ => Failure(format!("{shown}: {e}")),
    })?;
    emit(&shown, &report)
}
