//! Mechanisms assembled from parts: a rocker-bogie rover, a rover carrying
//! an arm, a hexapod from one leg model and a four-bar linkage.
//!
//! Axes: x forward, y to the left, z up; metres and radians.

use kinolab_common::trig;
use nalgebra::{Unit, Vector3};

use crate::dh::{rot_z, shift};
use crate::error::FieldError;
use crate::model::{JointKind, Model, ModelBuilder, Pose};

fn y_axis() -> Unit<Vector3<f64>> {
    Vector3::y_axis()
}

fn deg(limits: [f64; 2]) -> Option<[f64; 2]> {
    Some(limits.map(f64::to_radians))
}

/// A revolute joint with nothing after its motion.
fn hinge(
    b: &mut ModelBuilder,
    name: &str,
    parent: usize,
    origin: Pose,
    axis: Unit<Vector3<f64>>,
    limits: Option<[f64; 2]>,
) -> usize {
    let kind = if limits.is_some() {
        JointKind::Revolute
    } else {
        JointKind::Continuous
    };
    b.joint(
        name,
        kind,
        parent,
        origin,
        axis,
        0.0,
        Pose::identity(),
        limits,
    )
}

fn bolt(b: &mut ModelBuilder, name: &str, parent: usize, origin: Pose) -> usize {
    b.joint(
        name,
        JointKind::Fixed,
        parent,
        origin,
        Vector3::z_axis(),
        0.0,
        Pose::identity(),
        None,
    )
}

/// Wheel radius of the rocker-bogie rover.
pub const WHEEL_RADIUS: f64 = 0.1;

/// Six wheels: each rocker carries a front wheel and a bogie, each bogie a
/// middle and a rear wheel. The differential makes the right rocker turn
/// opposite to the left one, so the chassis pitches by their average.
pub fn rocker_bogie() -> Result<Model, FieldError> {
    let mut b = ModelBuilder::new("Rocker-bogie rover");
    let chassis = bolt(&mut b, "chassis", 0, shift(0.0, 0.0, 0.35));
    b.shape(chassis, [-0.3, 0.0, 0.0], [0.3, 0.0, 0.0], 0.1);
    let mut sides = Vec::new();
    for (side, y) in [("left", 0.3), ("right", -0.3)] {
        let rocker = hinge(
            &mut b,
            &format!("{side}-rocker"),
            chassis,
            shift(0.0, y, 0.0),
            y_axis(),
            deg([-30.0, 30.0]),
        );
        let front = [0.35, 0.0, -0.25];
        let pivot = [-0.2, 0.0, -0.15];
        b.frame(
            format!("{side}-front-wheel"),
            rocker,
            shift(front[0], 0.0, front[2]),
        );
        b.shape(rocker, [0.0; 3], front, 0.03);
        b.shape(rocker, [0.0; 3], pivot, 0.03);
        b.shape(rocker, front, front, WHEEL_RADIUS);
        let bogie = hinge(
            &mut b,
            &format!("{side}-bogie"),
            rocker,
            shift(pivot[0], 0.0, pivot[2]),
            y_axis(),
            deg([-40.0, 40.0]),
        );
        let (middle, rear) = ([0.15, 0.0, -0.1], [-0.15, 0.0, -0.1]);
        b.frame(
            format!("{side}-middle-wheel"),
            bogie,
            shift(middle[0], 0.0, middle[2]),
        );
        b.frame(
            format!("{side}-rear-wheel"),
            bogie,
            shift(rear[0], 0.0, rear[2]),
        );
        b.shape(bogie, middle, rear, 0.03);
        b.shape(bogie, middle, middle, WHEEL_RADIUS);
        b.shape(bogie, rear, rear, WHEEL_RADIUS);
        sides.push([rocker, bogie]);
    }
    // Seen from the side the two sides overlap; they never meet in 3D.
    for l in sides[0] {
        for r in sides[1] {
            b.ignore_pair(l, r);
        }
    }
    b.group("left side", None, sides[0].to_vec());
    b.group("right side", None, sides[1].to_vec());
    b.couple("right-rocker", "left-rocker", -1.0, 0.0);
    b.build()
}

