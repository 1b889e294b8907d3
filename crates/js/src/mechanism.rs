//! Mechanisms for JavaScript: one loaded model, any number of states.
//!
//! ```js
//! const puma = kinolab.Mechanism.load("catalogue:puma560");
//! puma.fk([0, 0, 0, 0, 0, 0]).matrix[0][3];            // 0.4521
//! const s = puma.ik({ position: [0.5, 0.1, 0.9] });      // { q, converged, … }
//! puma.collide(s.q, "side", [{ circle: [0.6, 0.8, 0.1] }]).colliding;
//! ```
//!
//! The object holds only the model, which never changes; every call takes
//! the joint values, so many views can share one model (the CLARAty way).

use kinolab_mechanism::{
    Goal, MechanismError, Model, Obstacle, Options, Plane, Pose, Target, Vector3, catalogue, file,
    report,
};
use serde::Deserialize;
use wasm_bindgen::prelude::*;

use crate::{from_js, json_to_js};

fn err(e: MechanismError) -> JsError {
    JsError::new(&e.to_string())
}

/// The built-in mechanisms: `[{ id, name, summary }]`.
#[wasm_bindgen]
pub fn mechanisms() -> Result<JsValue, JsError> {
    let list: Vec<serde_json::Value> = catalogue::CATALOGUE
        .iter()
        .map(
            |(id, name, summary)| serde_json::json!({ "id": id, "name": name, "summary": summary }),
        )
        .collect();
    json_to_js(&serde_json::Value::Array(list))
}

/// A loaded mechanism model.
#[wasm_bindgen]
#[derive(Debug)]
pub struct Mechanism {
    model: Model,
}

/// An inverse-kinematics request.
#[derive(Deserialize)]
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
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ObstacleSpec {
    circle: Option<[f64; 3]>,
    rect: Option<[f64; 4]>,
}

#[wasm_bindgen]
impl Mechanism {
    /// `catalogue:<id>` (or just the id), or a model file as JSON text or
    /// as an object. Mounts may name catalogue mechanisms.
    pub fn load(source: JsValue) -> Result<Mechanism, JsError> {
        let text = match source.as_string() {
            Some(text) => text,
            None => from_js::<serde_json::Value>("model", source)?.to_string(),
        };
        let trimmed = text.trim();
        let model = if trimmed.starts_with('{') {
            file::from_json(trimmed)
        } else {
            catalogue::mechanism(trimmed.strip_prefix("catalogue:").unwrap_or(trimmed))
        }
        .map_err(err)?;
        Ok(Mechanism { model })
    }

    /// `{ name, dof, variables: [{ name, type, limits, role }], joints,
    /// bodies, frames, groups, couplings, loops, shapes, solvers }`.
    pub fn describe(&self) -> Result<JsValue, JsError> {
        json_to_js(&report::describe(&self.model))
    }

    /// The zero state with couplings applied and loops closed.
    #[wasm_bindgen(js_name = homeState)]
    pub fn home_state(&self) -> Result<Vec<f64>, JsError> {
        let mut q = self.model.zero_state();
        self.model.close_loops(&mut q).map_err(err)?;
        Ok(q)
    }

    /// `{ frame, matrix }` as `kinolab fk` prints it; followers are set from
    /// their leaders and loops closed first.
    pub fn fk(&self, q: Vec<f64>, frame: Option<String>) -> Result<JsValue, JsError> {
        let q = self.settled(q)?;
        let name = frame.unwrap_or_else(|| "tool".into());
        let f = self.model.frame(&name).map_err(err)?;
        let pose = self.model.pose(&q, &f).map_err(err)?;
        json_to_js(&report::forward(&name, &pose))
    }

    /// `{ bodies: [{ name, matrix }] }`: every body's frame.
    pub fn place(&self, q: Vec<f64>) -> Result<JsValue, JsError> {
        let q = self.settled(q)?;
        let placed = self.model.place(&q).map_err(err)?;
        json_to_js(&report::placement(&self.model, &placed))
    }

    /// `{ rows }`: the 6 × dof geometric Jacobian of `frame` (default tool).
    pub fn jacobian(&self, q: Vec<f64>, frame: Option<String>) -> Result<JsValue, JsError> {
        let f = self
            .model
            .frame(frame.as_deref().unwrap_or("tool"))
            .map_err(err)?;
        let jac = self.model.jacobian(&q, &f).map_err(err)?;
        json_to_js(&report::jacobian(&jac))
    }

    /// `{ q, converged, position_error, rotation_error, iterations }` as
    /// `kinolab ik` prints it, for `{ frame?, position?, rotation?,
    /// relative_to?, seed?, max_iterations?, restarts? }`.
    pub fn ik(&self, request: JsValue) -> Result<JsValue, JsError> {
        let r: IkRequest = from_js("request", request)?;
        let frame = self
            .model
            .frame(r.frame.as_deref().unwrap_or("tool"))
            .map_err(err)?;
        let rotation = match r.rotation {
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
                        .map_err(err)?
                        .rotation,
                )
            }
        };
        let target = match (r.position, rotation) {
            (Some(p), Some(rot)) => Target::Pose(Pose::from_parts(Vector3::from(p).into(), rot)),
            (Some(p), None) => Target::Position(Vector3::from(p)),
            (None, Some(rot)) => Target::Orientation(rot),
            (None, None) => {
                return Err(JsError::new("request: give a position, a rotation or both"));
            }
        };
        let goal = match &r.relative_to {
            None => Goal::new(frame, target),
            Some(base) => Goal::relative(frame, target, self.model.frame(base).map_err(err)?),
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
        let s = self.model.solve(&[goal], &seed, &options).map_err(err)?;
        json_to_js(&report::inverse(&s))
    }

    /// `{ colliding, pairs, coarse_tests, fine_tests, clearance }` in the
    /// `plane` "plan" (x–y) or "side" (x–z), against `obstacles`
    /// (`[{ circle: [x, y, r] } | { rect: [x, y, halfW, halfH] }]`).
    pub fn collide(
        &self,
        q: Vec<f64>,
        plane: &str,
        obstacles: JsValue,
    ) -> Result<JsValue, JsError> {
        let q = self.settled(q)?;
        let plane = match plane {
            "plan" => Plane::Plan,
            "side" => Plane::Side,
            other => {
                return Err(JsError::new(&format!(
                    "plane: `{other}` is not `plan` or `side`"
                )));
            }
        };
        let specs: Vec<ObstacleSpec> = if obstacles.is_undefined() || obstacles.is_null() {
            Vec::new()
        } else {
            from_js("obstacles", obstacles)?
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
                _ => Err(JsError::new(&format!(
                    "obstacles[{i}]: give `circle` or `rect`"
                ))),
            })
            .collect::<Result<Vec<_>, _>>()?;
        let found = self.model.collisions(&q, plane, &obstacles).map_err(err)?;
        let clearance = self.model.clearance(&q, plane, &obstacles).map_err(err)?;
        json_to_js(&report::collisions(&self.model, &found, clearance))
    }
}

impl Mechanism {
    /// `q` with followers set and loops closed.
    fn settled(&self, mut q: Vec<f64>) -> Result<Vec<f64>, JsError> {
        self.model.close_loops(&mut q).map_err(err)?;
        Ok(q)
    }
}
