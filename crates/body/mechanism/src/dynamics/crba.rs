//! The joint-space mass matrix M(q) by composite rigid bodies: each joint
//! carries everything beyond it as one rigid body, and M's entries are
//! how one joint's motion of that composite loads each joint above it.

use nalgebra::DMatrix;

use super::Dynamics;
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

    /// M for the links in `work` (placed for the state).
    pub(super) fn crba(&self, work: &mut Dynamics) {
        work.crba.copy_from_slice(&self.rigid);
        for (i, j) in self.joints.iter().enumerate().rev() {
            if j.parent != 0 {
                let link = &work.links[i];
                let up = work.crba[j.child].seen_in_parent(&link.r, &link.p);
                work.crba[j.parent].add(&up);
            }
        }
        work.mass.fill(0.0);
        for (i, j) in self.joints.iter().enumerate() {
            let Some(k) = self.variable_of[i] else {
                continue;
            };
            let s = work.axes[i];
            let mut f = work.crba[j.child].times(&s);
            work.mass[(k, k)] = s.dot(&f);
            // Up the chain: the same wrench, seen by each joint above.
            let mut below = i;
            while let Some(above) = self.parent_joint[self.joints[below].parent] {
                f = work.links[below].seen_in_parent(&f);
                if let Some(m) = self.variable_of[above] {
                    let entry = work.axes[above].dot(&f);
                    work.mass[(k, m)] = entry;
                    work.mass[(m, k)] = entry;
                }
                below = above;
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
