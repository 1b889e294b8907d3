//! Bounding shapes and collision, in 2D on parry2d.
//!
//! Every shape is a capsule fixed to a body (a sphere when both ends meet):
//! the shadow of a 3D capsule on a plane is exactly a 2D capsule of the same
//! radius, so a query in the plan view (x–y) or the side view (x–z) tests
//! the shadows. Shapes are arranged coarse to fine as a tree: the whole
//! mechanism, its sub-mechanisms, each body, each capsule. A query walks
//! pairs of nodes and descends only where the coarse boxes overlap, then asks
//! parry2d about the capsules themselves.

use nalgebra::{Point3, Vector3};
use parry2d_f64::bounding_volume::{Aabb, BoundingVolume};
use parry2d_f64::math::{Pose as Pose2, Vector as V2};
use parry2d_f64::query;
use parry2d_f64::shape::{Ball, Capsule, Cuboid, Shape as ParryShape};

use crate::error::{FieldError, finite, finite_at};
use crate::model::Model;

/// A capsule on a body: the segment `a`–`b` (body frame, m) swollen by
/// `radius`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shape {
    pub body: usize,
    pub a: Vector3<f64>,
    pub b: Vector3<f64>,
    pub radius: f64,
}

impl Shape {
    pub(crate) fn check(&self, field: &str, bodies: usize) -> Result<(), FieldError> {
        if self.body >= bodies {
            return Err(FieldError::new(format!("{field}.body"), "no such body"));
        }
        for v in self.a.iter().chain(self.b.iter()) {
            finite_at(*v, || format!("{field}.a"))?;
        }
        if !(self.radius.is_finite() && self.radius > 0.0) {
            return Err(FieldError::new(
                format!("{field}.radius"),
                format!("must be a positive number of metres, got {}", self.radius),
            ));
        }
        Ok(())
    }
}

/// The plane a query works in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Plane {
    /// Seen from above: world x and y.
    Plan,
    /// Seen from the side: world x and z.
    Side,
}

impl Plane {
    pub fn project(self, p: &Vector3<f64>) -> [f64; 2] {
        match self {
            Plane::Plan => [p.x, p.y],
            Plane::Side => [p.x, p.z],
        }
    }
}

/// A fixed obstacle in the query plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Obstacle {
    Circle {
        center: [f64; 2],
        radius: f64,
    },
    /// An axis-aligned box.
    Rect {
        center: [f64; 2],
        half: [f64; 2],
    },
}

impl Obstacle {
    fn check(&self, i: usize) -> Result<(), FieldError> {
        let field = format!("obstacles[{i}]");
        let (numbers, sizes): (Vec<f64>, Vec<f64>) = match self {
            Obstacle::Circle { center, radius } => (center.to_vec(), vec![*radius]),
            Obstacle::Rect { center, half } => (center.to_vec(), half.to_vec()),
        };
        for v in numbers {
            finite(&field, v)?;
        }
        if sizes.iter().any(|s| !(s.is_finite() && *s > 0.0)) {
            return Err(FieldError::new(field, "sizes must be positive"));
        }
        Ok(())
    }

    fn parry(&self) -> (Pose2, Box<dyn ParryShape>) {
        match *self {
            Obstacle::Circle { center, radius } => (
                Pose2::from_translation(V2::new(center[0], center[1])),
                Box::new(Ball::new(radius)),
            ),
            Obstacle::Rect { center, half } => (
                Pose2::from_translation(V2::new(center[0], center[1])),
                Box::new(Cuboid::new(V2::new(half[0], half[1]))),
            ),
        }
    }
}

fn check_all(obstacles: &[Obstacle]) -> Result<(), FieldError> {
    for (i, o) in obstacles.iter().enumerate() {
        o.check(i)?;
    }
    Ok(())
}

/// One side of a colliding pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Part {
    Body(usize),
    Obstacle(usize),
}

/// What a collision query found, and how much work it took.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Collisions {
    /// Colliding pairs, each once, sorted.
    pub pairs: Vec<(Part, Part)>,
    /// Box-against-box tests made on the way down the tree.
    pub coarse_tests: usize,
    /// Capsule tests handed to parry2d.
    pub fine_tests: usize,
}

/// A node of the bounding tree: a box, and either children or one capsule.
struct Node {
    aabb: Aabb,
    children: Vec<usize>,
    leaf: Option<(usize, Capsule)>,
}

/// A capsule in the plane as parry2d sees it (already in world placement).
fn capsule(bodies: &[crate::Pose], s: &Shape, plane: Plane) -> Capsule {
    let at = &bodies[s.body];
    let [ax, ay] = plane.project(&(at * Point3::from(s.a)).coords);
    let [bx, by] = plane.project(&(at * Point3::from(s.b)).coords);
    Capsule::new(V2::new(ax, ay), V2::new(bx, by), s.radius)
}

