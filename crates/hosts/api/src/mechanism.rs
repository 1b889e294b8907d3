//! Mechanism models: the catalogue, a model's structure and home state,
//! forward and inverse kinematics, every body's frame, Jacobians and
//! collisions. A model is stateless: every query carries the joint values
//! it asks about, so one loaded model answers any number of them ([`On`]
//! loads it for one query; the JavaScript `Mechanism` keeps it).

use kinolab_common::FieldError;
use kinolab_mechanism::{
    Goal, Model, Obstacle, Options, OutsideLimit, Plane, Pose, Target, Vector3, catalogue, file,
    report, urdf,
};
use serde::{Deserialize, Serialize};

use crate::{Error, Files, Operation, Source};

/// The most model files one request reads through mounts, all levels
/// together: a file that mounts the next several times, down many levels,
/// would otherwise read exponentially many.
pub const MAX_MOUNTED_FILES: usize = 64;
/// The deepest chain of files mounting files.
pub const MAX_MOUNT_DEPTH: usize = 16;

/// A model: a model file's text (its mounts read through `files`), a URDF
/// file's text, or a catalogue id (`puma560` or `catalogue:puma560`).
pub fn model(source: &Source, files: &mut dyn Files) -> Result<Model, Error> {
    if let Source::Text(text) = source
        && urdf::looks_like_xml(text)
    {
        return robot(source).map(|r| r.model);
    }
    let mut mounts = Mounts {
        files,
        read: 0,
        exceeded: None,
    };
    let loaded = source.load(
        "model",
        "catalogue:",
        |text| mounts.model("", text, 0),
        catalogue::mechanism,
    );
    match (loaded, mounts.exceeded) {
        // The bound is the news, not the chain of mounts that reached it.
        (Err(_), Some(bound)) => Err(Error::input("model", FieldError::new("", bound))),
        (result, _) => result,
    }
}

/// A robot from a URDF file's text.
pub fn robot(source: &Source) -> Result<urdf::Robot, Error> {
    source.file_only("robot", "a URDF file", urdf::read)
}

/// Files read through mounts so far, and the bound hit, if one was.
struct Mounts<'f> {
    files: &'f mut dyn Files,
    read: usize,
    exceeded: Option<String>,
}

impl Mounts<'_> {
    /// Parse the model file `name` whose mounted files `self.files` reads.
    fn model(&mut self, name: &str, text: &str, depth: usize) -> Result<Model, FieldError> {
        file::from_json_with(text, &mut |mounted: &str| {
            self.read += 1;
            if depth >= MAX_MOUNT_DEPTH {
                self.exceeded = Some(format!("mounts nested more than {MAX_MOUNT_DEPTH} deep"));
            } else if self.read > MAX_MOUNTED_FILES {
                self.exceeded = Some(format!(
                    "mounts read more than {MAX_MOUNTED_FILES} model files in all \
                     (a file mounted several times, mounting others, multiplies them)"
                ));
            }
            if let Some(bound) = &self.exceeded {
                return Err(FieldError::new("", bound.clone()));
            }
            let (sub, text) = self
                .files
                .read(name, mounted)
                .map_err(|m| FieldError::new("", m))?;
            self.model(&sub, &text, depth + 1)
        })
    }
}

/// A question about one loaded model.
pub trait Query {
    type Report: Serialize;
    fn ask(&self, model: &Model) -> Result<Self::Report, Error>;
}

/// A query about the model `model`: load it, then ask.
#[derive(Debug, Clone)]
pub struct On<Q> {
    pub model: Source,
    pub query: Q,
}

impl<Q: Query> Operation for On<Q> {
    type Report = Q::Report;
    fn report(&self, files: &mut dyn Files) -> Result<Self::Report, Error> {
        self.query.ask(&model(&self.model, files)?)
    }
}

/// The report of `query` on a loaded model, as [`crate::answer`] gives it.
pub fn answer_on<Q: Query>(model: &Model, query: &Q) -> Result<serde_json::Value, Error> {
    crate::tidy(&query.ask(model)?)
}

/// An answer about one state of a model, with the joints whose values lie
/// outside their limits (`outside_limits`, left out when there are none).
/// Such a state is computed all the same: kinematics and dynamics are
/// geometry and physics, not a safety check.
#[derive(Debug, Clone, Serialize)]
pub struct Checked<R> {
    #[serde(flatten)]
    pub answer: R,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub outside_limits: Vec<OutsideLimit>,
}

impl<R> Checked<R> {
    pub fn of(model: &Model, q: &[f64], answer: R) -> Self {
        Checked {
            answer,
            outside_limits: model.outside_limits(q),
        }
    }
}

