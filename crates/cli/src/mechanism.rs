//! `kinolab fk` and `kinolab ik`: mechanism kinematics on model files
//! (`*.model.json`, see the contract), or `catalogue:<id>`.

use std::path::Path;

use kinolab_mechanism::{FieldError, Goal, Model, Options, Target, Vector3, report};
use serde_json::Value;

use crate::{Failure, input, numbers, report as emit};

fn load(path: &Path) -> Result<Model, Failure> {
    let shown = path.display().to_string();
    if let Some(id) = shown.strip_prefix("catalogue:") {
        return kinolab_mechanism::catalogue::mechanism(id)
            .map_err(|e| Failure(format!("{shown}: {e}")));
    }
    let text = input::read(path)?;
    let mut mounts = Mounts::default();
    read_model(path, &text, 0, &mut mounts).map_err(|e| match mounts.exceeded {
        // The bound is the news, not the chain of mounts that reached it.
        Some(bound) => Failure(format!("{shown}: {bound}")),
        None => Failure(format!("{shown}: {e}")),
    })
}

/// The most model files one command reads through mounts, all levels
/// together: a file that mounts the next several times, down many levels,
/// would otherwise read exponentially many.
const MAX_MOUNTED_FILES: usize = 64;
/// The deepest chain of files mounting files.
const MAX_MOUNT_DEPTH: usize = 16;

/// Files read through mounts so far, and the bound hit, if one was.
#[derive(Default)]
struct Mounts {
    read: usize,
    exceeded: Option<String>,
}

/// Parse a model file whose mounted sub-mechanisms are files next to it.
fn read_model(
    path: &Path,
    text: &str,
    depth: usize,
    mounts: &mut Mounts,
) -> Result<Model, FieldError> {
    let folder = path.parent().map(Path::to_path_buf).unwrap_or_default();
    kinolab_mechanism::file::from_json_with(text, &mut |name: &str| {
        mounts.read += 1;
        if depth >= MAX_MOUNT_DEPTH {
            mounts.exceeded = Some(format!("mounts nested more than {MAX_MOUNT_DEPTH} deep"));
        } else if mounts.read > MAX_MOUNTED_FILES {
            mounts.exceeded = Some(format!(
                "mounts read more than {MAX_MOUNTED_FILES} model files in all \
                 (a file mounted several times, mounting others, multiplies them)"
            ));
        }
        if let Some(bound) = &mounts.exceeded {
            return Err(FieldError::new("", bound.clone()));
        }
        let sub = folder.join(name);
        let text = input::read(&sub).map_err(|Failure(m)| FieldError::new("", m))?;
        read_model(&sub, &text, depth + 1, mounts)
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
    emit(&path.display().to_string(), &report::forward(&name, &pose))
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
    emit(&path.display().to_string(), &report::inverse(&solution))
}
