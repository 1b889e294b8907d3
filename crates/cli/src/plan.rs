//! `kinolab plan`: the shortest path across a world's occupancy grid;
//! `kinolab arena`: one architecture's run through a world with surprises.

use std::path::Path;

use kinolab_world::grid::Grid;
use kinolab_world::search::Algorithm;
use kinolab_world::{Vec2, World};
use serde_json::{Value, json};

use crate::{Failure, input, point, report as emit};

/// A world file, or `catalogue:<id>` for one of the lab's worlds.
pub(crate) fn load(path: &Path) -> Result<World, Failure> {
    let shown = path.display().to_string();
    match shown.strip_prefix("catalogue:") {
        Some(id) => kinolab_world::catalogue::world(id),
        None => World::from_json(&input::read(path)?),
    }
    .map_err(|e| Failure(format!("{shown}: {e}")))
}

pub(crate) fn plan(
    path: &Path,
    from: &str,
    to: &str,
    cell: f64,
    algorithm: Algorithm,
) -> Result<Value, Failure> {
    let world = load(path)?;
    let [fx, fy] = point("from", from)?;
    let [tx, ty] = point("to", to)?;
    let grid = Grid::new(&world, cell, world.robot_radius)
        .map_err(|e| Failure(format!("--{}: {}", e.field, e.message)))?;
    let path = grid
        .plan(Vec2::new(fx, fy), Vec2::new(tx, ty), algorithm)
        .map_err(|e| Failure(format!("--{}: {}", e.field, e.message)))?;
    match path {
        Some(p) => emit("plan", &p),
        None => Ok(json!({ "cost": null, "cells": [], "points": [] })),
    }
}

/// `kinolab arena`.
pub(crate) fn arena(
    world: &Path,
    request: &kinolab_architectures::run::Request,
) -> Result<Value, Failure> {
    let report = request.run(load(world)?).map_err(|e| {
        let field = e.field.replace('_', "-");
        Failure(format!("--{field}: {}", e.message))
    })?;
    emit("arena", &report)
}
