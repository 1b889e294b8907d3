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
    /// The most the law may ask for: |v| in m/s and |ω| in rad/s. The
    /// lab does not cap the command; the learner's law must.
    pub speed_limit: Option<[f64; 2]>,
}

/// The speed limit of the parking exercise: 0.5 m/s and 2 rad/s.
pub const PARK_LIMIT: [f64; 2] = [0.5, 2.0];

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
        title: "Park under a speed limit",
        task: "Write the control law that brings the robot to the goal, the origin, facing along x: within 1 cm and 5° in 20 s, from every start. The robot may never be asked for more than 0.5 m/s forwards or backwards, nor for more than 2 rad/s of turning.",
        starter: STARTER,
        hints: &[
            "Start from the law of this lesson, then look at what it asks for at the first call: far from the goal, v = k · rho is far above 0.5 m/s.",
            "Cutting v and omega to their limits separately changes the ratio omega / v, so the robot turns more or less sharply than the law asked.",
            "Find the factor that brings the larger of |v| / 0.5 and |omega| / 2 down to 1, and multiply both by it.",
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
        task: "The same parking job, but your law runs only twice a second and the wheels turn at most 12 rad/s. Reach the goal within 2 cm and 5° in 15 s, from every start.",
        starter: STARTER,
        hints: &[
            "Between two calls the robot drives on with the last command for 0.5 s.",
            "A held command keeps turning after the error it answered is gone: keep each gain times the period well below 1.",
            "Gains that are too small are stable but slow: the robot must still arrive within 15 s.",
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
        speed_limit: Some(PARK_LIMIT),
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
        rate: 2.0,
        max_wheel_speed: Some(12.0),
        within: 0.02,
        within_deg: 5.0,
        speed_limit: None,
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
    let over = t
        .speed_limit
        .and_then(|limit| over_limit(&run.calls, limit));
    let reason = if let Some(over) = over {
        Some(over)
    } else if let Some(d) = &run.diverged {
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

/// The first call that asked for more than `limit` ([m/s, rad/s]), in words.
fn over_limit(calls: &[kinolab_control::law::LawCall], [v_max, w_max]: [f64; 2]) -> Option<String> {
    // A hair over the limit is the limit, computed.
    let slack = 1e-9;
    calls.iter().find_map(|c| {
        if c.v.abs() > v_max + slack {
            Some(format!(
                "asked for {} m/s at t = {} s; the limit is {} m/s",
                fixed(c.v, 2),
                fixed(c.t, 2),
                fixed(v_max, 1)
            ))
        } else if c.omega.abs() > w_max + slack {
            Some(format!(
                "asked for {} rad/s of turning at t = {} s; the limit is {} rad/s",
                fixed(c.omega, 2),
                fixed(c.t, 2),
                fixed(w_max, 1)
            ))
        } else {
            None
        }
    })
}
