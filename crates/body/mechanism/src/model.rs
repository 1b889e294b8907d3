//! The mechanism model: bodies joined by joints into one tree rooted in the
//! world frame, plus named frames. The model is stateless — it says how the
//! parts fit, never where they are — so any number of views and solvers can
//! share one model, each with its own joint values (a [`crate::State`]).

use nalgebra::{Isometry3, Rotation3, Translation3, Unit, UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

use crate::compose::{Coupling, Group, LoopClosure, PendingCoupling, PendingLoop};
use crate::error::FieldError;
use crate::shapes::Shape;

/// How far past a limit a value may be and still count as on it (a limit
/// printed with fewer digits than the value).
const LIMIT_SLACK: f64 = 1e-9;

/// A joint whose value lies outside its limits.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OutsideLimit {
    pub joint: String,
    pub value: f64,
    pub limits: [f64; 2],
}

/// A rigid transform: rotation and translation.
pub type Pose = Isometry3<f64>;

/// Roll, pitch and yaw with `m = Rz(yaw) · Ry(pitch) · Rx(roll)` (URDF's
/// convention, and the model files'). Yaw comes first from the first column; roll and pitch are
/// then read from `Rz(-yaw) · m`, which keeps them exact even where pitch is
/// near ±90° and yaw is poorly defined.
pub(crate) fn rpy(rotation: &UnitQuaternion<f64>) -> [f64; 3] {
    let m = rotation.to_rotation_matrix().into_inner();
    let yaw = if m[(1, 0)].hypot(m[(0, 0)]) < 1e-12 {
        0.0
    } else {
        m[(1, 0)].atan2(m[(0, 0)])
    };
    let rest = Rotation3::from_axis_angle(&Vector3::z_axis(), -yaw).matrix() * m;
    let roll = (-rest[(1, 2)]).atan2(rest[(1, 1)]);
    let pitch = (-rest[(2, 0)]).atan2(rest[(0, 0)]);
    [roll, pitch, yaw]
}

/// How a joint lets its child body move.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum JointKind {
    /// Turns about its axis, within limits.
    Revolute,
    /// Turns about its axis without limits (a wheel).
    Continuous,
    /// Slides along its axis.
    Prismatic,
    /// Does not move: bolts two bodies together.
    Fixed,
}

impl JointKind {
    /// Whether the joint has a variable (a column in the state).
    pub fn moves(self) -> bool {
        !matches!(self, JointKind::Fixed)
    }
}

/// A joint between a parent and a child body. The child's frame is
/// `parent · origin · motion(q + offset) · post`, where the motion turns
/// about or slides along `axis` (given in the joint frame).
#[derive(Debug, Clone, PartialEq)]
pub struct Joint {
    pub name: String,
    pub kind: JointKind,
    pub parent: usize,
    pub child: usize,
    pub origin: Pose,
    pub axis: Unit<Vector3<f64>>,
    pub offset: f64,
    pub post: Pose,
    /// Lower and upper limit (rad or m), if any.
    pub limits: Option<[f64; 2]>,
}

impl Joint {
    /// The joint's own motion for joint value `q`.
    #[inline]
    pub fn motion(&self, q: f64) -> Pose {
        let v = q + self.offset;
        match self.kind {
            JointKind::Revolute | JointKind::Continuous => Pose::from_parts(
                Translation3::identity(),
                UnitQuaternion::from_axis_angle(&self.axis, v),
            ),
            JointKind::Prismatic => Pose::from_parts(
                Translation3::from(self.axis.into_inner() * v),
                UnitQuaternion::identity(),
            ),
            JointKind::Fixed => Pose::identity(),
        }
    }
}

/// A rigid part. Body 0 is the world.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    pub name: String,
    /// Its mass properties; `None`: massless (a frame, a tool point).
    pub inertial: Option<crate::Inertial>,
}

/// A named frame fixed to a body (a port: where a tool, sensor or other
/// mechanism attaches).
#[derive(Debug, Clone, PartialEq)]
pub struct Frame {
    pub name: String,
    pub body: usize,
    pub offset: Pose,
}

