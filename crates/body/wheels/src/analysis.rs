//! The three degrees, DOF and holonomy, and the layout's ICR.
//!
//! Everything here follows from which chassis motions the standard wheels
//! allow (the null space of C₁) and how far steering can move that space.

use nalgebra::Vector3;
use serde::Serialize;

use crate::chassis::{Chassis, group_meeting_point, intersect};
use crate::span::{RANK_TOLERANCE, Span3};
use crate::wheel::{Wheel, WheelKind, WheelRows};

/// Where a layout's instantaneous centre of rotation can be, in the robot
/// frame.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Icr {
    /// rank C₁ = 0: no standard wheel objects to any motion.
    Anywhere,
    /// rank C₁ = 1: on one line (all zero-motion lines coincide).
    Line {
        point: [f64; 2],
        direction: [f64; 2],
    },
    /// rank C₁ = 2: pinned to one point.
    Point { x: f64, y: f64 },
    /// rank C₁ = 2 with parallel zero-motion lines: pure translation along
    /// `direction`; the ICR is infinitely far along the axles.
    Infinity { direction: [f64; 2] },
    /// rank C₁ = 3: the zero-motion lines share no point; the robot cannot
    /// move without some wheel sliding.
    None,
}

/// The structural facts of a layout at its current steering angles.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Analysis {
    pub rank_c1: usize,
    pub rank_c1f: usize,
    pub rank_c1s: usize,
    /// Number of steering inputs (a linked group counts once).
    pub steering_inputs: usize,
    /// δm = 3 − rank C₁(β_s) = DDOF.
    pub mobility: usize,
    /// δs: how many independent ways steering can move the ICR.
    pub steerability: usize,
    /// δM = δm + δs.
    pub maneuverability: usize,
    /// Pose dimensions the robot can reach, from the Lie brackets of every
    /// motion it can make at some reachable steering.
    pub dof: usize,
    /// DDOF = DOF, for a robot that can move at all (DOF > 0).
    pub holonomic: bool,
    pub icr: Icr,
    /// Chassis twists allowed now: N(C₁(β_s)).
    pub admissible: Span3,
    /// Chassis twists allowed at some reachable steering.
    pub reachable: Span3,
}

impl Analysis {
    /// DDOF, the differentiable degrees of freedom: equal to δm.
    pub fn ddof(&self) -> usize {
        self.mobility
    }
}

impl Chassis {
    /// Rank, the three degrees, DOF, holonomy and the ICR. Allocates nothing.
    pub fn analyze(&self) -> Analysis {
        let wheels = self.wheels();
        let mut c1f = Span3::empty();
        let mut c1s = Span3::empty();
        let mut c1 = Span3::empty();
        let mut first_row = None;
        for (w, rows) in wheels.iter().zip(self.rows()) {
            let is_fixed = match w.kind {
                WheelKind::Fixed => true,
                WheelKind::Steered => false,
                _ => continue,
            };
            let row = rows.sliding;
            first_row.get_or_insert(row);
            if is_fixed {
                c1f.add(row);
            } else {
                c1s.add(row);
            }
            c1.add(row);
        }
        let admissible = c1.complement();
        let mobility = admissible.rank();

        // Steering can only move the ICR where the fixed wheels and the
        // steering linkages let it go: twists orthogonal to C₁f and to one
        // "virtual axle" row per linkage.
        let mut limits = c1f;
        for input in self.steering_inputs() {
            if input.wheels.len() > 1
                && let Some(row) = linkage_row(wheels, self.rows(), &input.wheels, c1f.rank())
            {
                limits.add(row);
            }
        }
        let reachable = limits.complement();
        let inputs = self.steering_inputs().len();
        // δs = rank C₁s counted over independent inputs (a linkage is one
        // input), and at most 2, or 1 once any fixed wheel is there. This
        // holds even for a layout that cannot move right now: its steering
        // inputs still move the rows of C₁s.
        // Steering never adds more than the poses it can reach beyond δm
        // (so DDOF ≤ δM ≤ DOF holds, as the sheet says).
        let dof = lie_closure(reachable).rank();
        let cap = if c1f.rank() > 0 { 1 } else { 2 };
        let steerability = inputs
            .min(c1s.rank())
            .min(cap)
            .min(dof.saturating_sub(mobility));
        let icr = layout_icr(c1.rank(), first_row, &admissible);
        Analysis {
            rank_c1: c1.rank(),
            rank_c1f: c1f.rank(),
            rank_c1s: c1s.rank(),
            steering_inputs: inputs,
            mobility,
            steerability,
            maneuverability: mobility + steerability,
            dof,
            holonomic: dof > 0 && mobility == dof,
            icr,
            admissible,
            reachable,
        }
    }
}

