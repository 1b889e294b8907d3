//! The joints as the walks use them, prepared once when a model is built.
//!
//! Walking down a chain, each joint used to cost two fixed products (its
//! origin, then the post transform) and a general rotation built from its
//! axis. Prepared, a step is one fixed product (the joint above's post and
//! this joint's origin, multiplied together beforehand, and skipped when
//! that is the identity) and a motion specialised to its axis: a turn
//! about x, y or z touches only the quaternion parts that axis needs. This
//! is what Pinocchio does with its joint types; the model stays stateless
//! and the prepared steps are part of it.

use kinolab_common::trig;
use nalgebra::{Quaternion, Unit, UnitQuaternion, Vector3};

use crate::model::{Joint, JointKind, Pose};

/// A coordinate axis, for turns that touch only the quaternion parts it
/// needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Principal {
    X,
    Y,
    Z,
}

impl Principal {
    pub(crate) fn of(a: &Vector3<f64>) -> Option<Principal> {
        [Principal::X, Principal::Y, Principal::Z]
            .into_iter()
            .find(|p| *a == p.unit())
    }

    /// The axis's coordinate: 0, 1 or 2.
    pub(crate) fn index(self) -> usize {
        self as usize
    }

    fn unit(self) -> Vector3<f64> {
        match self {
            Principal::X => Vector3::x(),
            Principal::Y => Vector3::y(),
            Principal::Z => Vector3::z(),
        }
    }

    /// `r · (c + s·axis)`: `r` turned by the angle whose half has sine `s`
    /// and cosine `c`, with the zero parts of the axis left out.
    #[inline]
    fn turn(self, r: &Quaternion<f64>, s: f64, c: f64) -> Quaternion<f64> {
        let (w, x, y, z) = (r.w, r.i, r.j, r.k);
        match self {
            Principal::X => {
                Quaternion::new(w * c - x * s, x * c + w * s, y * c + z * s, z * c - y * s)
            }
            Principal::Y => {
                Quaternion::new(w * c - y * s, x * c - z * s, y * c + w * s, z * c + x * s)
            }
            Principal::Z => {
                Quaternion::new(w * c - z * s, x * c + y * s, y * c - x * s, z * c + w * s)
            }
        }
    }

    /// The axis turned by `r`: a column of its rotation matrix, read
    /// straight from the quaternion.
    #[inline]
    fn turned_by(self, r: &Quaternion<f64>) -> Vector3<f64> {
        let (w, x, y, z) = (r.w, r.i, r.j, r.k);
        match self {
            Principal::X => Vector3::new(
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y + w * z),
                2.0 * (x * z - w * y),
            ),
            Principal::Y => Vector3::new(
                2.0 * (x * y - w * z),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z + w * x),
            ),
            Principal::Z => Vector3::new(
                2.0 * (x * z + w * y),
                2.0 * (y * z - w * x),
                1.0 - 2.0 * (x * x + y * y),
            ),
        }
    }
}

/// How a joint moves its child, by kind and axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Motion {
    Fixed,
    /// A turn about a coordinate axis.
    Turn(Principal),
    /// A turn about any other axis.
    TurnAbout(Unit<Vector3<f64>>),
    Slide(Vector3<f64>),
}

/// A fixed transform, sorted so the common ones skip most of a product:
/// a DH link's is a shift and a quarter turn (or none) about x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Fixed {
    shift: Option<Vector3<f64>>,
    turn: FixedTurn,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum FixedTurn {
    None,
    /// About a coordinate axis, by the angle whose half has this sine and
    /// cosine.
    About(Principal, f64, f64),
    Any(UnitQuaternion<f64>),
}

/// One joint on a walk down from the world.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Step {
    /// From the frame after the joint above moved (or the world) to this
    /// joint's axis frame: that joint's post transform times this one's
    /// origin; `None` when it is the identity.
    pub into: Option<Fixed>,
    pub motion: Motion,
    pub offset: f64,
}

/// Parts of a unit quaternion this small are rounding left over from a
/// quarter turn (cos 90° is 6e-17, not 0), not a turn.
const ROUNDING: f64 = 1e-15;

impl Fixed {
    fn of(p: &Pose) -> Option<Fixed> {
        let shift = p.translation.vector;
        let r = p.rotation.quaternion();
        let parts = [r.i, r.j, r.k];
        let zero = |k: usize| parts[k].abs() < ROUNDING;
        let turn = match (zero(0), zero(1), zero(2)) {
            (true, true, true) => FixedTurn::None,
            (false, true, true) => FixedTurn::About(Principal::X, r.i, r.w),
            (true, false, true) => FixedTurn::About(Principal::Y, r.j, r.w),
            (true, true, false) => FixedTurn::About(Principal::Z, r.k, r.w),
            _ => FixedTurn::Any(p.rotation),
        };
        let shift = (shift != Vector3::zeros()).then_some(shift);
        (shift.is_some() || turn != FixedTurn::None).then_some(Fixed { shift, turn })
    }

