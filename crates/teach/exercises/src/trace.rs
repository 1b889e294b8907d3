//! A learner's run, tick by tick, for the stepper: at each call of their
//! function, where the robot was, what the function was given, what it
//! answered, and what it printed and plotted. Runs are deterministic, so
//! the trace is the graded run itself, recorded.

use kinolab_architectures::Architecture;
use kinolab_architectures::run::Recording as ArenaRecording;
use kinolab_behaviours::run::{Frame, Recording};
use kinolab_fields::Field;
use kinolab_fields::follow::follow;
use kinolab_script::Output;
use kinolab_world::{Shape, World as Place};
use serde::{Deserialize, Serialize};

use crate::{Exercise, Outcome, Trial, World, architecture, behaviours};

/// What the stepper draws under the ticks. It is plain data, worked out
/// where the code ran: a trace crosses from the thread that ran the
/// learner's code to the page that shows it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Scene {
    /// The plane round the goal pose, at the origin facing along x.
    Plane { area: [f64; 4] },
    /// A world, its obstacles where they are at each tick's time (on the
    /// wire, as its world file).
    World(#[serde(with = "world_file")] Box<Place>),
    /// The whole field over `area`, the learner's primitive in it: its
    /// vector on a grid of cells (`[x, y, fx, fy]`), what the robot must
    /// not pass through, and the goal.
    Field {
        area: [f64; 4],
        arrows: Vec<[f64; 4]>,
        obstacles: Vec<Outline>,
        goal: Option<[f64; 2]>,
    },
    /// The hexapod from above: its centre of mass.
    Legs { com: [f64; 2] },
    /// An arm from the side (x along, z up): its joints and tool where
    /// the target would put them, and its reach.
    Arm { target: Vec<[f64; 2]>, reach: f64 },
}

/// An obstacle's outline, as the stepper draws it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Outline {
    Disc {
        centre: [f64; 2],
        radius: f64,
    },
    Polygon {
        points: Vec<[f64; 2]>,
    },
    Wall {
        from: [f64; 2],
        to: [f64; 2],
        thickness: f64,
    },
}

impl From<&Shape> for Outline {
    fn from(shape: &Shape) -> Self {
        let at = |p: &kinolab_world::Vec2| [p.x, p.y];
        match shape {
            Shape::Disc { centre, radius } => Outline::Disc {
                centre: at(centre),
                radius: *radius,
            },
            Shape::Polygon { points } => Outline::Polygon {
                points: points.iter().map(at).collect(),
            },
            Shape::Wall {
                from,
                to,
                thickness,
            } => Outline::Wall {
                from: at(from),
                to: at(to),
                thickness: *thickness,
            },
        }
    }
}

/// A world written as its world file, and read back.
mod world_file {
    use kinolab_world::World;
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(world: &World, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&world.to_json())
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Box<World>, D::Error> {
        let text = String::deserialize(d)?;
        World::from_json(&text)
            .map(Box::new)
            .map_err(serde::de::Error::custom)
    }
}

/// The grid of arrows a field scene shows.
const ARROWS: (usize, usize) = (22, 14);

/// One call of the learner's function.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Tick {
    /// Simulated time, s (for a walk, the phase).
    pub t: f64,
    /// The robot's pose: x, y (m), heading (rad).
    pub pose: [f64; 3],
    /// The function's inputs, by name, as text.
    pub given: Vec<(String, String)>,
    /// What it answered, as text.
    pub returned: String,
    pub output: Output,
    /// The range rays it saw (robot-frame angle, range), behaviours only.
    pub rays: Vec<[f64; 2]>,
    /// The feet (x, y, standing), walks only.
    pub feet: Vec<[f64; 3]>,
    /// The arm's joints and tool from the side (x, z), arms only.
    #[serde(default)]
    pub links: Vec<[f64; 2]>,
}

/// A world run with the learner's code, recorded.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Trace {
    pub scene: Scene,
    /// Where the robot went, start to end.
    pub path: Vec<[f64; 2]>,
    pub ticks: Vec<Tick>,
    pub outcome: Outcome,
}

/// The most ticks a trace keeps; longer runs keep every n-th call.
pub const MAX_TICKS: usize = 4000;

