//! Surprises placed from a world's own geometry, so they work in any
//! world with a goal: a door across the narrowest passage on the robot's
//! way, a person crossing that way ahead of it, the goal moved to another
//! place the robot can reach.

use kinolab_world::grid::Grid;
use kinolab_world::search::Algorithm;
use kinolab_world::{FieldError, Vec2, World};

use crate::surprise::{PERSON_RADIUS, Surprise};

/// The kinds of surprise that need a place.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Placed {
    Door,
    Person,
    MovedGoal,
}

/// Cell side of the grid the places are found on, m.
const CELL: f64 = 0.1;
/// The way's first and last stretch where nothing is put, m: not on top of
/// the robot, not on the goal.
const KEEP_CLEAR_START: f64 = 1.0;
const KEEP_CLEAR_END: f64 = 0.8;
/// How far a door's or a person's ends reach to each side at most, m.
const REACH: f64 = 2.5;
/// How far ahead of the robot the person crosses, m (or halfway there).
const CROSSING_AHEAD: f64 = 2.5;
/// A walking pace, m/s.
const PERSON_SPEED: f64 = 0.6;
/// The nearest a moved goal may be to the robot, m.
const MOVED_GOAL_AWAY: f64 = 1.5;

impl Placed {
    /// The surprise of this kind in `world` (with `world.goal`) for a robot
    /// at `robot` at time `t`, sprung at `t`.
    pub fn place(self, world: &World, robot: Vec2, t: f64) -> Result<Surprise, FieldError> {
        let goal = world
            .goal
            .ok_or_else(|| FieldError::new("goal", "the world has no goal to plan towards"))?;
        let grid = Grid::new(world, CELL, world.robot_radius)?;
        match self {
            Placed::Door => door(world, &way(&grid, robot, goal)?, t),
            Placed::Person => person(world, &way(&grid, robot, goal)?, t),
            Placed::MovedGoal => moved_goal(world, &grid, robot, goal, t),
        }
    }
}

/// The robot's shortest way to the goal, as points with the distance
/// travelled to each.
fn way(grid: &Grid, robot: Vec2, goal: Vec2) -> Result<Vec<(Vec2, f64)>, FieldError> {
    let path = grid
        .plan(robot, goal, Algorithm::AStar)?
        .ok_or_else(|| FieldError::new("surprise", "the robot has no way to the goal"))?;
    let mut along = 0.0;
    let mut previous: Option<Vec2> = None;
    Ok(path
        .points
        .iter()
        .map(|p| {
            let here = Vec2::new(p[0], p[1]);
            along += previous.map_or(0.0, |q| (here - q).norm());
            previous = Some(here);
            (here, along)
        })
        .collect())
}

/// The unit normal to the way at point `k` (left of the direction of travel).
fn normal(way: &[(Vec2, f64)], k: usize) -> Vec2 {
    let a = way[k.saturating_sub(1)].0;
    let b = way[(k + 1).min(way.len() - 1)].0;
    let d = b - a;
    let n = d.norm();
    if n < 1e-12 {
        Vec2::new(0.0, 1.0)
    } else {
        Vec2::new(-d.y / n, d.x / n)
    }
}

/// How far the free space reaches from `p` along `dir`, up to [`REACH`].
fn reach(world: &World, p: Vec2, dir: Vec2, t: f64) -> f64 {
    world.ray(p, dir, REACH, t).unwrap_or(REACH)
}

/// A door across the narrowest passage on the way, away from its ends.
fn door(world: &World, way: &[(Vec2, f64)], t: f64) -> Result<Surprise, FieldError> {
    let total = way.last().map_or(0.0, |w| w.1);
    let mut best: Option<(f64, Vec2, Vec2)> = None;
    for (k, &(p, along)) in way.iter().enumerate() {
        if along < KEEP_CLEAR_START || total - along < KEEP_CLEAR_END {
            continue;
        }
        let n = normal(way, k);
        let (left, right) = (reach(world, p, n, t), reach(world, p, -n, t));
        let width = left + right;
        if best.is_none_or(|(w, _, _)| width < w - 1e-9) {
            // Into the walls a little, so no gap is left beside the door.
            best = Some((width, p + n * (left + 0.05), p - n * (right + 0.05)));
        }
    }
    let (_, from, to) = best.ok_or_else(|| {
        FieldError::new("surprise", "the way to the goal is too short for a door")
    })?;
    Ok(Surprise::Door {
        from: clamp(world, from),
        to: clamp(world, to),
        at: t,
    })
}

/// A person walking across the way ahead of the robot, from one side to
/// the other.
fn person(world: &World, way: &[(Vec2, f64)], t: f64) -> Result<Surprise, FieldError> {
    let total = way.last().map_or(0.0, |w| w.1);
    let ahead = CROSSING_AHEAD.min(total / 2.0);
    let k = way
        .iter()
        .position(|w| w.1 >= ahead)
        .ok_or_else(|| FieldError::new("surprise", "the way to the goal is too short"))?;
    let (c, n) = (way[k].0, normal(way, k));
    let keep = PERSON_RADIUS + 0.05;
    let left = (reach(world, c, n, t) - keep).max(0.0);
    let right = (reach(world, c, -n, t) - keep).max(0.0);
    Ok(Surprise::Person {
        from: clamp(world, c + n * left),
        to: clamp(world, c - n * right),
        speed: PERSON_SPEED,
        at: t,
    })
}

/// The goal moved to the free cell the robot can reach that is farthest
/// from the old goal, with room round it and not beside the robot.
fn moved_goal(
    world: &World,
    grid: &Grid,
    robot: Vec2,
    goal: Vec2,
    t: f64,
) -> Result<Surprise, FieldError> {
    let start = grid
        .cell_of(robot)
        .filter(|c| grid.is_free(*c))
        .ok_or_else(|| FieldError::new("surprise", "the robot is not in a free cell"))?;
    let reachable = grid.distances_to(start);
    let room = world.robot_radius + 0.5;
    let mut best: Option<(f64, Vec2)> = None;
    for (index, d) in reachable.iter().enumerate() {
        if !d.is_finite() {
            continue;
        }
        let p = grid.centre(grid.cell_at(index));
        let fits = (p - robot).norm() >= MOVED_GOAL_AWAY
            && world.obstacle_distance(p, t) >= room
            && inside_by(world, p) >= room;
        let score = (p - goal).norm();
        if fits && best.is_none_or(|(s, _)| score > s + 1e-9) {
            best = Some((score, p));
        }
    }
    let (_, to) = best.ok_or_else(|| {
        FieldError::new(
            "surprise",
            "no other place the robot can reach has room for a goal",
        )
    })?;
    Ok(Surprise::Goal {
        to: [to.x, to.y],
        at: t,
    })
}

/// How far `p` is inside the world's bounds, m.
fn inside_by(world: &World, p: Vec2) -> f64 {
    let b = &world.bounds;
    (p.x - b.x_min)
        .min(b.x_max - p.x)
        .min(p.y - b.y_min)
        .min(b.y_max - p.y)
}

/// A point kept inside the world's bounds.
fn clamp(world: &World, p: Vec2) -> [f64; 2] {
    let b = &world.bounds;
    [p.x.clamp(b.x_min, b.x_max), p.y.clamp(b.y_min, b.y_max)]
}
