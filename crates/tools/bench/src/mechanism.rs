//! Mechanism kernels: forward kinematics, the Jacobian and inverse
//! kinematics on fixed, seeded inputs; plus the IK success survey.

use std::hint::black_box;
use std::sync::OnceLock;

use kinolab_mechanism::catalogue::mechanism;
use kinolab_mechanism::{FrameRef, Goal, Model, Options, Pose, Target};

/// A model and its tool frame.
#[derive(Debug)]
pub struct Arm {
    pub model: Model,
    pub tool: FrameRef,
}

fn arm(id: &str) -> Option<Arm> {
    let model = mechanism(id).ok()?;
    let tool = model.frame("tool").ok()?;
    Some(Arm { model, tool })
}

pub fn puma() -> Option<&'static Arm> {
    static PUMA: OnceLock<Option<Arm>> = OnceLock::new();
    PUMA.get_or_init(|| arm("puma560")).as_ref()
}

pub fn panda() -> Option<&'static Arm> {
    static PANDA: OnceLock<Option<Arm>> = OnceLock::new();
    PANDA.get_or_init(|| arm("panda")).as_ref()
}

/// A joint configuration used by the FK and Jacobian kernels.
pub const PUMA_Q: [f64; 6] = [0.3, -0.5, 0.8, 0.2, 0.6, -0.4];

/// Seeded random configurations inside the joint limits.
pub fn random_states(model: &Model, count: usize, seed: u64) -> Vec<Vec<f64>> {
    let mut s = seed;
    let mut next = move || {
        s = s
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..count)
        .map(|_| {
            (0..model.dof())
                .map(|i| {
                    let [lo, hi] = model
                        .variable_joint(i)
                        .and_then(|j| j.limits)
                        .unwrap_or([-std::f64::consts::PI, std::f64::consts::PI]);
                    lo + next() * (hi - lo)
                })
                .collect()
        })
        .collect()
}

/// Reachable targets: the tool's pose at random configurations.
pub fn targets(arm: &Arm, count: usize, seed: u64) -> Vec<Pose> {
    random_states(&arm.model, count, seed)
        .iter()
        .filter_map(|q| arm.model.pose(q, &arm.tool).ok())
        .collect()
}

/// Tolerances of the issue: 1e-6 m and 1e-6 rad.
pub fn ik_options() -> Options {
    Options {
        position_tolerance: 1e-6,
        rotation_tolerance: 1e-6,
        ..Options::default()
    }
}

/// Solve each target from the zero pose; returns how many converged.
pub fn solve_all(arm: &Arm, targets: &[Pose]) -> usize {
    solve_all_from(arm, targets, &arm.model.zero_state())
}

/// Solve each target from `seed`; returns how many converged.
pub fn solve_all_from(arm: &Arm, targets: &[Pose], seed: &[f64]) -> usize {
    let options = ik_options();
    targets
        .iter()
        .filter(|t| {
            arm.model
                .solve(&[Goal::new(arm.tool, Target::Pose(**t))], seed, &options)
                .is_ok_and(|s| s.converged)
        })
        .count()
}

fn ik_targets(which: &'static OnceLock<Vec<Pose>>, arm: Option<&'static Arm>) -> &'static [Pose] {
    which.get_or_init(|| arm.map(|a| targets(a, 100, 17)).unwrap_or_default())
}

/// FK of the Puma's tool frame.
pub fn fk_puma() -> f64 {
    puma()
        .and_then(|a| a.model.pose(black_box(&PUMA_Q), &a.tool).ok())
        .map_or(f64::NAN, |p| p.translation.vector.x + 1.0)
}

/// The Panda read from its URDF file, and its flange (`panda_link8`).
pub fn panda_urdf() -> Option<&'static Arm> {
    static PANDA: OnceLock<Option<Arm>> = OnceLock::new();
    PANDA
        .get_or_init(|| {
            let robot = kinolab_mechanism::urdf::read(PANDA_URDF).ok()?;
            let tool = robot.model.frame("panda_link8").ok()?;
            Some(Arm {
                model: robot.model,
                tool,
            })
        })
        .as_ref()
}

