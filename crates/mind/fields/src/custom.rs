//! A learner's primitive: `field(x, y)` returning `[fx, fy]`, added to the
//! field's sum like any built-in primitive. The sandbox draws it, finds
//! its equilibria (its Jacobian by central differences) and runs descents
//! through it. It is a pure function of the point: nothing is kept
//! between calls. The first error is kept, and the field reads as zero
//! there from then on; [`crate::Field::failed`] reports it.

use std::cell::RefCell;

use kinolab_script::value::{finite, number};
use kinolab_script::{Output, Script, ScriptError, Signature, When};

use crate::{Mat2, Vec2};

/// The function a field script defines.
pub const SIGNATURE: Signature = Signature {
    name: "field",
    params: &["x", "y"],
};

/// The step of the central differences, m.
const H: f64 = 1e-6;

/// A learner's primitive.
#[derive(Clone)]
pub struct Custom {
    pub source: String,
    script: Script,
    failed: RefCell<Option<ScriptError>>,
}

impl std::fmt::Debug for Custom {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Custom({} bytes)", self.source.len())
    }
}

impl PartialEq for Custom {
    fn eq(&self, other: &Self) -> bool {
        self.source == other.source
    }
}

impl Custom {
    /// Compile `source`, which must define `field(x, y)`.
    pub fn new(source: &str) -> Result<Self, ScriptError> {
        Ok(Self {
            source: source.to_owned(),
            script: Script::compile(source, SIGNATURE)?,
            failed: RefCell::new(None),
        })
    }

    /// What the script answers at `p`, and what it printed and plotted.
    pub fn answer(&self, p: Vec2) -> Result<(Vec2, Output), ScriptError> {
        let at = When::Point(p.x, p.y);
        let call = self.script.call_pure(vec![number(p.x), number(p.y)], at)?;
        let [fx, fy] =
            finite(&call.value, ["fx", "fy"], SIGNATURE, at).map_err(|e| self.script.place(e))?;
        Ok((Vec2::new(fx, fy), call.output))
    }

    /// The vector at `p` (zero once the script has failed).
    pub fn vector(&self, p: Vec2) -> Vec2 {
        if self.failed.borrow().is_some() {
            return Vec2::zeros();
        }
        match self.answer(p) {
            Ok((f, _)) => f,
            Err(e) => {
                *self.failed.borrow_mut() = Some(e);
                Vec2::zeros()
            }
        }
    }

    /// The vector at `p` and its Jacobian by central differences.
    pub fn linearise(&self, p: Vec2) -> (Vec2, Mat2) {
        let f = self.vector(p);
        let dx =
            (self.vector(p + Vec2::new(H, 0.0)) - self.vector(p - Vec2::new(H, 0.0))) / (2.0 * H);
        let dy =
            (self.vector(p + Vec2::new(0.0, H)) - self.vector(p - Vec2::new(0.0, H))) / (2.0 * H);
        (f, Mat2::from_columns(&[dx, dy]))
    }

    /// The error that stopped it, if one did.
    pub fn failed(&self) -> Option<ScriptError> {
        self.failed.borrow().clone()
    }
}