/// The rover part of the mobile manipulator: planar base motion (x, y,
/// yaw), a chassis and a mount point for an arm.
fn rover_base() -> Result<Model, FieldError> {
    let mut b = ModelBuilder::new("Rover");
    let x = b.joint(
        "x",
        JointKind::Prismatic,
        0,
        Pose::identity(),
        Vector3::x_axis(),
        0.0,
        Pose::identity(),
        Some([-5.0, 5.0]),
    );
    let y = b.joint(
        "y",
        JointKind::Prismatic,
        x,
        Pose::identity(),
        Vector3::y_axis(),
        0.0,
        Pose::identity(),
        Some([-5.0, 5.0]),
    );
    let yaw = hinge(&mut b, "yaw", y, Pose::identity(), Vector3::z_axis(), None);
    let chassis = bolt(&mut b, "chassis", yaw, shift(0.0, 0.0, 0.2));
    b.shape(chassis, [-0.3, 0.0, 0.0], [0.3, 0.0, 0.0], 0.2);
    for (name, px, py) in [
        ("front-left", 0.25, 0.25),
        ("front-right", 0.25, -0.25),
        ("rear-left", -0.25, 0.25),
        ("rear-right", -0.25, -0.25),
    ] {
        b.frame(format!("{name}-wheel"), chassis, shift(px, py, -0.1));
    }
    b.frame("arm-mount", chassis, shift(0.2, 0.0, 0.15));
    b.build()
}

/// A three-joint arm: waist about z, shoulder and elbow about y.
fn three_joint_arm() -> Result<Model, FieldError> {
    let mut b = ModelBuilder::new("Arm");
    let waist = hinge(
        &mut b,
        "waist",
        0,
        Pose::identity(),
        Vector3::z_axis(),
        deg([-170.0, 170.0]),
    );
    b.shape(waist, [0.0; 3], [0.0, 0.0, 0.1], 0.05);
    // About −y, so a positive shoulder angle lifts the arm.
    let up = -Vector3::y_axis();
    let shoulder = hinge(
        &mut b,
        "shoulder",
        waist,
        shift(0.0, 0.0, 0.1),
        up,
        deg([-90.0, 90.0]),
    );
    b.shape(shoulder, [0.0; 3], [0.5, 0.0, 0.0], 0.04);
    let elbow = hinge(
        &mut b,
        "elbow",
        shoulder,
        shift(0.5, 0.0, 0.0),
        up,
        deg([-150.0, 150.0]),
    );
    b.shape(elbow, [0.0; 3], [0.4, 0.0, 0.0], 0.035);
    b.frame("gripper", elbow, shift(0.4, 0.0, 0.0));
    b.build()
}

/// A mobile manipulator: the rover and the arm are separate mechanisms,
/// and the arm is mounted on the rover's mount point.
pub fn rover_arm() -> Result<Model, FieldError> {
    let rover = rover_base()?;
    let arm = three_joint_arm()?;
    let mount = rover.frame("arm-mount")?;
    let mut b = ModelBuilder::new("Rover with an arm");
    b.mount(&rover, 0, Pose::identity(), "rover", None);
    let chassis = b
        .bodies
        .iter()
        .position(|x| x.name == "rover/chassis")
        .ok_or_else(|| FieldError::new("model", "the rover has no chassis"))?;
    b.mount(&arm, chassis, mount.offset, "arm", None);
    b.build()
}

/// One hexapod leg: coxa about z, femur and tibia about y; the tibia
/// hangs straight down at zero, so the foot stands 0.15 m below the hip.
fn leg() -> Result<Model, FieldError> {
    let mut b = ModelBuilder::new("Leg");
    let coxa = hinge(
        &mut b,
        "coxa",
        0,
        Pose::identity(),
        Vector3::z_axis(),
        deg([-45.0, 45.0]),
    );
    b.shape(coxa, [0.0; 3], [0.05, 0.0, 0.0], 0.015);
    let femur = hinge(
        &mut b,
        "femur",
        coxa,
        shift(0.05, 0.0, 0.0),
        -Vector3::y_axis(),
        deg([-90.0, 90.0]),
    );
    b.shape(femur, [0.0; 3], [0.1, 0.0, 0.0], 0.015);
    let tibia = b.joint(
        "tibia",
        JointKind::Revolute,
        femur,
        shift(0.1, 0.0, 0.0),
        -Vector3::y_axis(),
        -std::f64::consts::FRAC_PI_2,
        Pose::identity(),
        deg([-120.0, 120.0]),
    );
    b.shape(tibia, [0.0; 3], [0.15, 0.0, 0.0], 0.015);
    b.frame("foot", tibia, shift(0.15, 0.0, 0.0));
    b.build()
}

