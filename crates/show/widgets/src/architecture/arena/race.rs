//! The three robots' run as the player drives it, and the surprises
//! sprung on it while it goes.

use kinolab_architectures::Arena;
use kinolab_architectures::Surprise;
use kinolab_architectures::arena::Entrant;
use kinolab_architectures::placing::Placed;
use kinolab_architectures::run::Sample;
use kinolab_common::trajectory::Sample as Motion;
use kinolab_world::Vec2;
use serde::{Deserialize, Serialize};

use super::settings::office_surprise;
use crate::player::Simulation;

/// A surprise sprung by a button while the robots run. Only its kind is
/// recorded: where it goes is worked out from the run at that instant,
/// which a replay reaches exactly, so it lands in the same place again.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub(super) enum Spring {
    Door,
    Person,
    MovedGoal,
}

impl Spring {
    pub(super) const ALL: [Spring; 3] = [Spring::Door, Spring::Person, Spring::MovedGoal];

    /// The office's name for it.
    fn id(self) -> &'static str {
        match self {
            Spring::Door => "door",
            Spring::Person => "person",
            Spring::MovedGoal => "moved-goal",
        }
    }

    pub(super) fn label(self) -> &'static str {
        match self {
            Spring::Door => "Close the door",
            Spring::Person => "Send a person in",
            Spring::MovedGoal => "Move the goal",
        }
    }

    fn placed(self) -> Placed {
        match self {
            Spring::Door => Placed::Door,
            Spring::Person => Placed::Person,
            Spring::MovedGoal => Placed::MovedGoal,
        }
    }
}

/// One tick: every robot's sample after it, and whether the robot moved
/// in it (one that has arrived, or whose time is up, stays put).
#[derive(Debug, Clone)]
pub(super) struct Frame {
    pub(super) robots: Vec<(Sample, bool)>,
}

/// Robot `e`'s sample now, as `kinolab arena` prints it.
pub(super) fn sample(e: &Entrant) -> Sample {
    let p = e.sim.pose;
    Sample {
        motion: Motion::new(e.sim.time, [p.x, p.y, p.theta], e.driven.vx, e.driven.omega),
        activity: e.activity.clone(),
    }
}

/// The arena as it runs.
#[derive(Debug, Clone)]
pub(super) struct Race {
    pub(super) arena: Arena,
    /// The office places its surprises where its examples say.
    office: bool,
    dt: f64,
    /// The surprises sprung so far, each as the command line writes it
    /// (with the time it was sprung).
    pub(super) sprung: Vec<Surprise>,
    /// Microseconds each robot's steps (sensing, controller, motion) took
    /// here, summed.
    pub(super) spent: [f64; 3],
}

impl Race {
    pub(super) fn new(arena: Arena, office: bool, dt: f64) -> Self {
        Self {
            arena,
            office,
            dt,
            sprung: Vec::new(),
            spent: [0.0; 3],
        }
    }

    /// Where `kind` goes if sprung now: the office's own example; in any
    /// other world, placed by the core from the world's geometry, ahead
    /// of the robot furthest along.
    pub(super) fn place(&self, kind: Spring) -> Result<Surprise, String> {
        let now = self.arena.time();
        if self.office {
            return office_surprise(kind.id()).map(|s| s.at(now));
        }
        let e = self
            .lead()
            .and_then(|i| self.arena.entrants.get(i))
            .ok_or("there is no robot to place it for")?;
        let at = Vec2::new(e.sim.pose.x, e.sim.pose.y);
        kind.placed()
            .place(&e.sim.world, at, now)
            .map_err(|e| e.to_string())
    }

    /// The robot furthest along: of those still going, the one nearest
    /// its goal (of all of them, when none is going).
    fn lead(&self) -> Option<usize> {
        let duration = self.arena.duration;
        let distance = |e: &Entrant| {
            e.sim.world.goal.map_or(f64::INFINITY, |g| {
                (Vec2::new(e.sim.pose.x, e.sim.pose.y) - g).norm()
            })
        };
        let nearest = |going: bool| {
            self.arena
                .entrants
                .iter()
                .enumerate()
                .filter(|(_, e)| !going || !e.finished(duration))
                .min_by(|(_, a), (_, b)| distance(a).total_cmp(&distance(b)))
                .map(|(i, _)| i)
        };
        nearest(true).or_else(|| nearest(false))
    }
}

impl Simulation for Race {
    type Tick = Frame;
    type Event = Spring;

    fn step(&mut self) -> Option<Frame> {
        if self.arena.done() {
            return None;
        }
        let duration = self.arena.duration;
        let going: Vec<bool> = self
            .arena
            .entrants
            .iter()
            .map(|e| !e.finished(duration))
            .collect();
        for (i, spent) in self.spent.iter_mut().enumerate() {
            let start = web_time::Instant::now();
            self.arena.step_one(i);
            *spent += start.elapsed().as_secs_f64() * 1e6;
        }
        let robots = self
            .arena
            .entrants
            .iter()
            .zip(going)
            .map(|(e, going)| (sample(e), going))
            .collect();
        Some(Frame { robots })
    }

    fn time(&self) -> f64 {
        self.arena.time()
    }

    fn dt(&self) -> f64 {
        self.dt
    }

    /// Spring `event` now; nothing when it has no place here (the widget
    /// says why before it springs one).
    fn spring(&mut self, event: &Spring) {
        let now = self.arena.time();
        if let Ok(surprise) = self.place(*event)
            && self.arena.spring(&surprise).is_ok()
        {
            self.sprung.push(surprise.at(now));
        }
    }
}