/// The constraint a multi-wheel steering linkage puts on the ICR, as a
/// sliding-like row, or `None` when it adds nothing to the fixed wheels.
fn linkage_row(
    wheels: &[Wheel],
    rows: &[WheelRows],
    group: &[usize],
    rank_c1f: usize,
) -> Option<Vector3<f64>> {
    if rank_c1f >= 2 {
        // The fixed wheels already pin the ICR; no linkage can add a limit.
        return None;
    }
    if rank_c1f == 1 {
        // Parallel wheels (a belt) forbid turning; any other linkage keeps
        // its meeting point on the fixed axle, which C₁f already says.
        // The first two entries of a standard wheel's sliding row are its
        // axle direction, already computed.
        let axle = |i: usize| (rows[i].sliding.x, rows[i].sliding.y);
        let (ax, ay) = axle(group[0]);
        let parallel = group[1..].iter().all(|&i| {
            let (bx, by) = axle(i);
            (ax * by - ay * bx).abs() < RANK_TOLERANCE
        });
        return parallel.then(|| Vector3::new(0.0, 0.0, 1.0));
    }
    match group_meeting_point(wheels, group) {
        // A belt keeps the wheels parallel: the chassis never turns.
        None => Some(Vector3::new(0.0, 0.0, 1.0)),
        // A linkage keeps the axles meeting at a point that slides along the
        // fixed wheels' axle (already in C₁f) or, without fixed wheels, along
        // the line through P and the meeting point.
        Some(_) if rank_c1f > 0 => None,
        Some([cx, cy]) => {
            let norm = cx.hypot(cy);
            let [ux, uy] = if norm > 1e-9 {
                [cx / norm, cy / norm]
            } else {
                [0.0, 1.0]
            };
            Some(line_row([cx, cy], [ux, uy]))
        }
    }
}

/// The row whose null space is every twist with its ICR on the line through
/// `point` along `direction` (a wheel's sliding row has this form).
pub(crate) fn line_row(point: [f64; 2], direction: [f64; 2]) -> Vector3<f64> {
    let [px, py] = point;
    let [ux, uy] = direction;
    Vector3::new(ux, uy, px * uy - py * ux)
}

/// The common axle line of the fixed wheels, when they allow exactly one.
pub(crate) fn fixed_axle_line(wheels: &[Wheel]) -> Option<([f64; 2], [f64; 2])> {
    let mut span = Span3::empty();
    let mut first = None;
    for w in wheels.iter().filter(|w| w.kind == WheelKind::Fixed) {
        span.add(w.rows().sliding);
        first.get_or_insert(w.zero_motion_line());
    }
    if span.rank() == 1 { first } else { None }
}

/// The Lie algebra generated by the motion fields ξ̇_I = R(θ)ᵀ u for u in
/// `motions`. These fields are left-invariant, so it is enough to work at
/// θ = 0, where the bracket of u and w is w_θ·S u − u_θ·S w with
/// S u = (−u_y, u_x, 0) the derivative of R(θ)ᵀ u.
pub fn lie_closure(motions: Span3) -> Span3 {
    let mut span = motions;
    loop {
        let before = span.rank();
        let basis = span;
        let basis = basis.basis();
        for (i, u) in basis.iter().enumerate() {
            for w in &basis[i + 1..] {
                span.add(bracket(u, w));
            }
        }
        if span.rank() == before {
            return span;
        }
    }
}

fn bracket(u: &Vector3<f64>, w: &Vector3<f64>) -> Vector3<f64> {
    let su = Vector3::new(-u.y, u.x, 0.0);
    let sw = Vector3::new(-w.y, w.x, 0.0);
    su * w.z - sw * u.z
}