impl Exercise {
    /// `source` run on `world`, recorded tick by tick.
    pub fn trace(&self, source: &str, world: &World) -> Trace {
        let mut tracing = self.tracing(source, world);
        while !tracing.advance(STEPS_PER_ADVANCE) {}
        tracing.finish()
    }

    /// `source` on `world`, to be recorded a piece at a time (see [`Tracing`]).
    pub fn tracing(&self, source: &str, world: &World) -> Tracing {
        let job = match &world.trial {
            Trial::Behaviours(t) => {
                let setup = behaviours::setup(self.hook, source, t);
                match Recording::new(&setup) {
                    Ok(recording) => Job::Behaviours(Box::new(BehavioursJob::new(recording, t))),
                    Err(e) => unstarted(&t.world, behaviours::judge(world, t, Err(e))),
                }
            }
            Trial::Arena(t) => {
                let setup = architecture::setup(source, t);
                match ArenaRecording::new(&setup, Architecture::Hybrid, architecture::EVERY) {
                    Ok(recording) => Job::Arena(Box::new(ArenaJob::new(recording, t.clone()))),
                    Err(e) => unstarted(&t.setup.world, architecture::judge(world, t, Err(e))),
                }
            }
            // Short runs: recorded at once.
            Trial::Control(t) => self.at_once(source, world, control(source, t)),
            Trial::Field(t) => self.at_once(source, world, field(source, t)),
            Trial::Legs(t) => self.at_once(source, world, legs(source, t)),
            Trial::Arm(t) => self.at_once(source, world, arm(source, t)),
        };
        Tracing {
            job,
            world: world.clone(),
        }
    }

    fn at_once(&self, source: &str, world: &World, (scene, path, mut ticks): Recorded) -> Job {
        thin(&mut ticks);
        Job::Done(Box::new(Trace {
            scene,
            path,
            ticks,
            outcome: self.run(source, world),
        }))
    }
}

/// A run that could not start: its world, and the outcome saying why.
fn unstarted(place: &Place, outcome: Outcome) -> Job {
    Job::Done(Box::new(Trace {
        scene: Scene::World(Box::new(place.clone())),
        path: Vec::new(),
        ticks: Vec::new(),
        outcome,
    }))
}

/// Steps [`Exercise::trace`] runs between looks at whether the run is over.
const STEPS_PER_ADVANCE: usize = 256;

/// A trace being recorded. A long run (a minute of an arena, a few
/// thousand calls of the learner's code) can take longer than a frame of
/// the page, so a host runs it a number of steps per frame with
/// [`Tracing::advance`] and takes the trace with [`Tracing::finish`] once
/// that says it is over. The run recorded is the graded run itself: its
/// outcome is judged from the same steps.
#[derive(Debug)]
pub struct Tracing {
    job: Job,
    world: World,
}

#[derive(Debug)]
enum Job {
    Done(Box<Trace>),
    Behaviours(Box<BehavioursJob>),
    Arena(Box<ArenaJob>),
}

impl Tracing {
    /// Run at most `steps` more steps; whether the run is over.
    pub fn advance(&mut self, steps: usize) -> bool {
        match &mut self.job {
            Job::Done(_) => true,
            Job::Behaviours(job) => job.advance(steps),
            Job::Arena(job) => job.advance(steps),
        }
    }

    /// How far the run has got, from 0 to 1.
    pub fn progress(&self) -> f64 {
        let (now, end) = match &self.job {
            Job::Done(_) => return 1.0,
            Job::Behaviours(job) => (job.recording.runner.sim.time, job.trial.duration),
            Job::Arena(job) => (
                job.recording.arena.entrants[0].sim.time,
                job.trial.setup.duration,
            ),
        };
        if end > 0.0 {
            (now / end).clamp(0.0, 1.0)
        } else {
            1.0
        }
    }

