//! Architecture kernels: A* on a large grid, and one frame of the
//! architecture arena (three robots, planning spread over frames).

use std::cell::RefCell;
use std::hint::black_box;

use kinolab_architectures::exercise::office;
use kinolab_architectures::{Architecture, Arena};
use kinolab_world::grid::Grid;
use kinolab_world::search::Algorithm;
use kinolab_world::{Rect, Vec2};

/// A 200 × 200 grid (10 m at 5 cm) with staggered walls to wind through.
fn maze() -> &'static Option<Grid> {
    static MAZE: std::sync::OnceLock<Option<Grid>> = std::sync::OnceLock::new();
    MAZE.get_or_init(|| {
        Grid::from_test(Rect::from([0.0, 0.0, 10.0, 10.0]), 0.05, |p: Vec2| {
            // Walls every 2 m, gaps alternating at the top and the bottom.
            let k = (p.x / 2.0).floor() as i64;
            let on_wall = (p.x - 2.0 * (k as f64 + 0.5)).abs() < 0.1 && k < 4;
            let gap = if k % 2 == 0 { p.y > 9.0 } else { p.y < 1.0 };
            !on_wall || gap
        })
        .ok()
    })
}

/// A* from one corner of the maze to the other: the path's cost.
pub fn astar_200() -> f64 {
    let Some(grid) = maze() else { return f64::NAN };
    grid.search(black_box((0, 0)), black_box((199, 199)), Algorithm::AStar)
        .cost
        .unwrap_or(f64::NAN)
}

thread_local! {
    static ARENA: RefCell<Option<Arena>> = const { RefCell::new(None) };
}

/// One frame of the arena in the office with a person stepping in: three
/// robots sense, decide (the planners at 2 ms a cell, a few cells a
/// frame) and move. Restarts when the run is over.
pub fn arena_frame() -> f64 {
    ARENA.with(|cell| {
        let mut arena = cell.borrow_mut();
        if arena.as_ref().is_none_or(Arena::done) {
            *arena = office(Some("person"))
                .ok()
                .and_then(|s| Arena::new(&s, &Architecture::ALL).ok());
        }
        match arena.as_mut() {
            Some(a) => {
                a.step();
                a.time()
            }
            None => f64::NAN,
        }
    })
}