/// The six mount points: name, position on the torso, outward heading.
pub const HEXAPOD_MOUNTS: [(&str, f64, f64, f64); 6] = [
    ("left-front", 0.12, 0.06, 45.0),
    ("left-middle", 0.0, 0.08, 90.0),
    ("left-rear", -0.12, 0.06, 135.0),
    ("right-rear", -0.12, -0.06, -135.0),
    ("right-middle", 0.0, -0.08, -90.0),
    ("right-front", 0.12, -0.06, -45.0),
];

pub fn hexapod() -> Result<Model, FieldError> {
    let leg = leg()?;
    let mut b = ModelBuilder::new("Hexapod");
    let torso = bolt(&mut b, "torso", 0, shift(0.0, 0.0, 0.15));
    b.shape(torso, [-0.12, 0.0, 0.0], [0.12, 0.0, 0.0], 0.07);
    for (name, x, y, heading) in HEXAPOD_MOUNTS {
        let at = shift(x, y, 0.0) * rot_z(heading.to_radians());
        b.frame(format!("{name}-mount"), torso, at);
        b.mount(&leg, torso, at, name, None);
    }
    b.build()
}

/// A four-bar linkage's link lengths, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FourBar {
    pub crank: f64,
    pub coupler: f64,
    pub rocker: f64,
    pub ground: f64,
}

/// The catalogue's crank-rocker (Grashof: 0.2 + 0.6 ≤ 0.5 + 0.6).
pub const FOUR_BAR: FourBar = FourBar {
    crank: 0.2,
    coupler: 0.6,
    rocker: 0.5,
    ground: 0.6,
};

/// Crank, coupler and rocker as an open chain from the left ground pivot;
/// the loop constraint puts the rocker's end back on the right pivot. The
/// passive joints' offsets are the assembled angles at crank angle 0, so
/// the zero state is closed.
pub fn four_bar(l: FourBar) -> Result<Model, FieldError> {
    // At crank angle 0 the crank tip B is at (crank, 0); C closes the
    // triangle B–C–D with |BC| = coupler and |CD| = rocker.
    let bd = l.ground - l.crank;
    let cos_b = (l.coupler * l.coupler + bd * bd - l.rocker * l.rocker) / (2.0 * l.coupler * bd);
    if !(-1.0..=1.0).contains(&cos_b) {
        return Err(FieldError::new(
            "links",
            "these lengths cannot be assembled at crank angle 0",
        ));
    }
    let at_b = cos_b.acos();
    let c = [
        l.crank + l.coupler * trig::cos(at_b),
        l.coupler * trig::sin(at_b),
    ];
    let to_d = trig::atan2(-c[1], l.ground - c[0]);
    let mut b = ModelBuilder::new("Four-bar linkage");
    let z = Vector3::z_axis();
    let crank = hinge(&mut b, "crank", 0, Pose::identity(), z, None);
    b.shape(crank, [0.0; 3], [l.crank, 0.0, 0.0], 0.02);
    let coupler = b.joint(
        "coupler",
        JointKind::Continuous,
        crank,
        shift(l.crank, 0.0, 0.0),
        z,
        at_b,
        Pose::identity(),
        None,
    );
    b.shape(coupler, [0.0; 3], [l.coupler, 0.0, 0.0], 0.02);
    b.frame("coupler-point", coupler, shift(0.5 * l.coupler, 0.15, 0.0));
    let rocker = b.joint(
        "rocker",
        JointKind::Continuous,
        coupler,
        shift(l.coupler, 0.0, 0.0),
        z,
        to_d - at_b,
        Pose::identity(),
        None,
    );
    b.shape(rocker, [0.0; 3], [l.rocker, 0.0, 0.0], 0.02);
    b.frame("rocker-end", rocker, shift(l.rocker, 0.0, 0.0));
    b.frame("ground-pivot", 0, shift(l.ground, 0.0, 0.0));
    b.close_loop(
        "four-bar loop",
        "rocker-end",
        "ground-pivot",
        false,
        &["coupler", "rocker"],
    );
    b.build()
}
