#![allow(clippy::unwrap_used)] // tests may stop at the first surprise
//! Grid planning against brute force: on random grids Dijkstra and A* find
//! the true shortest 8-connected distance (no corner cutting), agree with
//! each other, and A* expands no more cells.

use kinolab_world::grid::Grid;
use kinolab_world::search::Algorithm;
use kinolab_world::{Rect, Vec2};
use proptest::prelude::*;

fn grid(n: usize, blocked: &[bool]) -> Grid {
    let bounds = Rect::from([0.0, 0.0, n as f64, n as f64]);
    Grid::from_test(bounds, 1.0, |p: Vec2| {
        let (i, j) = (p.x.floor() as usize, p.y.floor() as usize);
        !blocked[j * n + i]
    })
    .unwrap()
}

/// Every cell's distance from `start` by relaxing every move until nothing
/// changes (Bellman–Ford): slow, obviously right.
fn brute_force(g: &Grid, start: (usize, usize)) -> Vec<f64> {
    let n = g.nx;
    let mut d = vec![f64::INFINITY; n * g.ny];
    if !g.is_free(start) {
        return d;
    }
    d[start.1 * n + start.0] = 0.0;
    for _ in 0..n * g.ny {
        let mut changed = false;
        for j in 0..g.ny {
            for i in 0..n {
                let here = d[j * n + i];
                if !here.is_finite() {
                    continue;
                }
                for ((a, b), step) in g.moves((i, j)) {
                    if here + step < d[b * n + a] - 1e-12 {
                        d[b * n + a] = here + step;
                        changed = true;
                    }
                }
            }
        }
        if !changed {
            break;
        }
    }
    d
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn searches_are_optimal_and_a_star_expands_no_more(
        blocked in prop::collection::vec(prop::bool::weighted(0.3), 100),
        start in (0usize..10, 0usize..10),
        goal in (0usize..10, 0usize..10),
    ) {
        let g = grid(10, &blocked);
        let truth = brute_force(&g, start)[goal.1 * 10 + goal.0];
        let d = g.search(start, goal, Algorithm::Dijkstra);
        let a = g.search(start, goal, Algorithm::AStar);
        match (d.cost, a.cost) {
            (Some(dc), Some(ac)) => {
                prop_assert!((dc - truth).abs() < 1e-9, "{dc} vs {truth}");
                prop_assert!((ac - truth).abs() < 1e-9, "{ac} vs {truth}");
                prop_assert!(a.expanded.len() <= d.expanded.len());
                // The path's steps are moves of the grid and sum to the cost.
                let mut sum = 0.0;
                for w in a.path.windows(2) {
                    let step = g.moves(w[0]).find(|(c, _)| *c == w[1]).map(|(_, s)| s);
                    prop_assert!(step.is_some(), "{:?} → {:?} is not a move", w[0], w[1]);
                    sum += step.unwrap_or_default();
                }
                prop_assert!((sum - ac).abs() < 1e-9);
            }
            (None, None) => prop_assert!(!truth.is_finite()),
            other => prop_assert!(false, "the searches disagree: {other:?}"),
        }
    }
}
