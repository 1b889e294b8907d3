//! Numerical inverse kinematics: damped least squares with adaptive damping
//! (Levenberg–Marquardt) over several Cartesian goals at once, inside the
//! joint limits, with bounded iterations and optional restarts.
//!
//! Each iteration stacks every goal's error e (position in metres, rotation
//! as an axis-angle vector in radians) and Jacobian rows J, and steps
//! Δq = Jᵀ (J Jᵀ + λ² I)⁻¹ e. A step that lowers the error is kept and λ
//! shrinks (towards Gauss–Newton, fast near the answer); one that does not
//! is undone and λ grows (towards small gradient steps, safe far away).

use nalgebra::{DMatrix, DVector, UnitQuaternion, Vector3};

use crate::error::MechanismError;
use crate::model::{FrameRef, Model, Pose};

/// What one frame should achieve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    /// Position and orientation.
    Pose(Pose),
    Position(Vector3<f64>),
    Orientation(UnitQuaternion<f64>),
}

/// A frame and its target: in the world, or in another frame of the same
/// mechanism (`relative_to`), which may itself move with the joints.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Goal {
    pub frame: FrameRef,
    pub target: Target,
    pub relative_to: Option<FrameRef>,
}

impl Goal {
    /// A target in the world frame.
    pub fn new(frame: FrameRef, target: Target) -> Self {
        Self {
            frame,
            target,
            relative_to: None,
        }
    }

    /// A target given in frame `base`.
    pub fn relative(frame: FrameRef, target: Target, base: FrameRef) -> Self {
        Self {
            frame,
            target,
            relative_to: Some(base),
        }
    }
}

/// Limits on the search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Iterations per attempt.
    pub max_iterations: usize,
    /// Extra attempts from spread-out starting points when one fails.
    pub restarts: usize,
    /// Converged when every position error is below this (m) …
    pub position_tolerance: f64,
    /// … and every rotation error below this (rad).
    pub rotation_tolerance: f64,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            max_iterations: 100,
            restarts: 40,
            position_tolerance: 1e-8,
            rotation_tolerance: 1e-8,
        }
    }
}

impl Options {
    fn done(&self, r: &Residual) -> bool {
        r.position <= self.position_tolerance && r.rotation <= self.rotation_tolerance
    }
}

/// The answer: the best joint values found and how good they are.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    pub q: Vec<f64>,
    pub converged: bool,
    /// Largest position error over the goals, m.
    pub position_error: f64,
    /// Largest rotation error over the goals, rad.
    pub rotation_error: f64,
    /// Iterations used, over all attempts.
    pub iterations: usize,
}

/// What one search works on: the goals, their stacked row count, and
/// which variables may move.
#[derive(Clone, Copy)]
struct Problem<'a> {
    goals: &'a [Goal],
    m: usize,
    movable: &'a [bool],
}

/// Stacked errors and the largest position and rotation error.
struct Residual {
    e: DVector<f64>,
    position: f64,
    rotation: f64,
}

fn rows(goal: &Goal) -> usize {
    match goal.target {
        Target::Pose(_) => 6,
        _ => 3,
    }
}

impl Model {
    fn residual(&self, q: &[f64], goals: &[Goal], m: usize) -> Residual {
        let mut e = DVector::zeros(m);
        let (mut position, mut rotation): (f64, f64) = (0.0, 0.0);
        let mut row = 0;
        for g in goals {
            let at = self.pose_unchecked(q, &g.frame);
            let base = g
                .relative_to
                .map_or_else(Pose::identity, |b| self.pose_unchecked(q, &b));
            let dp = |t: &Vector3<f64>| t - at.translation.vector;
            let dr = |r: &UnitQuaternion<f64>| (r * at.rotation.inverse()).scaled_axis();
            let parts: [Option<Vector3<f64>>; 2] = match &g.target {
                Target::Pose(p) => {
                    let p = base * p;
                    [Some(dp(&p.translation.vector)), Some(dr(&p.rotation))]
                }
                Target::Position(t) => {
                    [Some(dp(&(base * nalgebra::Point3::from(*t)).coords)), None]
                }
                Target::Orientation(r) => [None, Some(dr(&(base.rotation * r)))],
            };
            for (k, part) in parts.iter().enumerate() {
                if let Some(v) = part {
                    e.fixed_rows_mut::<3>(row).copy_from(v);
                    row += 3;
                    if k == 0 {
                        position = position.max(v.norm());
                    } else {
                        rotation = rotation.max(v.norm());
                    }
                }
            }
        }
        Residual {
            e,
            position,
            rotation,
        }
    }

