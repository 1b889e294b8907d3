//! Legged locomotion: the learner's leg sequencer `foot(leg, phase)` walks
//! the lab's hexapod through one cycle; every instant must be statically
//! stable, every foot must step, and the body must move forwards.

use kinolab_common::display::fixed;
use kinolab_locomotion::walker::{LEGS, Step, Walker, progress};

use crate::{Exercise, Hook, Outcome, World};

/// One walk: where the body's centre of mass is (body frame, m), how many
/// instants of the cycle are checked, and the least progress, m a cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct Trial {
    pub com: [f64; 2],
    pub samples: usize,
    pub min_progress: f64,
    /// The least stability margin allowed at any instant, m.
    pub min_margin: f64,
}

const STARTER: &str = r#"// leg: #{ name, index, x, y, z }: index 0-2 the left legs front to back,
// 3-5 the right; (x, y, z) the foot's resting point, body frame, m.
// phase: where in the cycle we are, from 0 to 1.
// Answer #{ stance: true or false, at: [x, y, z] }.
fn foot(leg, phase) {
    #{ stance: true, at: [leg.x, leg.y, leg.z] }
}
"#;

pub const EXERCISES: [Exercise; 2] = [
    Exercise {
        id: "legs-walk",
        unit: "legged-locomotion",
        lesson: "legged-locomotion/gaits",
        hook: Hook::Legs,
        signature: kinolab_locomotion::walker::FOOT,
        title: "Walk on six legs",
        task: "Write the leg sequencer: every foot must leave the ground at some point, the body must move forwards at least 5 cm a cycle, and at every instant the feet on the ground must hold the centre of mass inside their support polygon.",
        starter: STARTER,
        hints: &[
            "A foot on the ground slides backwards (the body moves forwards over it); a lifted foot swings forwards again, a little above the ground.",
            "Three feet on the ground are enough if they make a triangle round the centre of mass: front and rear of one side with the middle of the other.",
            "Give each leg its own moment to lift: a phase offset per leg, and the stance while (phase − offset) is in the last part of the cycle.",
        ],
        worlds: walk,
    },
    Exercise {
        id: "legs-careful",
        unit: "legged-locomotion",
        lesson: "legged-locomotion/balance",
        hook: Hook::Legs,
        signature: kinolab_locomotion::walker::FOOT,
        title: "A careful walker",
        task: "Now the hexapod carries a load: at every instant the centre of mass must stay at least 8 cm inside the support polygon, and the body must still move at least 3 cm a cycle.",
        starter: STARTER,
        hints: &[
            "A tripod has only three feet down at a time: its margin is small.",
            "Lift one leg at a time, so five feet always stand.",
            "Six legs, six moments: lift leg i while the phase is between i/6 and (i + 1)/6.",
        ],
        worlds: careful,
    },
];

fn world(name: &str, visible: bool, trial: Trial) -> World {
    World {
        name: name.into(),
        visible,
        trial: crate::Trial::Legs(trial),
    }
}

fn walk() -> Vec<World> {
    let t = |com, samples| Trial {
        com,
        samples,
        min_progress: 0.05,
        min_margin: 0.0,
    };
    vec![
        world("level body", true, t([0.0, 0.0], 24)),
        world("load a little forward", false, t([0.02, 0.0], 24)),
        world("load to one side", false, t([0.0, 0.015], 24)),
        world("checked finely", false, t([0.0, 0.0], 96)),
    ]
}

fn careful() -> Vec<World> {
    let t = |com, samples| Trial {
        com,
        samples,
        min_progress: 0.03,
        min_margin: 0.08,
    };
    vec![
        world("level body", true, t([0.0, 0.0], 36)),
        world("load a little back", false, t([-0.02, 0.0], 36)),
        world("checked finely", false, t([0.0, 0.0], 120)),
    ]
}

/// The walker for `t`, the learner's sequencer in charge.
pub(crate) fn walker(source: &str, t: &Trial) -> Result<Walker, String> {
    let mut gait =
        kinolab_locomotion::named("hexapod-tripod").ok_or("the hexapod's gait is missing")?;
    gait.com = t.com;
    Walker::new(gait, 0.03)
        .and_then(|w| w.with_sequencer(source))
        .map_err(|e| e.to_string())
}

pub(crate) fn run(source: &str, world: &World, t: &Trial) -> Outcome {
    let mut out = Outcome::new(world);
    let walker = match walker(source, t) {
        Ok(w) => w,
        Err(e) => return out.judged(Some(format!("the walk could not start: {e}"))),
    };
    let mut q = walker.model.zero_state();
    let mut steps: Vec<Step> = Vec::with_capacity(t.samples + 1);
    for k in 0..=t.samples {
        let tau = k as f64 / t.samples as f64;
        let plan = match walker.plan(tau) {
            Ok(p) => p,
            Err(e) => {
                out.error = Some(e);
                out.time = Some(tau);
                return out.judged(None);
            }
        };
        match walker.place(tau, &plan, &q) {
            Ok(step) => {
                q.clone_from(&step.q);
                steps.push(step);
            }
            Err(e) => return out.judged(Some(format!("the legs could not be placed: {e}"))),
        }
    }
    let reason = judge(&steps, t);
    let lowest = steps
        .iter()
        .map(|s| s.margin.unwrap_or(f64::NEG_INFINITY))
        .fold(f64::INFINITY, f64::min);
    out.time = reason.as_ref().map(|(tau, _)| *tau);
    out = out
        .metric("progress", progress(&steps))
        .metric("min_margin", if lowest.is_finite() { lowest } else { -1.0 });
    out.judged(reason.map(|(_, why)| why))
}

/// The first thing wrong with a walk, and the phase it happened at.
fn judge(steps: &[Step], t: &Trial) -> Option<(f64, String)> {
    for s in steps {
        if let Some(leg) = s.unreachable.first() {
            return Some((
                s.tau,
                format!(
                    "the {leg} foot could not reach its target at phase {}",
                    fixed(s.tau, 3)
                ),
            ));
        }
        match s.margin {
            None => {
                let down = s.stance.iter().filter(|d| **d).count();
                return Some((
                    s.tau,
                    format!(
                        "fell at phase {}: only {down} feet on the ground",
                        fixed(s.tau, 3)
                    ),
                ));
            }
            Some(m) if m <= t.min_margin => {
                let why = if t.min_margin > 0.0 {
                    format!(
                        "the margin fell to {} cm at phase {}, under {} cm",
                        fixed(m * 100.0, 1),
                        fixed(s.tau, 3),
                        fixed(t.min_margin * 100.0, 0)
                    )
                } else {
                    format!(
                        "fell at phase {}: the centre of mass left the support polygon",
                        fixed(s.tau, 3)
                    )
                };
                return Some((s.tau, why));
            }
            Some(_) => {}
        }
    }
    let end = steps.last().map_or(0.0, |s| s.tau);
    if let Some(i) = (0..LEGS.len()).find(|&i| steps.iter().all(|s| s.stance.get(i) == Some(&true)))
    {
        return Some((end, format!("the {} foot never left the ground", LEGS[i])));
    }
    let moved = progress(steps);
    (moved < t.min_progress).then(|| {
        (
            end,
            format!(
                "the body moved {} cm a cycle, not the {} cm asked",
                fixed(moved * 100.0, 1),
                fixed(t.min_progress * 100.0, 0)
            ),
        )
    })
}
