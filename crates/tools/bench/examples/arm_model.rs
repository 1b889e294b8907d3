//! Print an arm (`puma`, the default, or `panda`) and the state the kernels
//! use, in the plain format the Pinocchio anchor reads: one line per moving
//! joint (kind, axis, then its placement in the previous joint's frame as a
//! row-major rotation and a translation), each followed by the body's mass
//! in that joint's frame (`inertia m cx cy cz ixx ixy ixz iyy iyz izz`), the
//! tool frame's placement in the last joint's frame, and `q`, `qd`, `qdd`.
//! Joint offsets fold into `q`, fixed joints into the placements.
//!
//! `cargo xtask bench --anchors` runs it; it is not part of the lab.

// Its output is the point: the description goes to standard output.
#![allow(clippy::print_stdout)]

use kinolab_bench::mechanism::{self as bench, panda, puma};
use kinolab_mechanism::{Inertial, JointKind, Pose};

fn placement(p: &Pose) -> String {
    let r = p.rotation.to_rotation_matrix();
    let m = r.matrix();
    let t = p.translation.vector;
    let mut out = Vec::with_capacity(12);
    for i in 0..3 {
        for j in 0..3 {
            out.push(format!("{:.17e}", m[(i, j)]));
        }
    }
    out.extend(t.iter().map(|x| format!("{x:.17e}")));
    out.join(" ")
}

/// The body's mass moved into the joint's frame (the body sits `post` on).
fn inertia(body: Option<Inertial>, post: &Pose) -> String {
    let i = body.map_or(
        Inertial {
            mass: 0.0,
            com: nalgebra::Vector3::zeros(),
            inertia: nalgebra::Matrix3::zeros(),
        },
        |b| {
            b.moved(
                post.rotation.to_rotation_matrix().matrix(),
                &post.translation.vector,
            )
        },
    );
    let mut out = vec![i.mass, i.com.x, i.com.y, i.com.z];
    out.extend(i.entries());
    let words: Vec<String> = out.iter().map(|v| format!("{v:.17e}")).collect();
    format!("inertia {}", words.join(" "))
}

fn main() {
    let which = std::env::args().nth(1).unwrap_or_else(|| "puma".into());
    let (arm, state, qd, qdd): (_, &[f64], &[f64], &[f64]) = match which.as_str() {
        "panda" => (
            panda(),
            &bench::PANDA_Q,
            &bench::PANDA_QD,
            &bench::PANDA_QDD,
        ),
        _ => (puma(), &bench::PUMA_Q, &bench::PUMA_QD, &bench::PUMA_QDD),
    };
    let Some(arm) = arm else {
        eprintln!("arm_model: the catalogue has no {which}");
        std::process::exit(2);
    };
    let mut carry = Pose::identity();
    let mut q = Vec::new();
    for j in arm.model.joints() {
        let kind = match j.kind {
            JointKind::Fixed => {
                carry = carry * j.origin * j.post;
                continue;
            }
            JointKind::Prismatic => "prismatic",
            JointKind::Revolute | JointKind::Continuous => "revolute",
        };
        let a = j.axis.into_inner();
        println!(
            "{kind} {:.17e} {:.17e} {:.17e} {}",
            a.x,
            a.y,
            a.z,
            placement(&(carry * j.origin))
        );
        println!("{}", inertia(arm.model.bodies()[j.child].inertial, &j.post));
        q.push(state[q.len()] + j.offset);
        carry = j.post;
    }
    println!("tool {}", placement(&(carry * arm.tool.offset)));
    let line = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:.17e}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    println!("q {}", line(&q));
    println!("qd {}", line(qd));
    println!("qdd {}", line(qdd));
    if let Ok(p) = arm.model.pose(state, &arm.tool) {
        let t = p.translation.vector;
        println!("# ours tool {:.15} {:.15} {:.15}", t.x, t.y, t.z);
    }
    if let Ok(jac) = arm.model.jacobian(state, &arm.tool) {
        println!("# ours jacobian_norm {:.15}", jac.norm());
    }
    let g = kinolab_mechanism::dynamics::EARTH;
    if let Ok(tau) = arm.model.inverse_dynamics(state, qd, qdd, g) {
        println!("# ours tau {}", line(&tau));
    }
    if let Ok(m) = arm.model.mass_matrix(state) {
        println!("# ours mass_diagonal {}", line(m.diagonal().as_slice()));
    }
    if let Ok(a) = arm.model.forward_dynamics(state, qd, qdd, g) {
        println!("# ours forward {}", line(&a));
    }
}
