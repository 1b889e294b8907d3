//! Motion control for a differential-drive robot, as in Siegwart,
//! Nourbakhsh & Scaramuzza §3.6, with the lab's reference sheet.
//!
//! - [`Plan`] — open loop: lines, arcs and turns with trapezoidal
//!   [`Profile`]s, and the wheel commands they imply;
//! - [`Polar`] and [`Gains`] — the polar go-to-pose controller, its
//!   linearisation and the stability conditions ([`Stability`]);
//! - [`Run`] — the simulator (RK4 with the controller inside every stage;
//!   saturation, sampled-data control, seeded [`Noise`]) and its
//!   [`Trajectory`] and metrics;
//! - [`batch`] — many starts at once; [`exercise`] — graded tasks;
//! - run files and the JSON reports the command line and the JS API share
//!   ([`file`], [`report`]).
//!
//! Conventions: world frame x right, y up; robot x forward; angles in
//! radians; v in m/s, ω in rad/s.

pub mod batch;
mod error;
pub mod exercise;
pub mod file;
pub mod law;
mod noise;
mod plan;
mod polar;
mod pose;
pub mod report;
mod sim;

pub use error::FieldError;
pub use noise::{NOISE_INTERVAL, Noise};
pub use plan::{Limits, MAX_SEGMENTS, Plan, Profile, Scheduled, Segment};
pub use polar::{Condition, Direction, Gains, Polar, Stability, TEXTBOOK_GAINS};
pub use pose::Pose;
pub use sim::{
    Divergence, DriveModel, Driver, MAX_SAMPLES, MAX_STEPS, RUNAWAY_DISTANCE, Run, Sample,
    Tolerance, Trajectory,
};
