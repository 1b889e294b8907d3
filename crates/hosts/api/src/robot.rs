//! Robots from URDF files: forward kinematics with the joints named as the
//! file names them, and a description listing the joints a user sets (the
//! file's moving joints without `mimic`, in file order).

use std::collections::BTreeMap;

use kinolab_mechanism::{file::matrix_of, report, urdf::Robot};
use serde::Serialize;

use crate::mechanism::{Checked, Ik, Query, robot};
use crate::{Error, Files, Operation, Source};

/// How a robot's joints are set.
#[derive(Debug, Clone, PartialEq)]
pub enum Setting {
    /// Every movable joint, in file order.
    All(Vec<f64>),
    /// Some joints by name; the others at zero.
    Named(Vec<(String, f64)>),
}

impl Setting {
    fn state(&self, robot: &Robot) -> Result<Vec<f64>, Error> {
        match self {
            Setting::All(q) => robot.state(q),
            Setting::Named(set) => robot.state_named(set),
        }
        .map_err(|e| {
            let option = if matches!(self, Setting::All(_)) {
                "q"
            } else {
                "set"
            };
            let message = if e.field == option {
                e.message
            } else {
                e.to_string()
            };
            Error::argument(option, message)
        })
    }
}

/// `kinolab fk ROBOT.urdf`: one link's pose, or every link's.
#[derive(Debug, Clone)]
pub struct RobotFk {
    pub robot: Source,
    pub joints: Setting,
    /// A link (default: the end of the longest chain from the root).
    pub frame: Option<String>,
    pub all_frames: bool,
}

/// One frame, or all of them by link name.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum RobotFkReport {
    One(report::ForwardReport),
    All {
        frames: BTreeMap<String, [[f64; 4]; 4]>,
    },
}

impl Operation for RobotFk {
    type Report = Checked<RobotFkReport>;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let robot = robot(&self.robot)?;
        let q = self.joints.state(&robot)?;
        let model = &robot.model;
        let placed = model
            .place(&q)
            .map_err(|e| Error::argument("q", e.to_string()))?;
        if self.all_frames {
            let frames = model
                .bodies()
                .iter()
                .zip(&placed.bodies)
                .map(|(b, pose)| (b.name.clone(), matrix_of(pose)))
                .collect();
            return Ok(Checked::of(model, &q, RobotFkReport::All { frames }));
        }
        let name = self.frame.as_deref().unwrap_or(robot.tip());
        let f = model
            .frame(name)
            .map_err(|e| Error::argument("frame", e.message))?;
        let pose = placed.bodies[f.body] * f.offset;
        Ok(Checked::of(
            model,
            &q,
            RobotFkReport::One(report::forward(name, &pose)),
        ))
    }
}

/// `kinolab describe ROBOT.urdf`: the model's structure, the joints a user
/// sets in `--q` order, and what the reading left out.
#[derive(Debug, Clone)]
pub struct RobotDescribe {
    pub robot: Source,
}

#[derive(Debug, Clone, Serialize)]
pub struct RobotDescription {
    /// The joints `--q` sets, in its order.
    pub movable: Vec<String>,
    /// The default `--frame`.
    pub tip: String,
    pub notices: Vec<String>,
    #[serde(flatten)]
    pub model: report::Description,
}

impl Operation for RobotDescribe {
    type Report = RobotDescription;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let robot = robot(&self.robot)?;
        Ok(RobotDescription {
            movable: robot.driven().map(str::to_owned).collect(),
            tip: robot.tip().to_owned(),
            notices: robot.notices.clone(),
            model: report::describe(&robot.model),
        })
    }
}

/// `kinolab ik ROBOT.urdf`: IK with the seed and the answer in `--q` order
/// (the driven joints in file order) and the frame defaulting to the tip.
#[derive(Debug, Clone)]
pub struct RobotIk {
    pub robot: Source,
    pub ik: Ik,
}

impl Operation for RobotIk {
    type Report = report::InverseReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let robot = robot(&self.robot)?;
        let seed = match &self.ik.seed {
            Some(q) => Some(
                robot
                    .state(q)
                    .map_err(|e| Error::argument("seed", e.message))?,
            ),
            None => None,
        };
        let ik = Ik {
            frame: Some(self.ik.frame.clone().unwrap_or(robot.tip().to_owned())),
            seed,
            ..self.ik.clone()
        };
        let mut answer = ik.ask(&robot.model)?;
        answer.q = robot.values(&answer.q);
        Ok(answer)
    }
}