impl Model {
    pub fn shapes(&self) -> &[Shape] {
        &self.shapes
    }

    /// The body pairs the model lists as never colliding.
    pub fn ignored_pairs(&self) -> &[(usize, usize)] {
        &self.ignored
    }

    /// Body pairs that are never tested: those joined by a joint and those
    /// the model lists as touching by design.
    pub fn ignores(&self, a: usize, b: usize) -> bool {
        let (a, b) = (a.min(b), a.max(b));
        a == b
            || self.ignored.contains(&(a, b))
            || self
                .joints
                .iter()
                .any(|j| (j.parent.min(j.child), j.parent.max(j.child)) == (a, b))
    }

    /// The bounding tree for state `q` in `plane`, and its root (none
    /// without shapes).
    fn bounding_tree(
        &self,
        q: &[f64],
        plane: Plane,
    ) -> Result<(Vec<Node>, Option<usize>), FieldError> {
        let placed = self.place(q)?;
        let mut nodes: Vec<Node> = Vec::new();
        // Leaves under body nodes.
        let mut body_node: Vec<Option<usize>> = vec![None; self.bodies.len()];
        for (i, s) in self.shapes.iter().enumerate() {
            let c = capsule(&placed.bodies, s, plane);
            let aabb = c.compute_aabb(&Pose2::identity());
            nodes.push(Node {
                aabb,
                children: Vec::new(),
                leaf: Some((i, c)),
            });
            let leaf = nodes.len() - 1;
            match body_node[s.body] {
                Some(b) => {
                    let merged = nodes[b].aabb.merged(&aabb);
                    nodes[b].aabb = merged;
                    nodes[b].children.push(leaf);
                }
                None => {
                    nodes.push(Node {
                        aabb,
                        children: vec![leaf],
                        leaf: None,
                    });
                    body_node[s.body] = Some(nodes.len() - 1);
                }
            }
        }
        // Each body under its innermost group; groups under their parents.
        let depth = |g: usize| {
            let mut d = 0;
            let mut at = self.groups[g].parent;
            while let Some(p) = at {
                d += 1;
                at = self.groups.get(p).and_then(|g| g.parent);
                if d > self.groups.len() {
                    break;
                }
            }
            d
        };
        let mut group_node: Vec<Option<usize>> = vec![None; self.groups.len()];
        let mut root_children = Vec::new();
        for (b, node) in body_node.iter().enumerate() {
            let Some(node) = *node else { continue };
            let owner = (0..self.groups.len())
                .filter(|&g| self.groups[g].bodies.contains(&b))
                .max_by_key(|&g| depth(g));
            match owner {
                None => root_children.push(node),
                Some(g) => self.attach(&mut nodes, &mut group_node, &mut root_children, g, node),
            }
        }
        let Some(&first) = root_children.first() else {
            return Ok((nodes, None));
        };
        let mut aabb = nodes[first].aabb;
        for &c in &root_children {
            aabb.merge(&nodes[c].aabb);
        }
        nodes.push(Node {
            aabb,
            children: root_children,
            leaf: None,
        });
        let root = nodes.len() - 1;
        Ok((nodes, Some(root)))
    }

    /// Put `child` under group `g`'s node, creating the group's node (and
    /// its ancestors') on first use; boxes grow on the way up.
    fn attach(
        &self,
        nodes: &mut Vec<Node>,
        group_node: &mut [Option<usize>],
        root_children: &mut Vec<usize>,
        g: usize,
        child: usize,
    ) {
        let aabb = nodes[child].aabb;
        match group_node[g] {
            Some(n) => {
                nodes[n].children.push(child);
                let mut at = Some(g);
                while let Some(gi) = at {
                    if let Some(n) = group_node[gi] {
                        let merged = nodes[n].aabb.merged(&aabb);
                        nodes[n].aabb = merged;
                    }
                    at = self.groups[gi].parent;
                }
            }
            None => {
                nodes.push(Node {
                    aabb,
                    children: vec![child],
                    leaf: None,
                });
                let n = nodes.len() - 1;
                group_node[g] = Some(n);
                match self.groups[g].parent {
                    Some(p) if p < self.groups.len() && p != g => {
                        self.attach(nodes, group_node, root_children, p, n)
                    }
                    _ => root_children.push(n),
                }
            }
        }
    }

