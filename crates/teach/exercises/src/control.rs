//! Motion control: the learner's control law `control(rho, alpha, beta)`
//! returning `[v, omega]`, run by the go-to-pose simulation.

use kinolab_common::display::fixed;
use kinolab_control::file::from_json;

use crate::{Exercise, Hook, Outcome, World};

/// One run: where the robot starts, and the loop's rate and limits.
#[derive(Debug, Clone, PartialEq)]
pub struct Trial {
    pub start: [f64; 3],
    pub duration: f64,
    pub rate: f64,
    pub max_wheel_speed: Option<f64>,
    /// How close is arrived: metres and degrees.
    pub within: f64,
    pub within_deg: f64,
}

const STARTER: &str = r#"// rho: distance to the goal (m); alpha: where the goal is seen, from the
// robot's heading (rad); beta: the goal's heading, seen along the line to it.
fn control(rho, alpha, beta) {
    let v = 0.0;
    let omega = 0.0;
    [v, omega]
}
"#;

pub const EXERCISES: [Exercise; 2] = [
    Exercise {
        id: "control-park",
        unit: "motion-control",
        lesson: "motion-control/programming-the-robot",
        hook: Hook::Control,
        signature: kinolab_control::law::SIGNATURE,
        title: "Park at the goal",
        task: "Write the control law that brings the robot to the goal, the origin, facing along x: within 1 cm and 5° in 20 s, from every start.",
        starter: STARTER,
        hints: &[
            "Drive in proportion to the distance: v = k · rho.",
            "Turn towards the goal with alpha, and use beta to arrive facing the right way.",
            "The loop is stable when k_rho > 0, k_beta < 0 and k_alpha > k_rho.",
        ],
        worlds: park,
    },
    Exercise {
        id: "control-slow-loop",
        unit: "motion-control",
        lesson: "motion-control/real-control-loops",
        hook: Hook::Control,
        signature: kinolab_control::law::SIGNATURE,
        title: "A loop that runs five times a second",
        task: "The same parking job, but your law runs only 5 times a second and the wheels turn at most 12 rad/s. Reach the goal within 2 cm and 5° in 15 s.",
        starter: STARTER,
        hints: &[
            "Between two calls the robot drives on with the last command for 0.2 s.",
            "Large gains overshoot when the command is held: try gains a few times smaller.",
        ],
        worlds: slow_loop,
    },
];

fn world(name: &str, visible: bool, trial: Trial) -> World {
    World {
        name: name.into(),
        visible,
        trial: crate::Trial::Control(trial),
    }
}

fn park() -> Vec<World> {
    let t = |start| Trial {
        start,
        duration: 20.0,
        rate: 100.0,
        max_wheel_speed: None,
        within: 0.01,
        within_deg: 5.0,
    };
    vec![
        world("from the left", true, t([-1.0, 0.5, 0.0])),
        world("side on", true, t([-1.5, -1.0, 90.0])),
        world("facing away", false, t([1.0, 1.0, 180.0])),
        world("ahead and below", false, t([1.5, -1.0, 150.0])),
        world("straight behind", false, t([-2.0, 0.0, 0.0])),
    ]
}

fn slow_loop() -> Vec<World> {
    let t = |start| Trial {
        start,
        duration: 15.0,
        rate: 5.0,
        max_wheel_speed: Some(12.0),
        within: 0.02,
        within_deg: 5.0,
    };
    vec![
        world("from the left", true, t([-1.5, 0.5, 0.0])),
        world("facing away", false, t([1.2, 1.0, 180.0])),
        world("far below", false, t([-0.5, -2.0, 30.0])),
    ]
}

/// The run file for `source` on `t`.
pub fn run_file(source: &str, t: &Trial) -> String {
    let mut file = serde_json::json!({
        "controller": { "kind": "script", "source": source },
        "start": { "x": t.start[0], "y": t.start[1], "theta_deg": t.start[2] },
        "goal": { "x": 0.0, "y": 0.0, "theta_deg": 0.0 },
        "dt": 0.001, "duration": t.duration, "output_every": 20, "control_rate": t.rate,
        "tolerance": { "position": t.within, "heading_deg": t.within_deg },
    });
    if let Some(m) = t.max_wheel_speed {
        file["max_wheel_speed"] = m.into();
    }
    file.to_string()
}

pub(crate) fn run(source: &str, world: &World, t: &Trial) -> Outcome {
    let mut out = Outcome::new(world);
    let spec = match from_json(&run_file(source, t)) {
        Ok(s) => s,
        Err(e) => return out.judged(Some(format!("the run could not start: {e}"))),
    };
    let run = match spec.run.simulate() {
        Ok(r) => r,
        Err(e) => return out.judged(Some(format!("the run could not start: {e}"))),
    };
    let end = run.samples.last().map_or(0.0, |s| s.t);
    out.time = Some(run.time_to_goal.unwrap_or(end));
    out.error = run.error.clone();
    let heading = run.final_heading_error.to_degrees().abs();
    out = out
        .metric("distance", run.final_position_error)
        .metric("heading_deg", heading)
        .metric("path_length", run.path_length);
    let reason = if let Some(d) = &run.diverged {
        Some(format!(
            "ran away at t = {} s: the loop is unstable",
            fixed(d.t, 1)
        ))
    } else if run.reached {
        None
    } else if run.final_position_error > t.within {
        Some(format!(
            "not at the goal after {} s: {} m away",
            fixed(t.duration, 0),
            fixed(run.final_position_error, 2)
        ))
    } else {
        Some(format!("arrived facing {}° off", fixed(heading, 0)))
    };
    out.judged(reason)
}
