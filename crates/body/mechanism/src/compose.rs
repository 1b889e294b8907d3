//! Building bigger mechanisms from smaller ones, and tying joints together.
//!
//! - **Mounting**: a finished [`Model`] (one leg, one arm) is copied onto a
//!   body of another model at a mount point, its names prefixed, as often as
//!   needed: six mounts of one leg make a hexapod. Each mount becomes a
//!   [`Group`] in the mechanism hierarchy.
//! - **Coupling**: `q_follower = ratio · q_leader + offset`. The follower is
//!   not free: the state still holds its value, but only through the leader
//!   (the rocker-bogie's differential, a screw's turn-to-travel).
//! - **Loop closure**: a closed chain (a four-bar linkage) is modelled as an
//!   open tree plus a constraint that two frames coincide; the passive
//!   joints move to satisfy it while the driven ones stay put.

use nalgebra::Vector3;

use crate::error::FieldError;
use crate::ik::{Goal, Options, Target};
use crate::model::{FrameRef, Model, ModelBuilder, Pose};

/// `q[follower] = ratio · q[leader] + offset`, as state-variable indices.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coupling {
    pub follower: usize,
    pub leader: usize,
    pub ratio: f64,
    pub offset: f64,
}

/// Two frames that must coincide, closing a chain: in position only, or in
/// position and orientation.
#[derive(Debug, Clone, PartialEq)]
pub struct LoopClosure {
    pub name: String,
    pub a: FrameRef,
    pub b: FrameRef,
    pub whole_pose: bool,
    /// The variables that move to close the loop.
    pub passive: Vec<usize>,
}

/// A sub-mechanism: a name, its parent group and the bodies it owns.
#[derive(Debug, Clone, PartialEq)]
pub struct Group {
    pub name: String,
    pub parent: Option<usize>,
    pub bodies: Vec<usize>,
}

/// A coupling named by joints, resolved when the model is built.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PendingCoupling {
    pub follower: String,
    pub leader: String,
    pub ratio: f64,
    pub offset: f64,
}

/// A loop named by frames and joints, resolved when the model is built.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PendingLoop {
    pub name: String,
    pub a: String,
    pub b: String,
    pub whole_pose: bool,
    pub passive: Vec<String>,
}

impl ModelBuilder {
    /// Make joint `follower` move as `ratio · leader + offset`.
    pub fn couple(&mut self, follower: &str, leader: &str, ratio: f64, offset: f64) {
        self.couplings.push(PendingCoupling {
            follower: follower.into(),
            leader: leader.into(),
            ratio,
            offset,
        });
    }

    /// Close a chain: frames `a` and `b` must coincide (in position, or in
    /// the whole pose), which the joints named in `passive` ensure.
    pub fn close_loop(&mut self, name: &str, a: &str, b: &str, whole_pose: bool, passive: &[&str]) {
        self.loops.push(PendingLoop {
            name: name.into(),
            a: a.into(),
            b: b.into(),
            whole_pose,
            passive: passive.iter().map(|s| s.to_string()).collect(),
        });
    }

    /// A capsule from `a` to `b` (in `body`'s frame) of `radius`, as a
    /// bounding shape of `body`.
    pub fn shape(&mut self, body: usize, a: [f64; 3], b: [f64; 3], radius: f64) {
        self.shapes.push(crate::shapes::Shape {
            body,
            a: Vector3::from(a),
            b: Vector3::from(b),
            radius,
        });
    }

    /// Never test bodies `a` and `b` against each other.
    pub fn ignore_pair(&mut self, a: usize, b: usize) {
        self.ignored.push((a.min(b), a.max(b)));
    }

    /// Declare a sub-mechanism owning `bodies`; returns its index.
    pub fn group(&mut self, name: &str, parent: Option<usize>, bodies: Vec<usize>) -> usize {
        self.groups.push(Group {
            name: name.into(),
            parent,
            bodies,
        });
        self.groups.len() - 1
    }

