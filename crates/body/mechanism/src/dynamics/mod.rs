//! The other half of the mechanism model: what holds it up and what moves
//! it. Each body's mass, centre of mass and inertia ([`crate::Inertial`])
//! live in the stateless model; everything a computation needs between its
//! steps lives in a [`Dynamics`] workspace that its user keeps, so repeated
//! calls allocate nothing.
//!
//! - [`Model::inverse_dynamics_in`]: the recursive Newton–Euler algorithm,
//!   τ = M(q) q̈ + C(q, q̇) q̇ + g(q);
//! - [`Model::gravity_in`]: g(q), the torques that hold the robot still;
//! - [`Model::mass_matrix_in`]: M(q), by composite rigid bodies;
//! - [`Model::forward_dynamics_in`]: q̈ from τ, by articulated bodies;
//! - [`statics`]: loads at frames, joint stiffness and sag, total mass and
//!   centre of mass; [`motion`]: an arm let go, integrated, with its energy.
//!
//! All of it works in each body's own frame (Featherstone's spatial
//! algebra, written out with 3-vectors). Joints coupled by a `mimic` are
//! reduced coordinates: a follower moves with its leader, and its torque
//! is carried by the leader times the ratio, as a Jacobian's columns are
//! folded. Closed loops are not trees, and are refused.

mod aba;
mod crba;
pub mod motion;
pub mod servo;
mod spatial;
pub mod statics;
pub(crate) mod tree;

use nalgebra::{DMatrix, Vector3};

use crate::error::FieldError;
use crate::model::Model;
use spatial::{Link, Twist, Wrench};

/// Gravity at the Earth's surface in the root frame, m/s², z up.
pub const EARTH: [f64; 3] = [0.0, 0.0, -9.81];

/// Scratch space for one model's dynamics, kept by whoever asks (in the
/// spirit of Pinocchio's `Data`); one entry per node of the model's tree.
#[derive(Debug, Clone)]
pub struct Dynamics {
    /// Each node's frame in its parent's, this state.
    links: Vec<Link>,
    /// Each node's frame in the root's (the mass matrix works there).
    world: Vec<Link>,
    /// Per node: velocity, acceleration, force.
    v: Vec<Twist>,
    a: Vec<Twist>,
    f: Vec<Wrench>,
    /// Rates with followers set from their leaders.
    qd: Vec<f64>,
    qdd: Vec<f64>,
    tau: Vec<f64>,
    mass: DMatrix<f64>,
    aba: aba::Scratch,
    crba: Vec<crate::inertial::Rigid>,
}

impl Model {
    /// A workspace for this model's dynamics.
    pub fn dynamics(&self) -> Dynamics {
        let n = self.dof();
        let nodes = self.tree.len();
        Dynamics {
            links: vec![Link::IDENTITY; nodes],
            world: vec![Link::IDENTITY; nodes],
            v: vec![Twist::ZERO; nodes],
            a: vec![Twist::ZERO; nodes],
            f: vec![Wrench::ZERO; nodes],
            qd: vec![0.0; n],
            qdd: vec![0.0; n],
            tau: vec![0.0; n],
            mass: DMatrix::zeros(n, n),
            aba: aba::Scratch::new(nodes, n),
            crba: vec![crate::inertial::Rigid::ZERO; nodes],
        }
    }

    /// Whether any body has mass.
    pub fn has_mass(&self) -> bool {
        self.rigid.iter().any(|r| r.m > 0.0)
    }