    /// `t · self`.
    #[inline]
    pub fn apply(&self, t: &mut Pose) {
        if let Some(shift) = self.shift {
            t.translation.vector += t.rotation * shift;
        }
        match self.turn {
            FixedTurn::None => {}
            FixedTurn::About(axis, s, c) => {
                t.rotation =
                    UnitQuaternion::new_unchecked(axis.turn(t.rotation.quaternion(), s, c));
            }
            FixedTurn::Any(r) => t.rotation *= r,
        }
    }

    /// `self` as a pose (for the first step of a walk, which starts here).
    #[inline]
    pub fn pose(&self) -> Pose {
        let mut t = Pose::identity();
        self.apply(&mut t);
        t
    }
}

impl Motion {
    fn of(joint: &Joint) -> Motion {
        let a = joint.axis.into_inner();
        match joint.kind {
            JointKind::Fixed => Motion::Fixed,
            JointKind::Prismatic => Motion::Slide(a),
            JointKind::Revolute | JointKind::Continuous => {
                Principal::of(&a).map_or(Motion::TurnAbout(joint.axis), Motion::Turn)
            }
        }
    }

    /// Move `t` (on the joint's axis frame) through the joint at value `v`.
    #[inline]
    pub fn apply(&self, t: &mut Pose, v: f64) {
        match *self {
            Motion::Fixed => {}
            Motion::Slide(axis) => t.translation.vector += t.rotation * (axis * v),
            Motion::TurnAbout(axis) => t.rotation *= UnitQuaternion::from_axis_angle(&axis, v),
            Motion::Turn(axis) => {
                let (s, c) = trig::sin_cos(0.5 * v);
                t.rotation =
                    UnitQuaternion::new_unchecked(axis.turn(t.rotation.quaternion(), s, c));
            }
        }
    }

    /// The joint's axis in the world, for `t` on its axis frame.
    #[inline]
    pub fn world_axis(&self, t: &Pose) -> Vector3<f64> {
        match *self {
            Motion::Turn(axis) => axis.turned_by(t.rotation.quaternion()),
            Motion::TurnAbout(axis) => t.rotation * axis.into_inner(),
            Motion::Slide(axis) => t.rotation * axis,
            Motion::Fixed => Vector3::zeros(),
        }
    }
}

/// The steps of `joints` (ordered parents first), with `parent_joint[b]`
/// the joint whose child is body `b`.
pub(crate) fn prepare(joints: &[Joint], parent_joint: &[Option<usize>]) -> Vec<Step> {
    joints
        .iter()
        .map(|j| {
            let above = parent_joint[j.parent].map_or(Pose::identity(), |p| joints[p].post);
            Step {
                into: Fixed::of(&(above * j.origin)),
                motion: Motion::of(j),
                offset: j.offset,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn close(a: &Pose, b: &Pose) -> bool {
        (a.translation.vector - b.translation.vector).norm() < 1e-12
            && a.rotation.angle_to(&b.rotation) < 1e-12
    }

    proptest! {
        /// Each specialised turn equals the general rotation about its axis.
        #[test]
        fn specialised_turns_match_the_general_rotation(
            v in -10.0f64..10.0,
            rx in -3.0f64..3.0, ry in -3.0f64..3.0, rz in -3.0f64..3.0,
        ) {
            let start = Pose::from_parts(
                Vector3::new(0.1, -0.2, 0.3).into(),
                UnitQuaternion::from_euler_angles(rx, ry, rz),
            );
            for (motion, axis) in [
                (Motion::Turn(Principal::X), Vector3::x_axis()),
                (Motion::Turn(Principal::Y), Vector3::y_axis()),
                (Motion::Turn(Principal::Z), Vector3::z_axis()),
            ] {
                let mut fast = start;
                motion.apply(&mut fast, v);
                let mut general = start;
                Motion::TurnAbout(axis).apply(&mut general, v);
                prop_assert!(close(&fast, &general), "{motion:?} at {v}");
                let z = motion.world_axis(&start);
                prop_assert!((z - start.rotation * axis.into_inner()).norm() < 1e-12);
                // The same turn as a fixed transform, with a shift.
                let shift = Vector3::new(0.4, -0.1, 0.25);
                let fixed = Pose::from_parts(shift.into(), UnitQuaternion::from_axis_angle(&axis, v));
                let prepared = Fixed::of(&fixed).map_or(Pose::identity(), |f| f.pose());
                prop_assert!(close(&(start * prepared), &(start * fixed)));
                let mut applied = start;
                if let Some(f) = Fixed::of(&fixed) {
                    f.apply(&mut applied);
                }
                prop_assert!(close(&applied, &(start * fixed)));
            }
        }
    }
}