    /// The trace (of the run so far, when called before [`Tracing::advance`]
    /// said it is over).
    pub fn finish(self) -> Trace {
        let (scene, path, mut ticks, outcome) = match self.job {
            Job::Done(trace) => return *trace,
            Job::Behaviours(job) => {
                let BehavioursJob {
                    recording,
                    trial,
                    scene,
                    path,
                    ticks,
                    ..
                } = *job;
                let outcome = behaviours::judge(&self.world, &trial, Ok(recording.finish()));
                (scene, path, ticks, outcome)
            }
            Job::Arena(job) => {
                let ArenaJob {
                    recording,
                    trial,
                    scene,
                    path,
                    ticks,
                    ..
                } = *job;
                let outcome = architecture::judge(&self.world, &trial, Ok(recording.finish()));
                (scene, path, ticks, outcome)
            }
        };
        thin(&mut ticks);
        Trace {
            scene,
            path,
            ticks,
            outcome,
        }
    }
}

/// Every n-th tick (and the last), at most [`MAX_TICKS`].
fn thin(ticks: &mut Vec<Tick>) {
    let n = ticks.len().div_ceil(MAX_TICKS).max(1);
    if n == 1 {
        return;
    }
    let last = ticks.pop();
    let kept: Vec<Tick> = ticks.iter().step_by(n).cloned().collect();
    *ticks = kept;
    ticks.extend(last);
}

fn number(x: f64) -> String {
    kinolab_common::display::fixed(x, 3)
}

fn given(pairs: &[(&str, String)]) -> Vec<(String, String)> {
    pairs
        .iter()
        .map(|(k, v)| ((*k).to_owned(), v.clone()))
        .collect()
}

type Recorded = (Scene, Vec<[f64; 2]>, Vec<Tick>);

fn control(source: &str, t: &crate::control::Trial) -> Recorded {
    let area = [-2.5, -2.0, 2.5, 2.0];
    let Ok(spec) = kinolab_control::file::from_json(&crate::control::run_file(source, t)) else {
        return (Scene::Plane { area }, Vec::new(), Vec::new());
    };
    let Ok(run) = spec.run.simulate() else {
        return (Scene::Plane { area }, Vec::new(), Vec::new());
    };
    let pose_at = |time: f64| {
        let i = run.samples.partition_point(|s| s.t < time - 1e-9);
        let s = &run.samples[i.min(run.samples.len().saturating_sub(1))];
        [s.pose.x, s.pose.y, s.pose.theta]
    };
    let path = run.samples.iter().map(|s| [s.pose.x, s.pose.y]).collect();
    let ticks = run
        .calls
        .iter()
        .map(|c| Tick {
            t: c.t,
            pose: pose_at(c.t),
            given: given(&[
                ("rho", number(c.rho)),
                ("alpha", number(c.alpha)),
                ("beta", number(c.beta)),
            ]),
            returned: format!("[{}, {}]", number(c.v), number(c.omega)),
            output: c.output.clone(),
            rays: Vec::new(),
            feet: Vec::new(),
            links: Vec::new(),
        })
        .collect();
    (Scene::Plane { area }, path, ticks)
}

/// A behaviour run on the way: the percepts the learner's function saw
/// and what it answered, each step.
#[derive(Debug)]
struct BehavioursJob {
    recording: Recording,
    trial: behaviours::Trial,
    scene: Scene,
    path: Vec<[f64; 2]>,
    ticks: Vec<Tick>,
}

impl BehavioursJob {
    fn new(recording: Recording, t: &behaviours::Trial) -> Self {
        let start = recording.runner.sim.pose;
        Self {
            recording,
            trial: t.clone(),
            scene: Scene::World(Box::new(t.world.clone())),
            path: vec![[start.x, start.y]],
            ticks: Vec::new(),
        }
    }

    fn advance(&mut self, steps: usize) -> bool {
        for _ in 0..steps {
            let Some(frame) = self.recording.step() else {
                return true;
            };
            self.path.push([frame.pose.x, frame.pose.y]);
            self.ticks.extend(behaviours_tick(frame));
        }
        false
    }
}

