//! Mechanisms for JavaScript: one loaded model, any number of states.
//!
//! ```js
//! const puma = kinolab.Mechanism.load("catalogue:puma560");
//! puma.fk([0, 0, 0, 0, 0, 0]).matrix[0][3];            // 0.4521
//! const s = puma.ik({ position: [0.5, 0.1, 0.9] });      // { q, converged, … }
//! puma.collide(s.q, "side", [{ circle: [0.6, 0.8, 0.1] }]).colliding;
//! puma.toUrdf().urdf;                                      // for ROS
//! ```
//!
//! The object holds only the model, which never changes; every call takes
//! the joint values, so many views can share one model (the CLARAty way).

use kinolab_api::mechanism::{Describe, ExportUrdf, Fk, HomeState, Jacobian, Place};
use wasm_bindgen::prelude::*;

use crate::{calls, from_js, thrown, to_js};

/// What `kinolab mechanisms` prints: `[{ id, name, summary }]`.
#[wasm_bindgen]
pub fn mechanisms() -> Result<JsValue, JsError> {
    to_js(calls::mechanisms())
}

/// A loaded mechanism model.
#[wasm_bindgen]
#[derive(Debug)]
pub struct Mechanism {
    model: kinolab_mechanism::Model,
}

#[wasm_bindgen]
impl Mechanism {
    /// `catalogue:<id>` (or just the id), or a model file as JSON text or
    /// as an object. Mounts may name catalogue mechanisms.
    pub fn load(source: JsValue) -> Result<Mechanism, JsError> {
        let model = calls::load_mechanism(from_js("model", source)?).map_err(|e| thrown(&e))?;
        Ok(Mechanism { model })
    }

    /// What `kinolab describe` prints: `{ name, dof, variables: [{ name,
    /// type, limits, role }], joints, bodies, frames, groups, couplings,
    /// loops, shapes, solvers }`.
    pub fn describe(&self) -> Result<JsValue, JsError> {
        to_js(calls::on(&self.model, &Describe))
    }

    /// What `kinolab export-urdf` writes, and what URDF could not say:
    /// `{ urdf, notices }`.
    #[wasm_bindgen(js_name = toUrdf)]
    pub fn to_urdf(&self) -> Result<JsValue, JsError> {
        to_js(calls::on(&self.model, &ExportUrdf))
    }

    /// What `kinolab home-state` prints: the zero state clamped into the
    /// limits, with couplings applied and loops closed.
    #[wasm_bindgen(js_name = homeState)]
    pub fn home_state(&self) -> Result<JsValue, JsError> {
        to_js(calls::on(&self.model, &HomeState))
    }

    /// What `kinolab fk` prints: `{ frame, matrix }`; followers are set
    /// from their leaders and loops closed first.
    pub fn fk(&self, q: Vec<f64>, frame: Option<String>) -> Result<JsValue, JsError> {
        to_js(calls::on(&self.model, &Fk { q, frame }))
    }

    /// What `kinolab dynamics` prints, for `{ q | set, qd?, qdd | tau,
    /// gravity? }`: with `qdd`, `{ order, tau, gravity, mass_matrix }`
    /// (inverse dynamics, g(q) and M(q)); with `tau`, `{ order, qdd }`.
    pub fn dynamics(&self, request: JsValue) -> Result<JsValue, JsError> {
        to_js(calls::dynamics(&self.model, from_js("request", request)?))
    }

    /// What `kinolab statics` prints, for `{ q | set, loads?: [{ frame,
    /// force, moment? }], stiffness?, frame?, gravity? }`: `{ order,
    /// gravity, load, total, mass, com }`, with `deflection`, `sag` and
    /// `frame` when a stiffness is given.
    pub fn statics(&self, request: JsValue) -> Result<JsValue, JsError> {
        to_js(calls::statics(&self.model, from_js("request", request)?))
    }

    /// What `kinolab place` prints: `{ bodies: [{ name, matrix }] }`, every
    /// body's frame.
    pub fn place(&self, q: Vec<f64>) -> Result<JsValue, JsError> {
        to_js(calls::on(&self.model, &Place { q }))
    }

    /// What `kinolab jacobian` prints: `{ rows }`, the 6 × dof geometric
    /// Jacobian of `frame` (default tool), followers set and loops closed first.
    pub fn jacobian(&self, q: Vec<f64>, frame: Option<String>) -> Result<JsValue, JsError> {
        to_js(calls::on(&self.model, &Jacobian { q, frame }))
    }

    /// What `kinolab ik` prints: `{ q, converged, position_error,
    /// rotation_error, iterations }`, for `{ frame?, position?, rotation?,
    /// relative_to?, seed?, max_iterations?, restarts? }`.
    pub fn ik(&self, request: JsValue) -> Result<JsValue, JsError> {
        to_js(calls::ik(&self.model, from_js("request", request)?))
    }

    /// What `kinolab collide` prints: `{ colliding, pairs, coarse_tests,
    /// fine_tests, clearance }` in the `plane` "plan" (x–y) or "side"
    /// (x–z), against `obstacles` (`[{ circle: [x, y, r] } | { rect: [x,
    /// y, halfW, halfH] }]`).
    pub fn collide(
        &self,
        q: Vec<f64>,
        plane: &str,
        obstacles: JsValue,
    ) -> Result<JsValue, JsError> {
        to_js(calls::collide(
            &self.model,
            q,
            plane,
            from_js("obstacles", obstacles)?,
        ))
    }
}
