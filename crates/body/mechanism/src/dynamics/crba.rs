//! The joint-space mass matrix M(q) by composite rigid bodies: each joint
//! carries everything beyond it as one rigid body, and M's entries are
//! how one joint's motion of that composite loads each joint above it.

use nalgebra::DMatrix;

use super::Dynamics;
use super::spatial::{Link, Twist};
use super::tree::{Move, Node};
use crate::error::FieldError;
use crate::model::Model;

impl Model {
    /// M(q), symmetric, one row and column per state variable. Followers'
    /// rows and columns are folded into their leaders' (and left zero).
    pub fn mass_matrix_in<'w>(
        &self,
        work: &'w mut Dynamics,
        q: &[f64],
    ) -> Result<&'w DMatrix<f64>, FieldError> {
        self.check_dynamics(q, super::EARTH)?;
        self.place_links(work, q);
        self.crba(work);
        Ok(&work.mass)
    }

    /// [`Model::mass_matrix_in`] with a workspace of its own.
    pub fn mass_matrix(&self, q: &[f64]) -> Result<DMatrix<f64>, FieldError> {
        let mut work = self.dynamics();
        self.mass_matrix_in(&mut work, q).cloned()
    }

    /// M for the links in `work` (placed for the state). Everything is
    /// taken to the root frame first, so each entry is one product: joint
    /// j's axis against the wrench that joint i's composite body needs to
    /// move along its own axis (the form Pinocchio's CRBA takes).
    pub(super) fn crba(&self, work: &mut Dynamics) {
        let nodes = &self.tree.nodes;
        for (i, node) in nodes.iter().enumerate() {
            let local = &work.links[i];
            let world = match node.parent {
                Some(p) => work.world[p].then(local),
                None => *local,
            };
            work.world[i] = world;
            work.crba[i] = node.rigid.seen_in_parent(&world.r, &world.p);
            work.v[i] = axis_in_root(node, &world);
        }
        let count = nodes.len();
        // Slices of the tree's length let the compiler drop most bounds checks.
        let (composite, axes) = (&mut work.crba[..count], &work.v[..count]);
        for (i, node) in nodes.iter().enumerate().rev() {
            if let Some(p) = node.parent {
                let beyond = composite[i];
                composite[p].add(&beyond);
            }
        }
        let n = self.dof();
        let mass = work.mass.as_mut_slice();
        mass.fill(0.0);
        for (i, node) in nodes.iter().enumerate() {
            let k = node.variable;
            let f = composite[i].times(&axes[i]);
            mass[k * n + k] = axes[i].dot(&f);
            let mut above = node.parent;
            while let Some(a) = above {
                let m = nodes[a].variable;
                let entry = axes[a].dot(&f);
                mass[k * n + m] = entry;
                mass[m * n + k] = entry;
                above = nodes[a].parent;
            }
        }
        for c in &self.couplings {
            let follower = work.mass.column(c.follower).clone_owned();
            work.mass.column_mut(c.leader).axpy(c.ratio, &follower, 1.0);
            work.mass.column_mut(c.follower).fill(0.0);
            for col in 0..self.dof() {
                let moved = work.mass[(c.follower, col)];
                work.mass[(c.leader, col)] += c.ratio * moved;
                work.mass[(c.follower, col)] = 0.0;
            }
        }
    }
}

/// A node's unit motion in the root frame, where its frame sits at
/// `world`. About a coordinate axis, that is a column of the rotation.
#[inline]
fn axis_in_root(node: &Node, world: &Link) -> Twist {
    match node.motion {
        Move::Turn(axis) => {
            let w = world.r.column(axis.index()).into_owned();
            Twist {
                w,
                v: world.p.cross(&w),
            }
        }
        _ => world.twist_in_parent(&node.axis),
    }
}
