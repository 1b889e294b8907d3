//! Communication between components, as SmartSoft defines it: components
//! talk only through six communication patterns (send, query, push newest,
//! push timed, event, wiring), their messages carry copied values, and a
//! master may rewire who talks to whom while the system runs.
//!
//! The runtime is a discrete-event simulation on its own clock: every
//! message has a latency (fixed plus seeded jitter) and may be lost, and
//! the same system file and seed always give the same trace.
//!
//! - [`object`], [`pattern`], [`link`], [`trace`]: the vocabulary;
//! - [`component`] and [`runtime`]: components and the runtime that runs them;
//! - [`kinds`]: small components for each pattern, and [`robot`]: a robot
//!   system (laser, base, mapper, planner, motion, joystick, sequencer);
//! - [`system`]: system files; [`why`]: why a port got nothing;
//!   [`exercise`]: graded tasks.

pub mod component;
pub mod exercise;
pub mod kinds;
pub mod link;
pub mod object;
pub mod pattern;
pub mod robot;
pub mod runtime;
pub mod system;
pub mod trace;
pub mod view;
pub mod why;

pub use component::{Component, ComponentClone, Interface, Lifecycle};
pub use kinolab_common::FieldError;
pub use link::Latency;
pub use object::Object;
pub use pattern::{Pattern, PortSpec, Refusal, ServiceSpec, Signature};
pub use runtime::{Action, Ctx, Mode, Runtime, Ticket};
pub use system::{Report, System};
pub use trace::{Record, Status};