    /// Every goal's Jacobian rows, with coupled columns folded into their
    /// leaders and the columns of variables that may not move zeroed.
    fn jacobian_stack(
        &self,
        q: &[f64],
        goals: &[Goal],
        m: usize,
        movable: &[bool],
    ) -> DMatrix<f64> {
        let mut jac = DMatrix::zeros(m, self.dof());
        let mut six = DMatrix::zeros(6, self.dof());
        let mut row = 0;
        for g in goals {
            six.fill(0.0);
            let p = self.pose_unchecked(q, &g.frame).translation.vector;
            self.jacobian_add(q, &g.frame, &p, 1.0, &mut six, 0);
            if let Some(base) = &g.relative_to {
                // The target rides on `base`: its velocity at the frame's
                // point counts against the frame's own.
                self.jacobian_add(q, base, &p, -1.0, &mut six, 0);
            }
            let keep = match g.target {
                Target::Pose(_) => 0..6,
                Target::Position(_) => 0..3,
                Target::Orientation(_) => 3..6,
            };
            for (k, r) in keep.enumerate() {
                jac.row_mut(row + k).copy_from(&six.row(r));
            }
            row += rows(g);
        }
        self.fold_couplings(&mut jac);
        for (v, &free) in movable.iter().enumerate() {
            if !free {
                jac.column_mut(v).fill(0.0);
            }
        }
        jac
    }

    /// A starting point for restart `k`: spread over the joint ranges by a
    /// low-discrepancy (Kronecker) sequence, so no two restarts repeat.
    fn restart_point(&self, k: usize, seed: &[f64], movable: &[bool]) -> Vec<f64> {
        const STEPS: [f64; 8] = [
            0.414_213_562,
            0.732_050_808,
            0.236_067_977,
            0.645_751_311,
            0.316_624_790,
            0.605_551_275,
            0.123_105_626,
            0.358_898_944,
        ];
        self.variables
            .iter()
            .enumerate()
            .map(|(i, &j)| {
                if !movable[i] {
                    return seed[i];
                }
                let u = ((k as f64 + 1.0) * STEPS[i % STEPS.len()] + i as f64 * 0.5).fract();
                let [lo, hi] = self.joints[j]
                    .limits
                    .unwrap_or([-std::f64::consts::PI, std::f64::consts::PI]);
                lo + u * (hi - lo)
            })
            .collect()
    }

    /// The damped least-squares step from `q`, clamped into the limits.
    /// Joints pinned at a limit and pushed further drop out of the step
    /// (their columns are zeroed) and the step is recomputed for the rest.
    /// `None` when the system cannot be solved at this damping.
    fn step(
        &self,
        q: &[f64],
        r: &Residual,
        goals: &[Goal],
        m: usize,
        lambda: f64,
        movable: &[bool],
    ) -> Option<Vec<f64>> {
        let mut jac = self.jacobian_stack(q, goals, m, movable);
        for _ in 0..=self.dof() {
            let jt = jac.transpose();
            let mut a = &jac * &jt;
            for k in 0..m {
                a[(k, k)] += lambda * lambda;
            }
            let y = a.cholesky()?.solve(&r.e);
            let step = &jt * y;
            let mut trial: Vec<f64> = q.iter().zip(step.iter()).map(|(a, b)| a + b).collect();
            let mut pinned = false;
            for (v, t) in trial.iter().enumerate() {
                if let Some([lo, hi]) = self.variables.get(v).and_then(|&j| self.joints[j].limits)
                    && (*t < lo || *t > hi)
                    && jac.column(v).iter().any(|x| *x != 0.0)
                {
                    jac.column_mut(v).fill(0.0);
                    pinned = true;
                }
            }
            if !pinned {
                self.clamp(&mut trial);
                self.apply_couplings(&mut trial);
                return Some(trial);
            }
        }
        None
    }

