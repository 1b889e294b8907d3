//! From URDF text to plain links and joints, each remembering its line.
//! roxmltree does the XML (no DTD, so no entity tricks; a bounded node
//! count); this file only reads the elements URDF defines.

use nalgebra::{Translation3, UnitQuaternion, Vector3};
use roxmltree::{Document, Node, ParsingOptions};

use crate::error::{FieldError, MAGNITUDE_LIMIT};
use crate::model::{MAX_JOINTS, Pose};

/// The most XML nodes read: every element, attribute-free text and comment
/// of a robot far larger than [`MAX_JOINTS`] joints allows.
const MAX_NODES: u32 = 400_000;

/// A robot as the file lists it.
pub(super) struct Description {
    pub name: String,
    pub links: Vec<LinkSpec>,
    pub joints: Vec<JointSpec>,
}

/// Where an element is, for messages: `<joint name="elbow"> (line 42)`.
#[derive(Debug, Clone)]
pub(super) struct Place {
    pub tag: &'static str,
    pub name: String,
    pub line: u32,
}

impl Place {
    pub fn error(&self, message: impl Into<String>) -> FieldError {
        FieldError::new(
            format!("<{} name=\"{}\"> (line {})", self.tag, self.name, self.line),
            message,
        )
    }
}

pub(super) struct LinkSpec {
    pub at: Place,
    pub shapes: Vec<Geometry>,
    pub inertial: Option<crate::Inertial>,
}

/// One collision element: its pose on the link and its shape.
pub(super) struct Geometry {
    pub origin: Pose,
    pub shape: Solid,
}

pub(super) enum Solid {
    Box([f64; 3]),
    /// Cylinders and capsules, along their z axis.
    Rod {
        radius: f64,
        length: f64,
    },
    Sphere(f64),
    Mesh,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    Revolute,
    Continuous,
    Prismatic,
    Fixed,
    /// Floating and planar: read as fixed.
    Free(&'static str),
}

pub(super) struct JointSpec {
    pub at: Place,
    pub kind: Kind,
    pub parent: String,
    pub child: String,
    pub origin: Pose,
    pub axis: Vector3<f64>,
    pub limits: Option<[f64; 2]>,
    /// Leader, multiplier, offset.
    pub mimic: Option<(String, f64, f64)>,
    /// What was read differently from the file, if anything.
    pub notice: Option<String>,
}

/// Parse the text into links and joints.
pub(super) fn parse(text: &str) -> Result<Description, FieldError> {
    let options = ParsingOptions {
        allow_dtd: false,
        nodes_limit: MAX_NODES,
        ..ParsingOptions::default()
    };
    let text = &without_late_declaration(text);
    let doc = Document::parse_with_options(text, options).map_err(|e| {
        let pos = e.pos();
        FieldError::new(format!("line {}", pos.row), format!("not valid XML: {e}"))
    })?;
    let robot = doc.root_element();
    if robot.tag_name().name() != "robot" {
        return Err(FieldError::new(
            format!("<{}> (line 1)", robot.tag_name().name()),
            "a URDF file's outer element is <robot>",
        ));
    }
    let mut out = Description {
        name: robot.attribute("name").unwrap_or("robot").to_owned(),
        links: Vec::new(),
        joints: Vec::new(),
    };
    for node in robot.children().filter(Node::is_element) {
        match node.tag_name().name() {
            "link" => out.links.push(link(&doc, node)?),
            "joint" => out.joints.push(joint(&doc, node)?),
            // Materials, transmissions, gazebo tags: not kinematics.
            _ => {}
        }
        if out.joints.len() > MAX_JOINTS || out.links.len() > MAX_JOINTS + 1 {
            return Err(FieldError::new(
                "robot",
                format!("at most {MAX_JOINTS} joints and one link more are read"),
            ));
        }
    }
    Ok(out)
}

/// `text` with an XML declaration that comes after blank lines blanked
/// out: XML allows it only at the very start, but browsers, ROS and
/// Pinocchio read past the blank lines, and so does the lab. The
/// declaration becomes spaces, so every line keeps its number.
fn without_late_declaration(text: &str) -> std::borrow::Cow<'_, str> {
    let body = text.trim_start();
    let blank = text.len() - body.len();
    match (blank, body.starts_with("<?xml"), body.find("?>")) {
        (1.., true, Some(end)) => {
            let mut out = String::with_capacity(text.len());
            out.push_str(&text[..blank]);
            out.push_str(&" ".repeat(end + 2));
            out.push_str(&body[end + 2..]);
            std::borrow::Cow::Owned(out)
        }
        _ => std::borrow::Cow::Borrowed(text),
    }
}

