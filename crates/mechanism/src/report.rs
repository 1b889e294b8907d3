//! The JSON of `kinolab fk` and `kinolab ik` (field names as in the
//! command-line contract).

use serde_json::{Value, json};

use crate::file::matrix_of;
use crate::ik::Solution;
use crate::model::Pose;

/// Rounding noise (|x| < 1e-12) written as 0.
fn tidy(x: f64) -> f64 {
    if x.abs() < 1e-12 { 0.0 } else { x }
}

/// `kinolab fk`: the frame's name and its 4×4 matrix.
pub fn forward(frame: &str, pose: &Pose) -> Value {
    let m = matrix_of(pose).map(|row| row.map(tidy));
    json!({ "frame": frame, "matrix": m })
}

/// `kinolab ik`: joint values and how well they meet the target.
pub fn inverse(s: &Solution) -> Value {
    json!({
        "q": s.q.iter().map(|v| tidy(*v)).collect::<Vec<_>>(),
        "converged": s.converged,
        "position_error": s.position_error,
        "rotation_error": s.rotation_error,
        "iterations": s.iterations,
    })
}
