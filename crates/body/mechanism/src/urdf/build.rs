//! From the file's links and joints to a checked [`Model`]: one tree, its
//! root the world, names unique, mimic joints as couplings, collision
//! solids as bounding capsules.

use std::collections::HashMap;

use nalgebra::{Point3, Unit, Vector3};

use super::Robot;
use super::read::{Description, Geometry, JointSpec, Kind, Place, Solid};
use crate::error::FieldError;
use crate::model::{Joint, JointKind, ModelBuilder, Pose};

pub(super) fn robot(mut d: Description) -> Result<Robot, FieldError> {
    let mut notices = settle_mimics(&mut d);
    notices.extend(d.joints.iter().filter_map(|j| j.notice.clone()));
    let links = link_index(&d)?;
    let parents = parent_joints(&d, &links)?;
    let root = root(&d, &parents)?;
    let mut builder = ModelBuilder::new(d.name.clone());
    builder.keep_order = true;
    // Body 0 is the world: here, the root link.
    let mut body_of = vec![0; d.links.len()];
    builder.bodies[0].name = d.links[root].at.name.clone();
    for (i, link) in d.links.iter().enumerate() {
        if i != root {
            body_of[i] = builder.body(link.at.name.clone());
        }
        builder.bodies[body_of[i]].inertial = link.inertial;
        if let Some(why) = link.inertial.as_ref().and_then(crate::Inertial::problem) {
            notices.push(format!(
                "link `{}`: the inertia {why}; it is read as written",
                link.at.name
            ));
        }
    }
    for j in &d.joints {
        builder.joints.push(joint(j, &links, &body_of));
        if let Kind::Free(kind) = j.kind {
            notices.push(format!(
                "joint `{}` is {kind}: the lab holds it at its origin",
                j.at.name
            ));
        }
    }
    let mut meshes = 0;
    for (i, link) in d.links.iter().enumerate() {
        for g in &link.shapes {
            match capsule(g) {
                Some((a, b, r)) => builder.shape(body_of[i], a, b, r),
                None => meshes += 1,
            }
        }
    }
    if meshes > 0 {
        notices.push(format!(
            "{meshes} collision mesh(es) or empty solids skipped: the lab bounds links by boxes, cylinders, spheres and capsules"
        ));
    }
    couple(&d, &mut builder)?;
    let mut model = builder.build()?;
    let driven: Vec<usize> = d
        .joints
        .iter()
        .filter(|j| j.mimic.is_none() && !matches!(j.kind, Kind::Fixed | Kind::Free(_)))
        .filter_map(|j| model.variable(&j.at.name))
        .collect();
    model.driven.clone_from(&driven);
    let tip = model.tip().to_owned();
    Ok(Robot {
        model,
        driven,
        tip,
        notices,
    })
}

/// Each link's index by name; a name used twice is an error.
fn link_index(d: &Description) -> Result<HashMap<&str, usize>, FieldError> {
    let mut links = HashMap::new();
    for (i, l) in d.links.iter().enumerate() {
        if let Some(first) = links.insert(l.at.name.as_str(), i) {
            return Err(twice(&l.at, &d.links[first].at));
        }
    }
    let mut joints: HashMap<&str, &Place> = HashMap::new();
    for j in &d.joints {
        if let Some(first) = joints.insert(j.at.name.as_str(), &j.at) {
            return Err(twice(&j.at, first));
        }
    }
    Ok(links)
}

fn twice(at: &Place, first: &Place) -> FieldError {
    at.error(format!(
        "the name is used twice (first on line {})",
        first.line
    ))
}

/// For each link, the joint it hangs from and that joint's parent link.
/// Every joint must join two links of the file, and no link may hang from
/// two joints.
fn parent_joints(
    d: &Description,
    links: &HashMap<&str, usize>,
) -> Result<Vec<Option<(usize, usize)>>, FieldError> {
    let mut parents: Vec<Option<(usize, usize)>> = vec![None; d.links.len()];
    for (i, j) in d.joints.iter().enumerate() {
        let find = |name: &str, role: &str| {
            links.get(name).copied().ok_or_else(|| {
                j.at.error(format!("its {role} link `{name}` is not in the file"))
            })
        };
        let parent = find(&j.parent, "parent")?;
        let child = find(&j.child, "child")?;
        if parent == child {
            return Err(j.at.error(format!("joins link `{}` to itself", j.child)));
        }
        if let Some((other, _)) = parents[child].replace((i, parent)) {
            return Err(j.at.error(format!(
                "link `{}` already hangs from joint `{}` (line {})",
                j.child, d.joints[other].at.name, d.joints[other].at.line
            )));
        }
    }
    Ok(parents)
}