fn place(doc: &Document<'_>, node: Node<'_, '_>, tag: &'static str) -> Result<Place, FieldError> {
    let line = doc.text_pos_at(node.range().start).row;
    let name = node.attribute("name").unwrap_or_default().to_owned();
    if name.is_empty() {
        return Err(FieldError::new(
            format!("<{tag}> (line {line})"),
            "needs a name",
        ));
    }
    Ok(Place { tag, name, line })
}

fn child<'a, 'i>(node: Node<'a, 'i>, tag: &str) -> Option<Node<'a, 'i>> {
    node.children().find(|c| c.has_tag_name(tag))
}

fn link(doc: &Document<'_>, node: Node<'_, '_>) -> Result<LinkSpec, FieldError> {
    let at = place(doc, node, "link")?;
    let mut shapes = Vec::new();
    for collision in node.children().filter(|c| c.has_tag_name("collision")) {
        let origin = origin(&at, child(collision, "origin"))?;
        let Some(solid) =
            child(collision, "geometry").and_then(|g| g.children().find(Node::is_element))
        else {
            return Err(at.error("a <collision> needs a <geometry> with a shape in it"));
        };
        shapes.push(Geometry {
            origin,
            shape: geometry(&at, solid)?,
        });
    }
    let inertial = match child(node, "inertial") {
        Some(i) => Some(inertial(&at, i)?),
        None => None,
    };
    Ok(LinkSpec {
        at,
        shapes,
        inertial,
    })
}

/// `<inertial>`: the centre of mass and the inertia's axes (`<origin>`),
/// `<mass value>` and `<inertia ixx … izz>` about the centre of mass in
/// those axes; turned into the link's own axes.
fn inertial(at: &Place, node: Node<'_, '_>) -> Result<crate::Inertial, FieldError> {
    let frame = origin(at, child(node, "origin"))?;
    let [mass] = match child(node, "mass") {
        Some(m) => numbers(at, m, "value", None)?,
        None => return Err(at.error("an <inertial> needs a <mass value=\"…\"/>")),
    };
    let entries = match child(node, "inertia") {
        Some(i) => ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]
            .iter()
            .map(|name| numbers::<1>(at, i, name, Some([0.0])).map(|[v]| v))
            .collect::<Result<Vec<f64>, FieldError>>()?,
        None => vec![0.0; 6],
    };
    let mut six = [0.0; 6];
    six.copy_from_slice(&entries);
    let place = format!("<{} name=\"{}\"> (line {})", at.tag, at.name, at.line);
    let local = crate::Inertial::as_written(&place, mass, [0.0; 3], six)?;
    let r = *frame.rotation.to_rotation_matrix().matrix();
    Ok(local.moved(&r, &frame.translation.vector))
}

fn geometry(at: &Place, solid: Node<'_, '_>) -> Result<Solid, FieldError> {
    let size = |name: &str| -> Result<f64, FieldError> {
        let [v] = numbers(at, solid, name, None)?;
        if v < 0.0 {
            return Err(at.error(format!(
                "{} {name} must not be negative",
                solid.tag_name().name()
            )));
        }
        Ok(v)
    };
    Ok(match solid.tag_name().name() {
        "box" => {
            let s: [f64; 3] = numbers(at, solid, "size", None)?;
            if s.iter().any(|v| *v < 0.0) {
                return Err(at.error("box size must not be negative"));
            }
            Solid::Box(s)
        }
        "cylinder" | "capsule" => Solid::Rod {
            radius: size("radius")?,
            length: size("length")?,
        },
        "sphere" => Solid::Sphere(size("radius")?),
        _ => Solid::Mesh,
    })
}