/// The learner's call in `frame`, if the frame had one.
fn behaviours_tick(frame: Frame) -> Option<Tick> {
    let p = &frame.percepts;
    let call = frame.calls.into_iter().next()?;
    let goal = p.goal.map_or("()".to_owned(), |g| {
        format!(
            "bearing {}, distance {}",
            number(g.bearing),
            number(g.distance)
        )
    });
    let nearest = p
        .rays
        .iter()
        .min_by(|a, b| a.range.total_cmp(&b.range))
        .map_or("no rays".to_owned(), |r| {
            format!("{} m at {}", number(r.range), number(r.angle))
        });
    let [front, left, back, right] = p.bumpers;
    Some(Tick {
        t: p.time,
        pose: [frame.pose.x, frame.pose.y, frame.pose.theta],
        given: given(&[
            ("p.t", number(p.time)),
            ("p.goal", goal),
            ("nearest ray", nearest),
            (
                "p.bumpers",
                format!("front {front}, left {left}, back {back}, right {right}"),
            ),
            (
                "p.speed",
                format!("[{}, {}]", number(p.speed[0]), number(p.speed[1])),
            ),
        ]),
        returned: call.returned,
        output: call.output,
        rays: p.rays.iter().map(|r| [r.angle, r.range]).collect(),
        feet: Vec::new(),
        links: Vec::new(),
    })
}
fn field(source: &str, t: &crate::fields::Trial) -> Recorded {
    let area = [-0.5, -2.5, 7.0, 2.5];
    let Ok(f) = Field::from_json(&crate::fields::field_file(source, t.base)) else {
        let scene = Scene::Field {
            area,
            arrows: Vec::new(),
            obstacles: Vec::new(),
            goal: None,
        };
        return (scene, Vec::new(), Vec::new());
    };
    let pace = crate::fields::PACE;
    let path: Vec<[f64; 2]> =
        follow(&f, t.start.into(), pace).map_or_else(|_| Vec::new(), |w| w.path);
    let mut ticks = Vec::with_capacity(path.len());
    for (k, p) in path.iter().enumerate() {
        let Some(mine) = f.custom.first() else { break };
        let (returned, output) = match mine.answer((*p).into()) {
            Ok((v, out)) => (format!("[{}, {}]", number(v.x), number(v.y)), out),
            Err(e) => (format!("stopped: {}", e.message), Output::default()),
        };
        ticks.push(Tick {
            t: k as f64 * pace.dt,
            pose: [p[0], p[1], 0.0],
            given: given(&[("x", number(p[0])), ("y", number(p[1]))]),
            returned,
            output,
            rays: Vec::new(),
            feet: Vec::new(),
            links: Vec::new(),
        });
    }
    let cells = kinolab_world::Rect::from(area);
    let scene = Scene::Field {
        area,
        arrows: f
            .arrows(&cells, ARROWS.0, ARROWS.1)
            .into_iter()
            .map(|(p, v)| [p.x, p.y, v.x, v.y])
            .collect(),
        obstacles: f.obstacles().iter().map(Outline::from).collect(),
        goal: f.goal.map(|g| [g.x, g.y]),
    };
    (scene, path, ticks)
}

fn legs(source: &str, t: &crate::legs::Trial) -> Recorded {
    let scene = Scene::Legs { com: t.com };
    let Ok(walker) = crate::legs::walker(source, t) else {
        return (scene, Vec::new(), Vec::new());
    };
    let names = kinolab_locomotion::walker::LEGS;
    let mut ticks = Vec::new();
    for k in 0..=t.samples {
        let tau = k as f64 / t.samples as f64;
        let Ok(plan) = walker.plan_told(tau) else {
            break;
        };
        let answers: Vec<String> = plan
            .iter()
            .zip(names)
            .map(|(((down, at), _), leg)| {
                let how = if *down { "stands" } else { "lifts" };
                format!(
                    "{leg} {how} at [{}, {}, {}]",
                    number(at.x),
                    number(at.y),
                    number(at.z)
                )
            })
            .collect();
        let mut output = Output::default();
        for (_, out) in &plan {
            output.prints.extend(out.prints.iter().cloned());
            output.plots.extend(out.plots.iter().cloned());
        }
        ticks.push(Tick {
            t: tau,
            pose: [0.0, 0.0, 0.0],
            given: given(&[
                ("phase", number(tau)),
                ("leg", "each of the six in turn".into()),
            ]),
            returned: answers.join("; "),
            output,
            rays: Vec::new(),
            feet: plan
                .iter()
                .map(|((down, at), _)| [at.x, at.y, f64::from(u8::from(*down))])
                .collect(),
            links: Vec::new(),
        });
    }
    (scene, Vec::new(), ticks)
}

