//! An arm let go: its joints move as gravity, damping and the torques
//! applied make them, integrated step by step, and its energy tracked, so
//! a learner can see an integrator's drift and what halving the step does.
//!
//! The integrator is the classic 4th-order Runge–Kutta method on (q, q̇):
//! four evaluations of the forward dynamics a step, an error that shrinks
//! with the fourth power of the step. An undamped arm's energy should stay
//! put; how far it strays is the integrator's error, and halving the step
//! cuts it about sixteenfold.

use nalgebra::Vector3;

use super::Dynamics;
use crate::error::FieldError;
use crate::model::Model;

/// The most steps one run may take.
pub const MAX_STEPS: usize = 200_000;

/// How to integrate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Release {
    /// s.
    pub dt: f64,
    pub steps: usize,
    /// Viscous damping at every joint: τ = −c q̇ (N·m·s/rad).
    pub damping: f64,
    pub gravity: [f64; 3],
}

/// The arm at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct Instant {
    pub t: f64,
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    /// Kinetic plus potential energy, J (potential zero at the root).
    pub energy: f64,
}

/// An arm falling, a step at a time (a player steps it with its model).
#[derive(Debug, Clone)]
pub struct Falling {
    work: Dynamics,
    release: Release,
    pub now: Instant,
    /// The energy at the start, J.
    pub start_energy: f64,
    /// What the energy is measured against: the arm's weight times how
    /// far out its furthest mass starts, J (an energy of 0 at the start
    /// must not make every change infinite).
    scale: f64,
    steps: usize,
}

impl Model {
    /// The arm at `q` moving at `qd`, about to be let go.
    pub fn release(&self, q: &[f64], qd: &[f64], release: Release) -> Result<Falling, FieldError> {
        kinolab_common::error::positive("dt", release.dt)?;
        if release.dt > 0.1 {
            return Err(FieldError::new("dt", "at most 0.1 s a step"));
        }
        if release.steps > MAX_STEPS {
            return Err(FieldError::new(
                "steps",
                format!("at most {MAX_STEPS}, got {}", release.steps),
            ));
        }
        crate::error::finite("damping", release.damping)?;
        if release.damping < 0.0 {
            return Err(FieldError::new("damping", "must not be negative"));
        }
        self.check_dynamics(q, release.gravity)?;
        self.check_rates("qd", qd)?;
        let mut work = self.dynamics();
        let energy = self.energy(&mut work, q, qd, release.gravity);
        let placed = self.place(q)?;
        let (mut mass, mut far) = (0.0, 0.0_f64);
        for (b, body) in self.bodies.iter().enumerate() {
            if let Some(i) = body.inertial {
                mass += i.mass;
                far = far.max(
                    placed.bodies[b]
                        .transform_point(&i.com.into())
                        .coords
                        .norm(),
                );
            }
        }
        let scale = (mass * Vector3::from(release.gravity).norm() * far).max(energy.abs());
        Ok(Falling {
            work,
            release,
            now: Instant {
                t: 0.0,
                q: q.to_vec(),
                qd: qd.to_vec(),
                energy,
            },
            start_energy: energy,
            scale,
            steps: 0,
        })
    }

    /// Kinetic energy ½ Σ vᵀ I v plus potential −Σ m g · c, J.
    pub fn energy(&self, work: &mut Dynamics, q: &[f64], qd: &[f64], gravity: [f64; 3]) -> f64 {
        self.spread(&mut work.qd, qd);
        work.qdd.fill(0.0);
        self.place_links(work, q);
        // Velocities only: the pass out of the recursion, without gravity.
        self.rnea(work, [0.0; 3], true);
        let kinetic: f64 = (self.tree.nodes.iter().zip(&work.v))
            .map(|(node, v)| 0.5 * v.dot(&node.rigid.times(v)))
            .sum();
        let g = Vector3::from(gravity);
        let potential = match self.place(q) {
            Ok(placed) => self
                .bodies
                .iter()
                .enumerate()
                .filter_map(|(b, body)| body.inertial.map(|i| (b, i)))
                .map(|(b, i)| {
                    -i.mass * g.dot(&placed.bodies[b].transform_point(&i.com.into()).coords)
                })
                .sum(),
            Err(_) => 0.0,
        };
        kinetic + potential
    }
}

impl Falling {
    /// One step of `m` (the model it was released from); `false` once the
    /// run has taken all its steps.
    pub fn step(&mut self, m: &Model) -> Result<bool, FieldError> {
        if self.steps >= self.release.steps {
            return Ok(false);
        }
        let r = self.release;
        let damping = |qd: &[f64]| -> Vec<f64> { qd.iter().map(|v| -r.damping * v).collect() };
        rk4(
            m,
            &mut self.work,
            &mut self.now.q,
            &mut self.now.qd,
            r.dt,
            r.gravity,
            &damping,
        )?;
        self.now.t += r.dt;
        self.now.energy = m.energy(&mut self.work, &self.now.q, &self.now.qd, r.gravity);
        self.steps += 1;
        Ok(true)
    }

    /// How far the energy has strayed from the start, relative to the
    /// arm's weight times how far out its furthest mass started (or the
    /// start energy, when that is larger).
    pub fn drift(&self) -> f64 {
        (self.now.energy - self.start_energy).abs() / self.scale.max(1e-9)
    }
}

/// One Runge–Kutta step of `h` seconds: `q` and `qd` move as the arm's
/// dynamics under `gravity` and the joint torques `torque(q̇)` make them.
pub(crate) fn rk4(
    m: &Model,
    work: &mut Dynamics,
    q: &mut [f64],
    qd: &mut [f64],
    h: f64,
    gravity: [f64; 3],
    torque: &dyn Fn(&[f64]) -> Vec<f64>,
) -> Result<(), FieldError> {
    let mut rate = |q: &[f64], qd: &[f64]| -> Result<Vec<f64>, FieldError> {
        m.forward_dynamics_in(work, q, qd, &torque(qd), gravity)
            .map(<[f64]>::to_vec)
    };
    let along = |x: &[f64], k: &[f64], h: f64| -> Vec<f64> {
        x.iter().zip(k).map(|(a, b)| a + h * b).collect()
    };
    let a1 = rate(q, qd)?;
    let (q2, v2) = (along(q, qd, h / 2.0), along(qd, &a1, h / 2.0));
    let a2 = rate(&q2, &v2)?;
    let (q3, v3) = (along(q, &v2, h / 2.0), along(qd, &a2, h / 2.0));
    let a3 = rate(&q3, &v3)?;
    let (q4, v4) = (along(q, &v3, h), along(qd, &a3, h));
    let a4 = rate(&q4, &v4)?;
    let q0: Vec<f64> = q.to_vec();
    let qd0: Vec<f64> = qd.to_vec();
    for k in 0..q.len() {
        q[k] = q0[k] + h / 6.0 * (qd0[k] + 2.0 * v2[k] + 2.0 * v3[k] + v4[k]);
        qd[k] = qd0[k] + h / 6.0 * (a1[k] + 2.0 * a2[k] + 2.0 * a3[k] + a4[k]);
    }
    m.apply_couplings(q);
    Ok(())
}
