//! Wheeled-robot kinematics, as in Siegwart, Nourbakhsh & Scaramuzza ch. 3
//! (with the corrections of the lab's reference sheet).
//!
//! - [`Wheel`] — one wheel and its rolling and sliding rows;
//! - [`Chassis`] — validated wheels, steering inputs, J₁, J₂, C₁;
//! - [`Analysis`] — rank C₁, δm, δs, δM, DOF, holonomy and the [`Icr`];
//! - [`Chassis::inverse`] / [`Chassis::forward`] — kinematics both ways;
//! - [`catalogue`] — classic robots; [`closed_form`] — textbook formulas
//!   the general model is checked against;
//! - robot files and the compact layout code ([`Chassis::from_json`],
//!   [`Chassis::from_compact`]); [`challenge`] — graded exercises.
//!
//! Conventions: robot frame x forward, y left; angles in radians; a twist is
//! ξ̇_R = (ẋ_R, ẏ_R, θ̇) in the robot frame.

mod analysis;
pub mod catalogue;
pub mod challenge;
mod chassis;
pub mod closed_form;
mod error;
mod file;
mod kinematics;
pub mod report;
mod span;
mod wheel;

pub use analysis::{Analysis, Disagreement, Icr, lie_closure, twist_icr};
pub use chassis::{Chassis, MAX_WHEELS, SteeringInput};
pub use error::FieldError;
pub use file::RobotFile;
pub use kinematics::{
    ForwardSolution, InverseSolution, Violation, WheelCommand, integrate, rotation, to_inertial,
};
pub use nalgebra::{Matrix3, Vector3};
pub use span::{RANK_TOLERANCE, Span3};
pub use wheel::{SlidingExtra, Wheel, WheelKind, WheelRows};