/// The one link no joint hangs from; every other link must reach it.
fn root(d: &Description, parents: &[Option<(usize, usize)>]) -> Result<usize, FieldError> {
    let roots: Vec<usize> = (0..d.links.len())
        .filter(|&l| parents[l].is_none())
        .collect();
    let named = |ls: &[usize]| {
        ls.iter()
            .take(4)
            .map(|&l| format!("`{}` (line {})", d.links[l].at.name, d.links[l].at.line))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let root = match roots.as_slice() {
        [] if d.links.is_empty() => {
            return Err(FieldError::new("robot", "the file has no <link>"));
        }
        [root] => *root,
        [] => {
            return Err(FieldError::new(
                "robot",
                "the joints form a loop: no link is the root",
            ));
        }
        many => {
            return Err(FieldError::new(
                "robot",
                format!(
                    "{} links hang from no joint, so there is no one root: {}",
                    many.len(),
                    named(many)
                ),
            ));
        }
    };
    // A link whose parents never reach the root sits on a loop.
    for start in 0..d.links.len() {
        let mut at = start;
        let mut steps = 0;
        while let Some((j, parent)) = parents[at] {
            steps += 1;
            if steps > d.joints.len() {
                return Err(d.joints[j]
                    .at
                    .error("the joints form a loop through this joint"));
            }
            at = parent;
        }
    }
    Ok(root)
}

fn joint(j: &JointSpec, links: &HashMap<&str, usize>, body_of: &[usize]) -> Joint {
    let body = |name: &str| links.get(name).map_or(0, |&l| body_of[l]);
    let kind = match j.kind {
        Kind::Revolute => JointKind::Revolute,
        Kind::Continuous => JointKind::Continuous,
        Kind::Prismatic => JointKind::Prismatic,
        Kind::Fixed | Kind::Free(_) => JointKind::Fixed,
    };
    let axis = Unit::try_new(j.axis, 1e-12).unwrap_or(Vector3::x_axis());
    Joint {
        name: j.at.name.clone(),
        kind,
        parent: body(&j.parent),
        child: body(&j.child),
        origin: j.origin,
        axis,
        offset: 0.0,
        post: Pose::identity(),
        limits: j.limits,
    }
}

/// Mimic joints as couplings. A mimic of a mimic follows the first leader
/// with the multipliers and offsets composed.
/// Mimics that ROS and Pinocchio read past, skipped with a notice each: a
/// fixed joint's (it has nothing to move), and one naming a joint the file
/// does not have (the joint is read as a joint of its own).
fn settle_mimics(d: &mut Description) -> Vec<String> {
    let names: std::collections::HashSet<String> =
        d.joints.iter().map(|j| j.at.name.clone()).collect();
    let mut notices = Vec::new();
    for j in &mut d.joints {
        let Some((leader, ..)) = &j.mimic else {
            continue;
        };
        let why = if !j.kind_moves() {
            "it does not move"
        } else if !names.contains(leader) {
            "the file has no joint of that name"
        } else {
            continue;
        };
        notices.push(format!(
            "joint `{}` mimics `{leader}`, but {why}: the mimic is skipped",
            j.at.name
        ));
        j.mimic = None;
    }
    notices
}

fn couple(d: &Description, builder: &mut ModelBuilder) -> Result<(), FieldError> {
    let by_name: HashMap<&str, &JointSpec> =
        d.joints.iter().map(|j| (j.at.name.as_str(), j)).collect();
    for j in &d.joints {
        let Some((leader, k, offset)) = &j.mimic else {
            continue;
        };
        if !j.kind_moves() {
            return Err(j.at.error("a fixed joint cannot mimic another"));
        }
        let (mut leader, mut k, mut offset) = (leader.as_str(), *k, *offset);
        for _ in 0..=d.joints.len() {
            let Some(l) = by_name.get(leader) else {
                return Err(j.at.error(format!(
                    "mimics `{leader}`, which is not a joint of the file"
                )));
            };
            if !l.kind_moves() {
                return Err(j
                    .at
                    .error(format!("mimics `{leader}`, which does not move")));
            }
            match &l.mimic {
                None => break,
                Some((next, k2, o2)) => {
                    // q = k·(k2·q_next + o2) + offset
                    offset += k * o2;
                    k *= k2;
                    leader = next;
                }
            }
            if leader == j.at.name {
                return Err(j.at.error("its mimic chain comes back to itself"));
            }
        }
        builder.couple(&j.at.name, leader, k, offset);
    }
    Ok(())
}

impl JointSpec {
    fn kind_moves(&self) -> bool {
        matches!(
            self.kind,
            Kind::Revolute | Kind::Continuous | Kind::Prismatic
        )
    }
}

/// A capsule bounding one collision solid, in the link's frame: its two end
/// points and radius. None for a mesh or a solid of no size.
fn capsule(g: &Geometry) -> Option<([f64; 3], [f64; 3], f64)> {
    let (half, radius) = match g.shape {
        Solid::Mesh => return None,
        Solid::Sphere(r) => (Vector3::zeros(), r),
        Solid::Rod { radius, length } => (Vector3::z() * (length / 2.0), radius),
        Solid::Box(s) => {
            // Along the longest side; the radius reaches the far corners
            // of the cross-section.
            let long = (0..3).max_by(|&a, &b| s[a].total_cmp(&s[b])).unwrap_or(0);
            let [a, b] = [(long + 1) % 3, (long + 2) % 3];
            let mut half = Vector3::zeros();
            half[long] = s[long] / 2.0;
            (half, (s[a].powi(2) + s[b].powi(2)).sqrt() / 2.0)
        }
    };
    if radius <= 0.0 {
        return None;
    }
    let end = |sign: f64| {
        let p = g.origin * Point3::from(half * sign);
        [p.x, p.y, p.z]
    };
    Some((end(-1.0), end(1.0), radius))
}
