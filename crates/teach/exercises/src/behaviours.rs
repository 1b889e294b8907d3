//! Behaviours: the learner's behaviour `behave(p)`, or their coordinator
//! `coordinate(outputs, p)` over the library's behaviours, run in the
//! behaviour arena's simulation.

use kinolab_behaviours::coordinate::Coordinator;
use kinolab_behaviours::library::{Behaviour, Named};
use kinolab_behaviours::run::{RunReport, Sample, Setup, run as simulate};
use kinolab_common::FieldError;
use kinolab_common::display::fixed;
use kinolab_world::{EventKind, World};

use crate::{Exercise, Hook, Outcome, World as Graded};

/// One run: the world, the library's behaviours (a coordinator exercise
/// coordinates them; a behaviour exercise runs the learner's alone) and
/// what counts as success.
#[derive(Debug, Clone, PartialEq)]
pub struct Trial {
    pub world: World,
    pub library: Vec<Named>,
    pub duration: f64,
    pub seed: u64,
    /// The goal must be reached.
    pub reach_goal: bool,
    /// Exploring: the least ground covered, and how long the robot may
    /// stand still (see [`Explore`]).
    pub explore: Option<Explore>,
}

/// What exploring asks: ground covered (cells of [`CELL`] m the robot's
/// centre passed through), and never standing still for long: staying
/// within [`STILL_WITHIN`] m of one spot for more than `still` s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Explore {
    /// m².
    pub min_area: f64,
    /// s.
    pub still: f64,
}

/// The side of a coverage cell, m.
pub const CELL: f64 = 0.5;
/// Moving less than this from a spot counts as standing still, m.
pub const STILL_WITHIN: f64 = 0.1;

/// The learner's behaviour's name in the run.
pub const MINE: &str = "mine";

const WANDER_STARTER: &str = r#"// p.rays: each #{angle, range, hit} (rad, m, robot frame; angle 0 is ahead)
// p.bumpers: #{front, left, back, right}; p.t: the time, s
// Answer [v, omega] (m/s, rad/s), #{x, y} (a velocity, m/s) or ().
fn behave(p) {
    [0.2, 0.0]
}
"#;

const COORDINATE_STARTER: &str = r#"// outputs.seek: #{x, y}, a velocity (m/s, robot frame) towards the goal.
// outputs.avoid: () while nothing is within 0.7 m ahead; #{x, y} steering
// away from what is; [v, omega] backing off while a bumper is pressed.
// Answer the name of the behaviour that drives ("seek" or "avoid"),
// or a command of your own: [v, omega] or #{x, y}.
fn coordinate(outputs, p) {
    "seek"
}
"#;

pub const EXERCISES: [Exercise; 2] = [
    Exercise {
        id: "behaviour-explore",
        unit: "behaviours",
        lesson: "behaviours/what-a-behaviour-is",
        hook: Hook::Behaviour,
        signature: kinolab_behaviours::script::BEHAVE,
        title: "Explore without touching anything",
        task: "Write one behaviour that explores for 40 s: the robot must cover at least 4 m² of ground (cells of half a metre that it passes through), never stand still for more than 5 s, and never touch a wall or an obstacle.",
        starter: WANDER_STARTER,
        hints: &[
            "Look at the rays in front of the robot: the ones whose angle is near 0.",
            "When the nearest thing ahead is closer than about half a metre, stop driving forward and turn.",
            "Turn away from the side where the rays are shorter, and keep turning until the way ahead is clear; then drive straight on, so the robot reaches new ground.",
        ],
        worlds: explore,
    },
    Exercise {
        id: "behaviour-coordinate",
        unit: "behaviours",
        lesson: "behaviours/coordination",
        hook: Hook::Coordinator,
        signature: kinolab_behaviours::script::COORDINATE,
        title: "Choose who drives",
        task: "Two library behaviours run side by side: `seek` heads for the goal and `avoid` steers away from anything within 0.7 m ahead. Write the coordinator that gets the robot to the goal in 40 s without touching anything.",
        starter: COORDINATE_STARTER,
        hints: &[
            "A coordinator that always lets `seek` drive runs into the first obstacle in the way.",
            "`avoid` answers () when nothing is near: use that to decide who drives.",
            "Choosing is not the only way: you may add the two vectors and answer the sum.",
        ],
        worlds: coordinate,
    },
];

fn graded(name: &str, visible: bool, trial: Trial) -> Graded {
    Graded {
        name: name.into(),
        visible,
        trial: crate::Trial::Behaviours(trial),
    }
}

fn example(id: &str) -> World {
    kinolab_world::catalogue::world(id)
        .unwrap_or_else(|_| kinolab_world::catalogue::scattered(0, 0))
}

fn explore() -> Vec<Graded> {
    let t = |world: World, seed| Trial {
        world,
        library: Vec::new(),
        duration: 40.0,
        seed,
        reach_goal: false,
        explore: Some(Explore {
            min_area: 4.0,
            still: 5.0,
        }),
    };
    vec![
        graded("scattered obstacles", true, t(example("scattered"), 1)),
        graded("two rooms", true, t(example("two-rooms"), 2)),
        graded("a corridor", false, t(example("corridor"), 3)),
        graded("a U-shaped trap", false, t(example("u-trap"), 4)),
        graded(
            "nine discs",
            false,
            t(kinolab_world::catalogue::scattered(7, 9), 5),
        ),
    ]
}