    /// The joint torques and forces that give the robot accelerations
    /// `qdd` at `q` moving at `qd`, under `gravity` (m/s², root frame):
    /// τ = M(q) q̈ + C(q, q̇) q̇ + g(q), one per state variable. A
    /// follower's rates are taken from its leader, and its torque is
    /// carried by the leader (its own entry is 0).
    pub fn inverse_dynamics_in<'w>(
        &self,
        work: &'w mut Dynamics,
        q: &[f64],
        qd: &[f64],
        qdd: &[f64],
        gravity: [f64; 3],
    ) -> Result<&'w [f64], FieldError> {
        self.check_dynamics(q, gravity)?;
        self.check_rates("qd", qd)?;
        self.check_rates("qdd", qdd)?;
        self.spread(&mut work.qd, qd);
        self.spread(&mut work.qdd, qdd);
        self.place_links(work, q);
        self.rnea(work, gravity, true);
        Ok(&work.tau)
    }

    /// g(q): the torques that hold the robot still at `q` under `gravity`.
    pub fn gravity_in<'w>(
        &self,
        work: &'w mut Dynamics,
        q: &[f64],
        gravity: [f64; 3],
    ) -> Result<&'w [f64], FieldError> {
        self.check_dynamics(q, gravity)?;
        self.place_links(work, q);
        self.rnea(work, gravity, false);
        Ok(&work.tau)
    }

    /// [`Model::inverse_dynamics_in`] with a workspace of its own.
    pub fn inverse_dynamics(
        &self,
        q: &[f64],
        qd: &[f64],
        qdd: &[f64],
        gravity: [f64; 3],
    ) -> Result<Vec<f64>, FieldError> {
        let mut work = self.dynamics();
        self.inverse_dynamics_in(&mut work, q, qd, qdd, gravity)
            .map(<[f64]>::to_vec)
    }

    /// [`Model::gravity_in`] with a workspace of its own.
    pub fn gravity(&self, q: &[f64], gravity: [f64; 3]) -> Result<Vec<f64>, FieldError> {
        let mut work = self.dynamics();
        self.gravity_in(&mut work, q, gravity).map(<[f64]>::to_vec)
    }

    /// Every node's frame in its parent's at state `q`.
    fn place_links(&self, work: &mut Dynamics, q: &[f64]) {
        for (link, node) in work.links.iter_mut().zip(&self.tree.nodes) {
            *link = node.link(q[node.variable]);
        }
    }

    /// The recursion of Newton and Euler, out from the root and back:
    /// with `moving` false, only gravity (velocities and accelerations 0).
    fn rnea(&self, work: &mut Dynamics, gravity: [f64; 3], moving: bool) {
        // The root accelerates upwards: gravity, felt by every body.
        let root = Twist {
            w: Vector3::zeros(),
            v: -Vector3::from(gravity),
        };
        for (i, node) in self.tree.nodes.iter().enumerate() {
            let link = &work.links[i];
            let (pv, pa) = node
                .parent
                .map_or((Twist::ZERO, root), |p| (work.v[p], work.a[p]));
            let mut a = link.seen_in_child(&pa);
            let f = if moving {
                let vj = node.axis.scaled(work.qd[node.variable]);
                let v = link.seen_in_child(&pv).plus(&vj);
                a = a
                    .plus(&node.axis.scaled(work.qdd[node.variable]))
                    .plus(&v.cross(&vj));
                work.v[i] = v;
                let mut f = node.rigid.times(&a);
                f.add(&v.cross_wrench(&node.rigid.times(&v)));
                f
            } else {
                node.rigid.times(&a)
            };
            work.a[i] = a;
            work.f[i] = f;
        }
        work.tau.fill(0.0);
        for (i, node) in self.tree.nodes.iter().enumerate().rev() {
            work.tau[node.variable] = node.axis.dot(&work.f[i]);
            if let Some(p) = node.parent {
                let up = work.links[i].seen_in_parent(&work.f[i]);
                work.f[p].add(&up);
            }
        }
        self.fold(&mut work.tau);
    }

    /// `rates` with every follower's entry set from its leader's, into `out`.
    fn spread(&self, out: &mut [f64], rates: &[f64]) {
        out.copy_from_slice(rates);
        for c in &self.couplings {
            out[c.follower] = c.ratio * out[c.leader];
        }
    }

    /// Followers' torques carried by their leaders.
    fn fold(&self, tau: &mut [f64]) {
        for c in &self.couplings {
            tau[c.leader] += c.ratio * tau[c.follower];
            tau[c.follower] = 0.0;
        }
    }

    /// The state variables that move on their own (not followers), in the
    /// order a user gives them (for a URDF file, the file's order).
    pub fn independent(&self) -> impl Iterator<Item = usize> + '_ {
        self.driven.iter().copied()
    }

    fn check_dynamics(&self, q: &[f64], gravity: [f64; 3]) -> Result<(), FieldError> {
        self.check_state(q)?;
        if let Some(l) = self.loops.first() {
            return Err(FieldError::new(
                "model",
                format!(
                    "`{}` closes a loop (`{}`): the lab computes the dynamics of trees only",
                    self.name, l.name
                ),
            ));
        }
        crate::error::all_finite("gravity", &gravity)
    }

    fn check_rates(&self, field: &str, rates: &[f64]) -> Result<(), FieldError> {
        if rates.len() != self.dof() {
            return Err(FieldError::new(
                field,
                format!("{} values for {} joint variables", rates.len(), self.dof()),
            ));
        }
        crate::error::all_finite(field, rates)
    }
}