fn joint(doc: &Document<'_>, node: Node<'_, '_>) -> Result<JointSpec, FieldError> {
    let at = place(doc, node, "joint")?;
    let kind = match node.attribute("type").unwrap_or_default() {
        "revolute" => Kind::Revolute,
        "continuous" => Kind::Continuous,
        "prismatic" => Kind::Prismatic,
        "fixed" => Kind::Fixed,
        "floating" => Kind::Free("floating"),
        "planar" => Kind::Free("planar"),
        other => {
            return Err(at.error(format!(
                "type `{other}` is not revolute, continuous, prismatic, fixed, floating or planar"
            )));
        }
    };
    let link_of = |tag: &str| {
        child(node, tag)
            .and_then(|n| n.attribute("link"))
            .map(str::to_owned)
            .ok_or_else(|| at.error(format!("needs <{tag} link=\"…\"/>")))
    };
    let parent = link_of("parent")?;
    let child_link = link_of("child")?;
    let origin = origin(&at, child(node, "origin"))?;
    let axis = match child(node, "axis") {
        Some(axis) => Vector3::from(numbers(&at, axis, "xyz", None)?),
        None => Vector3::x(),
    };
    let moves_along_axis = matches!(kind, Kind::Revolute | Kind::Continuous | Kind::Prismatic);
    if moves_along_axis && axis.norm() < 1e-9 {
        return Err(at.error("the axis has zero length"));
    }
    let limits = match (kind, child(node, "limit")) {
        (Kind::Revolute | Kind::Prismatic, Some(limit)) => {
            // Any finite limit, however large, is read as written.
            let bound = |name: &str| -> Result<f64, FieldError> {
                let Some(text) = limit.attribute(name) else {
                    return Ok(0.0);
                };
                text.trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| {
                        at.error(format!("<limit {name}=\"{text}\"> needs a finite number"))
                    })
            };
            let (lo, hi) = (bound("lower")?, bound("upper")?);
            if lo > hi {
                return Err(at.error(format!("limit lower {lo} is above upper {hi}")));
            }
            // Equal bounds (both 0 when a file gives none) are URDF's
            // default: no position limit.
            (lo != hi).then_some([lo, hi])
        }
        (Kind::Revolute | Kind::Prismatic, None) => {
            return Err(at.error("a revolute or prismatic joint needs a <limit>"));
        }
        _ => None,
    };
    let mimic = match child(node, "mimic") {
        None => None,
        Some(m) => {
            let leader = m
                .attribute("joint")
                .ok_or_else(|| at.error("<mimic> needs joint=\"…\""))?;
            let [k] = numbers(&at, m, "multiplier", Some([1.0]))?;
            let [offset] = numbers(&at, m, "offset", Some([0.0]))?;
            Some((leader.to_owned(), k, offset))
        }
    };
    let notice =
        (matches!(kind, Kind::Revolute | Kind::Prismatic) && limits.is_none()).then(|| {
            format!(
                "joint `{}`: equal lower and upper limits, read as no position limit",
                at.name
            )
        });
    Ok(JointSpec {
        at,
        kind,
        parent,
        child: child_link,
        origin,
        axis,
        limits,
        mimic,
        notice,
    })
}

/// An `<origin xyz rpy>`: shift, then roll about x, pitch about y and yaw
/// about z of the parent frame. Missing: the identity.
fn origin(at: &Place, node: Option<Node<'_, '_>>) -> Result<Pose, FieldError> {
    let Some(node) = node else {
        return Ok(Pose::identity());
    };
    let xyz: [f64; 3] = numbers(at, node, "xyz", Some([0.0; 3]))?;
    let [r, p, y] = numbers(at, node, "rpy", Some([0.0; 3]))?;
    Ok(Pose::from_parts(
        Translation3::from(Vector3::from(xyz)),
        UnitQuaternion::from_euler_angles(r, p, y),
    ))
}

/// `N` finite numbers from the attribute `name` of `node`, separated by
/// spaces; `default` when the attribute is missing (else an error).
fn numbers<const N: usize>(
    at: &Place,
    node: Node<'_, '_>,
    name: &str,
    default: Option<[f64; N]>,
) -> Result<[f64; N], FieldError> {
    let tag = node.tag_name().name();
    let Some(text) = node.attribute(name) else {
        return default.ok_or_else(|| at.error(format!("<{tag}> needs {name}=\"…\"")));
    };
    let bad = || {
        at.error(format!(
            "<{tag} {name}=\"{text}\"> needs {N} finite number(s)"
        ))
    };
    let mut out = [0.0; N];
    let mut words = text.split_whitespace();
    for v in &mut out {
        let value: f64 = words.next().and_then(|w| w.parse().ok()).ok_or_else(bad)?;
        if !value.is_finite() || value.abs() > MAGNITUDE_LIMIT {
            return Err(bad());
        }
        *v = value;
    }
    if words.next().is_some() {
        return Err(bad());
    }
    Ok(out)
}
