//! `kinolab dynamics` and `kinolab statics`: what moves a mechanism and
//! what holds it still, for a URDF file, a model file or a catalogue id.
//!
//! The joints are the model's independent variables in the model's order:
//! for a URDF file, its moving joints without `mimic` in file order (the
//! order of `fk --q`); a follower moves with its leader, which carries its
//! torque. Every vector in and out is in that order, named in `order`.

use kinolab_mechanism::Model;
use kinolab_mechanism::dynamics::statics::Load;
use serde::Serialize;

use crate::Error;
use crate::mechanism::{Checked, Query};

/// How the joints are set: every one in order, or some by name (the
/// others at zero).
#[derive(Debug, Clone, PartialEq)]
pub enum Joints {
    All(Vec<f64>),
    Named(Vec<(String, f64)>),
}

/// The model's independent variables, and the full state for `joints`.
struct Setup {
    vars: Vec<usize>,
    order: Vec<String>,
    q: Vec<f64>,
}

impl Setup {
    fn new(model: &Model, joints: &Joints) -> Result<Self, Error> {
        let vars: Vec<usize> = model.independent().collect();
        let order: Vec<String> = vars
            .iter()
            .filter_map(|&v| model.variable_joint(v).map(|j| j.name.clone()))
            .collect();
        let mut q = model.zeros();
        match joints {
            Joints::All(values) => {
                expect_len(model, "q", values.len(), vars.len(), &order)?;
                for (&v, &x) in vars.iter().zip(values) {
                    q[v] = x;
                }
            }
            Joints::Named(set) => {
                for (name, x) in set {
                    let v = model
                        .variable(name)
                        .filter(|v| vars.contains(v))
                        .ok_or_else(|| {
                            Error::argument(
                                "set",
                                format!(
                                    "`{name}` is not a joint of `{}` (joints: {})",
                                    model.name(),
                                    order.join(", ")
                                ),
                            )
                        })?;
                    q[v] = *x;
                }
            }
        }
        for (i, x) in q.iter().enumerate() {
            if !x.is_finite() {
                return Err(Error::argument("q", format!("value {i} is not finite")));
            }
        }
        model.apply_couplings(&mut q);
        Ok(Self { vars, order, q })
    }

    /// `values` in `order` spread to a model vector (followers 0); `None`
    /// gives zeros.
    fn spread(&self, model: &Model, name: &str, values: Option<&[f64]>) -> Result<Vec<f64>, Error> {
        let mut out = vec![0.0; model.dof()];
        if let Some(values) = values {
            expect_len(model, name, values.len(), self.vars.len(), &self.order)?;
            for (&v, &x) in self.vars.iter().zip(values) {
                out[v] = x;
            }
        }
        Ok(out)
    }

    /// A model vector read in `order`.
    fn pick(&self, values: &[f64]) -> Vec<f64> {
        self.vars.iter().map(|&v| values[v]).collect()
    }
}

fn expect_len(
    model: &Model,
    name: &str,
    got: usize,
    want: usize,
    order: &[String],
) -> Result<(), Error> {
    if got == want {
        return Ok(());
    }
    Err(Error::argument(
        name,
        format!(
            "`{}` has {want} joints ({}), got {got} values",
            model.name(),
            order.join(", ")
        ),
    ))
}

fn core(argument: &str) -> impl Fn(kinolab_mechanism::FieldError) -> Error + '_ {
    move |e| Error::argument(argument, e.to_string())
}

/// What to compute: the torques for accelerations, or the reverse.
#[derive(Debug, Clone, PartialEq)]
pub enum Asked {
    Inverse { qdd: Vec<f64> },
    Forward { tau: Vec<f64> },
}

/// `kinolab dynamics MODEL (--q … | --set …) [--qd …] (--qdd … | --tau …) [--gravity …]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Dynamics {
    pub joints: Joints,
    pub qd: Option<Vec<f64>>,
    pub asked: Asked,
    pub gravity: Option<[f64; 3]>,
}

/// Inverse dynamics' answer, or forward dynamics'.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum DynamicsReport {
    Inverse {
        order: Vec<String>,
        tau: Vec<f64>,
        gravity: Vec<f64>,
        mass_matrix: Vec<Vec<f64>>,
    },
    Forward {
        order: Vec<String>,
        qdd: Vec<f64>,
    },
}

