//! Built-in mechanisms.

use std::f64::consts::FRAC_PI_2;

use crate::dh::{Convention, DhRow, chain, shift};
use crate::error::MechanismError;
use crate::model::{JointKind, Model, Pose};

/// Catalogue entries: id, name, one-line summary.
pub const CATALOGUE: &[(&str, &str, &str)] = &[
    (
        "planar-2r",
        "Planar 2R arm",
        "two revolute joints in a plane, links 1 m and 0.8 m",
    ),
    (
        "planar-3r",
        "Planar 3R arm",
        "three revolute joints in a plane: position and heading of the hand",
    ),
    (
        "puma560",
        "Puma 560",
        "the classic six-joint industrial arm, standard DH, on a 0.6718 m base",
    ),
    (
        "stanford",
        "Stanford arm",
        "a six-joint arm with a prismatic third joint, standard DH",
    ),
    (
        "panda",
        "Franka Panda",
        "a seven-joint redundant arm described in modified DH",
    ),
];

fn revolute(name: &str, a: f64, alpha: f64, d: f64, offset: f64, limits_deg: [f64; 2]) -> DhRow {
    DhRow {
        name: name.into(),
        kind: JointKind::Revolute,
        a,
        alpha,
        d,
        theta: 0.0,
        offset,
        limits: Some(limits_deg.map(f64::to_radians)),
    }
}

/// The Puma 560's standard DH table (Corke's figures), base height d₁.
pub fn puma560_rows() -> Vec<DhRow> {
    vec![
        revolute("q1", 0.0, FRAC_PI_2, 0.6718, 0.0, [-160.0, 160.0]),
        revolute("q2", 0.4318, 0.0, 0.0, 0.0, [-225.0, 45.0]),
        revolute("q3", 0.0203, -FRAC_PI_2, 0.15005, 0.0, [-45.0, 225.0]),
        revolute("q4", 0.0, FRAC_PI_2, 0.4318, 0.0, [-110.0, 170.0]),
        revolute("q5", 0.0, -FRAC_PI_2, 0.0, 0.0, [-100.0, 100.0]),
        revolute("q6", 0.0, 0.0, 0.0, 0.0, [-266.0, 266.0]),
    ]
}

/// A built-in mechanism by id.
pub fn mechanism(id: &str) -> Result<Model, MechanismError> {
    let planar = |links: &[f64]| -> Vec<DhRow> {
        links
            .iter()
            .enumerate()
            .map(|(i, &a)| revolute(&format!("q{}", i + 1), a, 0.0, 0.0, 0.0, [-170.0, 170.0]))
            .collect()
    };
    match id {
        "planar-2r" => chain(
            "Planar 2R arm",
            Convention::StandardDh,
            &planar(&[1.0, 0.8]),
            Pose::identity(),
            Pose::identity(),
        ),
        "planar-3r" => chain(
            "Planar 3R arm",
            Convention::StandardDh,
            &planar(&[1.0, 0.8, 0.3]),
            Pose::identity(),
            Pose::identity(),
        ),
        "puma560" => chain(
            "Puma 560",
            Convention::StandardDh,
            &puma560_rows(),
            Pose::identity(),
            Pose::identity(),
        ),
        "stanford" => {
            let mut rows = vec![
                revolute("q1", 0.0, -FRAC_PI_2, 0.412, 0.0, [-170.0, 170.0]),
                revolute("q2", 0.0, FRAC_PI_2, 0.154, 0.0, [-170.0, 170.0]),
                DhRow {
                    name: "q3".into(),
                    kind: JointKind::Prismatic,
                    a: 0.0203,
                    alpha: 0.0,
                    d: 0.0,
                    theta: -FRAC_PI_2,
                    offset: 0.0,
                    limits: Some([0.3048, 1.27]),
                },
                revolute("q4", 0.0, -FRAC_PI_2, 0.0, 0.0, [-170.0, 170.0]),
                revolute("q5", 0.0, FRAC_PI_2, 0.0, 0.0, [-90.0, 90.0]),
                revolute("q6", 0.0, 0.0, 0.263, 0.0, [-170.0, 170.0]),
            ];
            rows.shrink_to_fit();
            chain(
                "Stanford arm",
                Convention::StandardDh,
                &rows,
                Pose::identity(),
                Pose::identity(),
            )
        }
        "panda" => {
            // Modified DH from Franka's documentation; the flange 0.107 m on.
            let rows = vec![
                revolute("q1", 0.0, 0.0, 0.333, 0.0, [-166.0, 166.0]),
                revolute("q2", 0.0, -FRAC_PI_2, 0.0, 0.0, [-101.0, 101.0]),
                revolute("q3", 0.0, FRAC_PI_2, 0.316, 0.0, [-166.0, 166.0]),
                revolute("q4", 0.0825, FRAC_PI_2, 0.0, 0.0, [-176.0, -4.0]),
                revolute("q5", -0.0825, -FRAC_PI_2, 0.384, 0.0, [-166.0, 166.0]),
                revolute("q6", 0.0, FRAC_PI_2, 0.0, 0.0, [-1.0, 215.0]),
                revolute("q7", 0.088, FRAC_PI_2, 0.0, 0.0, [-166.0, 166.0]),
            ];
            chain(
                "Franka Panda",
                Convention::ModifiedDh,
                &rows,
                Pose::identity(),
                shift(0.0, 0.0, 0.107),
            )
        }
        other => {
            let known: Vec<&str> = CATALOGUE.iter().map(|(id, _, _)| *id).collect();
            Err(MechanismError::new(
                "model",
                format!(
                    "no built-in mechanism `{other}` (known: {})",
                    known.join(", ")
                ),
            ))
        }
    }
}
