//! `kinolab components`: a system of components run on the simulated
//! clock; the trace of every message and the final state.

use std::path::PathBuf;

use clap::Subcommand;
use kinolab_api::components;
use serde_json::Value;

use crate::Failure;
use crate::ask::{ask, source};

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Run a system of components (send, query, push, event and wiring patterns) on a simulated clock; print every message and the final state.
    Components {
        /// A system file (`*.system.json`, see the README), or `example:<id>` (`out-of-order`, `newest-vs-timed`, `events`, `robot`).
        system: PathBuf,
        /// Seconds of simulated time to run (the file's `until` when left out).
        #[arg(long, allow_hyphen_values = true)]
        until: Option<f64>,
    },
}

pub(crate) fn run(command: Command) -> Result<Value, Failure> {
    let Command::Components { system, until } = command;
    ask(
        &components::Components {
            system: source(&system)?,
            until,
        },
        Some(&system),
    )
}
