//! A robot holding still: the torques gravity and loads ask of its joints,
//! how much joints that give like springs then give, and how far that moves
//! a tool; its whole mass and where its centre of mass is.

use nalgebra::Vector3;

use crate::error::FieldError;
use crate::model::{FrameRef, Model};

/// A force and a moment that the world applies at a frame's origin, in
/// root-frame axes (N, N·m): a payload's weight, a push on the tool.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Load {
    pub frame: FrameRef,
    pub force: [f64; 3],
    pub moment: [f64; 3],
}

/// The torques that hold a robot still, one per state variable (followers'
/// carried by their leaders).
#[derive(Debug, Clone, PartialEq)]
pub struct Held {
    /// g(q): against gravity.
    pub gravity: Vec<f64>,
    /// −Σ Jᵀ F: against the loads.
    pub load: Vec<f64>,
    /// Their sum: what the joints must give.
    pub total: Vec<f64>,
}

/// How joints that give like springs move a frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Sag {
    /// Each joint's give, τ / k (rad or m); the joint moves by minus this:
    /// a spring that holds a torque is wound against it.
    pub deflection: Vec<f64>,
    /// How far the frame moves when every joint gives, m (root frame).
    pub sag: [f64; 3],
}

impl Model {
    /// The torques that hold the robot still at `q` under `gravity`, with
    /// `loads` applied.
    pub fn hold(&self, q: &[f64], loads: &[Load], gravity: [f64; 3]) -> Result<Held, FieldError> {
        let gravity = self.gravity(q, gravity)?;
        let mut load = vec![0.0; self.dof()];
        for (i, l) in loads.iter().enumerate() {
            for v in l.force.iter().chain(&l.moment) {
                crate::error::finite(format!("loads[{i}]"), *v)?;
            }
            let j = self.jacobian(q, &l.frame)?;
            let wrench = [l.force, l.moment].concat();
            for (k, out) in load.iter_mut().enumerate() {
                *out -= (0..6).map(|r| j[(r, k)] * wrench[r]).sum::<f64>();
            }
        }
        let total = gravity.iter().zip(&load).map(|(g, l)| g + l).collect();
        Ok(Held {
            gravity,
            load,
            total,
        })
    }

    /// What `torques` (one per state variable) do to joints of stiffness
    /// `stiffness` (N·m/rad or N/m, one per state variable; followers'
    /// ignored), and how far `frame` moves.
    pub fn sag(
        &self,
        q: &[f64],
        torques: &[f64],
        stiffness: &[f64],
        frame: &FrameRef,
    ) -> Result<Sag, FieldError> {
        self.check_state(q)?;
        if stiffness.len() != self.dof() || torques.len() != self.dof() {
            return Err(FieldError::new(
                "stiffness",
                format!("one value for each of the {} joint variables", self.dof()),
            ));
        }
        let mut deflection = vec![0.0; self.dof()];
        for v in self.independent() {
            let k = stiffness[v];
            if !(k.is_finite() && k > 0.0) {
                return Err(FieldError::new(
                    format!("stiffness[{v}]"),
                    format!("must be a positive number, got {k}"),
                ));
            }
            deflection[v] = torques[v] / k;
        }
        let mut given: Vec<f64> = q.iter().zip(&deflection).map(|(q, d)| q - d).collect();
        self.apply_couplings(&mut given);
        let before = self.pose(q, frame)?.translation.vector;
        let after = self.pose(&given, frame)?.translation.vector;
        let moved = after - before;
        Ok(Sag {
            deflection,
            sag: [moved.x, moved.y, moved.z],
        })
    }

    /// The whole robot's mass (every body, the root's too) and its centre
    /// of mass in the root frame at `q` (the root's origin when massless).
    pub fn mass_and_centre(&self, q: &[f64]) -> Result<(f64, [f64; 3]), FieldError> {
        let placed = self.place(q)?;
        let mut mass = 0.0;
        let mut moment = Vector3::zeros();
        for (b, body) in self.bodies.iter().enumerate() {
            if let Some(i) = body.inertial {
                mass += i.mass;
                moment += placed.bodies[b].transform_point(&i.com.into()).coords * i.mass;
            }
        }
        let c = if mass > 0.0 { moment / mass } else { moment };
        Ok((mass, [c.x, c.y, c.z]))
    }
}