/// A validated mechanism: a tree of bodies and joints, and named frames.
#[derive(Debug, Clone, PartialEq)]
pub struct Model {
    pub(crate) name: String,
    pub(crate) bodies: Vec<Body>,
    /// Ordered so that every joint's parent body is placed before it.
    pub(crate) joints: Vec<Joint>,
    pub(crate) frames: Vec<Frame>,
    /// The joint behind each state variable.
    pub(crate) variables: Vec<usize>,
    /// Each joint's variable, if it moves.
    pub(crate) variable_of: Vec<Option<usize>>,
    /// For each body, the joints from the world down to it, in order.
    pub(crate) chains: Vec<Vec<usize>>,
    /// For each joint, whether its origin and its post transform are the
    /// identity (DH joints have one of the two), so walks can skip them.
    pub(crate) plain: Vec<[bool; 2]>,
    /// Each joint prepared for walks (see `steps`).
    pub(crate) steps: Vec<crate::steps::Step>,
    /// Variables that follow others (`q_f = ratio · q_l + offset`).
    pub(crate) couplings: Vec<Coupling>,
    /// Loop constraints that close chains, with their passive variables.
    pub(crate) loops: Vec<LoopClosure>,
    /// Bounding shapes, several per body allowed.
    pub(crate) shapes: Vec<Shape>,
    /// Body pairs never tested against each other (they touch by design).
    pub(crate) ignored: Vec<(usize, usize)>,
    /// The mechanism hierarchy: sub-mechanisms and the bodies they own.
    pub(crate) groups: Vec<Group>,
    /// Specialised solvers asked before the generic one.
    pub(crate) commands: crate::special::Commands,
    /// Each body's joint from its parent (none for the world).
    pub(crate) parent_joint: Vec<Option<usize>>,
    /// Each body's mass as the dynamics use it (zero when massless).
    pub(crate) rigid: Vec<crate::inertial::Rigid>,
    /// The moving joints as the dynamics walk them (see `dynamics::tree`).
    pub(crate) tree: crate::dynamics::tree::Tree,
    /// The variables a user sets, in the order they are given: every
    /// variable but the followers, in the model's order, unless the file
    /// the model came from lists them otherwise (a URDF file's order).
    pub(crate) driven: Vec<usize>,
}

/// The most joints a model may have, mounted ones included: more than any
/// robot in the lab, and few enough that every query stays fast (each
/// frame keeps its chain to the root, so memory grows with its square).
pub const MAX_JOINTS: usize = 512;

/// `count` joints, or an error naming `field` when that is above [`MAX_JOINTS`].
pub fn check_size(field: &str, count: usize) -> Result<(), FieldError> {
    if count > MAX_JOINTS {
        return Err(FieldError::new(
            field,
            format!("at most {MAX_JOINTS} joints in a model, got {count}"),
        ));
    }
    Ok(())
}

/// Builds a [`Model`] part by part; [`ModelBuilder::build`] checks it.
#[derive(Debug, Clone, Default)]
pub struct ModelBuilder {
    pub(crate) name: String,
    pub(crate) bodies: Vec<Body>,
    pub(crate) joints: Vec<Joint>,
    pub(crate) frames: Vec<Frame>,
    pub(crate) couplings: Vec<PendingCoupling>,
    pub(crate) loops: Vec<PendingLoop>,
    pub(crate) shapes: Vec<Shape>,
    pub(crate) ignored: Vec<(usize, usize)>,
    pub(crate) groups: Vec<Group>,
    /// Keep the joints in the order given (parents still first) rather
    /// than by depth: a URDF file's order is the order users know.
    pub(crate) keep_order: bool,
}

/// The world frame's name.
pub const WORLD: &str = "world";