    /// One damped least-squares descent from `q`. With `give_up`, stop
    /// early when progress stalls (a local minimum, often against a limit).
    fn descend(
        &self,
        mut q: Vec<f64>,
        problem: &Problem<'_>,
        options: &Options,
        max_iterations: usize,
        give_up: bool,
    ) -> (Vec<f64>, Residual, usize) {
        let Problem { goals, m, movable } = *problem;
        self.clamp(&mut q);
        self.apply_couplings(&mut q);
        let mut r = self.residual(&q, goals, m);
        let mut lambda = 1e-2;
        let mut checkpoint = r.e.norm_squared();
        let mut used = 0;
        for it in 0..max_iterations {
            if options.done(&r) {
                break;
            }
            // Progress check: an attempt that has not cut its error by a
            // tenth over the last eight iterations is stuck.
            if give_up && it > 0 && it % 8 == 0 {
                let now = r.e.norm_squared();
                if now > 0.81 * checkpoint && now > 1e-8 {
                    break;
                }
                checkpoint = now;
            }
            used += 1;
            let Some(trial) = self.step(&q, &r, goals, m, lambda, movable) else {
                lambda *= 10.0;
                continue;
            };
            let tr = self.residual(&trial, goals, m);
            if tr.e.norm_squared() < r.e.norm_squared() {
                q = trial;
                r = tr;
                lambda = (lambda * 0.3).max(1e-12);
            } else {
                lambda *= 4.0;
                if lambda > 1e6 {
                    break;
                }
            }
        }
        (q, r, used)
    }

    /// Solve for joint values that meet every goal, starting from `seed`.
    /// Never fails for reachable or unreachable targets: it returns the best
    /// answer found, with `converged` saying whether it meets the tolerances.
    /// Couplings hold throughout and closed loops stay closed (their
    /// constraints join the goals).
    pub fn solve(
        &self,
        goals: &[Goal],
        seed: &[f64],
        options: &Options,
    ) -> Result<Solution, MechanismError> {
        self.check_state(seed)?;
        for command in &self.commands.0 {
            if let Some(q) = command.solve(self, goals, seed)
                && q.len() == self.dof()
            {
                let m: usize = goals.iter().map(rows).sum();
                let r = self.residual(&q, goals, m);
                if options.done(&r) {
                    return Ok(Solution {
                        converged: true,
                        q,
                        position_error: r.position,
                        rotation_error: r.rotation,
                        iterations: 0,
                    });
                }
            }
        }
        self.solve_generic(goals, seed, options)
    }

    /// [`Model::solve`] without asking the specialised solvers: the
    /// reference they are checked against.
    pub fn solve_generic(
        &self,
        goals: &[Goal],
        seed: &[f64],
        options: &Options,
    ) -> Result<Solution, MechanismError> {
        let movable: Vec<bool> = (0..self.dof()).map(|v| !self.is_follower(v)).collect();
        self.solve_masked(goals, seed, options, &movable)
    }

    /// [`Model::solve`] moving only the variables marked in `movable`.
    pub(crate) fn solve_masked(
        &self,
        goals: &[Goal],
        seed: &[f64],
        options: &Options,
        movable: &[bool],
    ) -> Result<Solution, MechanismError> {
        self.check_state(seed)?;
        let mut all = goals.to_vec();
        all.extend(self.loop_goals());
        let goals = &all[..];
        if goals.is_empty() {
            return Err(MechanismError::new("goals", "give at least one target"));
        }
        for g in goals {
            let finite = match &g.target {
                Target::Pose(p) => p
                    .translation
                    .vector
                    .iter()
                    .chain(p.rotation.coords.iter())
                    .all(|v| v.is_finite()),
                Target::Position(t) => t.iter().all(|v| v.is_finite()),
                Target::Orientation(r) => r.coords.iter().all(|v| v.is_finite()),
            };
            if !finite {
                return Err(MechanismError::new("target", "must be finite numbers"));
            }
        }
        let m: usize = goals.iter().map(rows).sum();
        let problem = Problem { goals, m, movable };
        let mut best: Option<(Vec<f64>, Residual)> = None;
        let mut iterations = 0;
        for attempt in 0..=options.restarts {
            let start = if attempt == 0 {
                seed.to_vec()
            } else {
                self.restart_point(attempt - 1, seed, movable)
            };
            let (q, r, used) = self.descend(start, &problem, options, options.max_iterations, true);
            iterations += used;
            let finished = options.done(&r);
            if best
                .as_ref()
                .is_none_or(|(_, b)| r.e.norm_squared() < b.e.norm_squared())
            {
                best = Some((q, r));
            }
            if finished {
                break;
            }
        }
        // Close but not there (typically near a singularity, where the
        // steps shrink slowly): keep going from the best point for longer.
        if let Some((q, r)) = best.take() {
            best = Some(if !options.done(&r) && r.e.norm() < 1e-3 {
                let (q, r, used) =
                    self.descend(q, &problem, options, 4 * options.max_iterations, false);
                iterations += used;
                (q, r)
            } else {
                (q, r)
            });
        }
        let Some((q, r)) = best else {
            return Err(MechanismError::new("goals", "no attempt was made"));
        };
        Ok(Solution {
            converged: options.done(&r),
            q,
            position_error: r.position,
            rotation_error: r.rotation,
            iterations,
        })
    }
}
