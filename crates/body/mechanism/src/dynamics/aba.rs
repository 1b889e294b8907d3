//! Forward dynamics: the accelerations that joint torques produce, by the
//! articulated-body algorithm (each body, with everything beyond it free
//! to move at its joints, behaves as one "articulated" inertia). With
//! coupled joints the tree has fewer freedoms than joints, and the same
//! answer comes from the reduced mass matrix and a Cholesky solve.

use nalgebra::{DMatrix, DVector, Matrix3, Vector3};

use super::Dynamics;
use super::spatial::{Link, Twist, Wrench};
use crate::error::FieldError;
use crate::inertial::{Rigid, cross_matrix};
use crate::model::Model;

/// A body's articulated inertia, the symmetric 6 × 6 matrix
/// [[a, b], [bᵀ, c]] (angular rows first) kept as its three blocks: once
/// the bodies beyond have been folded in it is no longer a rigid body's.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Articulated {
    a: Matrix3<f64>,
    b: Matrix3<f64>,
    c: Matrix3<f64>,
}

impl Articulated {
    const ZERO: Articulated = Articulated {
        a: Matrix3::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
        b: Matrix3::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
        c: Matrix3::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
    };

    fn of(r: &Rigid) -> Articulated {
        Articulated {
            a: r.io,
            b: cross_matrix(&r.h),
            c: Matrix3::identity() * r.m,
        }
    }

    /// The wrench this inertia gives a twist (a momentum, or with an
    /// axis, the column U = I S).
    #[inline]
    fn times(&self, t: &Twist) -> Wrench {
        Wrench {
            n: self.a * t.w + self.b * t.v,
            f: self.b.tr_mul(&t.w) + self.c * t.v,
        }
    }

    /// I − U Uᵀ / d: what is left once the joint with column `u` is free.
    #[inline]
    fn release(&mut self, u: &Wrench, d: f64) {
        let (n, f) = (u.n / d, u.f / d);
        self.a -= n * u.n.transpose();
        self.b -= n * u.f.transpose();
        self.c -= f * u.f.transpose();
    }

    /// Xᵀ I X: the same inertia about the parent's origin, in its axes.
    #[inline]
    fn seen_in_parent(&self, l: &Link) -> Articulated {
        let (r, rt) = (&l.r, l.r.transpose());
        let a = r * self.a * rt;
        let b = r * self.b * rt;
        let c = r * self.c * rt;
        let px = cross_matrix(&l.p);
        let k = b * px;
        Articulated {
            a: a - k - k.transpose() - px * c * px,
            b: b + px * c,
            c,
        }
    }

    fn add(&mut self, o: &Articulated) {
        self.a += o.a;
        self.b += o.b;
        self.c += o.c;
    }
}

/// What the three passes keep, per node: the articulated inertia, the
/// bias force, the velocity-product acceleration, the acceleration, and
/// the joint's U, D and u.
#[derive(Debug, Clone)]
pub(super) struct Scratch {
    ia: Vec<Articulated>,
    pa: Vec<Wrench>,
    c: Vec<Twist>,
    a: Vec<Twist>,
    u_vec: Vec<Wrench>,
    d: Vec<f64>,
    u: Vec<f64>,
    qdd: Vec<f64>,
}

impl Scratch {
    pub fn new(nodes: usize, dof: usize) -> Self {
        Self {
            ia: vec![Articulated::ZERO; nodes],
            pa: vec![Wrench::ZERO; nodes],
            c: vec![Twist::ZERO; nodes],
            a: vec![Twist::ZERO; nodes],
            u_vec: vec![Wrench::ZERO; nodes],
            d: vec![0.0; nodes],
            u: vec![0.0; nodes],
            qdd: vec![0.0; dof],
        }
    }
}

