//! Spatial vectors in a body's own frame: a twist (angular velocity and
//! the velocity of the frame's origin) and a wrench (moment about the
//! origin and force), with the few operations the recursions need.

use nalgebra::{Matrix3, Vector3};

use crate::inertial::Rigid;

/// Angular `w` and linear `v` velocity (or acceleration) of a body, seen at
/// its frame's origin, in its frame's axes.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Twist {
    pub w: Vector3<f64>,
    pub v: Vector3<f64>,
}

/// A moment `n` about a frame's origin and a force `f`, in its axes.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Wrench {
    pub n: Vector3<f64>,
    pub f: Vector3<f64>,
}

/// Where a child's frame sits in its parent's: x_parent = r · x_child + p.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Link {
    pub r: Matrix3<f64>,
    pub p: Vector3<f64>,
}

impl Twist {
    pub const ZERO: Twist = Twist {
        w: Vector3::new(0.0, 0.0, 0.0),
        v: Vector3::new(0.0, 0.0, 0.0),
    };

    #[inline]
    pub fn scaled(&self, k: f64) -> Twist {
        Twist {
            w: self.w * k,
            v: self.v * k,
        }
    }

    #[inline]
    pub fn plus(&self, o: &Twist) -> Twist {
        Twist {
            w: self.w + o.w,
            v: self.v + o.v,
        }
    }

    /// self ×m o: how `o`, fixed in a body moving with `self`, changes.
    #[inline]
    pub fn cross(&self, o: &Twist) -> Twist {
        Twist {
            w: self.w.cross(&o.w),
            v: self.w.cross(&o.v) + self.v.cross(&o.w),
        }
    }

    /// self ×f o: how a wrench `o`, fixed in a body moving with `self`,
    /// changes.
    #[inline]
    pub fn cross_wrench(&self, o: &Wrench) -> Wrench {
        Wrench {
            n: self.w.cross(&o.n) + self.v.cross(&o.f),
            f: self.w.cross(&o.f),
        }
    }

    /// The power of wrench `f` on this twist (a joint's torque, when the
    /// twist is the joint's axis).
    #[inline]
    pub fn dot(&self, f: &Wrench) -> f64 {
        self.w.dot(&f.n) + self.v.dot(&f.f)
    }
}

impl Wrench {
    pub const ZERO: Wrench = Wrench {
        n: Vector3::new(0.0, 0.0, 0.0),
        f: Vector3::new(0.0, 0.0, 0.0),
    };

    #[inline]
    pub fn add(&mut self, o: &Wrench) {
        self.n += o.n;
        self.f += o.f;
    }
}

impl Link {
    pub const IDENTITY: Link = Link {
        r: Matrix3::new(1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0),
        p: Vector3::new(0.0, 0.0, 0.0),
    };

    /// This frame followed by `next` (a frame given in this one).
    #[inline]
    pub fn then(&self, next: &Link) -> Link {
        Link {
            r: self.r * next.r,
            p: self.p + self.r * next.p,
        }
    }

    /// A child's twist seen in the parent's frame (the inverse of
    /// [`Link::seen_in_child`]).
    #[inline]
    pub fn twist_in_parent(&self, t: &Twist) -> Twist {
        let w = self.r * t.w;
        Twist {
            w,
            v: self.r * t.v + self.p.cross(&w),
        }
    }

    /// A parent's twist seen in the child's frame.
    #[inline]
    pub fn seen_in_child(&self, t: &Twist) -> Twist {
        Twist {
            w: self.r.tr_mul(&t.w),
            v: self.r.tr_mul(&(t.v + t.w.cross(&self.p))),
        }
    }

    /// A child's wrench seen in the parent's frame.
    #[inline]
    pub fn seen_in_parent(&self, f: &Wrench) -> Wrench {
        let force = self.r * f.f;
        Wrench {
            n: self.r * f.n + self.p.cross(&force),
            f: force,
        }
    }
}

impl Rigid {
    /// The momentum of the body moving with twist `t`.
    #[inline]
    pub fn times(&self, t: &Twist) -> Wrench {
        Wrench {
            n: self.io * t.w + self.h.cross(&t.v),
            f: t.v * self.m - self.h.cross(&t.w),
        }
    }
}