impl ModelBuilder {
    pub fn new(name: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            bodies: vec![Body {
                name: WORLD.into(),
                inertial: None,
            }],
            ..Self::default()
        }
    }

    /// Give body `body` its mass properties.
    pub fn set_inertial(&mut self, body: usize, inertial: crate::Inertial) {
        if let Some(b) = self.bodies.get_mut(body) {
            b.inertial = Some(inertial);
        }
    }

    /// Add a body; returns its index.
    pub fn body(&mut self, name: impl Into<String>) -> usize {
        self.bodies.push(Body {
            name: name.into(),
            inertial: None,
        });
        self.bodies.len() - 1
    }

    /// Add a joint from `parent` to a new body named after the joint;
    /// returns the new body's index.
    #[allow(clippy::too_many_arguments)]
    pub fn joint(
        &mut self,
        name: impl Into<String>,
        kind: JointKind,
        parent: usize,
        origin: Pose,
        axis: Unit<Vector3<f64>>,
        offset: f64,
        post: Pose,
        limits: Option<[f64; 2]>,
    ) -> usize {
        let name = name.into();
        let child = self.body(name.clone());
        self.joints.push(Joint {
            name,
            kind,
            parent,
            child,
            origin,
            axis,
            offset,
            post,
            limits,
        });
        child
    }

    /// The usual first body: `base`, bolted to the world at `base`.
    pub fn fixed_base(&mut self, base: Pose) -> usize {
        self.joint(
            "base",
            JointKind::Fixed,
            0,
            base,
            Vector3::z_axis(),
            0.0,
            Pose::identity(),
            None,
        )
    }

    /// Add a named frame on `body`.
    pub fn frame(&mut self, name: impl Into<String>, body: usize, offset: Pose) {
        self.frames.push(Frame {
            name: name.into(),
            body,
            offset,
        });
    }

    /// Check the tree and order it for traversal.
    pub fn build(self) -> Result<Model, FieldError> {
        check_size("joints", self.joints.len())?;
        self.check_names()?;
        let parent_joint = self.check_joints()?;
        self.check_extras()?;
        let chains = self.chains(&parent_joint)?;
        let (joints, chains) = self.depth_order(chains);
        let mut variables = Vec::new();
        let mut variable_of = vec![None; joints.len()];
        for (i, j) in joints.iter().enumerate() {
            if j.kind.moves() {
                variable_of[i] = Some(variables.len());
                variables.push(i);
            }
        }
        let plain = joints
            .iter()
            .map(|j| [j.origin == Pose::identity(), j.post == Pose::identity()])
            .collect();
        let mut parent_joint = vec![None; self.bodies.len()];
        for (i, j) in joints.iter().enumerate() {
            parent_joint[j.child] = Some(i);
        }
        let steps = crate::steps::prepare(&joints, &parent_joint);
        let rigid = self
            .bodies
            .iter()
            .map(|b| {
                b.inertial.map_or(crate::inertial::Rigid::ZERO, |i| {
                    crate::inertial::Rigid::of(&i)
                })
            })
            .collect();
        let mut model = Model {
            name: self.name,
            bodies: self.bodies,
            joints,
            frames: self.frames,
            variables,
            variable_of,
            chains,
            plain,
            steps,
            couplings: Vec::new(),
            loops: Vec::new(),
            shapes: self.shapes,
            ignored: self.ignored,
            groups: self.groups,
            commands: Default::default(),
            parent_joint,
            rigid,
            tree: Default::default(),
            driven: Vec::new(),
        };
        model.tree = crate::dynamics::tree::Tree::of(&model);
        model.couplings = crate::compose::resolve_couplings(&model, &self.couplings)?;
        model.loops = crate::compose::resolve_loops(&model, &self.loops)?;
        model.driven = (0..model.dof())
            .filter(|v| model.couplings.iter().all(|c| c.follower != *v))
            .collect();
        Ok(model)
    }

    /// Body and frame names share one namespace and must be unique.
    fn check_names(&self) -> Result<(), FieldError> {
        let mut names = std::collections::HashSet::new();
        for (i, b) in self.bodies.iter().enumerate() {
            if !names.insert(b.name.as_str()) {
                return Err(FieldError::new(
                    format!("bodies[{i}].name"),
                    format!("`{}` is used twice", b.name),
                ));
            }
        }
        for (i, f) in self.frames.iter().enumerate() {
            if f.body >= self.bodies.len() {
                return Err(FieldError::new(format!("frames[{i}].body"), "no such body"));
            }
            if !names.insert(f.name.as_str()) {
                return Err(FieldError::new(
                    format!("frames[{i}].name"),
                    format!("`{}` is used twice", f.name),
                ));
            }
        }
        Ok(())
    }

    /// Check each joint; returns, for each body, the joint it hangs from.
    fn check_joints(&self) -> Result<Vec<Option<usize>>, FieldError> {
        let n = self.bodies.len();
        let mut parent_joint: Vec<Option<usize>> = vec![None; n];
        for (i, j) in self.joints.iter().enumerate() {
            let field = |f: &str| format!("joints[{i}].{f}");
            if j.parent >= n || j.child >= n || j.child == 0 {
                return Err(FieldError::new(
                    field("parent"),
                    "joins a body that does not exist",
                ));
            }
            if parent_joint[j.child].replace(i).is_some() {
                let body = &self.bodies[j.child].name;
                return Err(FieldError::new(
                    field("child"),
                    format!("body `{body}` already hangs from another joint"),
                ));
            }
            if let Some([lo, hi]) = j.limits
                && !(lo.is_finite() && hi.is_finite() && lo <= hi)
            {
                return Err(FieldError::new(
                    field("limits"),
                    format!("need lower ≤ upper, got [{lo}, {hi}]"),
                ));
            }
            let translations = j.origin.translation.vector.iter();
            let mut numbers = translations
                .chain(j.post.translation.vector.iter())
                .chain(j.axis.iter())
                .chain(std::iter::once(&j.offset));
            if numbers.any(|v| !v.is_finite()) {
                return Err(FieldError::new(field("origin"), "must be finite numbers"));
            }
        }
        Ok(parent_joint)
    }

    /// Ignored pairs and shapes must name bodies that exist.
    fn check_extras(&self) -> Result<(), FieldError> {
        let n = self.bodies.len();
        for (i, &(a, b)) in self.ignored.iter().enumerate() {
            if a >= n || b >= n {
                return Err(FieldError::new(
                    format!("ignore[{i}]"),
                    "names a body that does not exist",
                ));
            }
        }
        for (i, s) in self.shapes.iter().enumerate() {
            s.check(&format!("shapes[{i}]"), n)?;
        }
        Ok(())
    }

    /// For each body, the joints from the world down to it. Follows parents
    /// upwards; a chain longer than the joint count means a loop.
    fn chains(&self, parent_joint: &[Option<usize>]) -> Result<Vec<Vec<usize>>, FieldError> {
        let mut chains = vec![Vec::new(); self.bodies.len()];
        for (b, chain) in chains.iter_mut().enumerate().skip(1) {
            let mut at = b;
            while at != 0 {
                let Some(j) = parent_joint[at] else {
                    return Err(FieldError::new(
                        format!("bodies[{b}]"),
                        format!("`{}` is not connected to the world", self.bodies[b].name),
                    ));
                };
                if chain.len() > self.joints.len() {
                    return Err(FieldError::new(
                        format!("bodies[{b}]"),
                        "the joints form a loop",
                    ));
                }
                chain.push(j);
                at = self.joints[j].parent;
            }
            chain.reverse();
        }
        Ok(chains)
    }

    /// Order joints so parents come first (by depth, or as given where a
    /// file's order is kept), and renumber the chains.
    fn depth_order(&self, mut chains: Vec<Vec<usize>>) -> (Vec<Joint>, Vec<Vec<usize>>) {
        let order = if self.keep_order {
            self.given_order()
        } else {
            let depth = |&j: &usize| [chains[self.joints[j].child].len() as f64, 0.0];
            kinolab_common::order::sorted_by((0..self.joints.len()).collect(), depth)
        };
        let mut new_index = vec![0; self.joints.len()];
        for (new, &old) in order.iter().enumerate() {
            new_index[old] = new;
        }
        let joints = order.iter().map(|&j| self.joints[j].clone()).collect();
        for j in chains.iter_mut().flatten() {
            *j = new_index[*j];
        }
        (joints, chains)
    }
}

