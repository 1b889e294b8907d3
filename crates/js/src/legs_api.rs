//! Gaits, central pattern generators and grid plans for JavaScript, on
//! plain JSON values (so they run natively too, against the command line).

use serde_json::Value;

use crate::api::{Reply, reply, text};

/// A file given as an object or as its JSON text.
fn json_text(file: Value) -> String {
    match file {
        Value::String(json) => json,
        other => other.to_string(),
    }
}

/// `kinolab gait --samples N`.
pub fn gait(file: Value, samples: usize) -> Reply {
    let gait = kinolab_locomotion::Gait::from_json(&json_text(file)).map_err(text)?;
    reply(&kinolab_locomotion::report::gait(&gait, samples).map_err(text)?)
}

/// `kinolab cpg`.
pub fn cpg(file: Value) -> Reply {
    let cpg = kinolab_locomotion::Cpg::from_json(&json_text(file)).map_err(text)?;
    reply(&kinolab_locomotion::report::cpg(&cpg).map_err(text)?)
}

/// `kinolab plan`: a world file (object, JSON text, or `catalogue:<id>`).
pub fn plan(world: Value, from: [f64; 2], to: [f64; 2], cell: f64) -> Reply {
    use kinolab_world::{Vec2, World};
    let text_of = json_text(world);
    let world = match text_of.strip_prefix("catalogue:") {
        Some(id) => kinolab_world::catalogue::world(id),
        None => World::from_json(&text_of),
    }
    .map_err(text)?;
    let grid = kinolab_world::grid::Grid::new(&world, cell, world.robot_radius).map_err(text)?;
    let path = grid
        .plan(
            Vec2::new(from[0], from[1]),
            Vec2::new(to[0], to[1]),
            kinolab_world::search::Algorithm::AStar,
        )
        .map_err(text)?;
    match path {
        Some(p) => reply(&p),
        None => Ok(serde_json::json!({ "cost": null, "cells": [], "points": [] })),
    }
}
