//! Arms described by DH tables, each with a capsule around every link.

use kinolab_common::trig;
use std::f64::consts::FRAC_PI_2;

use crate::dh::{Convention, DhRow, chain_builder, shift};
use crate::error::FieldError;
use crate::model::{JointKind, Model, ModelBuilder, Pose};

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

/// Capsules along a standard-DH chain: row i's link runs from the joint
/// axis (−a along x, −d along the previous z, in body i's frame: here
/// simply the origin of the previous body) to body i's origin.
fn standard_link_shapes(b: &mut ModelBuilder, rows: &[DhRow], radius: f64) {
    for (i, r) in rows.iter().enumerate() {
        let body = i + 2;
        // In body i's frame the previous origin sits at Rx(α)ᵀ·(−a, 0, 0)
        // minus d along the previous z, which is the body's y rotated by α.
        let (s, c) = trig::sin_cos(r.alpha);
        let d = if r.kind == JointKind::Prismatic {
            0.0
        } else {
            r.d
        };
        let start = [-r.a, -d * s, -d * c];
        if r.a.abs() + d.abs() > 1e-9 {
            b.shape(body, start, [0.0, 0.0, 0.0], radius);
        } else {
            b.shape(body, [0.0; 3], [0.0; 3], radius);
        }
    }
}

/// A planar arm of revolute joints with the given link lengths, moving in
/// the x–y plane, with its closed-form inverse kinematics plugged in.
pub fn planar(links: &[f64]) -> Result<Model, FieldError> {
    let rows: Vec<DhRow> = links
        .iter()
        .enumerate()
        .map(|(i, &a)| revolute(&format!("q{}", i + 1), a, 0.0, 0.0, 0.0, [-170.0, 170.0]))
        .collect();
    let name = if links.len() == 2 {
        "Planar 2R arm"
    } else {
        "Planar 3R arm"
    };
    let mut b = chain_builder(
        name,
        Convention::StandardDh,
        &rows,
        Pose::identity(),
        Pose::identity(),
    )?;
    standard_link_shapes(&mut b, &rows, 0.05);
    let mut model = b.build()?;
    crate::special::attach_planar(&mut model, links);
    Ok(model)
}

pub fn puma560() -> Result<Model, FieldError> {
    let rows = puma560_rows();
    let mut b = chain_builder(
        "Puma 560",
        Convention::StandardDh,
        &rows,
        Pose::identity(),
        Pose::identity(),
    )?;
    b.shape(1, [0.0, 0.0, 0.0], [0.0, 0.0, 0.6718], 0.1);
    standard_link_shapes(&mut b, &rows, 0.06);
    b.build()
}

pub fn stanford() -> Result<Model, FieldError> {
    let rows = vec![
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
    let mut b = chain_builder(
        "Stanford arm",
        Convention::StandardDh,
        &rows,
        Pose::identity(),
        Pose::identity(),
    )?;
    standard_link_shapes(&mut b, &rows, 0.05);
    // The sliding boom: from the shoulder back along the extension.
    b.shape(4, [0.0, 0.0, 0.0], [0.0, 0.0, -0.3], 0.05);
    b.build()
}

pub fn panda() -> Result<Model, FieldError> {
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
    let mut b = chain_builder(
        "Franka Panda",
        Convention::ModifiedDh,
        &rows,
        Pose::identity(),
        shift(0.0, 0.0, 0.107),
    )?;
    // Modified DH: row i's a and α belong to the previous link, so the
    // segment to joint i is fixed in the previous body: from its origin to
    // Rx(α)·(a, 0, d).
    for (i, r) in rows.iter().enumerate() {
        let (s, c) = trig::sin_cos(r.alpha);
        b.shape(i + 1, [0.0; 3], [r.a, -r.d * s, r.d * c], 0.06);
    }
    b.shape(rows.len() + 1, [0.0; 3], [0.0, 0.0, 0.107], 0.05);
    b.build()
}