impl ModelBuilder {
    /// The joints as given, except that a joint listed before its parent
    /// joint waits for it: each step takes the first joint whose parent
    /// body is placed (the tree is checked, so every joint is taken).
    fn given_order(&self) -> Vec<usize> {
        let n = self.joints.len();
        let mut placed = vec![false; self.bodies.len()];
        placed[0] = true;
        let mut taken = vec![false; n];
        let mut order = Vec::with_capacity(n);
        while order.len() < n {
            let Some(j) = (0..n).find(|&j| !taken[j] && placed[self.joints[j].parent]) else {
                break;
            };
            taken[j] = true;
            placed[self.joints[j].child] = true;
            order.push(j);
        }
        // Never short: a joint left over (impossible in a checked tree)
        // keeps its place at the end.
        order.extend((0..n).filter(|&j| !taken[j]));
        order
    }
}

impl Model {
    pub fn name(&self) -> &str {
        &self.name
    }

    pub fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    pub fn joints(&self) -> &[Joint] {
        &self.joints
    }

    pub fn frames(&self) -> &[Frame] {
        &self.frames
    }

    /// The body at the end of the longest chain from the world (the first
    /// such body when chains tie): a robot's hand or foot when its file
    /// names no tool.
    pub fn tip(&self) -> &str {
        self.bodies
            .iter()
            .enumerate()
            .max_by_key(|&(b, _)| (self.chains[b].len(), std::cmp::Reverse(b)))
            .map_or(WORLD, |(_, body)| body.name.as_str())
    }

