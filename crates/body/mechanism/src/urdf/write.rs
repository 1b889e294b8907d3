//! From a [`Model`] to URDF text that reads back to the same frames.
//!
//! URDF has one transform per joint, placed before the motion; the model
//! also allows a joint offset and a transform after the motion (a DH row).
//! So each joint is written with
//!
//! - origin = the model's origin turned by the offset (a motion about the
//!   joint's own axis commutes with the motion itself);
//! - a post transform, when there is one, as a fixed joint `NAME-post` from
//!   a link `NAME-moving` to the joint's child.
//!
//! Named frames become links on fixed joints, couplings become `mimic`,
//! bounding capsules become a cylinder with a sphere at each end. A closed
//! loop has no URDF form: the tree is written and the loop is left open,
//! with a notice.

use std::collections::BTreeSet;
use std::fmt::Write;

use nalgebra::Vector3;

use crate::error::MAGNITUDE_LIMIT;
use crate::model::{Joint, JointKind, Model, Pose, rpy};
use crate::shapes::Shape;

/// A model written as URDF, and what URDF could not say.
#[derive(Debug, Clone, PartialEq)]
pub struct Written {
    pub text: String,
    /// One line for each thing left out or written differently.
    pub notices: Vec<String>,
    /// Each named frame's link (the frame's name unless a body has it).
    pub frame_links: Vec<(String, String)>,
}

/// Write `model` as URDF.
pub fn write(model: &Model) -> Written {
    let mut out = Out::new(model);
    for (b, body) in model.bodies().iter().enumerate() {
        out.link_of(body, model.shapes().iter().filter(|s| s.body == b));
    }
    for joint in model.joints() {
        out.joint(joint);
    }
    for frame in model.frames() {
        let link = out.fresh(LINK, &frame.name, "frame");
        out.link(&link, std::iter::empty());
        let parent = model.bodies()[frame.body].name.clone();
        let joint = out.fresh(JOINT, &link, "fixed");
        out.fixed(&joint, &parent, &link, &frame.offset);
        out.frame_links.push((frame.name.clone(), link));
    }
    for closure in model.loops() {
        out.notices.push(format!(
            "loop `{}` is left open: URDF describes trees only, so nothing holds `{}` to `{}`",
            closure.name,
            model.bodies()[closure.a.body].name,
            model.bodies()[closure.b.body].name
        ));
    }
    let mut text = String::from("<?xml version=\"1.0\"?>\n");
    let _ = writeln!(
        text,
        "<!-- Written by Kinolab from the mechanism model \"{}\". -->",
        comment(model.name())
    );
    for notice in &out.notices {
        let _ = writeln!(text, "<!-- {} -->", comment(notice));
    }
    let _ = writeln!(text, "<robot name=\"{}\">", attr(model.name()));
    text.push_str(&out.text);
    text.push_str("</robot>\n");
    Written {
        text,
        notices: out.notices,
        frame_links: out.frame_links,
    }
}

const LINK: usize = 0;
const JOINT: usize = 1;

/// The text being written and the link names taken so far.
struct Out<'m> {
    model: &'m Model,
    text: String,
    /// Link names, then joint names, taken so far.
    taken: [BTreeSet<String>; 2],
    notices: Vec<String>,
    frame_links: Vec<(String, String)>,
}

impl<'m> Out<'m> {
    fn new(model: &'m Model) -> Self {
        Self {
            model,
            text: String::new(),
            taken: [
                model.bodies().iter().map(|b| b.name.clone()).collect(),
                model.joints().iter().map(|j| j.name.clone()).collect(),
            ],
            notices: Vec::new(),
            frame_links: Vec::new(),
        }
    }

    /// `name`, or `name-role`, `name-role-2`, … if a link (`kind` 0) or a
    /// joint (`kind` 1) already has it.
    fn fresh(&mut self, kind: usize, name: &str, role: &str) -> String {
        let taken = &mut self.taken[kind];
        let mut candidate = name.to_owned();
        let mut n = 1;
        while taken.contains(&candidate) {
            candidate = match n {
                1 => format!("{name}-{role}"),
                _ => format!("{name}-{role}-{n}"),
            };
            n += 1;
        }
        taken.insert(candidate.clone());
        candidate
    }

