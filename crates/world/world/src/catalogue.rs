//! Example worlds, shipped as world files.

use kinolab_common::random::SplitMix64;

use crate::obstacle::{Obstacle, Shape};
use crate::{FieldError, Pose, Rect, Vec2, World};

/// Each world's id and file.
pub const WORLDS: [(&str, &str); 7] = [
    ("two-rooms", include_str!("../worlds/two-rooms.json")),
    ("scattered", include_str!("../worlds/scattered.json")),
    ("u-trap", include_str!("../worlds/u-trap.json")),
    ("corridor", include_str!("../worlds/corridor.json")),
    ("lights", include_str!("../worlds/lights.json")),
    ("crossing", include_str!("../worlds/crossing.json")),
    ("office", include_str!("../worlds/office.json")),
];

/// The example world called `id`.
pub fn world(id: &str) -> Result<World, FieldError> {
    let (_, text) = WORLDS
        .iter()
        .find(|(name, _)| *name == id)
        .ok_or_else(|| FieldError::new("world", format!("no example world called `{id}`")))?;
    World::from_json(text)
}

/// An 8 × 5 m room crossed from (0.8, 2.5) to (7.2, 2.5), with `count`
/// discs (at most 12) scattered in between by `seed`. Discs keep 0.5 m
/// apart and clear of the start and the goal, so a robot can always pass.
pub fn scattered(seed: u64, count: usize) -> World {
    let mut world = World::empty(
        format!("scattered-{seed}"),
        Rect::from([0.0, 0.0, 8.0, 5.0]),
    );
    world.start = Pose::new(0.8, 2.5, 0.0);
    let goal = Vec2::new(7.2, 2.5);
    world.goal = Some(goal);
    let start = Vec2::new(0.8, 2.5);
    let mut rng = SplitMix64::new(seed);
    let mut discs: Vec<(Vec2, f64)> = Vec::new();
    for _ in 0..400 {
        if discs.len() >= count.min(12) {
            break;
        }
        let c = Vec2::new(rng.range(2.0, 6.0), rng.range(0.7, 4.3));
        let r = rng.range(0.2, 0.45);
        let apart = discs.iter().all(|(d, s)| (c - d).norm() > r + s + 0.5);
        if apart && (c - start).norm() > r + 0.9 && (c - goal).norm() > r + 0.9 {
            discs.push((c, r));
        }
    }
    world.obstacles = discs
        .into_iter()
        .map(|(centre, radius)| Obstacle::new(Shape::Disc { centre, radius }))
        .collect();
    world
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_example_reads_and_is_named_after_its_id() {
        for (id, _) in WORLDS {
            let w = world(id).unwrap_or_else(|e| panic!("{id}: {e}"));
            assert_eq!(w.name, id);
        }
        assert!(world("moon").is_err());
    }

    #[test]
    fn scattered_worlds_follow_their_seed() {
        assert_eq!(scattered(3, 6), scattered(3, 6));
        assert_ne!(scattered(3, 6), scattered(4, 6));
        let w = scattered(5, 6);
        assert_eq!(w.obstacles.len(), 6);
        let again = World::from_json(&w.to_json()).unwrap();
        assert_eq!(again, w);
    }
}