/// `q` checked against the model's joint count, with followers set from
/// their leaders and loops closed, as every query sees it.
fn settled(model: &Model, argument: &str, mut q: Vec<f64>) -> Result<Vec<f64>, Error> {
    joint_count(model, argument, &q)?;
    model
        .close_loops(&mut q)
        .map_err(|e| Error::argument(argument, e.to_string()))?;
    Ok(q)
}

fn joint_count(model: &Model, argument: &str, q: &[f64]) -> Result<(), Error> {
    if q.len() == model.dof() {
        return Ok(());
    }
    Err(Error::argument(
        argument,
        format!(
            "`{}` has {} joints, got {} values",
            model.name(),
            model.dof(),
            q.len()
        ),
    ))
}

fn frame(
    model: &Model,
    name: Option<&str>,
) -> Result<(String, kinolab_mechanism::FrameRef), Error> {
    let name = name.unwrap_or("tool");
    let f = model
        .frame(name)
        .map_err(|e| Error::argument("frame", e.message))?;
    Ok((name.to_owned(), f))
}

/// One catalogue mechanism.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Entry {
    pub id: &'static str,
    pub name: &'static str,
    pub summary: &'static str,
}

/// The built-in mechanisms.
#[derive(Debug, Clone, Copy)]
pub struct Mechanisms;

impl Operation for Mechanisms {
    type Report = Vec<Entry>;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        Ok(catalogue::CATALOGUE
            .iter()
            .map(|&(id, name, summary)| Entry { id, name, summary })
            .collect())
    }
}

/// A model's structure: joints, bodies, frames, couplings, loops, shapes.
#[derive(Debug, Clone, Copy)]
pub struct Describe;

impl Query for Describe {
    type Report = report::Description;
    fn ask(&self, model: &Model) -> Result<Self::Report, Error> {
        Ok(report::describe(model))
    }
}

/// The zero state, clamped into the limits, followers set and loops closed.
#[derive(Debug, Clone, Copy)]
pub struct HomeState;

impl Query for HomeState {
    type Report = Vec<f64>;
    fn ask(&self, model: &Model) -> Result<Self::Report, Error> {
        model.home_state().map_err(|e| Error::input("model", e))
    }
}

/// `kinolab fk`: the 4×4 pose of a frame (default: the tool).
#[derive(Debug, Clone)]
pub struct Fk {
    pub q: Vec<f64>,
    pub frame: Option<String>,
}

impl Query for Fk {
    type Report = Checked<report::ForwardReport>;
    fn ask(&self, model: &Model) -> Result<Self::Report, Error> {
        let q = settled(model, "q", self.q.clone())?;
        let (name, f) = frame(model, self.frame.as_deref())?;
        let pose = model
            .pose(&q, &f)
            .map_err(|e| Error::argument("q", e.to_string()))?;
        Ok(Checked::of(model, &q, report::forward(&name, &pose)))
    }
}

/// Every body's frame.
#[derive(Debug, Clone)]
pub struct Place {
    pub q: Vec<f64>,
}

impl Query for Place {
    type Report = Checked<report::PlacementReport>;
    fn ask(&self, model: &Model) -> Result<Self::Report, Error> {
        let q = settled(model, "q", self.q.clone())?;
        let placed = model
            .place(&q)
            .map_err(|e| Error::argument("q", e.to_string()))?;
        Ok(Checked::of(model, &q, report::placement(model, &placed)))
    }
}

/// The 6 × dof geometric Jacobian of a frame (default: the tool).
#[derive(Debug, Clone)]
pub struct Jacobian {
    pub q: Vec<f64>,
    pub frame: Option<String>,
}

impl Query for Jacobian {
    type Report = Checked<report::JacobianReport>;
    fn ask(&self, model: &Model) -> Result<Self::Report, Error> {
        let q = settled(model, "q", self.q.clone())?;
        let (_, f) = frame(model, self.frame.as_deref())?;
        let jac = model
            .jacobian(&q, &f)
            .map_err(|e| Error::argument("q", e.to_string()))?;
        Ok(Checked::of(model, &q, report::jacobian(&jac)))
    }
}

/// `kinolab ik`: joint values that put a frame at a target: a position, a
/// rotation (row-major) or both, optionally relative to another frame.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Ik {
    /// The frame to move (default `tool`).
    pub frame: Option<String>,
    pub position: Option<[f64; 3]>,
    /// Row-major 3×3 rotation.
    pub rotation: Option<[f64; 9]>,
    /// Give the target in this frame instead of the world.
    pub relative_to: Option<String>,
    /// Where the search starts (default: the home state).
    pub seed: Option<Vec<f64>>,
    pub max_iterations: Option<usize>,
    pub restarts: Option<usize>,
}

/// The most iterations and restarts a request may ask of the solver.
const MAX_ITERATIONS: usize = 1000;
const MAX_RESTARTS: usize = 200;

