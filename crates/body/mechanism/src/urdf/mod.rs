//! URDF, the robot description ROS, MoveIt, Pinocchio and Drake read: links
//! joined by joints into a tree, each joint placed on its parent link by an
//! `origin` and moving about or along an `axis` given in its own frame.
//! That is the mechanism model's transform form, so a URDF file reads
//! straight into a [`Model`]:
//!
//! - the root link is the world frame, every other link a body named as in
//!   the file, every joint a joint of the model;
//! - `floating` and `planar` joints stay at their origin (the lab's models
//!   are fixed to their base), with a notice;
//! - `mimic` is a coupling: `follower = multiplier · leader + offset`;
//! - collision boxes, cylinders, spheres and capsules become bounding
//!   capsules; meshes are skipped and counted in a notice.
//!
//! The joints a user sets are the file's moving joints without `mimic`, in
//! the order the file lists them ([`Robot::state`]).
//!
//! [`write`] goes the other way: any model as URDF that reads back to the
//! same frames (a DH row's transform after the motion becomes a fixed
//! joint; a closed loop is left open, with a notice).

mod build;
mod read;
mod write;

pub use write::{Written, write};

use crate::error::FieldError;
use crate::model::Model;

/// The largest URDF file read: far above any real robot's description.
pub const MAX_BYTES: usize = 4 * 1024 * 1024;

/// A robot read from URDF: its model, the joints a user sets, and what the
/// reading left out.
#[derive(Debug, Clone)]
pub struct Robot {
    pub model: Model,
    /// The model's state variable behind each driven joint, in file order.
    driven: Vec<usize>,
    /// The link the longest chain from the root ends at.
    tip: String,
    /// What was read differently from the file or skipped, one line each.
    pub notices: Vec<String>,
}

/// Whether `text` looks like XML rather than JSON (a URDF pasted or
/// loaded where a model file is also accepted).
pub fn looks_like_xml(text: &str) -> bool {
    text.trim_start_matches('\u{feff}')
        .trim_start()
        .starts_with('<')
}

/// Read a URDF file. Problems name the element and its line.
pub fn read(text: &str) -> Result<Robot, FieldError> {
    if text.len() > MAX_BYTES {
        return Err(FieldError::new(
            "",
            format!(
                "the file has {} bytes; at most {MAX_BYTES} are read",
                text.len()
            ),
        ));
    }
    let description = read::parse(text)?;
    build::robot(description)
}

impl Robot {
    /// The driven joints' names, in file order (the order of `--q`).
    pub fn driven(&self) -> impl Iterator<Item = &str> {
        self.driven.iter().filter_map(|&v| {
            self.model
                .variable_joint(v)
                .map(|joint| joint.name.as_str())
        })
    }

    /// The link at the end of the longest chain from the root.
    pub fn tip(&self) -> &str {
        &self.tip
    }

    /// The model's state for driven joint values in file order: followers
    /// set from their leaders. Each value must be finite; it may lie
    /// outside its joint's limits (FK is geometry).
    pub fn state(&self, q: &[f64]) -> Result<Vec<f64>, FieldError> {
        if q.len() != self.driven.len() {
            let names: Vec<&str> = self.driven().collect();
            return Err(FieldError::new(
                "q",
                format!(
                    "`{}` has {} movable joints ({}), got {} values",
                    self.model.name(),
                    names.len(),
                    names.join(", "),
                    q.len()
                ),
            ));
        }
        let mut state = self.model.zeros();
        for (&v, &value) in self.driven.iter().zip(q) {
            state[v] = self.checked(v, value)?;
        }
        self.model.apply_couplings(&mut state);
        Ok(state)
    }

    /// Rates (velocities, accelerations, torques) of the driven joints in
    /// file order, as a model's vector: the other entries 0 (a follower's
    /// rate comes from its leader).
    pub fn rates(&self, field: &str, rates: &[f64]) -> Result<Vec<f64>, FieldError> {
        if rates.len() != self.driven.len() {
            return Err(FieldError::new(
                field,
                format!(
                    "`{}` has {} movable joints, got {} values",
                    self.model.name(),
                    self.driven.len(),
                    rates.len()
                ),
            ));
        }
        let mut out = vec![0.0; self.model.dof()];
        for (&v, &r) in self.driven.iter().zip(rates) {
            out[v] = r;
        }
        Ok(out)
    }

    /// The driven joints' values in a model state, in file order.
    pub fn values(&self, state: &[f64]) -> Vec<f64> {
        self.driven
            .iter()
            .map(|&v| state.get(v).copied().unwrap_or(0.0))
            .collect()
    }

    /// The model's state with the named driven joints set and the others at
    /// zero (even where zero is outside a joint's limits).
    pub fn state_named(&self, set: &[(String, f64)]) -> Result<Vec<f64>, FieldError> {
        let mut state = self.model.zeros();
        for (name, value) in set {
            let v = self
                .model
                .variable(name)
                .filter(|v| self.driven.contains(v))
                .ok_or_else(|| {
                    let names: Vec<&str> = self.driven().collect();
                    FieldError::new(
                        "set",
                        format!(
                            "`{name}` is not a movable joint of `{}` (movable: {})",
                            self.model.name(),
                            names.join(", ")
                        ),
                    )
                })?;
            state[v] = self.checked(v, *value)?;
        }
        self.model.apply_couplings(&mut state);
        Ok(state)
    }

    /// `value` for variable `v`, if finite. Limits do not refuse it: the
    /// answers list the joints outside theirs ([`Model::outside_limits`]).
    fn checked(&self, v: usize, value: f64) -> Result<f64, FieldError> {
        let Some(joint) = self.model.variable_joint(v) else {
            return Err(FieldError::new("q", "no such joint"));
        };
        crate::error::finite_at(value, || joint.name.clone())?;
        Ok(value)
    }
}
