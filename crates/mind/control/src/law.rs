//! A learner's control law: `control(rho, alpha, beta)` returning
//! `[v, omega]`, run by the polar controller's simulation with its robot,
//! noise, saturation and sampling. The law runs as a sampled-data
//! controller (at the run's control rate, [`DEFAULT_RATE`] when it sets
//! none), as a control loop on a robot would; every call is recorded, so
//! a stepper can show what the law saw, returned and printed.

use kinolab_script::value::{finite, number};
use kinolab_script::{Output, Script, ScriptError, Signature};

use crate::polar::{Direction, Polar};

/// The function the learner writes.
pub const SIGNATURE: Signature = Signature {
    name: "control",
    params: &["rho", "alpha", "beta"],
};

/// How often the law runs when the run gives no control rate, Hz.
pub const DEFAULT_RATE: f64 = 100.0;

/// A compiled law and the direction it drives in.
#[derive(Debug, Clone, PartialEq)]
pub struct Law {
    pub source: String,
    pub direction: Direction,
    pub(crate) script: Script,
}

impl Law {
    /// Compile `source`; a syntax error or a missing `control` says where.
    pub fn new(source: &str, direction: Direction) -> Result<Self, ScriptError> {
        Ok(Self {
            source: source.to_owned(),
            direction,
            script: Script::compile(source, SIGNATURE)?,
        })
    }
}

/// One call of the law: what it saw, what it returned, what it printed.
#[derive(Debug, Clone, PartialEq)]
pub struct LawCall {
    pub t: f64,
    pub rho: f64,
    pub alpha: f64,
    pub beta: f64,
    pub v: f64,
    pub omega: f64,
    pub output: Output,
}

/// Call `script` with the polar coordinates `p` at `t`.
pub(crate) fn command(script: &mut Script, p: &Polar, t: f64) -> Result<LawCall, ScriptError> {
    let args = vec![number(p.rho), number(p.alpha), number(p.beta)];
    let call = script.call(args, t)?;
    let [v, omega] =
        finite(&call.value, ["v", "omega"], SIGNATURE, t).map_err(|e| script.place(e))?;
    Ok(LawCall {
        t,
        rho: p.rho,
        alpha: p.alpha,
        beta: p.beta,
        v,
        omega,
        output: call.output,
    })
}
