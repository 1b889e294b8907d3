//! Arms described by DH tables, each with a capsule around every link.

use kinolab_common::trig;
use std::f64::consts::FRAC_PI_2;

use crate::dh::{Convention, DhRow, chain_builder, shift};
use crate::error::FieldError;
use crate::model::{JointKind, Model, ModelBuilder, Pose};
use nalgebra::Vector3;

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
    give_masses(&mut b, 2, &PUMA560_MASSES)?;
    b.build()
}

/// A link's mass (kg), centre of mass (m) and inertia about it (kg·m²,
/// `[ixx, ixy, ixz, iyy, iyz, izz]`), in the link's DH frame.
type LinkMass = (f64, [f64; 3], [f64; 6]);

/// The Puma 560's links 1 to 6, as Armstrong, Khatib and Burdick measured
/// them ("The explicit dynamic model and inertial parameters of the PUMA
/// 560 arm", ICRA 1986), in the standard DH frames of Corke's Robotics
/// Toolbox. Two published tensors no real body can have, and the lab
/// mends them as little as it can: link 1's only published moment is about
/// its joint's axis (0.35 kg·m², its y axis), and its other two axes get
/// half of it each (which changes no torque: link 1 only ever turns about
/// that axis); link 3's smallest moment, 0.0125 kg·m², is raised to 0.020
/// so that no moment exceeds the other two together.
const PUMA560_MASSES: [LinkMass; 6] = [
    (0.0, [0.0, 0.0, 0.0], [0.175, 0.0, 0.0, 0.35, 0.0, 0.175]),
    (
        17.4,
        [-0.3638, 0.006, 0.2275],
        [0.13, 0.0, 0.0, 0.524, 0.0, 0.539],
    ),
    (
        4.8,
        [-0.0203, -0.0141, 0.070],
        [0.066, 0.0, 0.0, 0.086, 0.0, 0.020],
    ),
    (
        0.82,
        [0.0, 0.019, 0.0],
        [1.8e-3, 0.0, 0.0, 1.3e-3, 0.0, 1.8e-3],
    ),
    (
        0.34,
        [0.0, 0.0, 0.0],
        [0.3e-3, 0.0, 0.0, 0.4e-3, 0.0, 0.3e-3],
    ),
    (
        0.09,
        [0.0, 0.0, 0.032],
        [0.15e-3, 0.0, 0.0, 0.15e-3, 0.0, 0.04e-3],
    ),
];

/// The Franka Panda's base and links 1 to 7, as Gaz, Cognetti, Oliva,
/// Robuffo Giordano and De Luca identified them ("Dynamic identification
/// of the Franka Emika Panda robot with retrieval of feasible parameters
/// using penalty-based optimization", IEEE RA-L 2019), in the modified
/// DH frames of Franka's documentation (the values the robot's public
/// URDF carries).
const PANDA_MASSES: [LinkMass; 8] = [
    (
        0.629769,
        [-0.041018, -0.00014, 0.049974],
        [0.00315, 8.2904e-07, 0.00015, 0.00388, 8.2299e-06, 0.004285],
    ),
    (
        4.970684,
        [0.003875, 0.002081, -0.04762],
        [0.70337, -0.000139, 0.006772, 0.70661, 0.019169, 0.009117],
    ),
    (
        0.646926,
        [-0.003141, -0.02872, 0.003495],
        [0.007962, -0.003925, 0.010254, 0.02811, 0.000704, 0.025995],
    ),
    (
        3.228604,
        [2.7518e-02, 3.9252e-02, -6.6502e-02],
        [0.037242, -0.004761, -0.011396, 0.036155, -0.012805, 0.01083],
    ),
    (
        3.587895,
        [-5.317e-02, 1.04419e-01, 2.7454e-02],
        [0.025853, 0.007796, -0.001332, 0.019552, 0.008641, 0.028323],
    ),
    (
        1.225946,
        [-1.1953e-02, 4.1065e-02, -3.8437e-02],
        [0.035549, -0.002117, -0.004037, 0.029474, 0.000229, 0.008627],
    ),
    (
        1.666555,
        [6.0149e-02, -1.4117e-02, -1.0517e-02],
        [0.001964, 0.000109, -0.001158, 0.004354, 0.000341, 0.005433],
    ),
    (
        0.735522,
        [1.0517e-02, -4.252e-03, 6.1597e-02],
        [
            0.012516, -0.000428, -0.001196, 0.010027, -0.000741, 0.004815,
        ],
    ),
];

/// Give the links of a DH chain their masses: `links[i]` to the body
/// `first + i` (chain_builder's base is body 1, its first link body 2).
fn give_masses(b: &mut ModelBuilder, first: usize, links: &[LinkMass]) -> Result<(), FieldError> {
    for (i, (mass, com, inertia)) in links.iter().enumerate() {
        let body = first + i;
        let name = b.bodies[body].name.clone();
        b.bodies[body].inertial = Some(crate::Inertial::new(&name, *mass, *com, *inertia)?);
    }
    Ok(())
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
    give_masses(&mut b, 1, &PANDA_MASSES)?;
    b.build()
}

/// Rods `(length m, mass kg)` joined end to end, each turning about the
/// horizontal y axis, so the chain moves in the vertical x–z plane with
/// gravity along −z. At zero an arm points along +x, and a positive angle
/// raises it; a `hanging` chain points down (−z) at zero. Each rod's mass
/// is spread along it, with a little thickness; a `tool` frame sits at the
/// last rod's end.
pub fn vertical(name: &str, rods: &[(f64, f64)], hanging: bool) -> Result<Model, FieldError> {
    let mut b = ModelBuilder::new(name);
    let up = nalgebra::Unit::new_normalize(Vector3::new(0.0, -1.0, 0.0));
    let along = |l: f64| {
        if hanging {
            Vector3::new(0.0, 0.0, -l)
        } else {
            Vector3::new(l, 0.0, 0.0)
        }
    };
    let mut parent = 0;
    let mut origin = Pose::identity();
    for (i, &(length, mass)) in rods.iter().enumerate() {
        let body = b.joint(
            format!("joint{}", i + 1),
            JointKind::Revolute,
            parent,
            origin,
            up,
            0.0,
            Pose::identity(),
            Some([-std::f64::consts::PI, std::f64::consts::PI]),
        );
        // A rod of radius 2 cm: m l²/12 across it, m r²/2 along it.
        let across = mass * length * length / 12.0;
        let about = mass * 0.02 * 0.02 / 2.0;
        let c = along(length / 2.0);
        let (ixx, izz) = if hanging {
            (across, about)
        } else {
            (about, across)
        };
        let inertial = crate::Inertial::new(
            &format!("joint{}", i + 1),
            mass,
            [c.x, c.y, c.z],
            [ixx, 0.0, 0.0, across, 0.0, izz],
        )?;
        b.set_inertial(body, inertial);
        let end = along(length);
        b.shape(body, [0.0; 3], [end.x, end.y, end.z], 0.03);
        origin = Pose::translation(end.x, end.y, end.z);
        parent = body;
    }
    b.frame("tool", parent, origin);
    b.build()
}
