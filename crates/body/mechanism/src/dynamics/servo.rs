//! An arm under control: every control period a controller is asked for
//! the joint torques, which the motors hold until the next period, while
//! the arm's own dynamics (with any payload at its tool) play out under
//! gravity. The controller may be a learner's script,
//! `control(q, qd, target, payload)` answering one torque per joint.

use kinolab_script::value::{number, numbers};

/// A controller: the time, the joint angles and their rates in, one torque
/// per joint out.
pub type Controller<'a> = dyn FnMut(f64, &[f64], &[f64]) -> Result<Vec<f64>, ScriptError> + 'a;
use kinolab_script::{Dynamic, Script, ScriptError, Signature};
use nalgebra::Vector3;

use super::EARTH;
use crate::error::FieldError;
use crate::inertial::{Rigid, cross_matrix};
use crate::model::{FrameRef, Model};

/// The function a learner's arm controller defines.
pub const SIGNATURE: Signature = Signature {
    name: "control",
    params: &["q", "qd", "target", "payload"],
};

/// One run of an arm under control.
#[derive(Debug, Clone, PartialEq)]
pub struct Servo {
    /// Where the arm starts (at rest), and where it is asked to go, rad.
    pub start: Vec<f64>,
    pub target: Vec<f64>,
    /// The mass held at the tool, kg.
    pub payload: f64,
    /// s.
    pub duration: f64,
    /// How often the controller is asked, Hz.
    pub rate: f64,
    /// The largest torque any motor gives, N·m: a larger command is the
    /// controller's fault (the run stops there).
    pub torque_limit: f64,
}

/// The integration step, s.
const DT: f64 = 0.001;

/// The arm at one control period.
#[derive(Debug, Clone, PartialEq)]
pub struct ServoSample {
    pub t: f64,
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    /// The torques commanded for the period that starts here.
    pub tau: Vec<f64>,
}

/// How a run went.
#[derive(Debug, Clone, PartialEq)]
pub struct ServoRun {
    pub samples: Vec<ServoSample>,
    /// Why the run stopped early: a command over the limit, or the
    /// controller's error.
    pub stopped: Option<Stop>,
}

/// Why a run stopped early.
#[derive(Debug, Clone, PartialEq)]
pub enum Stop {
    /// Joint `joint` was asked for `tau` at `t`, over the limit.
    OverLimit { joint: usize, tau: f64, t: f64 },
    /// The controller failed.
    Error(ScriptError),
}

impl Model {
    /// The same arm holding `mass` kg, a point at `frame`'s origin.
    pub fn carrying(&self, frame: &FrameRef, mass: f64) -> Result<Model, FieldError> {
        if !(mass.is_finite() && mass >= 0.0) {
            return Err(FieldError::new(
                "payload",
                format!("must be 0 kg or more, got {mass}"),
            ));
        }
        let mut m = self.clone();
        let c = frame.offset.translation.vector;
        let cx = cross_matrix(&c);
        m.rigid[frame.body].add(&Rigid {
            m: mass,
            h: c * mass,
            io: -(cx * cx) * mass,
        });
        m.tree = super::tree::Tree::of(&m);
        Ok(m)
    }

    /// Run `servo`, asking `control(t, q, qd)` for the torques each
    /// period. The arm must have mass; its loops, if any, are refused.
    pub fn servo(
        &self,
        servo: &Servo,
        control: &mut Controller<'_>,
    ) -> Result<ServoRun, FieldError> {
        let n = self.dof();
        for (name, v) in [("start", &servo.start), ("target", &servo.target)] {
            if v.len() != n {
                return Err(FieldError::new(
                    name,
                    format!("{n} joint values, got {}", v.len()),
                ));
            }
        }
        kinolab_common::error::positive("rate", servo.rate)?;
        kinolab_common::error::positive("torque_limit", servo.torque_limit)?;
        kinolab_common::error::in_range("duration", servo.duration, 0.0, 120.0)?;
        let period = (1.0 / (servo.rate * DT)).round().max(1.0) as usize;
        let periods = (servo.duration * servo.rate).round() as usize;
        let mut work = self.dynamics();
        let (mut q, mut qd) = (servo.start.clone(), vec![0.0; n]);
        let mut samples = Vec::with_capacity(periods + 1);
        for k in 0..=periods {
            let t = k as f64 / servo.rate;
            let tau = match control(t, &q, &qd) {
                Ok(tau) => tau,
                Err(e) => {
                    return Ok(ServoRun {
                        samples,
                        stopped: Some(Stop::Error(e)),
                    });
                }
            };
            let over = tau.iter().position(|x| x.abs() > servo.torque_limit);
            samples.push(ServoSample {
                t,
                q: q.clone(),
                qd: qd.clone(),
                tau: tau.clone(),
            });
            if let Some(joint) = over {
                let stop = Stop::OverLimit {
                    joint,
                    tau: tau[joint],
                    t,
                };
                return Ok(ServoRun {
                    samples,
                    stopped: Some(stop),
                });
            }
            if k == periods {
                break;
            }
            let held = |_: &[f64]| tau.clone();
            for _ in 0..period {
                super::motion::rk4(self, &mut work, &mut q, &mut qd, DT, EARTH, &held)?;
            }
        }
        Ok(ServoRun {
            samples,
            stopped: None,
        })
    }

    /// [`Model::servo`] with a learner's controller, `source`.
    pub fn servo_script(&self, servo: &Servo, source: &str) -> Result<ServoRun, FieldError> {
        let mut script = match Script::compile(source, SIGNATURE) {
            Ok(s) => s,
            Err(e) => {
                return Ok(ServoRun {
                    samples: Vec::new(),
                    stopped: Some(Stop::Error(e)),
                });
            }
        };
        let n = self.dof();
        let (target, payload) = (numbers(&servo.target), number(servo.payload));
        self.servo(servo, &mut |t, q, qd| {
            let args = vec![numbers(q), numbers(qd), target.clone(), payload.clone()];
            let call = script.call(args, t)?;
            torques(&call.value, n, t).map_err(|e| script.place(e))
        })
    }
}

/// The script's answer as `n` finite torques.
fn torques(value: &Dynamic, n: usize, t: f64) -> Result<Vec<f64>, ScriptError> {
    let wanted = format!("a list of {n} torques, one per joint (N·m)");
    let shape = || {
        ScriptError::shape(
            SIGNATURE,
            &wanted,
            &kinolab_script::value::describe(value),
            t,
        )
    };
    let items = value.as_array_ref().map_err(|_| shape())?;
    if items.len() != n {
        return Err(shape());
    }
    items
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let x = kinolab_script::value::float(v).ok_or_else(shape)?;
            if x.is_finite() {
                Ok(x)
            } else {
                Err(ScriptError::not_finite(
                    SIGNATURE,
                    &format!("joint {}'s torque", i + 1),
                    x,
                    t,
                ))
            }
        })
        .collect()
}

/// The tool's position, for graders and widgets.
pub fn tool_at(model: &Model, tool: &FrameRef, q: &[f64]) -> Option<Vector3<f64>> {
    model.pose(q, tool).ok().map(|p| p.translation.vector)
}
