//! Forward dynamics: the accelerations that joint torques produce, by the
//! articulated-body algorithm (each body, with everything beyond it free
//! to move at its joints, behaves as one "articulated" inertia). With
//! coupled joints the tree has fewer freedoms than joints, and the same
//! answer comes from the reduced mass matrix and a Cholesky solve.

use nalgebra::{DMatrix, DVector, Matrix3, Matrix6, Vector3, Vector6};

use super::Dynamics;
use super::spatial::{Link, Twist};
use crate::error::FieldError;
use crate::inertial::{Rigid, cross_matrix};
use crate::model::Model;

/// What the three passes keep: per body its articulated inertia, bias
/// force and velocity-product acceleration; per joint U, D and u.
#[derive(Debug, Clone)]
pub(super) struct Scratch {
    ia: Vec<Matrix6<f64>>,
    pa: Vec<Vector6<f64>>,
    c: Vec<Vector6<f64>>,
    a: Vec<Vector6<f64>>,
    u_vec: Vec<Vector6<f64>>,
    d: Vec<f64>,
    u: Vec<f64>,
    qdd: Vec<f64>,
}

impl Scratch {
    pub fn new(bodies: usize, dof: usize) -> Self {
        Self {
            ia: vec![Matrix6::zeros(); bodies],
            pa: vec![Vector6::zeros(); bodies],
            c: vec![Vector6::zeros(); bodies],
            a: vec![Vector6::zeros(); bodies],
            u_vec: vec![Vector6::zeros(); bodies],
            d: vec![0.0; bodies],
            u: vec![0.0; bodies],
            qdd: vec![0.0; dof],
        }
    }
}

fn six(t: &Twist) -> Vector6<f64> {
    Vector6::new(t.w.x, t.w.y, t.w.z, t.v.x, t.v.y, t.v.z)
}

/// The body's spatial inertia as a 6 × 6 matrix (angular rows first).
fn matrix(b: &Rigid) -> Matrix6<f64> {
    let hx = cross_matrix(&b.h);
    let mut m = Matrix6::zeros();
    m.fixed_view_mut::<3, 3>(0, 0).copy_from(&b.io);
    m.fixed_view_mut::<3, 3>(0, 3).copy_from(&hx);
    m.fixed_view_mut::<3, 3>(3, 0).copy_from(&hx.transpose());
    m.fixed_view_mut::<3, 3>(3, 3)
        .copy_from(&(Matrix3::identity() * b.m));
    m
}

/// The motion transform from parent to child: twist_child = X · twist_parent.
fn motion_transform(l: &Link) -> Matrix6<f64> {
    let rt = l.r.transpose();
    let mut x = Matrix6::zeros();
    x.fixed_view_mut::<3, 3>(0, 0).copy_from(&rt);
    x.fixed_view_mut::<3, 3>(3, 3).copy_from(&rt);
    x.fixed_view_mut::<3, 3>(3, 0)
        .copy_from(&(-rt * cross_matrix(&l.p)));
    x
}

/// v ×f w for six-vectors.
fn cross_force(v: &Vector6<f64>, f: &Vector6<f64>) -> Vector6<f64> {
    let (w, lin) = (v.fixed_rows::<3>(0), v.fixed_rows::<3>(3));
    let (n, force) = (f.fixed_rows::<3>(0), f.fixed_rows::<3>(3));
    let top = w.cross(&n) + lin.cross(&force);
    let bottom = w.cross(&force);
    Vector6::new(top.x, top.y, top.z, bottom.x, bottom.y, bottom.z)
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
        work.v[0] = Twist::ZERO;
        for (i, j) in self.joints.iter().enumerate() {
            let c = j.child;
            let mut v = work.links[i].seen_in_child(&work.v[j.parent]);
            let mut bias = Twist::ZERO;
            if let Some(k) = self.variable_of[i] {
                let vj = work.axes[i].scaled(work.qd[k]);
                v = v.plus(&vj);
                bias = v.cross(&vj);
            }
            work.v[c] = v;
            s.c[c] = six(&bias);
            s.ia[c] = matrix(&self.rigid[c]);
            let momentum = s.ia[c] * six(&v);
            s.pa[c] = cross_force(&six(&v), &momentum);
        }
        for (i, j) in self.joints.iter().enumerate().rev() {
            let c = j.child;
            let (mut ia, mut pa) = (s.ia[c], s.pa[c]);
            if let Some(k) = self.variable_of[i] {
                let axis = six(&work.axes[i]);
                let u_vec = ia * axis;
                let d = axis.dot(&u_vec);
                if d.abs() < 1e-12 {
                    return Err(FieldError::new(
                        "model",
                        format!(
                            "nothing beyond joint `{}` has mass: no torque can accelerate it",
                            j.name
                        ),
                    ));
                }
                let u = tau[k] - axis.dot(&pa);
                ia -= u_vec * u_vec.transpose() / d;
                pa += u_vec * (u / d);
                s.u_vec[c] = u_vec;
                s.d[c] = d;
                s.u[c] = u;
            }
            pa += ia * s.c[c];
            if j.parent != 0 {
                let x = motion_transform(&work.links[i]);
                s.ia[j.parent] += x.transpose() * ia * x;
                s.pa[j.parent] += x.transpose() * pa;
            }
        }
        s.a[0] = vec_root(gravity);
        for (i, j) in self.joints.iter().enumerate() {
            let c = j.child;
            let mut acc = motion_transform(&work.links[i]) * s.a[j.parent] + s.c[c];
            if let Some(k) = self.variable_of[i] {
                let axis = six(&work.axes[i]);
                let qdd = (s.u[c] - s.u_vec[c].dot(&acc)) / s.d[c];
                s.qdd[k] = qdd;
                acc += axis * qdd;
            }
            s.a[c] = acc;
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

/// The root's acceleration: upwards, against gravity.
fn vec_root(gravity: [f64; 3]) -> Vector6<f64> {
    let g = -Vector3::from(gravity);
    Vector6::new(0.0, 0.0, 0.0, g.x, g.y, g.z)
}
