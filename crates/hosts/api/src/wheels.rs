//! Wheeled robots: what a layout can do (`analyze`), its kinematics both
//! ways (`drive`), the differential drive's closed form, and the catalogue.

use kinolab_common::FieldError;
use kinolab_wheels::{Chassis, Vector3, catalogue, closed_form, report};

use crate::{Error, Files, Operation, Source};

/// A robot: a robot file's text, a catalogue id (`tricycle` or
/// `catalogue:tricycle`), or a compact layout code
/// (`kind,alpha_deg,beta_deg,l,radius` per wheel, `;` between wheels).
pub fn robot(source: &Source) -> Result<Chassis, Error> {
    source.load("robot", "catalogue:", Chassis::from_json, |name| {
        if name.contains(',') {
            Chassis::from_compact("layout", name)
        } else {
            catalogue::robot(name)
        }
    })
}

/// `kinolab analyze`: ranks, degrees, DOF, holonomy and the ICR.
#[derive(Debug, Clone)]
pub struct Analyze {
    pub robot: Source,
}

impl Operation for Analyze {
    type Report = report::AnalysisReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        Ok(report::analysis(&robot(&self.robot)?))
    }
}

/// `kinolab drive --twist`: inverse kinematics of a robot-frame twist.
#[derive(Debug, Clone)]
pub struct DriveTwist {
    pub robot: Source,
    pub twist: [f64; 3],
    /// A heading (rad) to also give the motion in the inertial frame.
    pub theta: Option<f64>,
}

impl Operation for DriveTwist {
    type Report = report::InverseReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let chassis = robot(&self.robot)?;
        let [x, y, w] = self.twist;
        report::inverse(&chassis, Vector3::new(x, y, w), self.theta).map_err(argument("twist"))
    }
}

/// `kinolab drive --wheels`: the twist from each wheel's spin (`None`
/// where a spin is unknown).
#[derive(Debug, Clone)]
pub struct DriveWheels {
    pub robot: Source,
    pub spins: Vec<Option<f64>>,
    pub theta: Option<f64>,
}

impl Operation for DriveWheels {
    type Report = report::ForwardReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let chassis = robot(&self.robot)?;
        let wheels = chassis.wheels().len();
        if self.spins.len() != wheels {
            return Err(Error::argument(
                "wheels",
                format!(
                    "expected {wheels} spins (one per wheel of the robot, `-` or null for unknown), got {}",
                    self.spins.len()
                ),
            ));
        }
        report::forward(&chassis, &self.spins, self.theta).map_err(argument("wheels"))
    }
}

/// A problem with the twist or the spins, or with `theta`.
fn argument(name: &'static str) -> impl Fn(FieldError) -> Error {
    move |e| match e.field.as_str() {
        "theta" => Error::argument("theta", e.message),
        _ => Error::argument(name, e.to_string()),
    }
}

/// The differential drive's closed form: v, ω and the turn radius from
/// the wheel separation and the two wheels' ground speeds.
#[derive(Debug, Clone, Copy)]
pub struct DifferentialDrive {
    pub track: f64,
    pub v_left: f64,
    pub v_right: f64,
}

impl Operation for DifferentialDrive {
    type Report = closed_form::DiffDriveMotion;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        closed_form::differential_drive(self.track, self.v_left, self.v_right)
            .map_err(|e| Error::argument(e.field.clone(), e.message))
    }
}

/// The catalogue: each robot's id, name and summary.
#[derive(Debug, Clone, Copy)]
pub struct Robots;

impl Operation for Robots {
    type Report = &'static [catalogue::CatalogueEntry];
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        Ok(catalogue::CATALOGUE)
    }
}

/// One robot as a robot file (degrees, as people write them).
#[derive(Debug, Clone)]
pub struct RobotFile {
    pub robot: Source,
}

impl Operation for RobotFile {
    type Report = kinolab_wheels::RobotFile;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        Ok(robot(&self.robot)?.file())
    }
}