    fn link<'s>(&mut self, name: &str, shapes: impl Iterator<Item = &'s Shape>) {
        self.link_with(name, None, shapes);
    }

    /// A body's link: its capsules, and its mass when it has one.
    fn link_of<'s>(&mut self, body: &crate::Body, shapes: impl Iterator<Item = &'s Shape>) {
        self.link_with(&body.name, body.inertial.as_ref(), shapes);
    }

    fn link_with<'s>(
        &mut self,
        name: &str,
        inertial: Option<&crate::Inertial>,
        shapes: impl Iterator<Item = &'s Shape>,
    ) {
        let mut solids = String::new();
        if let Some(i) = inertial {
            // The tensor in the link's axes: the inertial origin turns none.
            let [ixx, ixy, ixz, iyy, iyz, izz] = i.entries();
            let _ = write!(
                solids,
                "    <inertial>\n      <origin xyz=\"{}\" rpy=\"0 0 0\"/>\n      <mass value=\"{}\"/>\n      <inertia ixx=\"{ixx}\" ixy=\"{ixy}\" ixz=\"{ixz}\" iyy=\"{iyy}\" iyz=\"{iyz}\" izz=\"{izz}\"/>\n    </inertial>\n",
                triple(&i.com),
                i.mass
            );
        }
        for shape in shapes {
            capsule(&mut solids, shape);
        }
        if solids.is_empty() {
            let _ = writeln!(self.text, "  <link name=\"{}\"/>", attr(name));
        } else {
            let _ = writeln!(self.text, "  <link name=\"{}\">", attr(name));
            self.text.push_str(&solids);
            self.text.push_str("  </link>\n");
        }
    }

    fn joint(&mut self, j: &Joint) {
        let bodies = self.model.bodies();
        let parent = bodies[j.parent].name.clone();
        let child = bodies[j.child].name.clone();
        let origin = j.origin * j.motion(0.0);
        let moving = if j.post == Pose::identity() {
            child.clone()
        } else {
            let moving = self.fresh(LINK, &format!("{}-moving", j.name), "link");
            self.link(&moving, std::iter::empty());
            moving
        };
        let (kind, limits) = self.kind_and_limits(j);
        let _ = writeln!(
            self.text,
            "  <joint name=\"{}\" type=\"{kind}\">",
            attr(&j.name)
        );
        self.ends(&parent, &moving, &origin);
        if j.kind.moves() {
            let _ = writeln!(self.text, "    <axis xyz=\"{}\"/>", triple(&j.axis));
        }
        if let Some([lo, hi]) = limits {
            let _ = writeln!(
                self.text,
                "    <limit lower=\"{lo}\" upper=\"{hi}\" effort=\"0\" velocity=\"0\"/>"
            );
        }
        self.mimic(j);
        self.text.push_str("  </joint>\n");
        if moving != child {
            let name = self.fresh(JOINT, &format!("{}-post", j.name), "joint");
            self.fixed(&name, &moving, &child, &j.post);
        }
    }

    /// The URDF joint type, and the limits it needs: a revolute joint
    /// without limits is `continuous`; a prismatic one gets the widest
    /// limits a reader takes, with a notice.
    fn kind_and_limits(&mut self, j: &Joint) -> (&'static str, Option<[f64; 2]>) {
        match (j.kind, j.limits) {
            (JointKind::Fixed, _) => ("fixed", None),
            (JointKind::Continuous, _) | (JointKind::Revolute, None) => ("continuous", None),
            (JointKind::Revolute, limits) => ("revolute", limits),
            (JointKind::Prismatic, Some(limits)) => ("prismatic", Some(limits)),
            (JointKind::Prismatic, None) => {
                self.notices.push(format!(
                    "prismatic joint `{}` has no limits; URDF needs them, so it gets ±{MAGNITUDE_LIMIT} m",
                    j.name
                ));
                ("prismatic", Some([-MAGNITUDE_LIMIT, MAGNITUDE_LIMIT]))
            }
        }
    }

    fn mimic(&mut self, j: &Joint) {
        let model = self.model;
        let Some(c) = model
            .couplings()
            .iter()
            .find(|c| model.variable_joint(c.follower).map(|f| &f.name) == Some(&j.name))
        else {
            return;
        };
        if let Some(leader) = model.variable_joint(c.leader) {
            let _ = writeln!(
                self.text,
                "    <mimic joint=\"{}\" multiplier=\"{}\" offset=\"{}\"/>",
                attr(&leader.name),
                c.ratio,
                c.offset
            );
        }
    }

    fn fixed(&mut self, name: &str, parent: &str, child: &str, origin: &Pose) {
        let _ = writeln!(
            self.text,
            "  <joint name=\"{}\" type=\"fixed\">",
            attr(name)
        );
        self.ends(parent, child, origin);
        self.text.push_str("  </joint>\n");
    }

    fn ends(&mut self, parent: &str, child: &str, origin: &Pose) {
        let _ = writeln!(self.text, "    <parent link=\"{}\"/>", attr(parent));
        let _ = writeln!(self.text, "    <child link=\"{}\"/>", attr(child));
        let _ = writeln!(self.text, "    {}", origin_element(origin));
    }
}

/// A capsule as URDF solids every reader knows: a cylinder between the end
/// points and a sphere on each (one sphere when the ends meet).
fn capsule(out: &mut String, s: &Shape) {
    let mid = (s.a + s.b) / 2.0;
    let along = s.b - s.a;
    let length = along.norm();
    let mut solid = |origin: Pose, geometry: String| {
        let _ = writeln!(
            out,
            "    <collision>\n      {}\n      <geometry>{geometry}</geometry>\n    </collision>",
            origin_element(&origin)
        );
    };
    let at = |p: Vector3<f64>| Pose::from_parts(p.into(), nalgebra::UnitQuaternion::identity());
    let sphere = format!("<sphere radius=\"{}\"/>", s.radius);
    if length <= 1e-12 {
        solid(at(mid), sphere);
        return;
    }
    let turn =
        nalgebra::UnitQuaternion::rotation_between(&Vector3::z(), &along).unwrap_or_else(|| {
            nalgebra::UnitQuaternion::from_axis_angle(&Vector3::x_axis(), std::f64::consts::PI)
        });
    solid(
        Pose::from_parts(mid.into(), turn),
        format!("<cylinder radius=\"{}\" length=\"{length}\"/>", s.radius),
    );
    solid(at(s.a), sphere.clone());
    solid(at(s.b), sphere);
}

fn origin_element(pose: &Pose) -> String {
    let [r, p, y] = rpy(&pose.rotation).map(tidy);
    format!(
        "<origin xyz=\"{}\" rpy=\"{r} {p} {y}\"/>",
        triple(&pose.translation.vector)
    )
}

fn triple(v: &Vector3<f64>) -> String {
    format!("{} {} {}", tidy(v.x), tidy(v.y), tidy(v.z))
}

/// `-0` written as `0`.
fn tidy(x: f64) -> f64 {
    if x == 0.0 { 0.0 } else { x }
}

/// Text safe inside a double-quoted attribute.
fn attr(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Text safe inside a comment (no `--`).
fn comment(s: &str) -> String {
    attr(s).replace("--", "- -")
}
