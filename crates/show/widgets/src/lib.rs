//! Kinolab's live widgets, on egui alone.
//!
//! A lesson names a widget in a ` ```widget ` block; [`registry::create`]
//! checks the block against the widget's schema (`kinolab-schema`) and
//! builds it. Widgets are grouped by what they teach:
//!
//! - [`locomotion`]: legs, balance and leg events;
//! - [`autonomy`]: closed and open worlds;
//! - [`wheels`]: wheel constraints, drive configurations, frames;
//! - [`control`]: speed profiles and the go-to-pose controller;
//! - [`mechanism`]: DH links and mechanism models;
//! - [`fields`]: potential fields and their traps;
//! - [`behaviour`]: behaviours and their coordination, Braitenberg's
//!   vehicles, blending against choosing.
//!
//! Shared pieces: [`widget`] (the trait every widget implements and the
//! small helpers they share), [`draw`] (one world↔screen view, draggable
//! handles with accessible names, grids, a 3D camera), [`link`] (widget
//! state in a link), [`export`] (files a widget asks the host to save),
//! [`open`] (files the learner drops or picks) and [`theme`]. Every number a widget shows comes from a core crate.
//!
//! Nothing here knows about windows or browsers: the lab's shell
//! (`kinolab-app`) hosts these widgets, as egui's demo app hosts its demos.

pub mod architecture;
pub mod autonomy;
pub mod behaviour;
pub mod code;
pub mod components;
pub mod control;
pub mod design;
pub mod draw;
pub mod export;
pub mod fields;
pub mod link;
pub mod locomotion;
pub mod mechanism;
pub mod open;
pub mod player;
pub mod probe;
pub mod registry;
pub mod theme;
pub mod wheels;
pub mod widget;

pub use widget::LabWidget;
