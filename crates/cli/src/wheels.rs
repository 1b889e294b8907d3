//! `kinolab analyze`, `kinolab drive` and `kinolab robots`: wheeled-robot
//! kinematics on robot files (`*.robot.json`, see the contract).

use std::path::Path;

use kinolab_wheels::catalogue::{CATALOGUE, robot};
use kinolab_wheels::{Chassis, Vector3, report};
use serde_json::{Value, json};

use crate::{Failure, input, number, numbers, report as emit};

/// A robot file, or `catalogue:<id>` for a built-in robot.
pub(crate) fn load(path: &Path) -> Result<Chassis, Failure> {
    let shown = path.display().to_string();
    if let Some(id) = shown.strip_prefix("catalogue:") {
        return robot(id).map_err(|e| Failure(format!("{shown}: {e}")));
    }
    let text = input::read(path)?;
    Chassis::from_json(&text).map_err(|e| Failure(format!("{shown}: {e}")))
}

pub(crate) fn analyze(path: &Path) -> Result<Value, Failure> {
    emit(&path.display().to_string(), &report::analysis(&load(path)?))
}

pub(crate) fn drive(
    path: &Path,
    twist: Option<&str>,
    spins: Option<&str>,
    theta: Option<f64>,
) -> Result<Value, Failure> {
    let chassis = load(path)?;
    let option = |e: kinolab_common::FieldError| {
        if e.field == "theta" {
            Failure(format!("--theta: {}", e.message))
        } else {
            Failure(format!(
                "{}: {e}",
                if twist.is_some() {
                    "--twist"
                } else {
                    "--wheels"
                }
            ))
        }
    };
    match (twist, spins) {
        (Some(text), None) => {
            let v = match numbers("twist", text)?.as_slice() {
                [x, y, w] => Vector3::new(*x, *y, *w),
                other => {
                    return Err(Failure(format!(
                        "--twist: expected three numbers VX,VY,OMEGA, got {}",
                        other.len()
                    )));
                }
            };
            emit(
                "--twist",
                &report::inverse(&chassis, v, theta).map_err(option)?,
            )
        }
        (None, Some(text)) => {
            let spins: Vec<Option<f64>> = text
                .split(',')
                .map(|part| match part.trim() {
                    "-" => Ok(None),
                    other => number("wheels", other).map(Some),
                })
                .collect::<Result<_, _>>()?;
            if spins.len() != chassis.wheels().len() {
                return Err(Failure(format!(
                    "--wheels: expected {} spins (one per wheel in {}, `-` for unknown), got {}",
                    chassis.wheels().len(),
                    path.display(),
                    spins.len()
                )));
            }
            emit(
                "--wheels",
                &report::forward(&chassis, &spins, theta).map_err(option)?,
            )
        }
        (Some(_), Some(_)) => Err(Failure(
            "drive: give either --twist (inverse kinematics) or --wheels (forward), not both"
                .into(),
        )),
        (None, None) => Err(Failure(
            "drive: give --twist VX,VY,OMEGA (inverse kinematics) or --wheels S1,S2,... (forward)"
                .into(),
        )),
    }
}

/// The catalogue, or one robot's file.
pub(crate) fn robots(id: Option<&str>) -> Result<Value, Failure> {
    match id {
        None => Ok(json!({ "robots": emit("robots", &CATALOGUE)? })),
        Some(id) => {
            let chassis = robot(id).map_err(|e| Failure(e.to_string()))?;
            serde_json::from_str(&chassis.to_json()).map_err(|e| Failure(format!("{id}: {e}")))
        }
    }
}
