//! Small components, one per pattern, for building systems by hand: a
//! query server and its client, a publisher and its subscribers, an event
//! watcher, a sender and a sink. Each reads its parameters from the system
//! file; errors name the field.

mod client;
mod publisher;
mod send;
mod server;
mod subscriber;
mod watcher;

use serde::de::DeserializeOwned;

pub use client::Client;
pub use publisher::Publisher;
pub use send::{Sender, Sink};
pub use server::Server;
pub use subscriber::Subscriber;
pub use watcher::Watcher;

use crate::FieldError;
use crate::component::Component;
use crate::pattern::Pattern;

/// Every kind a system file may name, generic and robot.
pub const KINDS: [&str; 14] = [
    "server",
    "client",
    "publisher",
    "subscriber",
    "watcher",
    "sender",
    "sink",
    "laser",
    "base",
    "mapper",
    "planner",
    "motion",
    "joystick",
    "sequencer",
];

/// Read a kind's parameters (an absent `params` is `{}`).
pub(crate) fn params<T: DeserializeOwned>(value: &serde_json::Value) -> Result<T, FieldError> {
    let value = if value.is_null() {
        serde_json::json!({})
    } else {
        value.clone()
    };
    let text = value.to_string();
    kinolab_common::error::from_json(&text).map_err(|e| e.within("params"))
}

/// A push pattern named in a file: `push-newest` or `push-timed`.
pub(crate) fn push_pattern(name: &str) -> Result<Pattern, FieldError> {
    match Pattern::from_name(name) {
        Some(p @ (Pattern::PushNewest | Pattern::PushTimed)) => Ok(p),
        _ => Err(FieldError::new(
            "params.pattern",
            format!("must be push-newest or push-timed, got `{name}`"),
        )),
    }
}

/// Build a component of `kind` from its parameters.
pub fn build(kind: &str, value: &serde_json::Value) -> Result<Box<dyn Component>, FieldError> {
    Ok(match kind {
        "server" => Box::new(Server::new(params(value)?)?),
        "client" => Box::new(Client::new(params(value)?)?),
        "publisher" => Box::new(Publisher::new(params(value)?)?),
        "subscriber" => Box::new(Subscriber::new(params(value)?)?),
        "watcher" => Box::new(Watcher::new(params(value)?)?),
        "sender" => Box::new(Sender::new(params(value)?)?),
        "sink" => Box::new(Sink::default()),
        robot => crate::robot::build(robot, value)?,
    })
}
