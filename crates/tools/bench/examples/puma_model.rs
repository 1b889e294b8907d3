//! Print the Puma (and the state the kernels use) in the plain format the
//! Pinocchio anchor reads: one line per moving joint (kind, axis, then its
//! placement in the previous joint's frame as a row-major rotation and a
//! translation), the tool frame's placement in the last joint's frame, and
//! `q`. Joint offsets fold into `q`, fixed joints into the placements.
//!
//! `cargo xtask bench --anchors` runs it; it is not part of the lab.

// Its output is the point: the description goes to standard output.
#![allow(clippy::print_stdout)]

use kinolab_bench::mechanism::{PUMA_Q, puma};
use kinolab_mechanism::{JointKind, Pose};

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

fn main() {
    let Some(arm) = puma() else {
        eprintln!("puma_model: the catalogue has no Puma");
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
        q.push(PUMA_Q[q.len()] + j.offset);
        carry = j.post;
    }
    println!("tool {}", placement(&(carry * arm.tool.offset)));
    let q: Vec<String> = q.iter().map(|v| format!("{v:.17e}")).collect();
    println!("q {}", q.join(" "));
    if let Ok(p) = arm.model.pose(&PUMA_Q, &arm.tool) {
        let t = p.translation.vector;
        println!("# ours tool {:.15} {:.15} {:.15}", t.x, t.y, t.z);
    }
    if let Ok(jac) = arm.model.jacobian(&PUMA_Q, &arm.tool) {
        println!("# ours jacobian_norm {:.15}", jac.norm());
    }
}
