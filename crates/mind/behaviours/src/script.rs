//! Learners' behaviours and coordinators, in the lab's script language.
//!
//! A behaviour is `behave(p)`, where `p` is what the robot senses now:
//! `p.t` (s), `p.rays` (each `#{angle, range, hit}`, robot frame, rad and
//! m), `p.sonar` (m, or `()`), `p.bumpers` (`#{front, left, back, right}`),
//! `p.light` (`[left, right]`), `p.goal` (`#{bearing, distance}`, or `()`
//! when there is none), `p.odometry` (`#{x, y, theta}`) and `p.speed`
//! (`[v, omega]`). It answers a command `[v, omega]` (m/s, rad/s), a
//! desired velocity `#{x, y}` (robot frame, m/s: a motor schema), or `()`
//! when it does not want to act (its releaser is off).
//!
//! A coordinator is `coordinate(outputs, p)`: `outputs` maps each
//! behaviour's name to its answer this step (`()` when released); it
//! answers the name of the behaviour that drives, or a command or vector
//! of its own, so a learner can write subsumption, voting or anything else.

use kinolab_script::value::{self, float, map, number, numbers};
use kinolab_script::{Dynamic, Output, Script, ScriptError, Signature};
use kinolab_world::sensors::Percepts;

use crate::{Response, Vec2};

/// The function a behaviour script defines.
pub const BEHAVE: Signature = Signature {
    name: "behave",
    params: &["p"],
};

/// The function a coordinator script defines.
pub const COORDINATE: Signature = Signature {
    name: "coordinate",
    params: &["outputs", "p"],
};

/// One call of a learner's function this step, for the stepper.
#[derive(Debug, Clone, PartialEq)]
pub struct ScriptCall {
    /// The behaviour's name, or `coordinator`.
    pub who: String,
    pub returned: String,
    pub output: Output,
}

/// What the robot senses, as a script sees it.
pub fn percepts(p: &Percepts) -> Dynamic {
    let rays: Vec<Dynamic> = p
        .rays
        .iter()
        .map(|r| {
            map([
                ("angle", number(r.angle)),
                ("range", number(r.range)),
                ("hit", Dynamic::from_bool(r.hit)),
            ])
        })
        .collect();
    let [front, left, back, right] = p.bumpers;
    let bumper = Dynamic::from_bool;
    map([
        ("t", number(p.time)),
        ("rays", Dynamic::from_array(rays)),
        ("sonar", p.sonar.map_or(Dynamic::UNIT, number)),
        (
            "bumpers",
            map([
                ("front", bumper(front)),
                ("left", bumper(left)),
                ("back", bumper(back)),
                ("right", bumper(right)),
            ]),
        ),
        ("light", numbers(&p.light)),
        (
            "goal",
            p.goal.map_or(Dynamic::UNIT, |g| {
                map([
                    ("bearing", number(g.bearing)),
                    ("distance", number(g.distance)),
                ])
            }),
        ),
        (
            "odometry",
            map([
                ("x", number(p.odometry.x)),
                ("y", number(p.odometry.y)),
                ("theta", number(p.odometry.theta)),
            ]),
        ),
        ("speed", numbers(&p.speed)),
    ])
}

/// A response as a script sees it (`()` for none).
pub fn response_value(r: Option<&Response>) -> Dynamic {
    match r {
        None => Dynamic::UNIT,
        Some(Response::Vector(v)) => map([("x", number(v.x)), ("y", number(v.y))]),
        Some(Response::Twist { v, omega }) => numbers(&[*v, *omega]),
        Some(Response::Wheels(w)) => map([("left", number(w[0])), ("right", number(w[1]))]),
    }
}

/// What a script answered, read as a response: `[v, omega]`, `#{x, y}`
/// or `()`.
pub fn response(
    value: &Dynamic,
    signature: Signature,
    t: f64,
) -> Result<Option<Response>, ScriptError> {
    if value.is_unit() {
        return Ok(None);
    }
    if value.is_array() {
        let [v, omega] = value::finite(value, ["v", "omega"], signature, t)?;
        return Ok(Some(Response::Twist { v, omega }));
    }
    let wanted = "[v, omega], #{x, y} or ()";
    let shape = || ScriptError::shape(signature, wanted, &value::describe(value), t);
    let entries = value.read_lock::<kinolab_script::Map>().ok_or_else(shape)?;
    let component = |key: &str| -> Result<f64, ScriptError> {
        let x = entries.get(key).and_then(float).ok_or_else(shape)?;
        if x.is_finite() {
            Ok(x)
        } else {
            Err(ScriptError::not_finite(signature, key, x, t))
        }
    };
    Ok(Some(Response::Vector(Vec2::new(
        component("x")?,
        component("y")?,
    ))))
}

/// Run a behaviour script on `p`.
pub fn behave(
    script: &mut Script,
    who: &str,
    p: &Percepts,
) -> Result<(Option<Response>, ScriptCall), ScriptError> {
    let call = script.call(vec![percepts(p)], p.time)?;
    let r = response(&call.value, BEHAVE, p.time).map_err(|e| script.place(e))?;
    Ok((
        r,
        ScriptCall {
            who: who.to_owned(),
            returned: value::describe(&call.value),
            output: call.output,
        },
    ))
}
