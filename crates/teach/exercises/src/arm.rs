//! Mechanisms: the learner's arm controller `control(q, qd, target,
//! payload)` answers the joint torques for a two-link arm in a vertical
//! plane, which the lab's dynamics then move under gravity, a payload at
//! the tool, and motors that give at most 100 N·m.

use kinolab_common::display::fixed;
use kinolab_mechanism::dynamics::servo::{Servo, ServoRun, Stop};
use kinolab_mechanism::{FrameRef, Model};

use crate::{Exercise, Hook, Outcome, World};

/// One run: where the arm starts and where it must hold (degrees), and
/// the payload at the tool (kg).
#[derive(Debug, Clone, PartialEq)]
pub struct Trial {
    pub start_deg: [f64; 2],
    pub target_deg: [f64; 2],
    pub payload: f64,
}

/// The run's length, the controller's rate and the motors' limit.
pub const DURATION: f64 = 4.0;
pub const RATE: f64 = 200.0;
pub const TORQUE_LIMIT: f64 = 100.0;
/// Held means within this of the target, every joint, for the last second.
pub const WITHIN_DEG: f64 = 0.5;
pub const HOLD: f64 = 1.0;

const STARTER: &str = r#"// q, qd: the two joint angles (rad, 0 is horizontal, up is positive) and
// their rates (rad/s); target: where to hold [q1, q2]; payload: kg at the tool.
// The links: 0.5 m and 3 kg, then 0.4 m and 2 kg, each mass spread along it.
// Answer the two joint torques [tau1, tau2], N·m, at most 100 each.
fn control(q, qd, target, payload) {
    let shoulder = 60.0 * (target[0] - q[0]) - 12.0 * qd[0];
    let elbow = 20.0 * (target[1] - q[1]) - 3.0 * qd[1];
    [shoulder, elbow]
}
"#;

pub const EXERCISES: [Exercise; 1] = [Exercise {
    id: "arm-hold",
    unit: "mechanisms",
    lesson: "mechanisms/holding-still-and-letting-go",
    hook: Hook::Arm,
    signature: kinolab_mechanism::dynamics::servo::SIGNATURE,
    title: "Hold the arm where it is asked",
    task: "A two-link arm in a vertical plane must move to the target angles and hold there, within 0.5° at both joints for the last second of a 4 s run, whatever it carries at the tool. Its motors give at most 100 N·m. The starter is a plain PD law: run it and see where the arm settles.",
    starter: STARTER,
    hints: &[
        "At rest, the PD law's torque is kp times the error: the arm settles where that torque holds up its weight, below the target.",
        "Raising kp shrinks the sag, but asks for more torque than the motors give far from the target.",
        "Add the torque that holds the arm still at q, the gravity torque: each mass times g times its horizontal distance from the joint (the payload sits at the tool, 0.9 m out when the arm is straight).",
    ],
    worlds: hold,
}];

fn world(
    name: &str,
    visible: bool,
    start_deg: [f64; 2],
    target_deg: [f64; 2],
    payload: f64,
) -> World {
    World {
        name: name.into(),
        visible,
        trial: crate::Trial::Arm(Trial {
            start_deg,
            target_deg,
            payload,
        }),
    }
}

fn hold() -> Vec<World> {
    vec![
        world("level, empty-handed", true, [-40.0, 0.0], [0.0, 0.0], 0.0),
        world(
            "reaching up with 1 kg",
            true,
            [10.0, 10.0],
            [40.0, 20.0],
            1.0,
        ),
        world(
            "held out with 2 kg",
            false,
            [-30.0, 0.0],
            [10.0, -10.0],
            2.0,
        ),
        world(
            "elbow bent with 0.5 kg",
            false,
            [-10.0, 40.0],
            [-20.0, 70.0],
            0.5,
        ),
        world("low with 1.5 kg", false, [-10.0, 30.0], [-40.0, 30.0], 1.5),
    ]
}

/// The arm and its tool.
pub fn arm() -> Result<(Model, FrameRef), String> {
    let model =
        kinolab_mechanism::catalogue::mechanism("vertical-2r").map_err(|e| e.to_string())?;
    let tool = model.frame("tool").map_err(|e| e.to_string())?;
    Ok((model, tool))
}

/// The servo run `t` asks for.
pub fn servo(t: &Trial) -> Servo {
    Servo {
        start: t.start_deg.iter().map(|d| d.to_radians()).collect(),
        target: t.target_deg.iter().map(|d| d.to_radians()).collect(),
        payload: t.payload,
        duration: DURATION,
        rate: RATE,
        torque_limit: TORQUE_LIMIT,
    }
}

/// `source` run on `t`: the arm carrying the payload, and its run.
pub fn simulate(source: &str, t: &Trial) -> Result<(Model, ServoRun), String> {
    let (model, tool) = arm()?;
    let carrying = model
        .carrying(&tool, t.payload)
        .map_err(|e| e.to_string())?;
    let run = carrying
        .servo_script(&servo(t), source)
        .map_err(|e| e.to_string())?;
    Ok((carrying, run))
}

pub(crate) fn run(source: &str, world: &World, t: &Trial) -> Outcome {
    let out = Outcome::new(world);
    match simulate(source, t) {
        Ok((_, run)) => judge(out, t, &run),
        Err(e) => out.judged(Some(format!("the run could not start: {e}"))),
    }
}

/// The outcome of a run.
pub(crate) fn judge(mut out: Outcome, t: &Trial, run: &ServoRun) -> Outcome {
    let end = run.samples.last().map_or(0.0, |s| s.t);
    out.time = Some(end);
    let peak = run
        .samples
        .iter()
        .flat_map(|s| s.tau.iter().map(|x| x.abs()))
        .fold(0.0, f64::max);
    out = out.metric("peak_torque", peak);
    match &run.stopped {
        Some(Stop::Error(e)) => {
            out.error = Some(e.clone());
            return out.judged(None);
        }
        Some(Stop::OverLimit { joint, tau, t }) => {
            let why = format!(
                "asked joint {} for {} N·m at t = {} s; the motors give at most {} N·m",
                joint + 1,
                fixed(*tau, 1),
                fixed(*t, 2),
                fixed(TORQUE_LIMIT, 0)
            );
            return out.judged(Some(why));
        }
        None => {}
    }
    // The worst error of the last second, joint by joint, with its sign.
    let held: Vec<&kinolab_mechanism::dynamics::servo::ServoSample> = run
        .samples
        .iter()
        .filter(|s| s.t >= DURATION - HOLD - 1e-9)
        .collect();
    let mut worst: (f64, usize) = (0.0, 0);
    for s in &held {
        for (k, (q, target)) in s.q.iter().zip(&t.target_deg).enumerate() {
            let off = q.to_degrees() - target;
            if off.abs() > worst.0.abs() {
                worst = (off, k);
            }
        }
    }
    out = out.metric("worst_error_deg", worst.0.abs());
    let reason = (worst.0.abs() > WITHIN_DEG).then(|| {
        let way = if worst.0 < 0.0 { "below" } else { "above" };
        format!(
            "joint {} was {}° {way} its target in the last second (within {}° asked)",
            worst.1 + 1,
            fixed(worst.0.abs(), 1),
            fixed(WITHIN_DEG, 1)
        )
    });
    out.judged(reason)
}