    /// The link a learner would grab to move the robot: of the links that
    /// the most independent revolute joints turn, the one nearest the
    /// root. A gripper's prismatic fingers, a mimic finger or a flange
    /// bolted on beyond it does not count, so a humanoid's hand is its
    /// wrist, not a fingertip. The world when nothing turns.
    pub fn hand(&self) -> &str {
        let turning = |b: usize| {
            let chain = &self.chains[b];
            let count = chain
                .iter()
                .filter(|&&j| {
                    self.joints[j].kind == JointKind::Revolute
                        && self.variable_of[j].is_some_and(|v| self.is_driven(v))
                })
                .count();
            (count, std::cmp::Reverse(chain.len()), std::cmp::Reverse(b))
        };
        (0..self.bodies.len())
            .max_by_key(|&b| turning(b))
            .filter(|&b| turning(b).0 > 0)
            .map_or(WORLD, |b| self.bodies[b].name.as_str())
    }

    /// Number of joint variables (the state's length).
    pub fn dof(&self) -> usize {
        self.variables.len()
    }

    /// The joint behind state variable `i`.
    pub fn variable_joint(&self, i: usize) -> Option<&Joint> {
        self.variables.get(i).map(|&j| &self.joints[j])
    }

    /// A frame by name: a body's own frame, or a named frame.
    pub fn frame(&self, name: &str) -> Result<FrameRef, FieldError> {
        if let Some(b) = self.bodies.iter().position(|b| b.name == name) {
            return Ok(FrameRef {
                body: b,
                offset: Pose::identity(),
            });
        }
        if let Some(f) = self.frames.iter().find(|f| f.name == name) {
            return Ok(FrameRef {
                body: f.body,
                offset: f.offset,
            });
        }
        let mut known: Vec<&str> = self.bodies.iter().map(|b| b.name.as_str()).collect();
        known.extend(self.frames.iter().map(|f| f.name.as_str()));
        Err(FieldError::new(
            "frame",
            format!("no frame named `{name}` (known: {})", known.join(", ")),
        ))
    }

    /// The joints whose values in state `q` lie outside their limits, in
    /// joint order. Kinematics and dynamics compute such states all the
    /// same; IK and the lab's sliders keep inside.
    pub fn outside_limits(&self, q: &[f64]) -> Vec<OutsideLimit> {
        self.joints
            .iter()
            .enumerate()
            .filter_map(|(j, joint)| {
                let value = *q.get(self.variable_of[j]?)?;
                let [lo, hi] = joint.limits?;
                let inside = (lo - LIMIT_SLACK..=hi + LIMIT_SLACK).contains(&value);
                (!inside).then(|| OutsideLimit {
                    joint: joint.name.clone(),
                    value,
                    limits: [lo, hi],
                })
            })
            .collect()
    }

    /// All zeros with couplings applied: the state `--set` starts from.
    pub fn zeros(&self) -> Vec<f64> {
        let mut q = vec![0.0; self.dof()];
        self.apply_couplings(&mut q);
        q
    }

    /// Joint values inside every limit, all zero where zero is allowed,
    /// with couplings applied.
    pub fn zero_state(&self) -> Vec<f64> {
        let mut q: Vec<f64> = self
            .variables
            .iter()
            .map(|&j| match self.joints[j].limits {
                Some([lo, hi]) => 0.0f64.clamp(lo, hi),
                None => 0.0,
            })
            .collect();
        self.apply_couplings(&mut q);
        q
    }

    /// The index of the state variable behind the joint called `name`.
    pub fn variable(&self, name: &str) -> Option<usize> {
        let j = self.joints.iter().position(|j| j.name == name)?;
        self.variable_of[j]
    }

    /// Check a state's length and numbers.
    pub fn check_state(&self, q: &[f64]) -> Result<(), FieldError> {
        if q.len() != self.dof() {
            return Err(FieldError::new(
                "q",
                format!(
                    "`{}` has {} joint variables, got {} values",
                    self.name,
                    self.dof(),
                    q.len()
                ),
            ));
        }
        crate::error::all_finite("q", q)
    }

    /// Clamp each value into its joint's limits.
    pub fn clamp(&self, q: &mut [f64]) {
        for (v, &j) in q.iter_mut().zip(&self.variables) {
            if let Some([lo, hi]) = self.joints[j].limits {
                *v = v.clamp(lo, hi);
            }
        }
    }
}

/// A frame resolved to a body and a fixed offset on it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameRef {
    pub body: usize,
    pub offset: Pose,
}