fn layout_icr(rank: usize, first_row: Option<Vector3<f64>>, admissible: &Span3) -> Icr {
    match (rank, first_row) {
        (0, _) | (_, None) => Icr::Anywhere,
        (1, Some(row)) => {
            // Twists with ICR (X, Y): ẋ = Yθ̇, ẏ = −Xθ̇. The row a·ẋ + b·ẏ + c·θ̇ = 0
            // becomes −b X + a Y + c = 0: a line along (a, b).
            let (a, b, c) = (row.x, row.y, row.z);
            let n2 = a * a + b * b;
            let point = [b * c / n2, -a * c / n2];
            let norm = n2.sqrt();
            Icr::Line {
                point,
                direction: canonical([a / norm, b / norm]),
            }
        }
        (2, _) => twist_icr(&admissible.basis()[0]),
        _ => Icr::None,
    }
}

/// The ICR of one chassis twist in the robot frame: (−ẏ_R/θ̇, ẋ_R/θ̇), or at
/// infinity for a translation (`direction` is the direction of travel).
/// A zero twist has no ICR.
pub fn twist_icr(twist: &Vector3<f64>) -> Icr {
    let norm = twist.norm();
    if !norm.is_finite() || norm == 0.0 {
        return Icr::None;
    }
    if twist.z.abs() > RANK_TOLERANCE * norm {
        Icr::Point {
            x: -twist.y / twist.z,
            y: twist.x / twist.z,
        }
    } else {
        let d = twist.x.hypot(twist.y);
        Icr::Infinity {
            direction: canonical([twist.x / d, twist.y / d]),
        }
    }
}

/// A direction written with its first clearly non-zero component positive,
/// so the same line always prints the same way.
fn canonical([x, y]: [f64; 2]) -> [f64; 2] {
    let clean = |v: f64| if v.abs() < 1e-15 { 0.0 } else { v };
    if x > 1e-12 || (x.abs() <= 1e-12 && y > 0.0) {
        [clean(x), clean(y)]
    } else {
        [clean(-x), clean(-y)]
    }
}

/// Which standard wheels keep a stuck layout (rank C₁ = 3) from moving.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Disagreement {
    /// The ICR most wheels agree on.
    pub consensus: Icr,
    /// Wheels whose zero-motion lines pass through it.
    pub agree: Vec<usize>,
    /// The others, with how far their zero-motion line misses it (metres
    /// for a point; the sine of the angle for a translation).
    pub disagree: Vec<(usize, f64)>,
}

impl Chassis {
    /// For a layout that cannot move, the largest group of standard wheels
    /// that agree on an ICR and the wheels that spoil it. `None` when the
    /// layout can move.
    pub fn disagreement(&self) -> Option<Disagreement> {
        if self.analyze().rank_c1 < 3 {
            return None;
        }
        let standard: Vec<(usize, &Wheel)> = self
            .wheels()
            .iter()
            .enumerate()
            .filter(|(_, w)| w.kind.constrains_chassis())
            .collect();
        let mut best: Option<(usize, Icr, Vector3<f64>)> = None;
        for (i, (_, a)) in standard.iter().enumerate() {
            for (_, b) in &standard[i + 1..] {
                let (twist, icr) = match intersect(a.zero_motion_line(), b.zero_motion_line()) {
                    Some([x, y]) => (Vector3::new(y, -x, 1.0), Icr::Point { x, y }),
                    None => {
                        let [nx, ny] = a.axle();
                        let direction = canonical([-ny, nx]);
                        (
                            Vector3::new(direction[0], direction[1], 0.0),
                            Icr::Infinity { direction },
                        )
                    }
                };
                let count = standard
                    .iter()
                    .filter(|(_, w)| miss(w, &twist) <= 1e-9 * twist.norm().max(1.0))
                    .count();
                if best.as_ref().is_none_or(|(n, _, _)| count > *n) {
                    best = Some((count, icr, twist));
                }
            }
        }
        let (_, consensus, twist) = best?;
        let tolerance = 1e-9 * twist.norm().max(1.0);
        let (agree, disagree): (Vec<_>, Vec<_>) = standard
            .iter()
            .map(|(i, w)| (*i, miss(w, &twist)))
            .partition(|(_, m)| *m <= tolerance);
        Some(Disagreement {
            consensus,
            agree: agree.into_iter().map(|(i, _)| i).collect(),
            disagree,
        })
    }
}

/// |sliding · twist|: for a rotation about a point, the distance from that
/// point to the wheel's zero-motion line.
fn miss(wheel: &Wheel, twist: &Vector3<f64>) -> f64 {
    wheel.rows().sliding.dot(twist).abs()
}
