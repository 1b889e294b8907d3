//! AnyMorphology on the lab's own mechanism model: elements are bodies,
//! pairs are joints, ports are where a joint or a named frame attaches.
//! Dissolving a pair (deleting the port it hangs on) cuts the tree; the
//! transform between two elements goes through the pairs on the path
//! between them, T(A→B) = T(A→R)·T(R→B) with R their common ancestor.

use kinolab_mechanism::{FrameRef, Model, Pose};

/// The joints from the root (the world) down to `body`, in order.
pub fn chain(model: &Model, body: usize) -> Vec<usize> {
    let mut out = Vec::new();
    let mut b = body;
    // A tree has at most as many steps to the root as it has joints.
    for _ in 0..model.joints().len() {
        match model.joints().iter().position(|j| j.child == b) {
            Some(j) => {
                out.push(j);
                b = model.joints()[j].parent;
            }
            None => break,
        }
    }
    out.reverse();
    out
}

/// The pairs on the path between elements `a` and `b`.
pub fn path(model: &Model, a: usize, b: usize) -> Vec<usize> {
    let (ca, cb) = (chain(model, a), chain(model, b));
    let common = ca.iter().zip(&cb).take_while(|(x, y)| x == y).count();
    ca[common..].iter().chain(&cb[common..]).copied().collect()
}

/// The pose of element `b` seen from element `a` at joint values `q`, or
/// `None` when a dissolved pair lies between them.
pub fn between(model: &Model, q: &[f64], a: usize, b: usize, dissolved: &[usize]) -> Option<Pose> {
    if path(model, a, b).iter().any(|j| dissolved.contains(j)) {
        return None;
    }
    let frame = |body| FrameRef {
        body,
        offset: Pose::identity(),
    };
    model.relative(q, &frame(a), &frame(b)).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_transform_through_the_ports_is_the_crates_own() {
        let model = kinolab_mechanism::catalogue::mechanism("rover-arm").unwrap();
        let q: Vec<f64> = (0..model.dof()).map(|i| 0.1 * i as f64 - 0.2).collect();
        let placed = model.place(&q).unwrap();
        let n = model.bodies().len();
        for a in 0..n {
            for b in (0..n).step_by(3) {
                let t = between(&model, &q, a, b, &[]).unwrap();
                let want = placed.bodies[a].inverse() * placed.bodies[b];
                let err = (t.to_homogeneous() - want.to_homogeneous()).abs().max();
                assert!(err < 1e-9, "{a}->{b}: {err}");
            }
        }
        // Dissolving a pair on the path leaves no transform; one elsewhere
        // does not matter.
        let last = n - 1;
        let on_path = chain(&model, last)[0];
        assert!(between(&model, &q, 0, last, &[on_path]).is_none());
        let elsewhere: Vec<usize> = (0..model.joints().len())
            .filter(|j| !path(&model, 0, last).contains(j))
            .collect();
        assert!(between(&model, &q, 0, last, &elsewhere).is_some());
    }
}
