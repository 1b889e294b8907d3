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

use crate::error::FieldError;
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
            restarts: 60,
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

/// Stacked errors and the largest position and rotation error, with what
/// the walk that measured them found on the way: each goal frame's point
/// and the world axes of the joints above it (and above its base), so the
/// Jacobian at the same state needs no second walk.
#[derive(Clone)]
struct Residual {
    e: DVector<f64>,
    position: f64,
    rotation: f64,
    points: Vec<Vector3<f64>>,
    /// Two lists per goal: the frame's joints, then its base's.
    axes: Vec<Vec<Axis>>,
}

impl Residual {
    fn new(m: usize, goals: usize) -> Self {
        Self {
            e: DVector::zeros(m),
            position: f64::INFINITY,
            rotation: f64::INFINITY,
            points: vec![Vector3::zeros(); goals],
            axes: vec![Vec::new(); 2 * goals],
        }
    }
}

/// Buffers one search reuses at every iteration, so iterating allocates
/// nothing.
struct Work {
    jac: DMatrix<f64>,
    six: DMatrix<f64>,
    /// J Jᵀ + λ² I, row-major, then its Cholesky factor.
    a: Vec<f64>,
    y: Vec<f64>,
    trial: Vec<f64>,
    trial_residual: Residual,
}

impl Work {
    fn new(m: usize, n: usize, goals: usize) -> Self {
        Self {
            jac: DMatrix::zeros(m, n),
            six: DMatrix::zeros(6, n),
            a: vec![0.0; m * m],
            y: vec![0.0; m],
            trial: Vec::with_capacity(n),
            trial_residual: Residual::new(m, goals),
        }
    }
}

/// Solve `A x = b` in place for a symmetric positive definite `A` (m × m,
/// row-major, lower triangle used) by Cholesky; `b` becomes `x`. False if
/// `A` is not positive definite.
fn cholesky_solve(a: &mut [f64], m: usize, b: &mut [f64]) -> bool {
    let mut inv = [0.0f64; 36];
    let mut inv_heap;
    let inv: &mut [f64] = if m <= inv.len() {
        &mut inv[..m]
    } else {
        inv_heap = vec![0.0; m];
        &mut inv_heap
    };
    for j in 0..m {
        let row_j = j * m;
        let mut d = a[row_j + j];
        for k in 0..j {
            d -= a[row_j + k] * a[row_j + k];
        }
        if d.is_nan() || d <= 0.0 {
            return false;
        }
        let r = 1.0 / d.sqrt();
        inv[j] = r;
        for i in j + 1..m {
            let row_i = i * m;
            let mut s = a[row_i + j];
            for k in 0..j {
                s -= a[row_i + k] * a[row_j + k];
            }
            a[row_i + j] = s * r;
        }
    }
    for i in 0..m {
        let mut s = b[i];
        for k in 0..i {
            s -= a[i * m + k] * b[k];
        }
        b[i] = s * inv[i];
    }
    for i in (0..m).rev() {
        let mut s = b[i];
        for k in i + 1..m {
            s -= a[k * m + i] * b[k];
        }
        b[i] = s * inv[i];
    }
    true
}

/// A moving joint's axis in the world: its variable, whether it slides,
/// its direction and a point on it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Axis {
    pub v: usize,
    pub prismatic: bool,
    pub z: Vector3<f64>,
    pub o: Vector3<f64>,
}

/// Add `sign` times the Jacobian columns of a point `p` moved by `axes`.
pub(crate) fn add_columns(axes: &[Axis], p: &Vector3<f64>, sign: f64, six: &mut DMatrix<f64>) {
    for a in axes {
        let (linear, angular) = if a.prismatic {
            (a.z, Vector3::zeros())
        } else {
            (a.z.cross(&(p - a.o)), a.z)
        };
        for k in 0..3 {
            six[(k, a.v)] += sign * linear[k];
            six[(3 + k, a.v)] += sign * angular[k];
        }
    }
}

fn rows(goal: &Goal) -> usize {
    match goal.target {
        Target::Pose(_) => 6,
        _ => 3,
    }
}

impl Model {
    fn residual(&self, q: &[f64], goals: &[Goal], m: usize) -> Residual {
        let mut r = Residual::new(m, goals.len());
        self.residual_into(q, goals, &mut r);
        r
    }

