//! The tree the dynamics walk, prepared once from a model.
//!
//! Only joints that move matter to the dynamics: a body bolted to another
//! by a fixed joint moves as part of it. So the recursions walk one node
//! per moving joint, and each node carries the mass of every body fixed to
//! it, expressed in the joint's own frame (where the axis is a coordinate
//! axis and passes through the origin). Between two nodes sits one
//! constant transform, the fixed joints and post transforms in between
//! multiplied out beforehand, followed by the joint's motion. Pinocchio
//! merges fixed joints into their parents the same way.

use kinolab_common::trig;
use nalgebra::{Matrix3, Rotation3, Unit, Vector3};

use super::spatial::{Link, Twist};
use crate::inertial::Rigid;
use crate::model::{JointKind, Model, Pose};
use crate::steps::Principal;

/// How a node's joint moves its frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Move {
    /// Turns about a coordinate axis.
    Turn(Principal),
    /// Turns about any other axis.
    TurnAbout(Unit<Vector3<f64>>),
    /// Slides along an axis.
    Slide(Vector3<f64>),
}

/// One moving joint and everything that moves with it.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Node {
    /// The node this one hangs from (`None`: the world).
    pub parent: Option<usize>,
    /// The model's joint.
    pub joint: usize,
    /// Its state variable.
    pub variable: usize,
    /// Added to the variable (DH offsets).
    pub offset: f64,
    /// The joint's frame at zero motion in its parent node's frame.
    pub into: Link,
    /// Whether `into` turns at all (for a pure shift, the motion is the rotation).
    pub turned: bool,
    pub motion: Move,
    /// The joint's unit motion in its own frame.
    pub axis: Twist,
    /// The bodies that move with the joint, about its frame's origin.
    pub rigid: Rigid,
}

/// The dynamics' view of a model: its moving joints, parents first.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Tree {
    pub nodes: Vec<Node>,
}

impl Tree {
    /// The tree of `model`, with each body's mass from `model.rigid`.
    pub fn of(model: &Model) -> Tree {
        let bodies = model.bodies.len();
        // Each body's node, and its frame in that node's frame.
        let mut anchor: Vec<Option<usize>> = vec![None; bodies];
        let mut within = vec![Pose::identity(); bodies];
        let mut nodes = Vec::new();
        for (i, j) in model.joints.iter().enumerate() {
            let (p, c) = (j.parent, j.child);
            match model.variable_of[i] {
                Some(variable) => {
                    let into = within[p] * j.origin;
                    let r = *into.rotation.to_rotation_matrix().matrix();
                    nodes.push(Node {
                        parent: anchor[p],
                        joint: i,
                        variable,
                        offset: j.offset,
                        into: Link {
                            r,
                            p: into.translation.vector,
                        },
                        turned: r != Matrix3::identity(),
                        motion: motion_of(j),
                        axis: axis_of(j),
                        rigid: Rigid::ZERO,
                    });
                    anchor[c] = Some(nodes.len() - 1);
                    within[c] = j.post;
                }
                None => {
                    anchor[c] = anchor[p];
                    within[c] = within[p] * j.origin * j.post;
                }
            }
        }
        for b in 1..bodies {
            if let Some(n) = anchor[b] {
                let t = within[b];
                let r = t.rotation.to_rotation_matrix();
                let seen = model.rigid[b].seen_in_parent(r.matrix(), &t.translation.vector);
                nodes[n].rigid.add(&seen);
            }
        }
        Tree { nodes }
    }

    pub fn len(&self) -> usize {
        self.nodes.len()
    }
}

impl Node {
    /// Where the joint's frame sits in its parent node's at joint value `q`.
    #[inline]
    pub fn link(&self, q: f64) -> Link {
        let v = q + self.offset;
        let into = &self.into;
        match self.motion {
            Move::Turn(axis) => {
                let (s, c) = trig::sin_cos(v);
                let r = if self.turned {
                    turned(&into.r, axis, s, c)
                } else {
                    turned(&Matrix3::identity(), axis, s, c)
                };
                Link { r, p: into.p }
            }
            Move::TurnAbout(axis) => Link {
                r: into.r * Rotation3::from_axis_angle(&axis, v).matrix(),
                p: into.p,
            },
            Move::Slide(axis) => Link {
                r: into.r,
                p: into.p + into.r * (axis * v),
            },
        }
    }
}

/// `m · R(axis, angle)` for the angle with sine `s` and cosine `c`: only
/// the two columns the turn mixes change.
#[inline]
fn turned(m: &Matrix3<f64>, axis: Principal, s: f64, c: f64) -> Matrix3<f64> {
    let (i, j) = match axis {
        Principal::X => (1, 2),
        Principal::Y => (2, 0),
        Principal::Z => (0, 1),
    };
    let (a, b) = (m.column(i).into_owned(), m.column(j).into_owned());
    let mut out = *m;
    out.set_column(i, &(a * c + b * s));
    out.set_column(j, &(b * c - a * s));
    out
}

fn motion_of(j: &crate::Joint) -> Move {
    let a = j.axis.into_inner();
    match j.kind {
        JointKind::Prismatic => Move::Slide(a),
        _ => Principal::of(&a).map_or(Move::TurnAbout(j.axis), Move::Turn),
    }
}

fn axis_of(j: &crate::Joint) -> Twist {
    let a = j.axis.into_inner();
    match j.kind {
        JointKind::Prismatic => Twist {
            w: Vector3::zeros(),
            v: a,
        },
        _ => Twist {
            w: a,
            v: Vector3::zeros(),
        },
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// The two-column turn equals the full rotation matrix product.
        #[test]
        fn the_short_turn_is_the_rotation(
            v in -7.0f64..7.0, rx in -3.0f64..3.0, ry in -3.0f64..3.0, rz in -3.0f64..3.0,
        ) {
            let m = *Rotation3::from_euler_angles(rx, ry, rz).matrix();
            for (p, axis) in [
                (Principal::X, Vector3::x_axis()),
                (Principal::Y, Vector3::y_axis()),
                (Principal::Z, Vector3::z_axis()),
            ] {
                let (s, c) = v.sin_cos();
                let full = m * Rotation3::from_axis_angle(&axis, v).matrix();
                prop_assert!((turned(&m, p, s, c) - full).norm() < 1e-12, "{p:?}");
            }
        }
    }
}
