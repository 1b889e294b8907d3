//! `kinolab analyze`, `drive`, `differential-drive` and `robots`:
//! wheeled-robot kinematics on robot files (`*.robot.json`, see the
//! contract) or catalogue robots.

use std::path::PathBuf;

use clap::Subcommand;
use kinolab_api::wheels;
use serde_json::Value;

use crate::Failure;
use crate::args::fixed;
use crate::ask::{ask, source};

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Rank of C1, the degrees of mobility, steerability and maneuverability, DOF and the ICR of a robot file.
    Analyze {
        /// A robot file (`*.robot.json`), or `catalogue:<id>`.
        robot: PathBuf,
    },
    /// Wheel kinematics: --twist gives each wheel's spin and steering (inverse); --wheels gives the twist (forward).
    Drive {
        /// A robot file (`*.robot.json`), or `catalogue:<id>`.
        robot: PathBuf,
        /// Robot-frame twist, m/s and rad/s: VX,VY,OMEGA
        #[arg(long, value_name = "VX,VY,OMEGA", allow_hyphen_values = true)]
        twist: Option<String>,
        /// One spin per wheel in file order, rad/s; `-` where unknown: S1,S2,...
        #[arg(long, value_name = "S1,S2,...", allow_hyphen_values = true)]
        wheels: Option<String>,
        /// Heading θ (rad) to also report the motion in the inertial frame.
        #[arg(long, allow_hyphen_values = true)]
        theta: Option<f64>,
    },
    /// The differential drive's closed form: v, ω and the turn radius from the wheel separation and wheel speeds.
    DifferentialDrive {
        /// Wheel separation W, m.
        #[arg(long, allow_hyphen_values = true)]
        track: f64,
        /// Left wheel's ground speed, m/s.
        #[arg(long, allow_hyphen_values = true)]
        left: f64,
        /// Right wheel's ground speed, m/s.
        #[arg(long, allow_hyphen_values = true)]
        right: f64,
    },
    /// List the catalogue robots, or print one as a robot file.
    Robots {
        /// A catalogue id such as `tricycle`, or a layout code.
        id: Option<String>,
    },
}

pub(crate) fn run(command: Command) -> Result<Value, Failure> {
    match command {
        Command::Analyze { robot } => ask(
            &wheels::Analyze {
                robot: source(&robot)?,
            },
            Some(&robot),
        ),
        Command::Drive {
            robot,
            twist,
            wheels,
            theta,
        } => drive(robot, twist, wheels, theta),
        Command::DifferentialDrive { track, left, right } => ask(
            &wheels::DifferentialDrive {
                track,
                v_left: left,
                v_right: right,
            },
            None,
        ),
        Command::Robots { id: None } => ask(&wheels::Robots, None),
        Command::Robots { id: Some(id) } => ask(
            &wheels::RobotFile {
                robot: kinolab_api::Source::Named(id),
            },
            None,
        ),
    }
}

fn drive(
    robot: PathBuf,
    twist: Option<String>,
    spins: Option<String>,
    theta: Option<f64>,
) -> Result<Value, Failure> {
    match (twist, spins) {
        (Some(text), None) => ask(
            &wheels::DriveTwist {
                robot: source(&robot)?,
                twist: fixed("twist", "VX,VY,OMEGA", &text)?,
                theta,
            },
            Some(&robot),
        ),
        (None, Some(text)) => {
            let spins = text
                .split(',')
                .map(|part| match part.trim() {
                    "-" => Ok(None),
                    other => fixed::<1>("wheels", "per wheel", other).map(|[x]| Some(x)),
                })
                .collect::<Result<_, _>>()?;
            ask(
                &wheels::DriveWheels {
                    robot: source(&robot)?,
                    spins,
                    theta,
                },
                Some(&robot),
            )
        }
        (Some(_), Some(_)) => Err(Failure(
            "drive: give either --twist (inverse kinematics) or --wheels (forward), not both"
                .into(),
        )),
        (None, None) => Err(Failure(
            "drive: give --twist VX,VY,OMEGA (inverse kinematics) or --wheels S1,S2,... (forward)"
                .into(),
        )),
    }
}
