//! Forward kinematics by walking the tree, and the geometric Jacobian.

use nalgebra::{DMatrix, Vector3};

use crate::error::MechanismError;
use crate::model::{FrameRef, Model, Pose};

/// Where everything is for one state: each body's frame and each joint's
/// frame (the axis, before the joint moves), in the world.
#[derive(Debug, Clone, PartialEq)]
pub struct Placement {
    pub bodies: Vec<Pose>,
    pub joints: Vec<Pose>,
}

impl Model {
    /// The value of joint `j` in state `q` (0 for fixed joints).
    #[inline]
    fn value(&self, q: &[f64], j: usize) -> f64 {
        self.variable_of[j].map_or(0.0, |v| q[v])
    }

    /// Every body's and joint's frame in the world.
    pub fn place(&self, q: &[f64]) -> Result<Placement, MechanismError> {
        self.check_state(q)?;
        let mut bodies = vec![Pose::identity(); self.bodies.len()];
        let mut joints = Vec::with_capacity(self.joints.len());
        for (i, j) in self.joints.iter().enumerate() {
            let at = bodies[j.parent] * j.origin;
            bodies[j.child] = at * j.motion(self.value(q, i)) * j.post;
            joints.push(at);
        }
        Ok(Placement { bodies, joints })
    }

    /// One frame in the world, walking only the joints above it.
    pub fn pose(&self, q: &[f64], frame: &FrameRef) -> Result<Pose, MechanismError> {
        self.check_state(q)?;
        Ok(self.pose_unchecked(q, frame))
    }

    #[inline]
    pub(crate) fn pose_unchecked(&self, q: &[f64], frame: &FrameRef) -> Pose {
        let mut t = Pose::identity();
        for &j in &self.chains[frame.body] {
            let joint = &self.joints[j];
            t = t * joint.origin * joint.motion(self.value(q, j)) * joint.post;
        }
        t * frame.offset
    }

    /// The pose of `to` seen from `from`: from⁻¹ · to.
    pub fn relative(
        &self,
        q: &[f64],
        from: &FrameRef,
        to: &FrameRef,
    ) -> Result<Pose, MechanismError> {
        Ok(self.pose(q, from)?.inverse() * self.pose(q, to)?)
    }

    /// The geometric Jacobian of `frame` (6 × dof): rows are the linear
    /// then the angular velocity of the frame in the world, columns the
    /// joint variables. Joints not above the frame give zero columns.
    pub fn jacobian(&self, q: &[f64], frame: &FrameRef) -> Result<DMatrix<f64>, MechanismError> {
        self.check_state(q)?;
        let mut jac = DMatrix::zeros(6, self.dof());
        let p = self.pose_unchecked(q, frame).translation.vector;
        self.jacobian_add(q, frame, &p, 1.0, &mut jac, 0);
        self.fold_couplings(&mut jac);
        Ok(jac)
    }

    /// Add `sign` times the Jacobian of a point `p` riding on `frame`'s
    /// body to rows `row..row+6` of `jac` (columns of the joints above it).
    pub(crate) fn jacobian_add(
        &self,
        q: &[f64],
        frame: &FrameRef,
        p: &Vector3<f64>,
        sign: f64,
        jac: &mut DMatrix<f64>,
        row: usize,
    ) {
        let mut t = Pose::identity();
        for &j in &self.chains[frame.body] {
            let joint = &self.joints[j];
            let at = t * joint.origin;
            t = at * joint.motion(self.value(q, j)) * joint.post;
            let Some(v) = self.variable_of[j] else {
                continue;
            };
            let z = at.rotation * joint.axis.into_inner();
            let (linear, angular) = match joint.kind {
                crate::JointKind::Prismatic => (z, Vector3::zeros()),
                _ => (z.cross(&(p - at.translation.vector)), z),
            };
            for k in 0..3 {
                jac[(row + k, v)] += sign * linear[k];
                jac[(row + 3 + k, v)] += sign * angular[k];
            }
        }
    }
}
