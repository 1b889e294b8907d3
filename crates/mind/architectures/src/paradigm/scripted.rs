//! A learner's sequencer for the hybrid robot: `next(state)` decides, each
//! step, whether to ask the planner for a new plan and which point the
//! skills aim at.
//!
//! `state` holds `t` (s), `at` (`[x, y]`), `goal` (`[x, y]`, or `()`),
//! `plan` (the waypoints still ahead, `[]` with none), `planned_for` (the
//! goal the plan was made for, or `()`), `planning` (a search is running),
//! `no_path` (the last search found no way) and `blocked` (the map shows
//! the way to the next waypoint blocked). It answers `#{ replan, target }`:
//! `replan` true asks for a plan (ignored while one is being made),
//! `target` an `[x, y]` for the skills, or `()` for the goal itself.

use kinolab_script::value::{map, number, numbers};
use kinolab_script::{Dynamic, Map, Script, ScriptError, Signature};
use kinolab_world::Vec2;

/// The function a sequencer script defines.
pub const SIGNATURE: Signature = Signature {
    name: "next",
    params: &["state"],
};

/// What the robot knows when the sequencer decides.
#[derive(Debug, Clone, PartialEq)]
pub struct Situation<'a> {
    pub t: f64,
    pub at: Vec2,
    pub goal: Option<Vec2>,
    pub plan: &'a [[f64; 2]],
    pub planned_for: Option<[f64; 2]>,
    pub planning: bool,
    pub no_path: bool,
    pub blocked: bool,
}

/// What the sequencer decided.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Decision {
    pub replan: bool,
    pub target: Option<Vec2>,
}

fn point(p: Option<[f64; 2]>) -> Dynamic {
    p.map_or(Dynamic::UNIT, |p| numbers(&p))
}

/// A goal as the script is handed it: on a micrometre grid. The robot
/// rebuilds the goal from a bearing and a distance, so it wobbles in its
/// last bits from step to step; rounded, a goal that has not moved comes
/// back exactly as it was, and `state.planned_for != state.goal` means
/// "it moved".
fn goal(p: Option<[f64; 2]>) -> Dynamic {
    let snap = |x: f64| (x * 1e6).round() / 1e6;
    point(p.map(|[x, y]| [snap(x), snap(y)]))
}

/// The situation as the script sees it.
fn state(s: &Situation<'_>) -> Dynamic {
    let plan: Vec<Dynamic> = s.plan.iter().map(|w| numbers(w)).collect();
    map([
        ("t", number(s.t)),
        ("at", numbers(&[s.at.x, s.at.y])),
        ("goal", goal(s.goal.map(|g| [g.x, g.y]))),
        ("plan", Dynamic::from_array(plan)),
        ("planned_for", goal(s.planned_for)),
        ("planning", Dynamic::from_bool(s.planning)),
        ("no_path", Dynamic::from_bool(s.no_path)),
        ("blocked", Dynamic::from_bool(s.blocked)),
    ])
}

/// One question to the learner's sequencer, for the stepper: what it was
/// given, what it answered, what it printed.
#[derive(Debug, Clone, PartialEq)]
pub struct Asked {
    pub given: Vec<(&'static str, String)>,
    pub returned: String,
    pub output: kinolab_script::Output,
}

/// The situation in words, entry by entry.
fn given(s: &Situation<'_>) -> Vec<(&'static str, String)> {
    let point =
        |p: Option<[f64; 2]>| p.map_or("()".to_owned(), |p| format!("[{:.2}, {:.2}]", p[0], p[1]));
    let plan = match s.plan {
        [] => "[]".to_owned(),
        [first, ..] => format!("{} waypoints, next {}", s.plan.len(), point(Some(*first))),
    };
    vec![
        ("t", format!("{:.2}", s.t)),
        ("at", point(Some([s.at.x, s.at.y]))),
        ("goal", point(s.goal.map(|g| [g.x, g.y]))),
        ("plan", plan),
        ("planned_for", point(s.planned_for)),
        ("planning", s.planning.to_string()),
        ("no_path", s.no_path.to_string()),
        ("blocked", s.blocked.to_string()),
    ]
}

/// Ask the script; its answer read as a decision.
pub fn decide(script: &mut Script, s: &Situation<'_>) -> Result<(Decision, Asked), ScriptError> {
    let call = script.call(vec![state(s)], s.t)?;
    let decision = read(&call, s).map_err(|e| script.place(e))?;
    let asked = Asked {
        given: given(s),
        returned: kinolab_script::value::describe(&call.value),
        output: call.output,
    };
    Ok((decision, asked))
}

/// The script's answer as a decision.
fn read(call: &kinolab_script::Call, s: &Situation<'_>) -> Result<Decision, ScriptError> {
    let wanted = "#{ replan: true or false, target: [x, y] or () }";
    let shape = || {
        ScriptError::shape(
            SIGNATURE,
            wanted,
            &kinolab_script::value::describe(&call.value),
            s.t,
        )
    };
    let answer = call.value.read_lock::<Map>().ok_or_else(shape)?;
    let replan = match answer.get("replan") {
        None => false,
        Some(v) => v.as_bool().map_err(|_| shape())?,
    };
    let target = match answer.get("target") {
        None => None,
        Some(v) if v.is_unit() => None,
        Some(v) => {
            let [x, y] = kinolab_script::value::finite(v, ["x", "y"], SIGNATURE, s.t)?;
            Some(Vec2::new(x, y))
        }
    };
    Ok(Decision { replan, target })
}
