//! Specialised solvers, plugged into a model as commands.
//!
//! The generic algorithms work for any mechanism; some mechanisms have a
//! closed-form answer that is exact and cheaper. A command is asked first:
//! it answers what it recognises and declines the rest, which then goes to
//! the generic algorithm. Inverse commands solve goals, forward commands
//! place frames. Each command is checked against the generic algorithm in
//! the tests.

use kinolab_common::angle::wrap;
use kinolab_common::trig;
use std::fmt;
use std::sync::Arc;

use crate::ik::{Goal, Target};
use crate::model::{FrameRef, Model, Pose};

/// A closed-form inverse-kinematics algorithm for one kind of mechanism.
pub trait InverseCommand: Send + Sync {
    /// A short name shown to learners ("analytic 2R").
    fn name(&self) -> &str;

    /// Joint values meeting `goals` exactly, nearest `seed` among the
    /// solutions; `None` when these goals are not its kind or it has no
    /// exact answer inside the limits (the generic solver then takes over).
    fn solve(&self, model: &Model, goals: &[Goal], seed: &[f64]) -> Option<Vec<f64>>;
}

/// A closed-form forward kinematics for a frame of one kind of mechanism.
pub trait ForwardCommand: Send + Sync {
    /// A short name shown to learners ("closed-form planar FK").
    fn name(&self) -> &str;

    /// The frame's pose for joint values `q`; `None` when it is not this
    /// command's frame.
    fn pose(&self, q: &[f64], frame: &FrameRef) -> Option<Pose>;
}

/// The commands a model carries: inverse ones, then forward ones.
#[derive(Clone, Default)]
pub struct Commands(
    pub(crate) Vec<Arc<dyn InverseCommand>>,
    pub(crate) Vec<Arc<dyn ForwardCommand>>,
);

impl Commands {
    fn names(&self) -> Vec<&str> {
        self.1
            .iter()
            .map(|c| c.name())
            .chain(self.0.iter().map(|c| c.name()))
            .collect()
    }
}

impl fmt::Debug for Commands {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(self.names()).finish()
    }
}

impl PartialEq for Commands {
    fn eq(&self, other: &Self) -> bool {
        self.names() == other.names()
    }
}

impl Model {
    /// Plug in a specialised inverse-kinematics solver; later ones are
    /// asked first.
    pub fn add_command(&mut self, command: Arc<dyn InverseCommand>) {
        self.commands.0.insert(0, command);
    }

    /// Plug in a closed-form forward kinematics; later ones are asked first.
    pub fn add_forward_command(&mut self, command: Arc<dyn ForwardCommand>) {
        self.commands.1.insert(0, command);
    }

    /// The names of the plugged-in commands, forward ones first.
    pub fn command_names(&self) -> Vec<&str> {
        self.commands.names()
    }

    /// A frame's pose from a plugged-in closed form, if one knows it.
    pub(crate) fn pose_by_command(&self, q: &[f64], frame: &FrameRef) -> Option<Pose> {
        self.commands.1.iter().find_map(|c| c.pose(q, frame))
    }
}

/// Closed-form forward kinematics of a planar arm's tool: turn by the sum
/// of the joint angles, reach by the sum of the link vectors.
#[derive(Debug, Clone)]
pub struct PlanarForward {
    pub links: Vec<f64>,
    pub tool: FrameRef,
}

impl ForwardCommand for PlanarForward {
    fn name(&self) -> &str {
        "closed-form planar FK"
    }

    fn pose(&self, q: &[f64], frame: &FrameRef) -> Option<Pose> {
        if *frame != self.tool || q.len() != self.links.len() {
            return None;
        }
        let (mut x, mut y, mut angle) = (0.0, 0.0, 0.0);
        for (l, qi) in self.links.iter().zip(q) {
            angle += qi;
            let (s, c) = trig::sin_cos(angle);
            x += l * c;
            y += l * s;
        }
        Some(Pose::from_parts(
            nalgebra::Translation3::new(x, y, 0.0),
            nalgebra::UnitQuaternion::from_axis_angle(&nalgebra::Vector3::z_axis(), angle),
        ))
    }
}

