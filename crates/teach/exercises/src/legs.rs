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
    /// At most one foot in the air at any instant.
    pub one_at_a_time: bool,
}

/// A step: each foot's longest time in the air, as a share of the cycle,
/// and how high it must rise above its resting point then, m.
pub const MIN_SWING: f64 = 1.0 / 12.0;
pub const MIN_LIFT: f64 = 0.01;
/// A foot that stands is on the ground: within this of its resting
/// height, m. Feet that stand move together: within this of each other
/// from one instant to the next, m.
pub const GROUND: f64 = 0.005;
pub const SLIP: f64 = 0.003;

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
        task: "Write the leg sequencer. Every foot must take a real step: in the air for at least a twelfth of the cycle, rising at least 1 cm. Feet on the ground must stay on it and move together, as the body moves over them. The body must move forwards at least 5 cm a cycle, and at every instant the feet on the ground must hold the centre of mass inside their support polygon.",
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
        lesson: "legged-locomotion/gaits",
        hook: Hook::Legs,
        signature: kinolab_locomotion::walker::FOOT,
        title: "A careful walker",
        task: "Now the hexapod carries a load. Lift one foot at a time, so that five always stand; keep the centre of mass at least 8 cm inside the support polygon at every instant; and still move the body at least 3 cm a cycle, with real steps as before.",
        starter: STARTER,
        hints: &[
            "Six legs, six moments: give leg i the phase from i/6 to (i + 1)/6 to swing in, and let it stand the rest of the cycle.",
            "A foot that stands five sixths of the cycle slides back slowly; it must swing forwards the same distance in its sixth.",
            "Which leg swings after which matters for the margin: a foot just set down next to the one lifting keeps the polygon wide. Try swinging the legs of one side from the back to the front.",
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
        one_at_a_time: false,
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
        one_at_a_time: true,
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
    let rest: Vec<f64> = walker.neutral().iter().map(|n| n.z).collect();
    let reason = judge(&steps, &rest, t);
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

/// The first thing wrong with a walk, and the phase it happened at
/// (`rest`: each foot's resting height, m).
fn judge(steps: &[Step], rest: &[f64], t: &Trial) -> Option<(f64, String)> {
    steps
        .iter()
        .find_map(|s| instant(s, rest, t))
        .or_else(|| slipping(steps))
        .or_else(|| stepping(steps, rest))
        .or_else(|| {
            let end = steps.last().map_or(0.0, |s| s.tau);
            let moved = progress(steps);
            (moved < t.min_progress).then(|| {
                let why = format!(
                    "the body moved {} cm a cycle, not the {} cm asked",
                    fixed(moved * 100.0, 1),
                    fixed(t.min_progress * 100.0, 0)
                );
                (end, why)
            })
        })
}

/// What is wrong at one instant: a foot out of reach, a standing foot in
/// the air, too many feet lifted, the body falling or too near to it.
fn instant(s: &Step, rest: &[f64], t: &Trial) -> Option<(f64, String)> {
    let phase = fixed(s.tau, 3);
    if let Some(leg) = s.unreachable.first() {
        return Some((
            s.tau,
            format!("the {leg} foot could not reach its target at phase {phase}"),
        ));
    }
    let floating = (0..LEGS.len()).find(|&i| s.stance[i] && s.targets[i][2] - rest[i] > GROUND);
    if let Some(i) = floating {
        let above = (s.targets[i][2] - rest[i]) * 100.0;
        let why = format!(
            "the {} foot is said to stand at phase {phase}, but it is {} cm above the ground",
            LEGS[i],
            fixed(above, 1)
        );
        return Some((s.tau, why));
    }
    let up: Vec<&str> = (0..LEGS.len())
        .filter(|&i| !s.stance[i])
        .map(|i| LEGS[i])
        .collect();
    if t.one_at_a_time && up.len() > 1 {
        let why = format!(
            "{} feet were in the air at phase {phase} ({}): a careful walker lifts one at a time",
            up.len(),
            up.join(", ")
        );
        return Some((s.tau, why));
    }
    match s.margin {
        None => Some((
            s.tau,
            format!(
                "fell at phase {phase}: only {} feet on the ground",
                6 - up.len()
            ),
        )),
        Some(m) if m <= t.min_margin && t.min_margin > 0.0 => Some((
            s.tau,
            format!(
                "the margin fell to {} cm at phase {phase}, under {} cm",
                fixed(m * 100.0, 1),
                fixed(t.min_margin * 100.0, 0)
            ),
        )),
        Some(m) if m <= t.min_margin => Some((
            s.tau,
            format!("fell at phase {phase}: the centre of mass left the support polygon"),
        )),
        Some(_) => None,
    }
}

/// A foot that stands but slides against the others: between two
/// instants, the feet on the ground at both must move alike.
fn slipping(steps: &[Step]) -> Option<(f64, String)> {
    steps.windows(2).find_map(|w| {
        let both: Vec<usize> = (0..LEGS.len())
            .filter(|&i| w[0].stance[i] && w[1].stance[i])
            .collect();
        let moved = |i: usize| {
            let (a, b) = (w[0].targets[i], w[1].targets[i]);
            [b[0] - a[0], b[1] - a[1], b[2] - a[2]]
        };
        let n = both.len() as f64;
        let mean = both.iter().fold([0.0; 3], |acc, &i| {
            let d = moved(i);
            [acc[0] + d[0] / n, acc[1] + d[1] / n, acc[2] + d[2] / n]
        });
        let off = |i: usize| {
            let d = moved(i);
            (d[0] - mean[0]).hypot(d[1] - mean[1]).hypot(d[2] - mean[2])
        };
        let i = both.iter().copied().find(|&i| off(i) > SLIP)?;
        let why = format!(
            "the {} foot slid against the other feet on the ground between phase {} and {}: feet that stand move together, as the body moves over them",
            LEGS[i],
            fixed(w[0].tau, 3),
            fixed(w[1].tau, 3)
        );
        Some((w[1].tau, why))
    })
}

/// A foot that never takes a real step: never lifted, lifted too briefly,
/// or swung without rising.
fn stepping(steps: &[Step], rest: &[f64]) -> Option<(f64, String)> {
    // The last instant is the first again (phase 1 is phase 0).
    let cycle = &steps[..steps.len().saturating_sub(1)];
    let end = steps.last().map_or(0.0, |s| s.tau);
    (0..LEGS.len()).find_map(|i| {
        let (longest, rise) = swing(cycle, i, rest[i]);
        let share = longest as f64 / cycle.len().max(1) as f64;
        let why = if longest == 0 {
            format!("the {} foot never left the ground", LEGS[i])
        } else if share < MIN_SWING {
            format!(
                "the {} foot was in the air for only {} of the cycle: a step takes at least {}",
                LEGS[i],
                fixed(share, 3),
                fixed(MIN_SWING, 3)
            )
        } else if rise < MIN_LIFT {
            format!(
                "the {} foot swung without lifting: it rose only {} cm (a step rises at least {} cm)",
                LEGS[i],
                fixed(rise * 100.0, 1),
                fixed(MIN_LIFT * 100.0, 0)
            )
        } else {
            return None;
        };
        Some((end, why))
    })
}

/// Leg `i`'s longest run of instants in the air (round the cycle), and
/// the highest it rose above `rest` while in the air.
fn swing(cycle: &[Step], i: usize, rest: f64) -> (usize, f64) {
    let n = cycle.len();
    let up = |k: usize| !cycle[k % n].stance[i];
    if n == 0 || (0..n).all(up) {
        return (n, f64::INFINITY);
    }
    let (mut longest, mut run, mut rise) = (0, 0, f64::NEG_INFINITY);
    // Twice round, so a swing across phase 0 is counted whole.
    for k in 0..2 * n {
        run = if up(k) { run + 1 } else { 0 };
        longest = longest.max(run.min(n));
        if up(k) {
            rise = rise.max(cycle[k % n].targets[i][2] - rest);
        }
    }
    (longest, rise)
}
