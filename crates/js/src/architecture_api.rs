//! Architectures for JavaScript, on plain JSON values (so they run natively
//! too, against the command line).

use serde_json::Value;

use crate::api::{Reply, reply, text};

/// `kinolab arena`: a world file (object, JSON text, or `catalogue:<id>`)
/// and the options `{ architecture, perturb, planning_cost_ms, duration,
/// seed, every }`.
pub fn arena(world: Value, options: Value) -> Reply {
    let text_of = match world {
        Value::String(json) => json,
        other => other.to_string(),
    };
    let world = match text_of.strip_prefix("catalogue:") {
        Some(id) => kinolab_world::catalogue::world(id),
        None => kinolab_world::World::from_json(&text_of),
    }
    .map_err(text)?;
    let request: kinolab_architectures::run::Request =
        kinolab_common::error::from_json(&options.to_string()).map_err(text)?;
    reply(&request.run(world).map_err(text)?)
}

/// Each sensor's route and the wiring's paradigm, for `feeds[sensor][function]`
/// (sensors: range rays, sonar, bumpers, light sensors, goal bearing,
/// odometry; functions: avoid, go to goal, seek light, follow wall, world model).
pub fn routes(feeds: Value) -> Reply {
    let feeds: [[bool; 5]; 6] =
        kinolab_common::error::from_json(&feeds.to_string()).map_err(text)?;
    reply(&kinolab_architectures::routes::Wiring { feeds }.report())
}

/// `kinolab components`: a system file (object, JSON text, or
/// `example:<id>`) run until `until` s (the file's when `None`).
pub fn components(system: Value, until: Option<f64>) -> Reply {
    let text_of = match system {
        Value::String(json) => json,
        other => other.to_string(),
    };
    let system = match text_of.strip_prefix("example:") {
        Some(id) => kinolab_components::system::example(id),
        None => kinolab_components::System::from_json(&text_of),
    }
    .map_err(text)?;
    reply(&system.run(until).map_err(text)?)
}