    /// Copy `sub` onto body `on` at the mount pose `at`, prefixing every
    /// name with `prefix/`. The sub-model's world becomes the mount point.
    /// Returns the new group holding the mounted bodies.
    pub fn mount(
        &mut self,
        sub: &Model,
        on: usize,
        at: Pose,
        prefix: &str,
        parent: Option<usize>,
    ) -> usize {
        let name = |s: &str| format!("{prefix}/{s}");
        let mut map = vec![on; sub.bodies.len()];
        for (i, b) in sub.bodies.iter().enumerate().skip(1) {
            map[i] = self.body(name(&b.name));
            self.bodies[map[i]].inertial = b.inertial;
        }
        let base_of = |body: usize, pose: Pose| if body == 0 { at * pose } else { pose };
        for j in &sub.joints {
            let mut joint = j.clone();
            joint.name = name(&j.name);
            joint.origin = base_of(j.parent, j.origin);
            joint.parent = map[j.parent];
            joint.child = map[j.child];
            self.joints.push(joint);
        }
        for f in &sub.frames {
            let offset = base_of(f.body, f.offset);
            self.frame(name(&f.name), map[f.body], offset);
        }
        let joint_name = |v: usize| name(&sub.joints[sub.variables[v]].name);
        for c in &sub.couplings {
            self.couple(
                &joint_name(c.follower),
                &joint_name(c.leader),
                c.ratio,
                c.offset,
            );
        }
        for l in &sub.loops {
            let frame_name = |f: &FrameRef| -> String {
                let found = sub
                    .frames
                    .iter()
                    .find(|fr| fr.body == f.body && fr.offset == f.offset)
                    .map(|fr| fr.name.clone())
                    .unwrap_or_else(|| sub.bodies[f.body].name.clone());
                name(&found)
            };
            self.loops.push(PendingLoop {
                name: name(&l.name),
                a: frame_name(&l.a),
                b: frame_name(&l.b),
                whole_pose: l.whole_pose,
                passive: l.passive.iter().map(|&v| joint_name(v)).collect(),
            });
        }
        for s in &sub.shapes {
            let mut shape = *s;
            shape.body = map[s.body];
            if s.body == 0 {
                shape.a = (at * nalgebra::Point3::from(s.a)).coords;
                shape.b = (at * nalgebra::Point3::from(s.b)).coords;
            }
            self.shapes.push(shape);
        }
        for &(a, b) in &sub.ignored {
            self.ignore_pair(map[a], map[b]);
        }
        let mine: Vec<usize> = (1..sub.bodies.len()).map(|i| map[i]).collect();
        let group = self.group(prefix, parent, mine);
        let first = self.groups.len();
        for g in &sub.groups {
            let parent = Some(g.parent.map_or(group, |p| first + p));
            self.groups.push(Group {
                name: name(&g.name),
                parent,
                bodies: g.bodies.iter().map(|&b| map[b]).collect(),
            });
        }
        group
    }
}

fn joint_variable(model: &Model, field: &str, name: &str) -> Result<usize, FieldError> {
    match model.joints.iter().position(|j| j.name == name) {
        None => Err(FieldError::new(field, format!("no joint named `{name}`"))),
        Some(j) => model.variable_of[j]
            .ok_or_else(|| FieldError::new(field, format!("joint `{name}` is fixed"))),
    }
}

pub(crate) fn resolve_couplings(
    model: &Model,
    pending: &[PendingCoupling],
) -> Result<Vec<Coupling>, FieldError> {
    let mut out: Vec<Coupling> = Vec::new();
    for (i, c) in pending.iter().enumerate() {
        let field = |f: &str| format!("couplings[{i}].{f}");
        let follower = joint_variable(model, &field("follower"), &c.follower)?;
        let leader = joint_variable(model, &field("leader"), &c.leader)?;
        crate::error::finite(field("ratio"), c.ratio)?;
        crate::error::finite(field("offset"), c.offset)?;
        if follower == leader {
            return Err(FieldError::new(
                field("leader"),
                "a joint cannot follow itself",
            ));
        }
        if out.iter().any(|o| o.follower == follower) {
            return Err(FieldError::new(
                field("follower"),
                format!("`{}` already follows another joint", c.follower),
            ));
        }
        out.push(Coupling {
            follower,
            leader,
            ratio: c.ratio,
            offset: c.offset,
        });
    }
    for (i, c) in out.iter().enumerate() {
        if out.iter().any(|o| o.follower == c.leader) {
            return Err(FieldError::new(
                format!("couplings[{i}].leader"),
                "the leader follows another joint itself; couple both to the first",
            ));
        }
    }
    Ok(out)
}

pub(crate) fn resolve_loops(
    model: &Model,
    pending: &[PendingLoop],
) -> Result<Vec<LoopClosure>, FieldError> {
    let mut out = Vec::new();
    for (i, l) in pending.iter().enumerate() {
        let field = |f: &str| format!("loops[{i}].{f}");
        let frame = |f: &str, name: &str| {
            model
                .frame(name)
                .map_err(|e| FieldError::new(field(f), e.message))
        };
        let passive = l
            .passive
            .iter()
            .enumerate()
            .map(|(k, p)| {
                let v = joint_variable(model, &field(&format!("passive[{k}]")), p)?;
                if model.couplings.iter().any(|c| c.follower == v) {
                    return Err(FieldError::new(
                        field(&format!("passive[{k}]")),
                        format!("`{p}` follows a coupling and cannot also close a loop"),
                    ));
                }
                Ok(v)
            })
            .collect::<Result<Vec<_>, _>>()?;
        if passive.is_empty() {
            return Err(FieldError::new(
                field("passive"),
                "name the joints that close the loop",
            ));
        }
        out.push(LoopClosure {
            name: l.name.clone(),
            a: frame("a", &l.a)?,
            b: frame("b", &l.b)?,
            whole_pose: l.whole_pose,
            passive,
        });
    }
    Ok(out)
}