impl Query for Ik {
    type Report = report::InverseReport;
    fn ask(&self, model: &Model) -> Result<Self::Report, Error> {
        let r = self;
        let (_, f) = frame(model, r.frame.as_deref())?;
        let target = target(r.position, r.rotation)?;
        let goal = match &r.relative_to {
            None => Goal::new(f, target),
            Some(base) => {
                let base = model
                    .frame(base)
                    .map_err(|e| Error::argument("relative_to", e.message))?;
                Goal::relative(f, target, base)
            }
        };
        let seed = match &r.seed {
            Some(q) => {
                joint_count(model, "seed", q)?;
                q.clone()
            }
            None => model.home_state().map_err(|e| Error::input("model", e))?,
        };
        let defaults = Options::default();
        let options = Options {
            max_iterations: r
                .max_iterations
                .unwrap_or(defaults.max_iterations)
                .min(MAX_ITERATIONS),
            restarts: r.restarts.unwrap_or(defaults.restarts).min(MAX_RESTARTS),
            ..defaults
        };
        let solution = model
            .solve(&[goal], &seed, &options)
            .map_err(|e| Error::input("model", e))?;
        Ok(report::inverse(&solution))
    }
}

/// A target from an optional position and an optional row-major rotation.
fn target(position: Option<[f64; 3]>, rotation: Option<[f64; 9]>) -> Result<Target, Error> {
    let rotation = match rotation {
        None => None,
        Some(m) => {
            let h = [
                [m[0], m[1], m[2], 0.0],
                [m[3], m[4], m[5], 0.0],
                [m[6], m[7], m[8], 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ];
            let pose = file::pose_from_matrix("rotation", &h)
                .map_err(|e| Error::argument("rotation", e.message))?;
            Some(pose.rotation)
        }
    };
    if let Some(p) = position {
        for (i, v) in p.iter().enumerate() {
            kinolab_common::error::finite(format!("position[{i}]"), *v)
                .map_err(|e| Error::argument("position", e.to_string()))?;
        }
    }
    match (position, rotation) {
        (Some(p), Some(rot)) => Ok(Target::Pose(Pose::from_parts(Vector3::from(p).into(), rot))),
        (Some(p), None) => Ok(Target::Position(Vector3::from(p))),
        (None, Some(rot)) => Ok(Target::Orientation(rot)),
        (None, None) => Err(Error::argument(
            "position",
            "give a position, a rotation or both",
        )),
    }
}

/// An obstacle in a view plane: `{ circle: [x, y, r] }` or
/// `{ rect: [x, y, halfW, halfH] }`.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObstacleSpec {
    pub circle: Option<[f64; 3]>,
    pub rect: Option<[f64; 4]>,
}

/// Colliding body pairs and the clearance, in a view plane (`plan`: x–y,
/// `side`: x–z), among the bodies' shapes and against obstacles.
#[derive(Debug, Clone)]
pub struct Collide {
    pub q: Vec<f64>,
    pub plane: String,
    pub obstacles: Vec<ObstacleSpec>,
}

impl Query for Collide {
    type Report = report::CollisionReport;
    fn ask(&self, model: &Model) -> Result<Self::Report, Error> {
        let q = settled(model, "q", self.q.clone())?;
        let plane = match self.plane.as_str() {
            "plan" => Plane::Plan,
            "side" => Plane::Side,
            other => {
                return Err(Error::argument(
                    "plane",
                    format!("`{other}` is not `plan` or `side`"),
                ));
            }
        };
        let obstacles = self
            .obstacles
            .iter()
            .enumerate()
            .map(|(i, o)| match (o.circle, o.rect) {
                (Some([x, y, r]), None) => Ok(Obstacle::Circle {
                    center: [x, y],
                    radius: r,
                }),
                (None, Some([x, y, w, h])) => Ok(Obstacle::Rect {
                    center: [x, y],
                    half: [w, h],
                }),
                _ => Err(Error::argument(
                    "obstacles",
                    format!("[{i}]: give `circle` or `rect`"),
                )),
            })
            .collect::<Result<Vec<_>, _>>()?;
        let collide = |e: FieldError| Error::argument("obstacles", e.to_string());
        let found = model.collisions(&q, plane, &obstacles).map_err(collide)?;
        let clearance = model.clearance(&q, plane, &obstacles).map_err(collide)?;
        Ok(report::collisions(model, &found, clearance))
    }
}

/// `kinolab export-urdf MODEL`: the model as URDF text, and what URDF
/// could not say (`Mechanism.toUrdf()` in JavaScript).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ExportUrdf;

#[derive(Debug, Clone, Serialize)]
pub struct Exported {
    pub urdf: String,
    pub notices: Vec<String>,
}

impl Query for ExportUrdf {
    type Report = Exported;
    fn ask(&self, model: &Model) -> Result<Self::Report, Error> {
        let written = urdf::write(model);
        Ok(Exported {
            urdf: written.text,
            notices: written.notices,
        })
    }
}