    /// Self-collisions and collisions with `obstacles` in `plane`, found by
    /// descending the bounding tree.
    pub fn collisions(
        &self,
        q: &[f64],
        plane: Plane,
        obstacles: &[Obstacle],
    ) -> Result<Collisions, FieldError> {
        let mut visit = Collide::default();
        self.walk_tree(q, plane, obstacles, &mut visit)?;
        Ok(visit.finish())
    }

    /// The same answer as [`Model::collisions`] by testing every capsule
    /// pair: the reference the tree search is checked against.
    pub fn collisions_brute_force(
        &self,
        q: &[f64],
        plane: Plane,
        obstacles: &[Obstacle],
    ) -> Result<Collisions, FieldError> {
        let mut visit = Collide::default();
        self.walk_all(q, plane, obstacles, &mut visit)?;
        Ok(visit.finish())
    }

    /// The smallest gap between any two bodies that may collide, and
    /// between bodies and obstacles (0 when something touches). Walks the
    /// bounding tree like [`Model::collisions`], skipping every pair of
    /// boxes already further apart than the best gap found so far.
    pub fn clearance(
        &self,
        q: &[f64],
        plane: Plane,
        obstacles: &[Obstacle],
    ) -> Result<Option<(f64, Part, Part)>, FieldError> {
        let mut visit = Gap::default();
        self.walk_tree(q, plane, obstacles, &mut visit)?;
        Ok(visit.best)
    }

    /// [`Model::clearance`] over every capsule pair: the reference the
    /// tree walk is checked against.
    pub fn clearance_brute_force(
        &self,
        q: &[f64],
        plane: Plane,
        obstacles: &[Obstacle],
    ) -> Result<Option<(f64, Part, Part)>, FieldError> {
        let mut visit = Gap::default();
        self.walk_all(q, plane, obstacles, &mut visit)?;
        Ok(visit.best)
    }

    /// Hand `visit` the capsule pairs (and capsule–obstacle pairs) whose
    /// boxes it wants opened, from the root of the bounding tree down.
    fn walk_tree(
        &self,
        q: &[f64],
        plane: Plane,
        obstacles: &[Obstacle],
        visit: &mut dyn Visit,
    ) -> Result<(), FieldError> {
        check_all(obstacles)?;
        let (nodes, root) = self.bounding_tree(q, plane)?;
        let Some(root) = root else { return Ok(()) };
        self.walk_within(&nodes, root, visit);
        for (i, o) in obstacles.iter().enumerate() {
            let (pose, shape) = o.parry();
            let thing = Thing {
                index: i,
                aabb: shape.compute_aabb(&pose),
                pose,
                shape,
            };
            self.walk_against(&nodes, root, &thing, visit);
        }
        Ok(())
    }

    /// Every pair under one node: each child's own pairs, then each pair
    /// of children.
    fn walk_within(&self, nodes: &[Node], n: usize, visit: &mut dyn Visit) {
        let children = &nodes[n].children;
        for (i, &a) in children.iter().enumerate() {
            self.walk_within(nodes, a, visit);
            for &b in &children[i + 1..] {
                self.walk_between(nodes, a, b, visit);
            }
        }
    }

    /// The pairs with one capsule under `a` and one under `b`.
    fn walk_between(&self, nodes: &[Node], a: usize, b: usize, visit: &mut dyn Visit) {
        if !visit.open(&nodes[a].aabb, &nodes[b].aabb) {
            return;
        }
        match (&nodes[a].leaf, &nodes[b].leaf) {
            (Some((sa, ca)), Some((sb, cb))) => {
                let (ba, bb) = (self.shapes[*sa].body, self.shapes[*sb].body);
                if !self.ignores(ba, bb) {
                    visit.pair(ba, ca, bb, cb);
                }
            }
            // Split the node that has children (the bigger box first).
            _ => {
                let split_a = nodes[b].leaf.is_some()
                    || (nodes[a].leaf.is_none()
                        && nodes[a].aabb.volume() >= nodes[b].aabb.volume());
                if split_a {
                    for &c in &nodes[a].children {
                        self.walk_between(nodes, c, b, visit);
                    }
                } else {
                    for &c in &nodes[b].children {
                        self.walk_between(nodes, a, c, visit);
                    }
                }
            }
        }
    }

    /// The capsules under node `n` against one obstacle.
    fn walk_against(&self, nodes: &[Node], n: usize, thing: &Thing, visit: &mut dyn Visit) {
        if !visit.open(&nodes[n].aabb, &thing.aabb) {
            return;
        }
        if let Some((s, c)) = &nodes[n].leaf {
            visit.obstacle(self.shapes[*s].body, c, thing);
            return;
        }
        for &c in &nodes[n].children {
            self.walk_against(nodes, c, thing, visit);
        }
    }