impl Query for Dynamics {
    type Report = Checked<DynamicsReport>;
    fn ask(&self, model: &Model) -> Result<Self::Report, Error> {
        let s = Setup::new(model, &self.joints)?;
        let gravity = self.gravity.unwrap_or(kinolab_mechanism::dynamics::EARTH);
        let qd = s.spread(model, "qd", self.qd.as_deref())?;
        let mut work = model.dynamics();
        match &self.asked {
            Asked::Inverse { qdd } => {
                let qdd = s.spread(model, "qdd", Some(qdd))?;
                let tau = s.pick(
                    model
                        .inverse_dynamics_in(&mut work, &s.q, &qd, &qdd, gravity)
                        .map_err(core("q"))?,
                );
                let g = s.pick(
                    model
                        .gravity_in(&mut work, &s.q, gravity)
                        .map_err(core("q"))?,
                );
                let m = model.mass_matrix_in(&mut work, &s.q).map_err(core("q"))?;
                let mass_matrix = s
                    .vars
                    .iter()
                    .map(|&r| s.vars.iter().map(|&c| m[(r, c)]).collect())
                    .collect();
                let answer = DynamicsReport::Inverse {
                    order: s.order,
                    tau,
                    gravity: g,
                    mass_matrix,
                };
                Ok(Checked::of(model, &s.q, answer))
            }
            Asked::Forward { tau } => {
                if !model.has_mass() {
                    return Err(Error::argument(
                        "model",
                        format!(
                            "`{}` has no mass anywhere: no torque can accelerate it",
                            model.name()
                        ),
                    ));
                }
                let tau = s.spread(model, "tau", Some(tau))?;
                let qdd = model
                    .forward_dynamics_in(&mut work, &s.q, &qd, &tau, gravity)
                    .map_err(core("model"))?;
                let answer = DynamicsReport::Forward {
                    qdd: s.pick(qdd),
                    order: s.order,
                };
                Ok(Checked::of(model, &s.q, answer))
            }
        }
    }
}

/// A load: a force and a moment the world applies at a frame's origin.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadSpec {
    pub frame: String,
    pub force: [f64; 3],
    pub moment: [f64; 3],
}

/// Joint stiffness (N·m/rad or N/m): one value for every joint, or one
/// for each joint by name.
#[derive(Debug, Clone, PartialEq)]
pub enum Stiffness {
    All(f64),
    Named(Vec<(String, f64)>),
}

/// `kinolab statics MODEL (--q … | --set …) [--load …]… [--stiffness …] [--frame …] [--gravity …]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Statics {
    pub joints: Joints,
    pub loads: Vec<LoadSpec>,
    pub stiffness: Option<Stiffness>,
    pub frame: Option<String>,
    pub gravity: Option<[f64; 3]>,
}

#[derive(Debug, Clone, Serialize)]
pub struct StaticsReport {
    pub order: Vec<String>,
    pub gravity: Vec<f64>,
    pub load: Vec<f64>,
    pub total: Vec<f64>,
    pub mass: f64,
    pub com: [f64; 3],
    #[serde(skip_serializing_if = "Option::is_none")]
    pub deflection: Option<Vec<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sag: Option<[f64; 3]>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub frame: Option<String>,
}

/// A frame by name; by default the model's `tool`, or else the end of its
/// longest chain (a URDF file's tip, as `fk` takes it).
fn frame_named(
    model: &Model,
    name: Option<&str>,
    argument: &str,
) -> Result<(String, kinolab_mechanism::FrameRef), Error> {
    let name = match name {
        Some(n) => n.to_owned(),
        None if model.frame("tool").is_ok() => "tool".to_owned(),
        None => model.tip().to_owned(),
    };
    let f = model
        .frame(&name)
        .map_err(|e| Error::argument(argument, e.message))?;
    Ok((name, f))
}

impl Query for Statics {
    type Report = Checked<StaticsReport>;
    fn ask(&self, model: &Model) -> Result<Self::Report, Error> {
        let s = Setup::new(model, &self.joints)?;
        let gravity = self.gravity.unwrap_or(kinolab_mechanism::dynamics::EARTH);
        let loads = self
            .loads
            .iter()
            .map(|l| {
                let (_, frame) = frame_named(model, Some(&l.frame), "load")?;
                Ok(Load {
                    frame,
                    force: l.force,
                    moment: l.moment,
                })
            })
            .collect::<Result<Vec<_>, Error>>()?;
        let held = model.hold(&s.q, &loads, gravity).map_err(core("q"))?;
        let (mass, com) = model.mass_and_centre(&s.q).map_err(core("q"))?;
        let mut report = StaticsReport {
            order: s.order.clone(),
            gravity: s.pick(&held.gravity),
            load: s.pick(&held.load),
            total: s.pick(&held.total),
            mass,
            com,
            deflection: None,
            sag: None,
            frame: None,
        };
        if let Some(k) = &self.stiffness {
            let mut per = vec![0.0; model.dof()];
            match k {
                Stiffness::All(k) => per.iter_mut().for_each(|x| *x = *k),
                Stiffness::Named(set) => {
                    let mut named = vec![None; model.dof()];
                    for (name, k) in set {
                        let v = model
                            .variable(name)
                            .filter(|v| s.vars.contains(v))
                            .ok_or_else(|| {
                                Error::argument(
                                    "stiffness",
                                    format!(
                                        "`{name}` is not a joint (joints: {})",
                                        s.order.join(", ")
                                    ),
                                )
                            })?;
                        named[v] = Some(*k);
                    }
                    for &v in &s.vars {
                        per[v] = named[v].ok_or_else(|| {
                            let name = model.variable_joint(v).map_or("?", |j| j.name.as_str());
                            Error::argument(
                                "stiffness",
                                format!("no stiffness for joint `{name}`: give every joint one"),
                            )
                        })?;
                    }
                }
            }
            let (name, frame) = frame_named(model, self.frame.as_deref(), "frame")?;
            let sag = model
                .sag(&s.q, &held.total, &per, &frame)
                .map_err(core("stiffness"))?;
            report.deflection = Some(s.pick(&sag.deflection));
            report.sag = Some(sag.sag);
            report.frame = Some(name);
        }
        Ok(Checked::of(model, &s.q, report))
    }
}