/// `seek` (gain 0.4) and `avoid` (within 0.7 m, gain 0.4).
pub fn seek_and_avoid() -> Vec<Named> {
    vec![
        Named::new(
            "seek",
            Behaviour::GoToGoal {
                gain: 0.4,
                slow_within: 0.5,
            },
        ),
        Named::new(
            "avoid",
            Behaviour::Avoid {
                range: 0.7,
                gain: 0.4,
            },
        ),
    ]
}

fn coordinate() -> Vec<Graded> {
    let t = |seed: u64, count| Trial {
        world: kinolab_world::catalogue::scattered(seed, count),
        library: seek_and_avoid(),
        duration: 40.0,
        seed,
        reach_goal: true,
        explore: None,
    };
    vec![
        graded("six discs", true, t(1, 6)),
        graded("ten discs", true, t(2, 10)),
        graded("twelve discs", false, t(5, 12)),
        graded("eight discs", false, t(6, 8)),
        graded("ten other discs", false, t(9, 10)),
    ]
}

/// The run set up for `source` on `t`.
pub fn setup(hook: Hook, source: &str, t: &Trial) -> Setup {
    let source = source.to_owned();
    let (behaviours, coordinator) = if hook == Hook::Coordinator {
        (t.library.clone(), Coordinator::Script { source })
    } else {
        let mut all = t.library.clone();
        all.push(Named::new(MINE, Behaviour::Script { source }));
        let gains = Default::default();
        (all, Coordinator::Sum { gains })
    };
    let mut s = Setup::new(t.world.clone(), behaviours, coordinator);
    s.duration = t.duration;
    s.seed = t.seed;
    s.stop_at_goal = t.reach_goal;
    s
}

pub(crate) fn run(hook: Hook, source: &str, world: &Graded, t: &Trial) -> Outcome {
    judge(world, t, simulate(&setup(hook, source, t)))
}

/// The outcome of a run (or of one that could not start).
pub(crate) fn judge(world: &Graded, t: &Trial, report: Result<RunReport, FieldError>) -> Outcome {
    let mut out = Outcome::new(world);
    let report = match report {
        Ok(r) => r,
        Err(e) => return out.judged(Some(format!("the run could not start: {e}"))),
    };
    let m = &report.metrics;
    out.error = report.error.clone();
    out.time = report.samples.last().map(|s| s.motion.t);
    out = out
        .metric("path_length", m.path_length)
        .metric("min_clearance", m.min_clearance)
        .metric("collisions", m.collisions as f64);
    let bump = report
        .events
        .iter()
        .find(|e| matches!(e.kind, EventKind::Bump { .. }));
    let explored = t.explore.map(|e| (e, covered(&report.samples)));
    if let Some((_, area)) = explored {
        out = out.metric("area", area);
    }
    let reason = if let Some(b) = bump {
        out.time = Some(b.t);
        Some(format!("touched an obstacle at {} s", fixed(b.t, 1)))
    } else if t.reach_goal && !m.reached {
        Some(format!("not at the goal after {} s", fixed(t.duration, 0)))
    } else if let Some((e, area)) = explored {
        explored_enough(&report.samples, e, area)
    } else {
        None
    };
    out.judged(reason)
}

/// Ground covered: the area of the [`CELL`]-sized cells the robot's
/// centre passed through, m².
pub fn covered(samples: &[Sample]) -> f64 {
    let mut cells: Vec<(i64, i64)> = samples
        .iter()
        .map(|s| {
            let cell = |v: f64| (v / CELL).floor() as i64;
            (cell(s.motion.x), cell(s.motion.y))
        })
        .collect();
    cells.sort_unstable();
    cells.dedup();
    cells.len() as f64 * CELL * CELL
}

/// When the robot first stood still (within [`STILL_WITHIN`] m of one
/// spot) for more than `still` s, if it did.
pub fn stood_still(samples: &[Sample], still: f64) -> Option<f64> {
    let end = samples.last()?.motion.t;
    samples.iter().enumerate().find_map(|(i, s)| {
        let here = (s.motion.x, s.motion.y);
        let left = samples[i..]
            .iter()
            .find(|q| (q.motion.x - here.0).hypot(q.motion.y - here.1) > STILL_WITHIN);
        let until = left.map_or(end, |q| q.motion.t);
        (until - s.motion.t > still).then_some(s.motion.t)
    })
}

/// Why an exploring run fell short, if it did.
fn explored_enough(samples: &[Sample], e: Explore, area: f64) -> Option<String> {
    if let Some(t) = stood_still(samples, e.still) {
        return Some(format!(
            "stood still from {} s for more than {} s",
            fixed(t, 1),
            fixed(e.still, 0)
        ));
    }
    (area < e.min_area).then(|| {
        format!(
            "covered only {} m² of the {} m² asked",
            fixed(area, 2),
            fixed(e.min_area, 0)
        )
    })
}
