#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Surprises placed from a world's geometry work in every world with a
//! goal: the door blocks the way the robot would take, the person walks
//! across it ahead of the robot, the moved goal is somewhere the robot can
//! still reach. Each round-trips through the command line's spec.

use kinolab_architectures::placing::Placed;
use kinolab_architectures::{Architecture, Arena, ArenaSetup, Surprise};
use kinolab_world::grid::Grid;
use kinolab_world::search::Algorithm;
use kinolab_world::{Sensors, Vec2, World};

/// Every catalogue world with a goal.
fn worlds() -> Vec<World> {
    let worlds: Vec<World> = kinolab_world::catalogue::WORLDS
        .iter()
        .map(|(id, _)| kinolab_world::catalogue::world(id).unwrap())
        .filter(|w| w.goal.is_some())
        .collect();
    assert!(worlds.len() >= 4, "{} worlds with a goal", worlds.len());
    worlds
}

fn start(w: &World) -> Vec2 {
    Vec2::new(w.start.x, w.start.y)
}

/// The shortest way's length from the start to the goal in `world`.
fn way_cost(world: &World, to: Vec2) -> Option<f64> {
    let grid = Grid::new(world, 0.1, world.robot_radius).unwrap();
    grid.plan(start(world), to, Algorithm::AStar)
        .unwrap()
        .map(|p| p.cost)
}

/// Whether segments ab and cd cross.
fn crosses(a: Vec2, b: Vec2, c: Vec2, d: Vec2) -> bool {
    let side = |p: Vec2, q: Vec2, r: Vec2| (q - p).perp(&(r - p));
    side(a, b, c) * side(a, b, d) <= 0.0 && side(c, d, a) * side(c, d, b) <= 0.0
}

fn v(p: [f64; 2]) -> Vec2 {
    Vec2::new(p[0], p[1])
}

/// The way's points from the start to the goal.
fn way(world: &World) -> Vec<Vec2> {
    let grid = Grid::new(world, 0.1, world.robot_radius).unwrap();
    grid.plan(start(world), world.goal.unwrap(), Algorithm::AStar)
        .unwrap()
        .unwrap()
        .points
        .iter()
        .map(|p| v(*p))
        .collect()
}

fn crosses_way(world: &World, a: Vec2, b: Vec2) -> bool {
    way(world).windows(2).any(|w| crosses(a, b, w[0], w[1]))
}

fn round_trip(s: &Surprise) {
    assert_eq!(
        &Surprise::parse("perturb", &s.spec()).unwrap(),
        s,
        "{}",
        s.spec()
    );
}

#[test]
fn a_door_blocks_the_way_the_robot_would_take() {
    for world in worlds() {
        let goal = world.goal.unwrap();
        let before = way_cost(&world, goal).unwrap();
        let door = Placed::Door.place(&world, start(&world), 0.0).unwrap();
        let Surprise::Door { from, to, at } = door.clone() else {
            panic!("{door:?}")
        };
        assert_eq!(at, 0.0);
        assert!(
            crosses_way(&world, v(from), v(to)),
            "{}: {door:?}",
            world.name
        );
        let mut closed = world.clone();
        door.apply(&mut closed, &mut Sensors::default());
        // The door is there from the start: the old way is shut, so the
        // robot must go another, longer way round or cannot get there.
        let after = way_cost(&closed, goal);
        assert!(
            after.is_none_or(|c| c > before + 1e-9 && !crosses_way(&closed, v(from), v(to))),
            "{}: {before} → {after:?} with {door:?}",
            world.name
        );
        round_trip(&door);
    }
}

#[test]
fn a_person_crosses_the_way_ahead_of_the_robot() {
    for world in worlds() {
        let person = Placed::Person.place(&world, start(&world), 4.5).unwrap();
        let Surprise::Person {
            from,
            to,
            speed,
            at,
        } = person.clone()
        else {
            panic!("{person:?}")
        };
        assert_eq!((speed, at), (0.6, 4.5));
        assert!(
            crosses_way(&world, v(from), v(to)),
            "{}: {person:?}",
            world.name
        );
        assert!(
            (v(from) - v(to)).norm() >= 0.4,
            "{}: {person:?}",
            world.name
        );
        for end in [from, to] {
            assert!(
                world.obstacle_distance(v(end), at) >= 0.25,
                "{}: {person:?} starts or ends in a wall",
                world.name
            );
            assert!(
                (v(end) - start(&world)).norm() > 0.8,
                "{}: {person:?}",
                world.name
            );
        }
        round_trip(&person);
    }
}

#[test]
fn a_moved_goal_is_somewhere_else_the_robot_can_reach() {
    for world in worlds() {
        let old = world.goal.unwrap();
        let moved = Placed::MovedGoal.place(&world, start(&world), 8.0).unwrap();
        let Surprise::Goal { to, at } = moved.clone() else {
            panic!("{moved:?}")
        };
        assert_eq!(at, 8.0);
        assert!((v(to) - old).norm() > 1.0, "{}: {moved:?}", world.name);
        assert!(
            (v(to) - start(&world)).norm() >= 1.5,
            "{}: {moved:?}",
            world.name
        );
        assert!(
            way_cost(&world, v(to)).is_some(),
            "{}: {moved:?}",
            world.name
        );
        round_trip(&moved);
    }
}

#[test]
fn the_hybrid_robot_reaches_a_moved_goal() {
    // A goal squeezed against the world's edge would be out of reach.
    for world in worlds() {
        let moved = Placed::MovedGoal.place(&world, start(&world), 4.0).unwrap();
        let mut setup = ArenaSetup::new(world.clone());
        setup.surprises.push(moved.clone());
        let report = kinolab_architectures::run::run(&setup, Architecture::Hybrid, 10).unwrap();
        assert!(report.metrics.reached, "{}: {moved:?}", world.name);
    }
}

#[test]
fn every_placed_surprise_springs_in_a_running_arena() {
    for world in worlds() {
        let setup = ArenaSetup::new(world.clone());
        let mut arena = Arena::new(&setup, &Architecture::ALL).unwrap();
        for _ in 0..40 {
            arena.step();
        }
        let at = arena.entrants[0].sim.position();
        for kind in [Placed::Door, Placed::Person, Placed::MovedGoal] {
            let s = kind.place(&world, at, arena.time()).unwrap();
            arena.spring(&s).unwrap();
        }
        while !arena.done() {
            arena.step();
        }
        assert!(arena.time() > 2.0, "{}", world.name);
    }
}
