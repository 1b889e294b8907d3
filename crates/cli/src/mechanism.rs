//! `kinolab fk` and `kinolab ik`: mechanism kinematics on model files
//! (`*.model.json`, see the contract), or `catalogue:<id>`.

use std::path::Path;

use kinolab_common::display::tidy_report;
use kinolab_mechanism::{FieldError, Goal, Model, Options, Target, Vector3, report};
use serde_json::Value;

use crate::{Failure, numbers};

fn load(path: &Path) -> Result<Model, Failure> {
    let shown = path.display().to_string();
    if let Some(id) = shown.strip_prefix("catalogue:") {
        return kinolab_mechanism::catalogue::mechanism(id)
            .map_err(|e| Failure(format!("{shown}: {e}")));
    }
    let text =
        std::fs::read_to_string(path).map_err(|e| Failure(format!("{shown}: cannot read: {e}")))?;
    read_model(path, &text, 0).map_err(|e| Failure(format!("{shown}: {e}")))
}

/// Parse a model file whose mounted sub-mechanisms are files next to it.
fn read_model(path: &Path, text: &str, depth: usize) -> Result<Model, FieldError> {
    let folder = path.parent().map(Path::to_path_buf).unwrap_or_default();
    kinolab_mechanism::file::from_json_with(text, &mut |name: &str| {
        if depth >= 16 {
            return Err(FieldError::new("", "mounts nested more than 16 deep"));
        }
        let sub = folder.join(name);
        let text = std::fs::read_to_string(&sub)
            .map_err(|e| FieldError::new("", format!("cannot read {}: {e}", sub.display())))?;
        read_model(&sub, &text, depth + 1)
    })
}

fn frame_of(
    model: &Model,
    frame: Option<&str>,
) -> Result<(String, kinolab_mechanism::FrameRef), Failure> {
    let name = frame.unwrap_or("tool");
    let f = model
        .frame(name)
        .map_err(|e| Failure(format!("--frame: {}", e.message)))?;
    Ok((name.to_string(), f))
}

fn joint_values(option: &str, model: &Model, text: &str) -> Result<Vec<f64>, Failure> {
    let q = numbers(option, text)?;
    if q.len() != model.dof() {
        return Err(Failure(format!(
            "--{option}: `{}` has {} joints, got {} values",
            model.name(),
            model.dof(),
            q.len()
        )));
    }
    Ok(q)
}

pub(crate) fn fk(path: &Path, q: &str, frame: Option<&str>) -> Result<Value, Failure> {
    let model = load(path)?;
    let mut q = joint_values("q", &model, q)?;
    // Followers follow their leaders and closed chains close, whatever
    // values were given for them.
    model
        .close_loops(&mut q)
        .map_err(|e| Failure(format!("--q: {e}")))?;
    let (name, f) = frame_of(&model, frame)?;
    let pose = model
        .pose(&q, &f)
        .map_err(|e| Failure(format!("--q: {e}")))?;
    Ok(tidy_report(&report::forward(&name, &pose)))
}

pub(crate) fn ik(
    path: &Path,
    position: &str,
    rotation: Option<&str>,
    seed: Option<&str>,
    frame: Option<&str>,
) -> Result<Value, Failure> {
    let model = load(path)?;
    let (_, f) = frame_of(&model, frame)?;
    let p = match numbers("position", position)?.as_slice() {
        [x, y, z] => Vector3::new(*x, *y, *z),
        other => {
            return Err(Failure(format!(
                "--position: expected X,Y,Z, got {} numbers",
                other.len()
            )));
        }
    };
    let target = match rotation {
        None => Target::Position(p),
        Some(text) => {
            let r = numbers("rotation", text)?;
            if r.len() != 9 {
                return Err(Failure(format!(
                    "--rotation: expected 9 numbers R11,...,R33 (row-major), got {}",
                    r.len()
                )));
            }
            let m = [
                [r[0], r[1], r[2], p.x],
                [r[3], r[4], r[5], p.y],
                [r[6], r[7], r[8], p.z],
                [0.0, 0.0, 0.0, 1.0],
            ];
            let pose = kinolab_mechanism::file::pose_from_matrix("rotation", &m)
                .map_err(|e| Failure(format!("--{e}")))?;
            Target::Pose(pose)
        }
    };
    let seed = match seed {
        Some(text) => joint_values("seed", &model, text)?,
        None => model
            .home_state()
            .map_err(|e| Failure(format!("{}: {e}", path.display())))?,
    };
    let solution = model
        .solve(&[Goal::new(f, target)], &seed, &Options::default())
        .map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    Ok(tidy_report(&report::inverse(&solution)))
}
