//! The world model and the planner: the cartographer converges to the true
//! grid under noise; a plan spread over steps is the plan made at once;
//! waypoints see each other.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use kinolab_architectures::arena::arena_sensors;
use kinolab_architectures::follow::{clear_line, waypoints};
use kinolab_architectures::map::Cartographer;
use kinolab_architectures::planner::{Outcome, Planner};
use kinolab_world::catalogue::{scattered, world};
use kinolab_world::search::Algorithm;
use kinolab_world::{Body, Command, Pose, Sim, Vec2};
use proptest::prelude::*;

/// Cells whose centre is more than a cell from every obstacle boundary
/// and from the fence: there the true answer is not in doubt.
fn clear_cut(map: &Cartographer, w: &kinolab_world::World) -> Vec<((usize, usize), bool)> {
    let mut out = Vec::new();
    for j in 0..map.ny {
        for i in 0..map.nx {
            let c = map.centre((i, j));
            let b = w.bounds;
            let fence = (c.x - b.x_min)
                .min(b.x_max - c.x)
                .min(c.y - b.y_min)
                .min(b.y_max - c.y);
            if fence < map.cell {
                continue;
            }
            let d = w.obstacle_distance(c, 0.0);
            let inside = w.obstacles.iter().any(|o| o.distance(c, 0.0) <= 0.0);
            if d > map.cell
                || inside
                    && w.obstacles
                        .iter()
                        .all(|o| o.distance(c, 0.0) <= 0.0 || o.distance(c, 0.0) > map.cell)
            {
                out.push(((i, j), d <= 0.0));
            }
        }
    }
    out
}

#[test]
fn the_cartographer_converges_to_the_true_grid_under_noise() {
    let w = world("office").unwrap();
    let mut sensors = arena_sensors();
    if let Some(r) = sensors.rays.as_mut() {
        r.noise = 0.1;
    }
    let mut map = Cartographer::empty(w.bounds, 0.1, 0.2).unwrap();
    // Look around from a tour of poses in both rooms, turning on the spot.
    let stops = [
        (1.0, 1.5),
        (2.5, 1.0),
        (4.0, 2.5),
        (1.5, 5.0),
        (4.0, 5.0),
        (6.0, 1.5),
        (8.5, 0.5),
        (6.0, 4.5),
        (8.5, 4.5),
        (8.5, 2.8),
    ];
    let mut seen = vec![false; map.nx * map.ny];
    for (k, (x, y)) in stops.iter().enumerate() {
        let mut start = w.clone();
        start.start = Pose::new(*x, *y, 0.0);
        let mut sim = Sim::new(start, Body::default(), sensors, 0.05, k as u64).unwrap();
        for _ in 0..80 {
            let p = sim.sense();
            map.update(sim.pose, &p, 0.18);
            for r in &p.rays {
                let end = Vec2::new(sim.pose.x, sim.pose.y)
                    + kinolab_world::unit(sim.pose.theta + r.angle) * r.range;
                if let Some((i, j)) = map.cell_of(end) {
                    seen[j * map.nx + i] = true;
                }
            }
            sim.advance(Command::unicycle(0.0, 1.0));
        }
    }
    let mut wrong = Vec::new();
    let mut checked = 0;
    for ((i, j), occupied) in clear_cut(&map, &w) {
        // Free cells the rays crossed, and occupied cells they ended on.
        if occupied && !seen[j * map.nx + i] {
            continue;
        }
        checked += 1;
        if map.occupied((i, j)) != occupied {
            wrong.push((i, j));
        }
    }
    assert!(checked > 3000, "{checked}");
    // Noise of one cell's size leaves a handful of stray cells at most.
    assert!(
        wrong.len() * 200 < checked,
        "{} of {checked} wrong: {:?}",
        wrong.len(),
        &wrong[..wrong.len().min(10)]
    );
}

#[test]
fn a_plan_spread_over_steps_is_the_plan_made_at_once() {
    let w = world("office").unwrap();
    let map = Cartographer::from_world(&w, 0.1, 0.2, |_| true).unwrap();
    let (from, to) = (Vec2::new(1.0, 1.5), Vec2::new(9.0, 1.5));
    let mut instant = Planner::new(0.0).unwrap();
    instant.request(&map, from, to, 0.0).unwrap();
    let Some(Outcome::Found(a)) = instant.tick(0.05, 0.0) else {
        panic!("no plan")
    };
    // 5 ms a cell at 50 ms a step: ten cells a step.
    let mut slow = Planner::new(0.005).unwrap();
    slow.request(&map, from, to, 0.0).unwrap();
    let mut steps = 0;
    let b = loop {
        steps += 1;
        if let Some(Outcome::Found(b)) = slow.tick(0.05, steps as f64 * 0.05) {
            break b;
        }
        assert!(steps < 10_000);
    };
    assert_eq!(a.waypoints, b.waypoints);
    assert_eq!(a.expanded, b.expanded);
    assert_eq!(steps, a.expanded.div_ceil(10), "{} cells", a.expanded);
    // The plan's cost is the grid planner's optimum on the same grid.
    let grid = map.grid(Some(from)).unwrap();
    let best = grid.plan(from, to, Algorithm::Dijkstra).unwrap().unwrap();
    assert!((a.cost - best.cost).abs() < 1e-9);
    assert_eq!(a.waypoints.last(), Some(&[9.0, 1.5]));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn waypoints_see_each_other_and_end_at_the_goal(seed in 0u64..1000, count in 0usize..12) {
        let w = scattered(seed, count);
        let map = Cartographer::from_world(&w, 0.1, 0.2, |_| true).unwrap();
        let grid = map.grid(None).unwrap();
        let (from, goal) = (Vec2::new(0.8, 2.5), Vec2::new(7.2, 2.5));
        let (Some(a), Some(b)) = (grid.cell_of(from), grid.cell_of(goal)) else { return Ok(()) };
        let found = grid.search(a, b, Algorithm::AStar);
        prop_assume!(found.cost.is_some());
        let points = waypoints(&grid, &found.path, goal);
        prop_assert_eq!(points.last().copied(), Some(goal));
        let mut at = grid.centre(a);
        let mut length = 0.0;
        for p in &points {
            prop_assert!(clear_line(&grid, at, *p), "{at:?} → {p:?}");
            length += (p - at).norm();
            at = *p;
        }
        // Pulled tight, never longer than the cell path.
        prop_assert!(length <= found.cost.unwrap() + grid.cell);
    }
}
