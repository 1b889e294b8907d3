//! Every operation of the lab, once: a typed request in, a typed report
//! out.
//!
//! The command line (`kinolab-cli`) and the JavaScript package
//! (`kinolab-js`) are two hosts of this one API. A host only turns what it
//! was given (options and files; JavaScript values) into a request, asks
//! [`answer`] for the report, and shows the report or the [`Error`] its
//! own way. Parsing the inputs, running the core and building the report
//! all happen here, so both hosts say the same thing to the last byte.
//!
//! Each request is a struct implementing [`Operation`], named in
//! [`OPERATIONS`] with its command and its JavaScript function:
//!
//! - [`wheels`]: a robot's mobility, its kinematics both ways, the catalogue;
//! - [`control`]: the go-to-pose controller's runs and its gains;
//! - [`mechanism`]: forward and inverse kinematics, Jacobians, placement
//!   and collisions of mechanism models;
//! - [`fields`]: potential fields, their equilibria and descents;
//! - [`behaviours`]: behaviours run in a world;
//! - [`legs`]: leg events, static stability, gaits and oscillators, a
//!   push on the cart-table model, the hexapod walking;
//! - [`plans`]: grid plans, architectures in the arena, sensing routes;
//! - [`components`]: systems of communicating components;
//! - [`teach`]: lessons, widgets, the automation unit's pick cell and
//!   Simon's ant;
//! - [`script`]: graded code exercises, a learner's script checked and a
//!   class's scripts graded.

mod error;
mod parallel;
mod source;

pub mod behaviours;
pub mod components;
pub mod control;
pub mod fields;
pub mod forces;
pub mod legs;
pub mod mechanism;
pub mod plans;
pub mod robot;
pub mod script;
pub mod teach;
pub mod wheels;

pub use error::{Error, Place};
pub use source::{Files, NoFiles, Source};

use serde::Serialize;
use serde_json::Value;

/// One thing the lab can be asked.
pub trait Operation {
    /// What it answers.
    type Report: Serialize;

    /// Parse the inputs, run the core and build the report. `files` reads
    /// the files an input names (a model's mounts); a host without files
    /// passes [`NoFiles`].
    fn report(&self, files: &mut dyn Files) -> Result<Self::Report, Error>;
}

/// The report of `operation` as JSON: what the command line prints and the
/// JavaScript function returns. Rounding noise is removed and a number that
/// is not finite is an error (see [`kinolab_common::display::tidy_report`]).
pub fn answer<O: Operation>(operation: &O, files: &mut dyn Files) -> Result<Value, Error> {
    tidy(&operation.report(files)?)
}

/// A report as JSON, tidied as [`answer`] does.
pub fn tidy(report: &impl Serialize) -> Result<Value, Error> {
    kinolab_common::display::tidy_report(report).map_err(|e| Error::result(e.message))
}

/// An operation's two names: the `kinolab` command (with its mode option,
/// when one command does several things) and the JavaScript function.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Names {
    pub command: &'static str,
    pub js: &'static str,
}

/// Every operation, by its command and its JavaScript function. A test
/// holds both hosts to this list.
pub const OPERATIONS: &[Names] = &[
    names("leg-events", "legEvents"),
    names("stability", "staticStability"),
    names("analyze", "analyzeRobot"),
    names("drive --twist", "driveTwist"),
    names("drive --wheels", "driveWheels"),
    names("differential-drive", "differentialDrive"),
    names("robots", "robots"),
    names("robots ID", "robotFile"),
    names("simulate", "simulate"),
    names("batch", "batchSimulate"),
    names("gains", "controllerStability"),
    names("mechanisms", "mechanisms"),
    names("describe", "Mechanism.describe"),
    names("home-state", "Mechanism.homeState"),
    names("fk", "Mechanism.fk"),
    names("ik", "Mechanism.ik"),
    names("place", "Mechanism.place"),
    names("jacobian", "Mechanism.jacobian"),
    names("collide", "Mechanism.collide"),
    names("dynamics", "Mechanism.dynamics"),
    names("statics", "Mechanism.statics"),
    names("field --at", "fieldVectors"),
    names("field --minima", "fieldMinima"),
    names("field --descend", "fieldDescend"),
    names("catalogues", "catalogues"),
    names("run", "runBehaviours"),
    names("gait", "gait"),
    names("cpg", "cpg"),
    names("zmp", "zmp"),
    names("walk", "walk"),
    names("plan", "plan"),
    names("arena", "arena"),
    names("routes", "routes"),
    names("components", "components"),
    names("lessons", "lessons"),
    names("check-lesson", "checkLesson"),
    names("widgets", "widgets"),
    names("pick-cell", "pickCell"),
    names("ant", "antWalk"),
    names("script exercises", "exercises"),
    names("script check", "checkScript"),
    names("script grade", "gradeScripts"),
];

const fn names(command: &'static str, js: &'static str) -> Names {
    Names { command, js }
}
