//! The JSON reports the command line prints and the JavaScript API returns,
//! in one place so both say exactly the same thing (field names as in the
//! command-line contract; angles in outputs end in `_deg` when in degrees).

use serde_json::{Value, json};

use crate::analysis::twist_icr;
use crate::chassis::Chassis;
use crate::error::WheelsError;
use crate::kinematics::to_inertial;
use nalgebra::Vector3;

/// Rounding noise (|x| < 1e-12, and −0) written as 0, so cos 90° does not
/// print as 6.1e-17 on an exercise sheet.
pub fn tidy(value: Value) -> Value {
    match value {
        Value::Number(n) => match n.as_f64() {
            Some(x) if n.is_f64() && x.abs() < 1e-12 => json!(0.0),
            _ => Value::Number(n),
        },
        Value::Array(items) => Value::Array(items.into_iter().map(tidy).collect()),
        Value::Object(map) => Value::Object(map.into_iter().map(|(k, v)| (k, tidy(v))).collect()),
        other => other,
    }
}

/// Degrees, with the last bits rounded away so 90° prints as 90.
pub fn degrees(radians: f64) -> f64 {
    (radians.to_degrees() * 1e9).round() / 1e9
}

/// `kinolab analyze`: ranks, the three degrees, DOF, holonomy, the ICR, each
/// wheel's zero-motion line and, for a stuck layout, who disagrees.
pub fn analysis(chassis: &Chassis) -> Value {
    let a = chassis.analyze();
    let wheels: Vec<Value> = chassis
        .wheels()
        .iter()
        .map(|w| {
            let (point, direction) = w.zero_motion_line();
            let mut entry = json!({ "kind": w.kind.name(), "position": w.position() });
            if w.kind.constrains_chassis() {
                entry["zero_motion_line"] = json!({ "point": point, "direction": direction });
            }
            entry
        })
        .collect();
    let mut out = json!({
        "name": chassis.name(),
        "rank_c1": a.rank_c1,
        "rank_c1f": a.rank_c1f,
        "rank_c1s": a.rank_c1s,
        "steering_inputs": a.steering_inputs,
        "degree_of_mobility": a.mobility,
        "degree_of_steerability": a.steerability,
        "degree_of_maneuverability": a.maneuverability,
        "ddof": a.ddof(),
        "dof": a.dof,
        "holonomic": a.holonomic,
        "icr": a.icr,
        "wheels": wheels,
    });
    if let Some(d) = chassis.disagreement() {
        out["disagreement"] = json!({
            "consensus": d.consensus,
            "agree": d.agree,
            "disagree": d.disagree.iter().map(|(i, miss)| json!({ "wheel": i, "miss": miss })).collect::<Vec<_>>(),
        });
    }
    tidy(out)
}

/// `kinolab drive --twist`: inverse kinematics.
pub fn inverse(
    chassis: &Chassis,
    twist: Vector3<f64>,
    theta: Option<f64>,
) -> Result<Value, WheelsError> {
    let ik = chassis.inverse(twist)?;
    let wheels: Vec<Value> = ik
        .wheels
        .iter()
        .map(|c| {
            let mut entry = json!({
                "spin": c.spin,
                "steer_deg": degrees(c.steer),
                "steer_rate_deg": degrees(c.steer_rate),
            });
            if let Some(roller) = c.roller_speed {
                entry["roller_speed"] = json!(roller);
            }
            entry
        })
        .collect();
    let out = json!({
        "feasible": ik.feasible,
        "wheels": wheels,
        "violations": ik.violations,
    });
    finish(out, twist, theta)
}

/// `kinolab drive --wheels`: forward kinematics.
pub fn forward(
    chassis: &Chassis,
    spins: &[Option<f64>],
    theta: Option<f64>,
) -> Result<Value, WheelsError> {
    let fk = chassis.forward(spins)?;
    let twist = Vector3::from(fk.twist);
    let out = json!({
        "twist": fk.twist,
        "residual": fk.residual,
        "consistent": fk.consistent,
        "determined": fk.determined,
    });
    finish(out, twist, theta)
}

/// Add the ICR of the twist and, given a heading, its inertial motion; tidy.
fn finish(mut out: Value, twist: Vector3<f64>, theta: Option<f64>) -> Result<Value, WheelsError> {
    out["icr"] = json!(twist_icr(&twist));
    if let Some(theta) = theta {
        crate::error::finite("theta", theta)?;
        out["twist_inertial"] = json!(to_inertial(theta, twist).as_slice());
    }
    Ok(tidy(out))
}
