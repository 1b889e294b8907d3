//! `kinolab gait` (a periodic gait sampled through its cycle, with its
//! static stability margin) and `kinolab cpg` (phase oscillators settling
//! into a gait).

use std::path::Path;

use kinolab_locomotion::{Cpg, Gait, report};
use serde_json::Value;

use crate::{Failure, input, report as emit};

/// A gait file, or `catalogue:<id>` for a named gait of the sheet.
fn load_gait(path: &Path) -> Result<Gait, Failure> {
    let shown = path.display().to_string();
    match shown.strip_prefix("catalogue:") {
        Some(id) => kinolab_locomotion::named(id).ok_or_else(|| {
            let known: Vec<&str> = kinolab_locomotion::named_ids().collect();
            Failure(format!(
                "{shown}: no gait called `{id}` (known: {})",
                known.join(", ")
            ))
        }),
        None => Gait::from_json(&input::read(path)?).map_err(|e| Failure(format!("{shown}: {e}"))),
    }
}

pub(crate) fn gait(path: &Path, samples: usize) -> Result<Value, Failure> {
    let shown = path.display().to_string();
    let gait = load_gait(path)?;
    let r = report::gait(&gait, samples).map_err(|e| match e.field.as_str() {
        "samples" => Failure(format!("--samples: {}", e.message)),
        _ => Failure(format!("{shown}: {e}")),
    })?;
    emit(&shown, &r)
}

pub(crate) fn cpg(path: &Path) -> Result<Value, Failure> {
    let shown = path.display().to_string();
    let cpg = Cpg::from_json(&input::read(path)?).map_err(|e| Failure(format!("{shown}: {e}")))?;
    let r = report::cpg(&cpg).map_err(|e| Failure(format!("{shown}: {e}")))?;
    emit(&shown, &r)
}