const PANDA_URDF: &str = include_str!("../../../body/mechanism/robots/panda.urdf");

/// One Panda configuration: the seven arm joints (and, in the URDF, the
/// fingers at zero).
pub const PANDA_Q: [f64; 7] = [0.3, -0.5, 0.2, -1.8, 0.4, 1.6, -0.6];

/// FK of the Panda's flange, the arm written as modified DH.
pub fn fk_panda_dh() -> f64 {
    panda()
        .and_then(|a| a.model.pose(black_box(&PANDA_Q), &a.tool).ok())
        .map_or(f64::NAN, |p| p.translation.vector.x + 1.0)
}

/// FK of the same flange, the arm read from its URDF file.
pub fn fk_panda_urdf() -> f64 {
    let mut q = [0.0; 9];
    q[..7].copy_from_slice(&PANDA_Q);
    panda_urdf()
        .and_then(|a| a.model.pose(black_box(&q[..a.model.dof()]), &a.tool).ok())
        .map_or(f64::NAN, |p| p.translation.vector.x + 1.0)
}

/// Read and build a 50-link chain from URDF text.
pub fn urdf_parse_50() -> f64 {
    static TEXT: OnceLock<String> = OnceLock::new();
    let text = TEXT.get_or_init(|| {
        let mut s = String::from("<robot name=\"chain\"><link name=\"l0\"/>\n");
        for i in 1..=50 {
            s += &format!(
                "<link name=\"l{i}\"><collision><geometry><box size=\"0.1 0.05 0.05\"/></geometry></collision></link>\n\
                 <joint name=\"j{i}\" type=\"revolute\"><parent link=\"l{}\"/><child link=\"l{i}\"/>\
                 <origin xyz=\"0.1 0 0\" rpy=\"0 0 0.1\"/><axis xyz=\"0 0 1\"/>\
                 <limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\n",
                i - 1
            );
        }
        s + "</robot>"
    });
    kinolab_mechanism::urdf::read(black_box(text)).map_or(f64::NAN, |r| r.model.dof() as f64)
}

/// All-frames FK of the rocker-bogie rover.
pub fn fk_rover_all() -> f64 {
    static ROVER: OnceLock<Option<Model>> = OnceLock::new();
    let Some(rover) = ROVER
        .get_or_init(|| mechanism("rocker-bogie").ok())
        .as_ref()
    else {
        return f64::NAN;
    };
    let q = [0.1, -0.1, 0.2, -0.15];
    rover.place(black_box(&q)).map_or(f64::NAN, |p| {
        p.bodies.iter().map(|b| b.translation.vector.z).sum()
    })
}

thread_local! {
    /// The Puma's workspace, kept between calls as the lab's widgets keep
    /// theirs (and as Pinocchio's `Data` is kept).
    static PUMA_WORK: std::cell::RefCell<kinolab_mechanism::Workspace> =
        std::cell::RefCell::new(puma().map(|a| a.model.workspace()).unwrap_or_default());
}

/// The Puma tool's geometric Jacobian (6 × 6), into a kept workspace.
pub fn jacobian_puma() -> f64 {
    let Some(a) = puma() else { return f64::NAN };
    PUMA_WORK.with_borrow_mut(|work| {
        a.model
            .jacobian_in(work, black_box(&PUMA_Q), &a.tool)
            .map_or(f64::NAN, |j| j[(0, 0)] + j[(5, 5)])
    })
}

/// IK of 100 seeded reachable Puma targets from the zero pose.
pub fn ik_puma_100() -> f64 {
    static T: OnceLock<Vec<Pose>> = OnceLock::new();
    let targets = ik_targets(&T, puma());
    puma().map_or(f64::NAN, |a| solve_all(a, black_box(targets)) as f64)
}

/// The start pose of the comparison with the `k` crate, whose solver
/// cannot start from the Puma's singular zero pose.
pub const BENT_START: [f64; 6] = [0.0, -0.6, 0.9, 0.0, 0.6, 0.0];

