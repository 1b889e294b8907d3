//! Potential fields: the learner's primitive `field(x, y)` joins a field's
//! sum, and a point robot takes the whole field as its velocity (up to a
//! top speed) from several starts; it must reach the goal without passing
//! through anything.

use kinolab_common::display::fixed;
use kinolab_fields::Field;
use kinolab_fields::follow::{Ended, Pace, follow};

use crate::{Exercise, Hook, Outcome, World};

/// One run: the field the learner's primitive is added to (a field file),
/// and where the point robot starts.
#[derive(Debug, Clone, PartialEq)]
pub struct Trial {
    pub base: &'static str,
    pub start: [f64; 2],
}

/// The robot's pace: 0.05 s a step, at most 0.5 m/s, for at most 60 s.
pub(crate) const PACE: Pace = Pace {
    dt: 0.05,
    max_speed: 0.5,
    max_steps: 1200,
    tolerance: 0.05,
};

const PULL_STARTER: &str = r#"// The goal is at (4, 0); two rocks push the robot away.
// Answer the pull at (x, y): a vector [fx, fy].
fn field(x, y) {
    [0.0, 0.0]
}
"#;

const ESCAPE_STARTER: &str = r#"// The goal at (6, 0) pulls; the U-shaped wall from x = 2.6 to 4 pushes.
// Add a field that gets the robot out of the U and round it.
fn field(x, y) {
    [0.0, 0.0]
}
"#;

/// Two rocks between the starts and the goal; no pull: the learner's.
const ROCKS: &str = r#"{ "name": "two rocks", "goal": { "x": 4.0, "y": 0.0 }, "fields": [
  { "kind": "repulsive", "x": 2.0, "y": 0.6, "radius": 0.3, "gain": 1.5, "profile": "linear", "range": 0.6 },
  { "kind": "repulsive", "x": 2.4, "y": -0.7, "radius": 0.3, "gain": 1.5, "profile": "linear", "range": 0.6 }
] }"#;

/// The lab's U-shaped wall, its pull included.
fn u_wall() -> &'static str {
    kinolab_fields::catalogue::preset("u-shaped-wall").map_or("", |p| p.file)
}

pub const EXERCISES: [Exercise; 2] = [
    Exercise {
        id: "field-pull",
        unit: "potential-fields",
        lesson: "potential-fields/five-primitives",
        hook: Hook::Field,
        signature: kinolab_fields::custom::SIGNATURE,
        title: "Pull towards the goal",
        task: "The field has two rocks that push and no pull. Write the attractive primitive that brings the robot to the goal at (4, 0) from every start, past the rocks and never through them. The robot moves with the field: its length is the speed, up to 0.5 m/s.",
        starter: PULL_STARTER,
        hints: &[
            "The pull points from (x, y) towards the goal: [4 − x, 0 − y].",
            "Far away that vector is long: it overpowers the rocks' push and drags the robot straight through them. Near the goal it shrinks, and the robot creeps.",
            "Keep the pull's length steady: divide by the distance (a unit vector) and let it shrink only in the last few centimetres.",
        ],
        worlds: pull,
    },
    Exercise {
        id: "field-escape",
        unit: "potential-fields",
        lesson: "potential-fields/ways-out",
        hook: Hook::Field,
        signature: kinolab_fields::custom::SIGNATURE,
        title: "Out of the U",
        task: "In the U-shaped wall's field a robot that starts in the U's mouth ends trapped inside it. Add a field that gets it to the goal at (6, 0) from every start, round the wall and never through it.",
        starter: ESCAPE_STARTER,
        hints: &[
            "The trap is the point where the wall's push and the goal's pull cancel: your field must break that balance, and a plain stronger pull breaks it by walking the robot through the wall.",
            "Push the robot sideways, away from the axis y = 0, while it is in front of or inside the U.",
            "Only act where the trap is: outside that region return [0.0, 0.0] so the goal's pull finishes the job.",
        ],
        worlds: escape,
    },
];

fn world(name: &str, visible: bool, base: &'static str, start: [f64; 2]) -> World {
    World {
        name: name.into(),
        visible,
        trial: crate::Trial::Field(Trial { base, start }),
    }
}

fn pull() -> Vec<World> {
    vec![
        world("from the origin", true, ROCKS, [0.0, 0.0]),
        world("from above", true, ROCKS, [0.5, 1.5]),
        world("from below", false, ROCKS, [0.3, -1.6]),
        world("from beyond the goal", false, ROCKS, [6.0, 1.0]),
        world("between the rocks", false, ROCKS, [2.2, 0.0]),
    ]
}

fn escape() -> Vec<World> {
    let u = u_wall();
    vec![
        world("in the mouth", true, u, [0.5, 0.3]),
        world("below the axis", true, u, [1.5, -0.5]),
        world("deep inside", false, u, [3.2, 0.1]),
        world("on the axis", false, u, [0.2, 0.0]),
        world("near the top arm", false, u, [2.0, 0.8]),
    ]
}

/// The field file with the learner's primitive added to `base`.
pub fn field_file(source: &str, base: &str) -> String {
    let mut file: serde_json::Value = serde_json::from_str(base).unwrap_or_default();
    if let Some(fields) = file.get_mut("fields").and_then(|f| f.as_array_mut()) {
        fields.push(serde_json::json!({ "kind": "script", "source": source }));
    }
    file.to_string()
}

fn place(p: [f64; 2]) -> String {
    format!("({}, {})", fixed(p[0], 2), fixed(p[1], 2))
}

pub(crate) fn run(source: &str, world: &World, t: &Trial) -> Outcome {
    let mut out = Outcome::new(world);
    let field = match Field::from_json(&field_file(source, t.base)) {
        Ok(f) => f,
        Err(e) => return out.judged(Some(format!("the field could not be read: {e}"))),
    };
    let walk = match follow(&field, t.start.into(), PACE) {
        Ok(w) => w,
        Err(e) => return out.judged(Some(format!("the walk could not start: {e}"))),
    };
    out.error = field.failed();
    let steps = walk.path.len().saturating_sub(1);
    let end = walk.path.last().copied().unwrap_or(t.start);
    out.time = Some(steps as f64 * PACE.dt);
    out = out
        .metric("steps", steps as f64)
        .metric("top_speed", walk.top_speed)
        .metric("end_x", end[0])
        .metric("end_y", end[1]);
    let seconds = fixed(steps as f64 * PACE.dt, 1);
    let reason = match walk.ended {
        Ended::Reached => None,
        Ended::Hit { .. } => Some(format!(
            "ran into an obstacle at {}, {seconds} s in: the field pushed it through",
            place(end)
        )),
        Ended::Stalled => Some(format!("stuck at {} after {seconds} s", place(end))),
        Ended::OutOfSteps => Some(format!(
            "not at the goal after {seconds} s: ended at {}",
            place(end)
        )),
    };
    out.judged(reason)
}