/// Both elbow solutions of a planar 2R arm reaching (x, y), if any.
fn two_link(l1: f64, l2: f64, x: f64, y: f64) -> Option<[[f64; 2]; 2]> {
    let c2 = (x * x + y * y - l1 * l1 - l2 * l2) / (2.0 * l1 * l2);
    if !(-1.0..=1.0).contains(&c2) {
        return None;
    }
    let s2 = (1.0 - c2 * c2).max(0.0).sqrt();
    Some([s2, -s2].map(|s| {
        let q2 = trig::atan2(s, c2);
        let q1 = trig::atan2(y, x) - trig::atan2(l2 * s, l1 + l2 * c2);
        [wrap(q1), q2]
    }))
}

/// The candidate inside the limits nearest the seed.
fn nearest(model: &Model, candidates: Vec<Vec<f64>>, seed: &[f64]) -> Option<Vec<f64>> {
    let inside = |q: &Vec<f64>| {
        q.iter().enumerate().all(|(i, v)| {
            model
                .variable_joint(i)
                .and_then(|j| j.limits)
                .is_none_or(|[lo, hi]| (lo..=hi).contains(v))
        })
    };
    let distance = |q: &Vec<f64>| {
        q.iter()
            .zip(seed)
            .map(|(a, b)| wrap(a - b).powi(2))
            .sum::<f64>()
    };
    candidates
        .into_iter()
        .filter(inside)
        .min_by(|a, b| distance(a).total_cmp(&distance(b)))
}

/// A single goal on `tool` in the world, or nothing.
fn only_goal<'a>(goals: &'a [Goal], tool: &FrameRef) -> Option<&'a Target> {
    match goals {
        [g] if g.relative_to.is_none() && g.frame == *tool => Some(&g.target),
        _ => None,
    }
}

/// Closed-form IK of the planar 2R arm: a position in its plane.
#[derive(Debug, Clone)]
pub struct Planar2R {
    pub links: [f64; 2],
    pub tool: FrameRef,
}

impl InverseCommand for Planar2R {
    fn name(&self) -> &str {
        "analytic 2R"
    }

    fn solve(&self, model: &Model, goals: &[Goal], seed: &[f64]) -> Option<Vec<f64>> {
        let Target::Position(p) = only_goal(goals, &self.tool)? else {
            return None;
        };
        if p.z.abs() > 1e-12 {
            return None;
        }
        let [l1, l2] = self.links;
        let both = two_link(l1, l2, p.x, p.y)?;
        nearest(model, both.iter().map(|q| q.to_vec()).collect(), seed)
    }
}

/// Closed-form IK of the planar 3R arm: a position and a heading in its
/// plane (a pose whose rotation is about z).
#[derive(Debug, Clone)]
pub struct Planar3R {
    pub links: [f64; 3],
    pub tool: FrameRef,
}

impl InverseCommand for Planar3R {
    fn name(&self) -> &str {
        "analytic 3R"
    }

    fn solve(&self, model: &Model, goals: &[Goal], seed: &[f64]) -> Option<Vec<f64>> {
        let Target::Pose(pose) = only_goal(goals, &self.tool)? else {
            return None;
        };
        let p = pose.translation.vector;
        let axis = pose
            .rotation
            .axis()
            .map_or(nalgebra::Vector3::z(), |a| a.into_inner());
        if p.z.abs() > 1e-12 || (pose.rotation.angle() > 1e-12 && axis.z.abs() < 1.0 - 1e-12) {
            return None;
        }
        let phi = pose.rotation.euler_angles().2;
        let [l1, l2, l3] = self.links;
        let (wx, wy) = (p.x - l3 * trig::cos(phi), p.y - l3 * trig::sin(phi));
        let both = two_link(l1, l2, wx, wy)?;
        let candidates = both
            .iter()
            .map(|[q1, q2]| vec![*q1, *q2, wrap(phi - q1 - q2)])
            .collect();
        nearest(model, candidates, seed)
    }
}

/// Give the catalogue's planar arms their closed-form solvers.
pub(crate) fn attach_planar(model: &mut Model, links: &[f64]) {
    let Ok(tool) = model.frame("tool") else {
        return;
    };
    match *links {
        [a, b] => model.add_command(Arc::new(Planar2R {
            links: [a, b],
            tool,
        })),
        [a, b, c] => model.add_command(Arc::new(Planar3R {
            links: [a, b, c],
            tool,
        })),
        _ => {}
    }
    model.add_forward_command(Arc::new(PlanarForward {
        links: links.to_vec(),
        tool,
    }));
}
