//! Mechanism queries on plain JSON values: the logic behind the JS
//! `Mechanism` class, runnable natively so it can be compared with
//! `kinolab fk` and `kinolab ik`.

use kinolab_common::FieldError;
use kinolab_mechanism::{
    Goal, Model, Obstacle, Options, Plane, Pose, Target, Vector3, catalogue, file, report,
};
use serde::Deserialize;
use serde_json::Value;

use crate::api::{Reply, arg};

fn text(e: FieldError) -> String {
    e.to_string()
}

fn reply(report: &impl serde::Serialize) -> Reply {
    kinolab_common::display::tidy_report(report).map_err(|e| e.to_string())
}

/// The built-in mechanisms: `[{ id, name, summary }]`.
pub fn mechanisms() -> Reply {
    #[derive(serde::Serialize)]
    struct Entry {
        id: &'static str,
        name: &'static str,
        summary: &'static str,
    }
    let list: Vec<Entry> = catalogue::CATALOGUE
        .iter()
        .map(|&(id, name, summary)| Entry { id, name, summary })
        .collect();
    reply(&list)
}

/// An inverse-kinematics request.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct IkRequest {
    /// The frame to move (default `tool`).
    frame: Option<String>,
    position: Option<[f64; 3]>,
    /// Row-major 3×3 rotation.
    rotation: Option<[f64; 9]>,
    /// Give the target in this frame instead of the world.
    relative_to: Option<String>,
    seed: Option<Vec<f64>>,
    max_iterations: Option<usize>,
    restarts: Option<usize>,
}

/// An obstacle: `{ circle: [x, y, r] }` or `{ rect: [x, y, halfW, halfH] }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ObstacleSpec {
    circle: Option<[f64; 3]>,
    rect: Option<[f64; 4]>,
}

/// One loaded model; every query takes the joint values.
#[derive(Debug)]
pub struct MechanismApi {
    pub model: Model,
}

impl MechanismApi {
    /// `catalogue:<id>` (or just the id), or a model file as JSON text or
    /// as an object. Mounts may name catalogue mechanisms.
    pub fn load(source: Value) -> Result<Self, String> {
        let json = match source {
            Value::String(json) => json,
            other => other.to_string(),
        };
        let trimmed = json.trim();
        let model = if trimmed.starts_with('{') {
            file::from_json(trimmed)
        } else {
            catalogue::mechanism(trimmed.strip_prefix("catalogue:").unwrap_or(trimmed))
        }
        .map_err(text)?;
        Ok(Self { model })
    }

    pub fn describe(&self) -> Reply {
        reply(&report::describe(&self.model))
    }

    pub fn home_state(&self) -> Result<Vec<f64>, String> {
        self.model.home_state().map_err(text)
    }

    /// `q` with followers set and loops closed, as every query sees it.
    fn settled(&self, mut q: Vec<f64>) -> Result<Vec<f64>, String> {
        self.model.close_loops(&mut q).map_err(text)?;
        Ok(q)
    }

    /// `kinolab fk`.
    pub fn fk(&self, q: Vec<f64>, frame: Option<&str>) -> Reply {
        let q = self.settled(q)?;
        let name = frame.unwrap_or("tool");
        let f = self.model.frame(name).map_err(text)?;
        let pose = self.model.pose(&q, &f).map_err(text)?;
        reply(&report::forward(name, &pose))
    }

    /// Every body's frame.
    pub fn place(&self, q: Vec<f64>) -> Reply {
        let q = self.settled(q)?;
        let placed = self.model.place(&q).map_err(text)?;
        reply(&report::placement(&self.model, &placed))
    }

    /// The 6 × dof geometric Jacobian of `frame` (default tool), at the
    /// settled state.
    pub fn jacobian(&self, q: Vec<f64>, frame: Option<&str>) -> Reply {
        let q = self.settled(q)?;
        let f = self.model.frame(frame.unwrap_or("tool")).map_err(text)?;
        let jac = self.model.jacobian(&q, &f).map_err(text)?;
        reply(&report::jacobian(&jac))
    }

    /// `kinolab ik` for `{ frame?, position?, rotation?, relative_to?,
    /// seed?, max_iterations?, restarts? }`; the seed defaults to the home
    /// state, as on the command line.
    pub fn ik(&self, request: Value) -> Reply {
        let r: IkRequest = arg("request", request)?;
        let frame = self
            .model
            .frame(r.frame.as_deref().unwrap_or("tool"))
            .map_err(text)?;
        let target = target(r.position, r.rotation)?;
        let goal = match &r.relative_to {
            None => Goal::new(frame, target),
            Some(base) => Goal::relative(frame, target, self.model.frame(base).map_err(text)?),
        };
        let seed = match r.seed {
            Some(q) => q,
            None => self.home_state()?,
        };
        let defaults = Options::default();
        let options = Options {
            max_iterations: r
                .max_iterations
                .unwrap_or(defaults.max_iterations)
                .min(1000),
            restarts: r.restarts.unwrap_or(defaults.restarts).min(200),
            ..defaults
        };
        let s = self.model.solve(&[goal], &seed, &options).map_err(text)?;
        reply(&report::inverse(&s))
    }

    /// Colliding pairs and clearance in the `plane` "plan" (x–y) or "side"
    /// (x–z), against `[{ circle } | { rect }]` obstacles.
    pub fn collide(&self, q: Vec<f64>, plane: &str, obstacles: Value) -> Reply {
        let q = self.settled(q)?;
        let plane = match plane {
            "plan" => Plane::Plan,
            "side" => Plane::Side,
            other => return Err(format!("plane: `{other}` is not `plan` or `side`")),
        };
        let specs: Vec<ObstacleSpec> = if obstacles.is_null() {
            Vec::new()
        } else {
            arg("obstacles", obstacles)?
        };
        let obstacles = specs
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
                _ => Err(format!("obstacles[{i}]: give `circle` or `rect`")),
            })
            .collect::<Result<Vec<_>, _>>()?;
        let found = self.model.collisions(&q, plane, &obstacles).map_err(text)?;
        let clearance = self.model.clearance(&q, plane, &obstacles).map_err(text)?;
        reply(&report::collisions(&self.model, &found, clearance))
    }
}

/// A target from an optional position and an optional row-major rotation.
pub fn target(position: Option<[f64; 3]>, rotation: Option<[f64; 9]>) -> Result<Target, String> {
    let rotation = match rotation {
        None => None,
        Some(m) => {
            let h = [
                [m[0], m[1], m[2], 0.0],
                [m[3], m[4], m[5], 0.0],
                [m[6], m[7], m[8], 0.0],
                [0.0, 0.0, 0.0, 1.0],
            ];
            Some(
                file::pose_from_matrix("rotation", &h)
                    .map_err(text)?
                    .rotation,
            )
        }
    };
    match (position, rotation) {
        (Some(p), Some(rot)) => Ok(Target::Pose(Pose::from_parts(Vector3::from(p).into(), rot))),
        (Some(p), None) => Ok(Target::Position(Vector3::from(p))),
        (None, Some(rot)) => Ok(Target::Orientation(rot)),
        (None, None) => Err("request: give a position, a rotation or both".into()),
    }
}
