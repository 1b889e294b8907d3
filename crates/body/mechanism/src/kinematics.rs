//! Forward kinematics by walking the tree, and the geometric Jacobian.

use nalgebra::DMatrix;

use crate::error::FieldError;
use crate::model::{FrameRef, Model, Pose};
use crate::steps::{Motion, Step};

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
    pub fn place(&self, q: &[f64]) -> Result<Placement, FieldError> {
        self.check_state(q)?;
        let mut bodies = vec![Pose::identity(); self.bodies.len()];
        let mut joints = Vec::with_capacity(self.joints.len());
        for (i, j) in self.joints.iter().enumerate() {
            let mut t = bodies[j.parent];
            self.enter(&mut t, i);
            joints.push(t);
            self.cross(&mut t, i, q);
            bodies[j.child] = t;
        }
        Ok(Placement { bodies, joints })
    }

    /// An arm as a line of points in `plane`: the origin of each joint's
    /// moving body, in joint order, then `frame`'s origin (what a drawing
    /// of the arm from above or from the side joins up).
    pub fn chain_in_plane(
        &self,
        q: &[f64],
        frame: &FrameRef,
        plane: crate::shapes::Plane,
    ) -> Result<Vec<[f64; 2]>, FieldError> {
        let placed = self.place(q)?;
        let mut points: Vec<[f64; 2]> = self
            .joints
            .iter()
            .map(|j| plane.project(&placed.bodies[j.child].translation.vector))
            .collect();
        let end = placed.bodies[frame.body] * frame.offset;
        points.push(plane.project(&end.translation.vector));
        Ok(points)
    }

    /// Move `t` from joint `j`'s parent frame onto the joint's axis.
    #[inline]
    fn enter(&self, t: &mut Pose, j: usize) {
        if !self.plain[j][0] {
            *t *= self.joints[j].origin;
        }
    }

    /// Move `t` from joint `j`'s axis through its motion for state `q` to
    /// the child body's frame. A turn only changes the rotation and a slide
    /// only the translation, so neither needs a full product.
    #[inline]
    fn cross(&self, t: &mut Pose, j: usize, q: &[f64]) {
        let joint = &self.joints[j];
        let v = self.value(q, j) + joint.offset;
        match joint.kind {
            crate::JointKind::Revolute | crate::JointKind::Continuous => {
                t.rotation *= nalgebra::UnitQuaternion::from_axis_angle(&joint.axis, v);
            }
            crate::JointKind::Prismatic => {
                t.translation.vector += t.rotation * (joint.axis.into_inner() * v);
            }
            crate::JointKind::Fixed => {}
        }
        if !self.plain[j][1] {
            *t *= joint.post;
        }
    }

    /// One frame in the world, walking only the joints above it (or from
    /// a plugged-in closed form, when one knows this frame).
    pub fn pose(&self, q: &[f64], frame: &FrameRef) -> Result<Pose, FieldError> {
        self.check_state(q)?;
        Ok(self
            .pose_by_command(q, frame)
            .unwrap_or_else(|| self.pose_unchecked(q, frame)))
    }

    /// [`Model::pose`] by walking the tree, never by a plugged-in command:
    /// the reference the closed forms are checked against.
    pub fn pose_generic(&self, q: &[f64], frame: &FrameRef) -> Result<Pose, FieldError> {
        self.check_state(q)?;
        Ok(self.pose_unchecked(q, frame))
    }

    #[inline]
    pub(crate) fn pose_unchecked(&self, q: &[f64], frame: &FrameRef) -> Pose {
        let t = self.walk(q, &self.chains[frame.body], |_, _, _| {});
        if frame.offset == Pose::identity() {
            t
        } else {
            t * frame.offset
        }
    }

    /// Walk `chain` (joints from the world down) at state `q` with the
    /// prepared steps, showing `visit` each joint's axis frame before it
    /// moves; returns the frame of the last joint's child body.
    #[inline]
    fn walk(&self, q: &[f64], chain: &[usize], mut visit: impl FnMut(usize, &Step, &Pose)) -> Pose {
        let mut t = Pose::identity();
        for (k, &j) in chain.iter().enumerate() {
            let step = &self.steps[j];
            match (&step.into, k) {
                (Some(into), 0) => t = into.pose(),
                (Some(into), _) => into.apply(&mut t),
                (None, _) => {}
            }
            visit(j, step, &t);
            step.motion.apply(&mut t, self.value(q, j) + step.offset);
        }
        if let Some(&last) = chain.last()
            && !self.plain[last][1]
        {
            t *= self.joints[last].post;
        }
        t
    }

    /// The pose of `to` seen from `from`: from⁻¹ · to.
    pub fn relative(&self, q: &[f64], from: &FrameRef, to: &FrameRef) -> Result<Pose, FieldError> {
        Ok(self.pose(q, from)?.inverse() * self.pose(q, to)?)
    }

    /// The geometric Jacobian of `frame` (6 × dof): rows are the linear
    /// then the angular velocity of the frame in the world, columns the
    /// joint variables. Joints not above the frame give zero columns.
    pub fn jacobian(&self, q: &[f64], frame: &FrameRef) -> Result<DMatrix<f64>, FieldError> {
        let mut work = self.workspace();
        self.jacobian_in(&mut work, q, frame)?;
        Ok(work.jacobian)
    }

    /// [`Model::jacobian`] into a workspace kept between calls, so that
    /// repeated queries allocate nothing.
    pub fn jacobian_in<'w>(
        &self,
        work: &'w mut Workspace,
        q: &[f64],
        frame: &FrameRef,
    ) -> Result<&'w DMatrix<f64>, FieldError> {
        self.check_state(q)?;
        if work.jacobian.shape() != (6, self.dof()) {
            work.jacobian = DMatrix::zeros(6, self.dof());
        } else {
            work.jacobian.fill(0.0);
        }
        // One walk gives both the frame's point and the joints' axes.
        let p = self.walk_axes(q, frame, &mut work.axes).translation.vector;
        crate::ik::add_columns(&work.axes, &p, 1.0, &mut work.jacobian);
        self.fold_couplings(&mut work.jacobian);
        Ok(&work.jacobian)
    }

    /// A workspace for this model's queries.
    pub fn workspace(&self) -> Workspace {
        Workspace {
            axes: Vec::with_capacity(self.dof()),
            jacobian: DMatrix::zeros(6, self.dof()),
        }
    }

    /// Walk down to `frame`, noting the world axis of every moving joint on
    /// the way; returns the frame's pose.
    pub(crate) fn walk_axes(
        &self,
        q: &[f64],
        frame: &FrameRef,
        out: &mut Vec<crate::ik::Axis>,
    ) -> Pose {
        out.clear();
        let t = self.walk(q, &self.chains[frame.body], |j, step, t| {
            if let Some(v) = self.variable_of[j] {
                out.push(crate::ik::Axis {
                    v,
                    prismatic: matches!(step.motion, Motion::Slide(_)),
                    z: step.motion.world_axis(t),
                    o: t.translation.vector,
                });
            }
        });
        if frame.offset == Pose::identity() {
            t
        } else {
            t * frame.offset
        }
    }
}

/// Scratch space for one model's queries, kept by whoever asks them (in
/// the spirit of Pinocchio's `Data`): the Jacobian and the joint axes met
/// on the way. The model itself stays stateless.
#[derive(Debug, Clone, Default)]
pub struct Workspace {
    axes: Vec<crate::ik::Axis>,
    jacobian: DMatrix<f64>,
}