    /// Every capsule pair and every capsule–obstacle pair, no tree.
    fn walk_all(
        &self,
        q: &[f64],
        plane: Plane,
        obstacles: &[Obstacle],
        visit: &mut dyn Visit,
    ) -> Result<(), FieldError> {
        check_all(obstacles)?;
        let placed = self.place(q)?;
        let caps: Vec<(usize, Capsule)> = self
            .shapes
            .iter()
            .map(|s| (s.body, capsule(&placed.bodies, s, plane)))
            .collect();
        let things: Vec<Thing> = obstacles
            .iter()
            .enumerate()
            .map(|(index, o)| {
                let (pose, shape) = o.parry();
                Thing {
                    index,
                    aabb: shape.compute_aabb(&pose),
                    pose,
                    shape,
                }
            })
            .collect();
        for (i, (bi, ci)) in caps.iter().enumerate() {
            for (bj, cj) in &caps[i + 1..] {
                if !self.ignores(*bi, *bj) {
                    visit.pair(*bi, ci, *bj, cj);
                }
            }
            for thing in &things {
                visit.obstacle(*bi, ci, thing);
            }
        }
        Ok(())
    }
}

/// An obstacle as parry2d sees it.
struct Thing {
    index: usize,
    pose: Pose2,
    shape: Box<dyn ParryShape>,
    aabb: Aabb,
}

/// What a walk does: whether two boxes are worth opening, and what to do
/// with two capsules (of bodies `ba` and `bb`) or a capsule and an obstacle.
trait Visit {
    fn open(&mut self, a: &Aabb, b: &Aabb) -> bool;
    fn pair(&mut self, ba: usize, ca: &Capsule, bb: usize, cb: &Capsule);
    fn obstacle(&mut self, body: usize, c: &Capsule, thing: &Thing);
}

/// Collision: open overlapping boxes, keep intersecting pairs.
#[derive(Default)]
struct Collide {
    out: Collisions,
}

impl Collide {
    fn finish(mut self) -> Collisions {
        self.out.pairs.sort();
        self.out.pairs.dedup();
        self.out
    }
}

impl Visit for Collide {
    fn open(&mut self, a: &Aabb, b: &Aabb) -> bool {
        self.out.coarse_tests += 1;
        a.intersects(b)
    }

    fn pair(&mut self, ba: usize, ca: &Capsule, bb: usize, cb: &Capsule) {
        self.out.fine_tests += 1;
        let id = Pose2::identity();
        if query::intersection_test(&id, ca, &id, cb).is_ok_and(|r| r.intersecting) {
            self.out
                .pairs
                .push((Part::Body(ba.min(bb)), Part::Body(ba.max(bb))));
        }
    }

    fn obstacle(&mut self, body: usize, c: &Capsule, thing: &Thing) {
        self.out.fine_tests += 1;
        if query::intersection_test(&Pose2::identity(), c, &thing.pose, thing.shape.as_ref())
            .is_ok_and(|r| r.intersecting)
        {
            self.out
                .pairs
                .push((Part::Body(body), Part::Obstacle(thing.index)));
        }
    }
}

/// Clearance: open boxes closer than the best gap so far, keep the
/// smallest gap.
#[derive(Default)]
struct Gap {
    best: Option<(f64, Part, Part)>,
}

impl Gap {
    fn offer(&mut self, d: f64, a: Part, b: Part) {
        if self.best.is_none_or(|(bd, _, _)| d < bd) {
            self.best = Some((d, a, b));
        }
    }
}

impl Visit for Gap {
    fn open(&mut self, a: &Aabb, b: &Aabb) -> bool {
        self.best.is_none_or(|(d, _, _)| box_gap(a, b) < d)
    }

    fn pair(&mut self, ba: usize, ca: &Capsule, bb: usize, cb: &Capsule) {
        let id = Pose2::identity();
        if let Ok(d) = query::distance(&id, ca, &id, cb) {
            self.offer(d.distance, Part::Body(ba.min(bb)), Part::Body(ba.max(bb)));
        }
    }

    fn obstacle(&mut self, body: usize, c: &Capsule, thing: &Thing) {
        if let Ok(d) = query::distance(&Pose2::identity(), c, &thing.pose, thing.shape.as_ref()) {
            self.offer(d.distance, Part::Body(body), Part::Obstacle(thing.index));
        }
    }
}

/// The distance between two boxes (0 when they overlap): a lower bound on
/// the distance between anything inside them.
fn box_gap(a: &Aabb, b: &Aabb) -> f64 {
    let dx = (a.mins.x - b.maxs.x).max(b.mins.x - a.maxs.x).max(0.0);
    let dy = (a.mins.y - b.maxs.y).max(b.mins.y - a.maxs.y).max(0.0);
    dx.hypot(dy)
}