    fn residual_into(&self, q: &[f64], goals: &[Goal], r: &mut Residual) {
        let (mut position, mut rotation): (f64, f64) = (0.0, 0.0);
        let mut row = 0;
        for (i, g) in goals.iter().enumerate() {
            let at = self.walk_axes(q, &g.frame, &mut r.axes[2 * i]);
            r.points[i] = at.translation.vector;
            let base = match &g.relative_to {
                Some(b) => self.walk_axes(q, b, &mut r.axes[2 * i + 1]),
                None => {
                    r.axes[2 * i + 1].clear();
                    Pose::identity()
                }
            };
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
                    r.e.fixed_rows_mut::<3>(row).copy_from(v);
                    row += 3;
                    if k == 0 {
                        position = position.max(v.norm());
                    } else {
                        rotation = rotation.max(v.norm());
                    }
                }
            }
        }
        r.position = position;
        r.rotation = rotation;
    }

    /// Every goal's Jacobian rows into `w.jac`, with coupled columns folded
    /// into their leaders and the columns of variables that may not move
    /// zeroed.
    fn jacobian_stack(&self, r: &Residual, problem: &Problem<'_>, w: &mut Work) {
        let mut row = 0;
        for (i, g) in problem.goals.iter().enumerate() {
            w.six.fill(0.0);
            let p = r.points[i];
            add_columns(&r.axes[2 * i], &p, 1.0, &mut w.six);
            // A target riding on a base: the base's velocity at the frame's
            // point counts against the frame's own.
            add_columns(&r.axes[2 * i + 1], &p, -1.0, &mut w.six);
            let keep = match g.target {
                Target::Pose(_) => 0..6,
                Target::Position(_) => 0..3,
                Target::Orientation(_) => 3..6,
            };
            for (k, r) in keep.enumerate() {
                for c in 0..w.six.ncols() {
                    w.jac[(row + k, c)] = w.six[(r, c)];
                }
            }
            row += rows(g);
        }
        if !self.couplings.is_empty() {
            self.fold_couplings(&mut w.jac);
        }
        for (v, &free) in problem.movable.iter().enumerate() {
            if !free {
                w.jac.column_mut(v).fill(0.0);
            }
        }
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
        let mut q: Vec<f64> = self
            .variables
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
            .collect();
        self.apply_couplings(&mut q);
        q
    }

    /// Where the attempts start: the seed and the spread-out restart
    /// points, closest to the goals first (the seed wins ties, so a small
    /// move from where the mechanism is stays on the same branch).
    fn starts(&self, seed: &[f64], problem: &Problem<'_>, restarts: usize) -> Vec<Vec<f64>> {
        let mut q0 = seed.to_vec();
        self.clamp(&mut q0);
        self.apply_couplings(&mut q0);
        let mut r = Residual::new(problem.m, problem.goals.len());
        let mut scored: Vec<(f64, Vec<f64>)> = Vec::with_capacity(restarts + 1);
        self.residual_into(&q0, problem.goals, &mut r);
        scored.push((0.5 * r.e.norm_squared(), q0));
        // Scoring costs a walk per candidate; the first few are enough to
        // avoid a start on the far side of the workspace.
        let scoring = 8;
        let mut rest = Vec::new();
        for k in 0..restarts {
            let q = self.restart_point(k, seed, problem.movable);
            if k < scoring {
                self.residual_into(&q, problem.goals, &mut r);
                scored.push((r.e.norm_squared(), q));
            } else {
                rest.push(q);
            }
        }
        let scored = kinolab_common::order::sorted_by(scored, |s| [s.0, 0.0]);
        scored.into_iter().map(|(_, q)| q).chain(rest).collect()
    }

    /// The damped least-squares step from `q` into `w.trial`, clamped into
    /// the limits. Joints pinned at a limit and pushed further drop out of
    /// the step (their columns are zeroed) and the step is recomputed for
    /// the rest. False when the system cannot be solved at this damping.
    fn step(
        &self,
        q: &[f64],
        r: &Residual,
        problem: &Problem<'_>,
        lambda: f64,
        w: &mut Work,
    ) -> bool {
        let (m, n) = (problem.m, self.dof());
        self.jacobian_stack(r, problem, w);
        for _ in 0..=n {
            // A = J Jᵀ + λ² I (lower triangle, one column of J at a
            // time); solve A y = e; the step is Jᵀ y.
            w.a.fill(0.0);
            for i in 0..m {
                w.a[i * m + i] = lambda * lambda;
            }
            for c in 0..n {
                let col = w.jac.column(c);
                let col = col.as_slice();
                for i in 0..m {
                    let ji = col[i];
                    if ji != 0.0 {
                        let row = &mut w.a[i * m..i * m + i + 1];
                        for (a, jk) in row.iter_mut().zip(col) {
                            *a += ji * jk;
                        }
                    }
                }
            }
            w.y.copy_from_slice(r.e.as_slice());
            if !cholesky_solve(&mut w.a, m, &mut w.y) {
                return false;
            }
            w.trial.clear();
            for (c, qc) in q.iter().enumerate() {
                let col = w.jac.column(c);
                let s: f64 = col.as_slice().iter().zip(&w.y).map(|(a, b)| a * b).sum();
                w.trial.push(qc + s);
            }
            let mut pinned = false;
            for v in 0..n {
                let t = w.trial[v];
                if let Some([lo, hi]) = self.joints[self.variables[v]].limits
                    && (t < lo || t > hi)
                    && w.jac.column(v).iter().any(|x| *x != 0.0)
                {
                    w.jac.column_mut(v).fill(0.0);
                    pinned = true;
                }
            }
            if !pinned {
                self.clamp(&mut w.trial);
                self.apply_couplings(&mut w.trial);
                return true;
            }
        }
        false
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
        w: &mut Work,
    ) -> (Vec<f64>, Residual, usize) {
        self.clamp(&mut q);
        self.apply_couplings(&mut q);
        let mut r = self.residual(&q, problem.goals, problem.m);
        // Start cautious (far from the answer a full Gauss–Newton step
        // overshoots), grow the damping quickly when a step fails and
        // relax it gently when one succeeds. Tuned on 10 000 Puma and Panda
        // targets (see the benchmark's IK survey).
        let mut lambda = 0.3;
        let mut checkpoint = r.e.norm_squared();
        let mut used = 0;
        for it in 0..max_iterations {
            if options.done(&r) {
                break;
            }
            // Progress check: an attempt that has not cut its squared error
            // by a tenth over the last four iterations is stuck; another
            // start is cheaper than waiting.
            if give_up && it > 0 && it % 4 == 0 {
                let now = r.e.norm_squared();
                if now > 0.9 * checkpoint && now > 1e-8 {
                    break;
                }
                checkpoint = now;
            }
            used += 1;
            if !self.step(&q, &r, problem, lambda, w) {
                lambda *= 10.0;
                continue;
            }
            let mut tr = std::mem::replace(&mut w.trial_residual, Residual::new(0, 0));
            self.residual_into(&w.trial, problem.goals, &mut tr);
            if tr.e.norm_squared() < r.e.norm_squared() {
                std::mem::swap(&mut q, &mut w.trial);
                std::mem::swap(&mut r, &mut tr);
                lambda = (lambda * 0.6).max(1e-12);
            } else {
                lambda *= 3.0;
                if lambda > 1e6 {
                    w.trial_residual = tr;
                    break;
                }
            }
            w.trial_residual = tr;
        }
        (q, r, used)
    }

    /// Solve for joint values that meet every goal, starting from `seed`.
    /// Never fails for reachable or unreachable targets: it returns the best
    /// answer found, with `converged` saying whether it meets the tolerances.
    /// Couplings hold throughout and closed loops stay closed (their
    /// constraints join the goals).
    ///
    /// A solution is only called converged when its joint values and its
    /// errors are finite numbers: an overflow never passes for an answer.
    pub fn solve(
        &self,
        goals: &[Goal],
        seed: &[f64],
        options: &Options,
    ) -> Result<Solution, FieldError> {
        for (i, goal) in goals.iter().enumerate() {
            let p = match &goal.target {
                Target::Position(p) => *p,
                Target::Pose(pose) => pose.translation.vector,
                Target::Orientation(_) => Vector3::zeros(),
            };
            for v in p.iter() {
                crate::error::finite_at(*v, || format!("goals[{i}].position"))?;
            }
        }
        let mut solution = self.solve_checked(goals, seed, options)?;
        let finite = solution.q.iter().all(|v| v.is_finite())
            && solution.position_error.is_finite()
            && solution.rotation_error.is_finite();
        solution.converged &= finite;
        Ok(solution)
    }

    fn solve_checked(
        &self,
        goals: &[Goal],
        seed: &[f64],
        options: &Options,
    ) -> Result<Solution, FieldError> {
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
    ) -> Result<Solution, FieldError> {
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
    ) -> Result<Solution, FieldError> {
        self.check_state(seed)?;
        let mut all = goals.to_vec();
        all.extend(self.loop_goals());
        let goals = &all[..];
        if goals.is_empty() {
            return Err(FieldError::new("goals", "give at least one target"));
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
                return Err(FieldError::new("target", "must be finite numbers"));
            }
        }
        let m: usize = goals.iter().map(rows).sum();
        let problem = Problem { goals, m, movable };
        let mut work = Work::new(m, self.dof(), goals.len());
        let starts = self.starts(seed, &problem, options.restarts);
        let mut best: Option<(Vec<f64>, Residual)> = None;
        let mut iterations = 0;
        for start in starts {
            let (q, r, used) = self.descend(
                start,
                &problem,
                options,
                options.max_iterations,
                true,
                &mut work,
            );
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
                let (q, r, used) = self.descend(
                    q,
                    &problem,
                    options,
                    4 * options.max_iterations,
                    false,
                    &mut work,
                );
                iterations += used;
                (q, r)
            } else {
                (q, r)
            });
        }
        let Some((q, r)) = best else {
            return Err(FieldError::new("goals", "no attempt was made"));
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
