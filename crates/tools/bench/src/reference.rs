//! The `k` crate (openrr's kinematics library) on the same arm and the
//! same targets, for comparison. Native only, behind the `compare-k`
//! feature, so ordinary builds and tests never compile it.

use std::hint::black_box;
use std::sync::OnceLock;

use k::nalgebra as kn;
use k::prelude::*;
use kinolab_mechanism::{JointKind, Model, Pose};

use crate::mechanism::{PUMA_Q, puma, targets};

fn iso(p: &Pose) -> kn::Isometry3<f64> {
    let t = p.translation.vector;
    let r = p.rotation.coords;
    kn::Isometry3::from_parts(
        kn::Translation3::new(t.x, t.y, t.z),
        kn::UnitQuaternion::from_quaternion(kn::Quaternion::new(r.w, r.x, r.y, r.z)),
    )
}

/// The same serial chain in `k`: each of our joints' `post` transform
/// moves into the next node's origin.
pub fn chain_of(model: &Model, tool: &Pose) -> Option<k::SerialChain<f64>> {
    let mut carry = Pose::identity();
    let mut nodes: Vec<k::Node<f64>> = Vec::new();
    for j in model.joints() {
        let origin = carry * j.origin;
        let a = j.axis.into_inner();
        let axis = kn::Unit::new_normalize(kn::Vector3::new(a.x, a.y, a.z));
        let joint_type = match j.kind {
            JointKind::Fixed => k::JointType::Fixed,
            JointKind::Prismatic => k::JointType::Linear { axis },
            _ => k::JointType::Rotational { axis },
        };
        let node: k::Node<f64> = k::NodeBuilder::new()
            .name(&j.name)
            .origin(iso(&origin))
            .joint_type(joint_type)
            .into_node();
        if j.offset != 0.0 {
            return None;
        }
        if let Some(parent) = nodes.last() {
            node.set_parent(parent);
        }
        nodes.push(node);
        carry = j.post;
    }
    let end: k::Node<f64> = k::NodeBuilder::new()
        .name("tool")
        .origin(iso(&(carry * tool)))
        .into_node();
    end.set_parent(nodes.last()?);
    Some(k::SerialChain::from_end(&end))
}

thread_local! {
    /// `k` shares its nodes through reference counting, so the chain lives
    /// per thread (the benchmarks run on one).
    static PUMA_K: Option<k::SerialChain<f64>> =
        puma().and_then(|a| chain_of(&a.model, &Pose::identity()));
}

/// FK of the Puma's tool in `k`.
pub fn k_fk_puma() -> f64 {
    PUMA_K.with(|chain| {
        let Some(chain) = chain else { return f64::NAN };
        if chain.set_joint_positions(black_box(&PUMA_Q)).is_err() {
            return f64::NAN;
        }
        chain.end_transform().translation.vector.x + 1.0
    })
}

/// `k`'s Jacobian IK on the same 100 Puma targets, from [`K_SEED`], at the
/// same tolerance and 100 iterations; returns how many converged.
pub fn k_ik_puma_100() -> f64 {
    static T: OnceLock<Vec<Pose>> = OnceLock::new();
    let targets = T.get_or_init(|| puma().map(|a| targets(a, 100, 17)).unwrap_or_default());
    PUMA_K.with(|chain| {
        chain
            .as_ref()
            .map_or(f64::NAN, |c| solve_all_k(c, targets) as f64)
    })
}

/// Where `k` starts: its Jacobian solver inverts the Jacobian without
/// damping, so it cannot start from the Puma's zero pose (the wrist is
/// singular there, q5 = 0); this bent pose is regular.
pub const K_SEED: [f64; 6] = crate::mechanism::BENT_START;

pub fn solve_all_k(chain: &k::SerialChain<f64>, targets: &[Pose]) -> usize {
    let solver = k::JacobianIkSolver::new(1e-6, 1e-6, 0.5, 100);
    targets
        .iter()
        .filter(|t| {
            chain.set_joint_positions_unchecked(&K_SEED);
            solver.solve(chain, &iso(t)).is_ok()
        })
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_k_puma_is_our_puma() {
        let Some(ours) = puma() else {
            panic!("no puma")
        };
        let Some(theirs) = chain_of(&ours.model, &Pose::identity()) else {
            panic!("no k puma")
        };
        for q in crate::mechanism::random_states(&ours.model, 20, 5) {
            let a = ours
                .model
                .pose(&q, &ours.tool)
                .unwrap_or_else(|e| panic!("{e}"));
            theirs.set_joint_positions_unchecked(&q);
            let b = theirs.end_transform();
            let d = (a.translation.vector.x - b.translation.vector.x).abs()
                + (a.translation.vector.y - b.translation.vector.y).abs()
                + (a.translation.vector.z - b.translation.vector.z).abs();
            assert!(d < 1e-12, "{q:?}: {d}");
        }
    }
}
