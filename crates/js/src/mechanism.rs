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

use wasm_bindgen::prelude::*;

use crate::mechanism_api::{self, MechanismApi};
use crate::{from_js, to_js};

/// The built-in mechanisms: `[{ id, name, summary }]`.
#[wasm_bindgen]
pub fn mechanisms() -> Result<JsValue, JsError> {
    to_js(mechanism_api::mechanisms())
}

/// A loaded mechanism model.
#[wasm_bindgen]
#[derive(Debug)]
pub struct Mechanism {
    inner: MechanismApi,
}

#[wasm_bindgen]
impl Mechanism {
    /// `catalogue:<id>` (or just the id), or a model file as JSON text or
    /// as an object. Mounts may name catalogue mechanisms.
    pub fn load(source: JsValue) -> Result<Mechanism, JsError> {
        let inner = MechanismApi::load(from_js("model", source)?).map_err(|e| crate::thrown(&e))?;
        Ok(Mechanism { inner })
    }

    /// `{ name, dof, variables: [{ name, type, limits, role }], joints,
    /// bodies, frames, groups, couplings, loops, shapes, solvers }`.
    pub fn describe(&self) -> Result<JsValue, JsError> {
        to_js(self.inner.describe())
    }

    /// The zero state with couplings applied and loops closed.
    #[wasm_bindgen(js_name = homeState)]
    pub fn home_state(&self) -> Result<Vec<f64>, JsError> {
        self.inner.home_state().map_err(|e| crate::thrown(&e))
    }

    /// `{ frame, matrix }` as `kinolab fk` prints it; followers are set from
    /// their leaders and loops closed first.
    pub fn fk(&self, q: Vec<f64>, frame: Option<String>) -> Result<JsValue, JsError> {
        to_js(self.inner.fk(q, frame.as_deref()))
    }

    /// `{ bodies: [{ name, matrix }] }`: every body's frame.
    pub fn place(&self, q: Vec<f64>) -> Result<JsValue, JsError> {
        to_js(self.inner.place(q))
    }

    /// `{ rows }`: the 6 × dof geometric Jacobian of `frame` (default tool),
    /// with followers set and loops closed first.
    pub fn jacobian(&self, q: Vec<f64>, frame: Option<String>) -> Result<JsValue, JsError> {
        to_js(self.inner.jacobian(q, frame.as_deref()))
    }

    /// `{ q, converged, position_error, rotation_error, iterations }` as
    /// `kinolab ik` prints it, for `{ frame?, position?, rotation?,
    /// relative_to?, seed?, max_iterations?, restarts? }`.
    pub fn ik(&self, request: JsValue) -> Result<JsValue, JsError> {
        to_js(self.inner.ik(from_js("request", request)?))
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
        to_js(
            self.inner
                .collide(q, plane, from_js("obstacles", obstacles)?),
        )
    }
}