impl Model {
    /// q̈ for torques `tau` at `q` moving at `qd`, under `gravity`: the
    /// inverse of [`Model::inverse_dynamics_in`]. Followers' entries of
    /// `qd` and `tau` are ignored (a leader carries its followers); their
    /// accelerations follow their leaders'. A robot whose moving parts have
    /// no mass cannot be accelerated by torques, and is refused.
    pub fn forward_dynamics_in<'w>(
        &self,
        work: &'w mut Dynamics,
        q: &[f64],
        qd: &[f64],
        tau: &[f64],
        gravity: [f64; 3],
    ) -> Result<&'w [f64], FieldError> {
        self.check_dynamics(q, gravity)?;
        self.check_rates("qd", qd)?;
        self.check_rates("tau", tau)?;
        self.spread(&mut work.qd, qd);
        self.place_links(work, q);
        if self.couplings.is_empty() {
            self.aba(work, tau, gravity)?;
        } else {
            self.reduced_forward(work, tau, gravity)?;
        }
        Ok(&work.aba.qdd)
    }

    /// [`Model::forward_dynamics_in`] with a workspace of its own.
    pub fn forward_dynamics(
        &self,
        q: &[f64],
        qd: &[f64],
        tau: &[f64],
        gravity: [f64; 3],
    ) -> Result<Vec<f64>, FieldError> {
        let mut work = self.dynamics();
        self.forward_dynamics_in(&mut work, q, qd, tau, gravity)
            .map(<[f64]>::to_vec)
    }

    fn aba(&self, work: &mut Dynamics, tau: &[f64], gravity: [f64; 3]) -> Result<(), FieldError> {
        let s = &mut work.aba;
        let nodes = &self.tree.nodes;
        for (i, node) in nodes.iter().enumerate() {
            let pv = node.parent.map_or(Twist::ZERO, |p| work.v[p]);
            let vj = node.axis.scaled(work.qd[node.variable]);
            let v = work.links[i].seen_in_child(&pv).plus(&vj);
            work.v[i] = v;
            s.c[i] = v.cross(&vj);
            s.ia[i] = Articulated::of(&node.rigid);
            s.pa[i] = v.cross_wrench(&node.rigid.times(&v));
        }
        for (i, node) in nodes.iter().enumerate().rev() {
            let (mut ia, mut pa) = (s.ia[i], s.pa[i]);
            let u_vec = ia.times(&node.axis);
            let d = node.axis.dot(&u_vec);
            if d.abs() < 1e-12 {
                return Err(FieldError::new(
                    "model",
                    format!(
                        "nothing beyond joint `{}` has mass: no torque can accelerate it",
                        self.joints[node.joint].name
                    ),
                ));
            }
            let u = tau[node.variable] - node.axis.dot(&pa);
            ia.release(&u_vec, d);
            pa.add(&scaled(&u_vec, u / d));
            pa.add(&ia.times(&s.c[i]));
            (s.u_vec[i], s.d[i], s.u[i]) = (u_vec, d, u);
            if let Some(p) = node.parent {
                let link = &work.links[i];
                let up = ia.seen_in_parent(link);
                s.ia[p].add(&up);
                let up = link.seen_in_parent(&pa);
                s.pa[p].add(&up);
            }
        }
        let root = Twist {
            w: Vector3::zeros(),
            v: -Vector3::from(gravity),
        };
        for (i, node) in nodes.iter().enumerate() {
            let pa = node.parent.map_or(root, |p| s.a[p]);
            let acc = work.links[i].seen_in_child(&pa).plus(&s.c[i]);
            let qdd = (s.u[i] - acc.dot(&s.u_vec[i])) / s.d[i];
            s.qdd[node.variable] = qdd;
            s.a[i] = acc.plus(&node.axis.scaled(qdd));
        }
        Ok(())
    }

    /// Forward dynamics in the independent variables: M_r q̈_r = τ_r − b_r.
    fn reduced_forward(
        &self,
        work: &mut Dynamics,
        tau: &[f64],
        gravity: [f64; 3],
    ) -> Result<(), FieldError> {
        work.qdd.fill(0.0);
        self.rnea(work, gravity, true);
        let bias = work.tau.clone();
        self.crba(work);
        let free: Vec<usize> = self.independent().collect();
        let m = DMatrix::from_fn(free.len(), free.len(), |r, c| work.mass[(free[r], free[c])]);
        let rhs = DVector::from_fn(free.len(), |r, _| tau[free[r]] - bias[free[r]]);
        let solved = m.cholesky().map(|ch| ch.solve(&rhs)).ok_or_else(|| {
            FieldError::new(
                "model",
                "the mass matrix is singular: some moving part has no mass",
            )
        })?;
        work.aba.qdd.fill(0.0);
        for (r, &v) in free.iter().enumerate() {
            work.aba.qdd[v] = solved[r];
        }
        for c in &self.couplings {
            work.aba.qdd[c.follower] = c.ratio * work.aba.qdd[c.leader];
        }
        Ok(())
    }
}

fn scaled(w: &Wrench, k: f64) -> Wrench {
    Wrench {
        n: w.n * k,
        f: w.f * k,
    }
}