/// How far a state is from closing every loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Closure {
    pub closed: bool,
    /// Largest gap between the frames that should meet, m.
    pub gap: f64,
    /// Largest orientation mismatch, rad (0 for position-only loops).
    pub twist: f64,
}

impl Model {
    pub fn couplings(&self) -> &[Coupling] {
        &self.couplings
    }

    pub fn loops(&self) -> &[LoopClosure] {
        &self.loops
    }

    pub fn groups(&self) -> &[Group] {
        &self.groups
    }

    /// Set every follower from its leader.
    pub fn apply_couplings(&self, q: &mut [f64]) {
        for c in &self.couplings {
            if let (Some(&l), true) = (q.get(c.leader), c.follower < q.len()) {
                q[c.follower] = c.ratio * l + c.offset;
            }
        }
    }

    /// Whether variable `v` is the learner's to set: neither a follower
    /// nor a passive joint of a loop.
    pub fn is_driven(&self, v: usize) -> bool {
        !self.couplings.iter().any(|c| c.follower == v)
            && !self.loops.iter().any(|l| l.passive.contains(&v))
    }

    /// Whether variable `v` follows a coupling.
    pub fn is_follower(&self, v: usize) -> bool {
        self.couplings.iter().any(|c| c.follower == v)
    }

    /// Fold the followers' Jacobian columns into their leaders' (the chain
    /// rule for `q_f = ratio · q_l + offset`) and zero the followers'.
    pub(crate) fn fold_couplings(&self, jac: &mut nalgebra::DMatrix<f64>) {
        for c in &self.couplings {
            let follower = jac.column(c.follower).clone_owned();
            let mut leader = jac.column_mut(c.leader);
            leader.axpy(c.ratio, &follower, 1.0);
            jac.column_mut(c.follower).fill(0.0);
        }
    }

    /// The goals that keep every loop closed.
    pub(crate) fn loop_goals(&self) -> Vec<Goal> {
        self.loops
            .iter()
            .map(|l| Goal {
                frame: l.a,
                target: if l.whole_pose {
                    Target::Pose(Pose::identity())
                } else {
                    Target::Position(Vector3::zeros())
                },
                relative_to: Some(l.b),
            })
            .collect()
    }

    /// How well `q` closes every loop (within 1e-9 m and rad counts as closed).
    pub fn closure(&self, q: &[f64]) -> Result<Closure, FieldError> {
        self.check_state(q)?;
        let (mut gap, mut twist): (f64, f64) = (0.0, 0.0);
        for l in &self.loops {
            let rel = self.pose_unchecked(q, &l.b).inverse() * self.pose_unchecked(q, &l.a);
            gap = gap.max(rel.translation.vector.norm());
            if l.whole_pose {
                twist = twist.max(rel.rotation.angle());
            }
        }
        Ok(Closure {
            closed: gap <= 1e-9 && twist <= 1e-9,
            gap,
            twist,
        })
    }

    /// The zero state (clamped into the limits) with couplings applied and
    /// loops closed: where the lab, the command line and the JS API start.
    pub fn home_state(&self) -> Result<Vec<f64>, FieldError> {
        let mut q = self.zero_state();
        self.close_loops(&mut q)?;
        Ok(q)
    }

    /// Move the passive joints so every loop closes, keeping the driven
    /// ones; couplings are applied first. Returns how well it worked: a
    /// linkage that cannot close at these driven values (a four-bar crank
    /// past its dead point) keeps the nearest configuration found.
    pub fn close_loops(&self, q: &mut [f64]) -> Result<Closure, FieldError> {
        self.check_state(q)?;
        self.apply_couplings(q);
        if self.loops.is_empty() {
            return self.closure(q);
        }
        let movable: Vec<bool> = (0..self.dof())
            .map(|v| self.loops.iter().any(|l| l.passive.contains(&v)))
            .collect();
        let options = Options {
            max_iterations: 60,
            restarts: 8,
            position_tolerance: 1e-10,
            rotation_tolerance: 1e-10,
        };
        let solution = self.solve_masked(&[], q, &options, &movable)?;
        q.copy_from_slice(&solution.q);
        self.closure(q)
    }
}