/// IK of the same 100 Puma targets from [`BENT_START`].
pub fn ik_puma_100_bent() -> f64 {
    static T: OnceLock<Vec<Pose>> = OnceLock::new();
    let targets = ik_targets(&T, puma());
    puma().map_or(f64::NAN, |a| {
        solve_all_from(a, black_box(targets), &BENT_START) as f64
    })
}

/// IK of 100 seeded reachable Panda targets from the zero pose.
pub fn ik_panda_100() -> f64 {
    static T: OnceLock<Vec<Pose>> = OnceLock::new();
    let targets = ik_targets(&T, panda());
    panda().map_or(f64::NAN, |a| solve_all(a, black_box(targets)) as f64)
}

/// Joint rates the dynamics kernels use (velocities, accelerations).
pub const PUMA_QD: [f64; 6] = [0.4, -0.3, 0.5, -0.2, 0.3, 0.1];
pub const PUMA_QDD: [f64; 6] = [-0.5, 0.2, 0.4, 0.6, -0.1, 0.3];
pub const PANDA_QD: [f64; 7] = [0.4, -0.3, 0.5, -0.2, 0.3, 0.1, -0.4];
pub const PANDA_QDD: [f64; 7] = [-0.5, 0.2, 0.4, 0.6, -0.1, 0.3, 0.2];

thread_local! {
    /// Each arm's dynamics workspace, kept between calls as a controller
    /// keeps it.
    static PUMA_DYNAMICS: std::cell::RefCell<Option<kinolab_mechanism::Dynamics>> =
        const { std::cell::RefCell::new(None) };
    static PANDA_DYNAMICS: std::cell::RefCell<Option<kinolab_mechanism::Dynamics>> =
        const { std::cell::RefCell::new(None) };
}

/// Which computation a dynamics kernel times.
#[derive(Debug, Clone, Copy)]
enum Solve {
    Rnea,
    Gravity,
    Crba,
    Aba,
}

fn dynamics_on(panda_arm: bool, solve: Solve) -> f64 {
    let (arm, q, qd, qdd): (_, &[f64], &[f64], &[f64]) = if panda_arm {
        (panda(), &PANDA_Q, &PANDA_QD, &PANDA_QDD)
    } else {
        (puma(), &PUMA_Q, &PUMA_QD, &PUMA_QDD)
    };
    let Some(arm) = arm else { return f64::NAN };
    let m = &arm.model;
    let g = kinolab_mechanism::dynamics::EARTH;
    let cell = if panda_arm {
        &PANDA_DYNAMICS
    } else {
        &PUMA_DYNAMICS
    };
    cell.with_borrow_mut(|work| {
        let work = work.get_or_insert_with(|| m.dynamics());
        let (q, qd, qdd) = (black_box(q), black_box(qd), black_box(qdd));
        let first = match solve {
            Solve::Rnea => m.inverse_dynamics_in(work, q, qd, qdd, g).map(|t| t[0]),
            Solve::Gravity => m.gravity_in(work, q, g).map(|t| t[0]),
            Solve::Crba => m.mass_matrix_in(work, q).map(|mm| mm[(0, 0)]),
            Solve::Aba => m.forward_dynamics_in(work, q, qd, qdd, g).map(|a| a[0]),
        };
        first.unwrap_or(f64::NAN)
    })
}

pub fn rnea_puma() -> f64 {
    dynamics_on(false, Solve::Rnea)
}
pub fn gravity_puma() -> f64 {
    dynamics_on(false, Solve::Gravity)
}
pub fn crba_puma() -> f64 {
    dynamics_on(false, Solve::Crba)
}
pub fn aba_puma() -> f64 {
    dynamics_on(false, Solve::Aba)
}
pub fn rnea_panda() -> f64 {
    dynamics_on(true, Solve::Rnea)
}
pub fn gravity_panda() -> f64 {
    dynamics_on(true, Solve::Gravity)
}
pub fn crba_panda() -> f64 {
    dynamics_on(true, Solve::Crba)
}
pub fn aba_panda() -> f64 {
    dynamics_on(true, Solve::Aba)
}