/// The hybrid robot's run on the way: what its sequencer (the learner's
/// `next`) was asked and answered, each time it was asked. After the
/// sequencer fails the run goes on to its end (it is graded that way),
/// with nothing more to show.
#[derive(Debug)]
struct ArenaJob {
    recording: ArenaRecording,
    trial: architecture::Trial,
    scene: Scene,
    path: Vec<[f64; 2]>,
    ticks: Vec<Tick>,
    /// The sequencer has failed: nothing more is recorded.
    failed: bool,
}

impl ArenaJob {
    fn new(recording: ArenaRecording, trial: architecture::Trial) -> Self {
        let e = &recording.arena.entrants[0];
        let start = e.sim.pose;
        Self {
            trial,
            scene: Scene::World(Box::new(e.sim.world.clone())),
            path: vec![[start.x, start.y]],
            ticks: Vec::new(),
            failed: false,
            recording,
        }
    }

    fn advance(&mut self, steps: usize) -> bool {
        for _ in 0..steps {
            if !self.recording.step() {
                return true;
            }
            if self.failed {
                continue;
            }
            let e = &self.recording.arena.entrants[0];
            let pose = e.sim.pose;
            self.path.push([pose.x, pose.y]);
            self.failed = e.controller.failed().is_some();
            let Some(asked) = e.controller.asked() else {
                continue;
            };
            if self
                .ticks
                .last()
                .is_some_and(|last| last.t >= e.sim.time - 1e-9)
            {
                continue;
            }
            self.ticks.push(Tick {
                t: e.sim.time,
                pose: [pose.x, pose.y, pose.theta],
                given: asked
                    .given
                    .iter()
                    .map(|(k, v)| (format!("state.{k}"), v.clone()))
                    .collect(),
                returned: asked.returned.clone(),
                output: asked.output.clone(),
                rays: Vec::new(),
                feet: Vec::new(),
                links: Vec::new(),
            });
        }
        false
    }
}

/// Where the arm's joints and tool are at `q`, from the side (x, z).
fn arm_points(model: &kinolab_mechanism::Model, q: &[f64]) -> Vec<[f64; 2]> {
    model
        .frame("tool")
        .and_then(|tool| model.chain_in_plane(q, &tool, kinolab_mechanism::Plane::Side))
        .unwrap_or_default()
}

fn arm(source: &str, t: &crate::arm::Trial) -> Recorded {
    let target: Vec<f64> = t.target_deg.iter().map(|d| d.to_radians()).collect();
    let Ok((model, run)) = crate::arm::simulate(source, t) else {
        return (
            Scene::Arm {
                target: Vec::new(),
                reach: 1.0,
            },
            Vec::new(),
            Vec::new(),
        );
    };
    let reach = 1.0;
    let scene = Scene::Arm {
        target: arm_points(&model, &target),
        reach,
    };
    let deg = |v: &[f64]| {
        let parts: Vec<String> = v.iter().map(|x| number(x.to_degrees())).collect();
        format!("[{}]°", parts.join(", "))
    };
    let mut path = Vec::new();
    let ticks = run
        .samples
        .iter()
        .map(|s| {
            let links = arm_points(&model, &s.q);
            if let Some(tool) = links.last() {
                path.push(*tool);
            }
            let torques: Vec<String> = s.tau.iter().map(|x| number(*x)).collect();
            Tick {
                t: s.t,
                pose: [0.0, 0.0, 0.0],
                given: given(&[
                    ("q", deg(&s.q)),
                    ("qd", format!("{} rad/s", deg(&s.qd).trim_end_matches('°'))),
                    ("target", deg(&target)),
                    ("payload", format!("{} kg", number(t.payload))),
                ]),
                returned: format!("[{}] N·m", torques.join(", ")),
                output: Output::default(),
                rays: Vec::new(),
                feet: Vec::new(),
                links,
            }
        })
        .collect();
    (scene, path, ticks)
}
