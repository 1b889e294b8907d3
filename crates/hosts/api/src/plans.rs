//! Plans and architectures: the shortest path across a world's grid, one
//! architecture's run through a world with surprises, and where a wiring
//! of sensors to functions sends each sensor's data.

use kinolab_architectures::routes::{RouteReport, Wiring};
use kinolab_architectures::run::{ArenaReport, Request};
use kinolab_world::grid::{Grid, GridPath};
use kinolab_world::search::Algorithm;
use kinolab_world::{Vec2, World};
use serde::Serialize;

use crate::{Error, Files, Operation, Source};

/// A world: a world file's text, or an example world's id
/// (`catalogue:two-rooms`).
pub fn world(source: &Source) -> Result<World, Error> {
    source.load(
        "world",
        "catalogue:",
        World::from_json,
        kinolab_world::catalogue::world,
    )
}

/// `kinolab plan`: A* (octile heuristic) or Dijkstra over the grid.
#[derive(Debug, Clone)]
pub struct Plan {
    pub world: Source,
    pub from: [f64; 2],
    pub to: [f64; 2],
    pub cell: f64,
    pub algorithm: Algorithm,
}

/// A plan, or no path: `cost` null and no cells.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum PlanReport {
    Found(GridPath),
    NoPath {
        cost: Option<f64>,
        cells: Vec<[usize; 2]>,
        points: Vec<[f64; 2]>,
    },
}

impl Operation for Plan {
    type Report = PlanReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let world = world(&self.world)?;
        let as_argument = |e: kinolab_common::FieldError| Error::argument(e.field, e.message);
        let grid = Grid::new(&world, self.cell, world.robot_radius).map_err(as_argument)?;
        let point = |p: [f64; 2]| Vec2::new(p[0], p[1]);
        let path = grid
            .plan(point(self.from), point(self.to), self.algorithm)
            .map_err(as_argument)?;
        Ok(match path {
            Some(p) => PlanReport::Found(p),
            None => PlanReport::NoPath {
                cost: None,
                cells: Vec::new(),
                points: Vec::new(),
            },
        })
    }
}

/// `kinolab arena`: one architecture through a world with surprises.
#[derive(Debug, Clone)]
pub struct Arena {
    pub world: Source,
    pub request: Request,
}

impl Operation for Arena {
    type Report = ArenaReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let world = world(&self.world)?;
        self.request
            .run(world)
            .map_err(|e| Error::argument(e.field, e.message))
    }
}

/// Each sensor's route and the paradigm of a wiring: `feeds[sensor][function]`
/// for the sensors (range rays, sonar, bumpers, light sensors, goal
/// bearing, odometry) and functions (avoid, go to goal, seek light, follow
/// wall, world model).
#[derive(Debug, Clone, Copy)]
pub struct Routes {
    pub feeds: [[bool; 5]; 6],
}

impl Operation for Routes {
    type Report = RouteReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        Ok(Wiring { feeds: self.feeds }.report())
    }
}
