//! One player for every simulation: play, pause, step a tick forwards or
//! back, scrub, ¼×/1×/4×, restart, and the instant in a link.
//!
//! A widget wraps its core run in a [`Simulation`] (stepped one tick at a
//! time, cloned for checkpoints, told about events such as a surprise) and
//! hands it to a [`Player`]. Runs are deterministic, so the player records
//! only a small [`Simulation::Tick`] per tick for timelines and plots, and
//! a copy of the whole run every few ticks; showing any earlier instant
//! replays from the nearest copy before it, so what is shown at 12.4 s is
//! exactly the state the run had then. Memory is bounded: at most
//! [`MAX_CHECKPOINTS`] copies (when a run grows past that, every other copy
//! is dropped and the spacing doubles), and at most [`MAX_TICKS`] ticks
//! (the player stops recording there and says so).
//!
//! [`controls`](Player::controls) and [`timeline`](Player::timeline) draw
//! the buttons, the time and the scrub bar ([`ui`] module); the widget
//! draws the run at [`Player::state`].

mod ui;

use serde::Serialize;
use serde::de::DeserializeOwned;

/// The most whole-run copies the player keeps.
pub const MAX_CHECKPOINTS: usize = 64;
/// The most ticks the player records (an hour at 20 ticks a second, or
/// ten minutes at 300); the run pauses there.
pub const MAX_TICKS: usize = 72_000;
/// Ticks a replay runs between looks at the clock (a tick of the
/// architecture arena, four robots sensing and planning, can take a
/// millisecond).
const TICKS_PER_LOOK: usize = 4;
/// Ticks between copies while a run is short.
const FIRST_SPACING: usize = 16;

/// A deterministic run the player can drive.
pub trait Simulation: Clone {
    /// What the player keeps of each tick (the time, a pose, who was in
    /// control): small, since every tick's is kept.
    type Tick: Clone;
    /// Something sprung on the run while it goes (a surprise, a kick).
    type Event: Clone + PartialEq + std::fmt::Debug + Serialize + DeserializeOwned;

    /// Advance one tick; `None` when the run is over (nothing changes).
    fn step(&mut self) -> Option<Self::Tick>;
    /// Simulated time now, s.
    fn time(&self) -> f64;
    /// Simulated time per tick, s (for pacing at 1×).
    fn dt(&self) -> f64;
    /// Apply `event` now.
    fn spring(&mut self, event: &Self::Event);
}

/// How fast the run plays, against the wall clock.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
pub enum Speed {
    Quarter,
    One,
    Four,
}

impl Speed {
    pub const ALL: [Speed; 3] = [Speed::Quarter, Speed::One, Speed::Four];

    pub fn factor(self) -> f64 {
        match self {
            Speed::Quarter => 0.25,
            Speed::One => 1.0,
            Speed::Four => 4.0,
        }
    }

    pub fn label(self) -> &'static str {
        match self {
            Speed::Quarter => "¼×",
            Speed::One => "1×",
            Speed::Four => "4×",
        }
    }
}

/// A run, its recording and the instant shown.
#[derive(Debug, Clone)]
pub struct Player<S: Simulation> {
    /// The run after `ticks.len()` ticks, with every event applied.
    live: S,
    ticks: Vec<S::Tick>,
    /// `times[k]`: simulated time after `k` ticks.
    times: Vec<f64>,
    /// `checkpoints[i]`: the run after `i · spacing` ticks.
    checkpoints: Vec<S>,
    spacing: usize,
    /// Events and the tick after which each was sprung.
    events: Vec<(usize, S::Event)>,
    /// Ticks shown: from 0 (the start) to `ticks.len()` (the live end).
    cursor: usize,
    /// The run at `cursor`, when that is not the live end.
    shown: Option<(usize, S)>,
    over: bool,
    pub playing: bool,
    pub speed: Speed,
    /// Ticks owed to the wall clock and not yet run.
    owed: f64,
    /// A link's replay still under way (see [`Player::replay`]).
    catching: Option<Catching<S::Event>>,
}

/// What is left of a link's replay: the events still to spring, each at its
/// time, and the instant to land on.
#[derive(Debug, Clone)]
struct Catching<E> {
    events: std::collections::VecDeque<(f64, E)>,
    instant: f64,
}

/// The most wall-clock time long work (a link's replay, a run recorded
/// for a stepper) takes in one frame: a link to an hour into a run must
/// not freeze the page, so the rest runs over the next frames. (Debug
/// builds, which only tests run, are ten times slower and do the whole of
/// it at once, so a test sees the result at once.)
pub const FRAME_BUDGET: std::time::Duration = if cfg!(debug_assertions) {
    std::time::Duration::from_secs(30)
} else {
    std::time::Duration::from_millis(8)
};

impl<S: Simulation> Player<S> {
    /// A player at the start of `run`, paused.
    pub fn new(run: S) -> Self {
        Self {
            times: vec![run.time()],
            checkpoints: vec![run.clone()],
            live: run,
            ticks: Vec::new(),
            spacing: FIRST_SPACING,
            events: Vec::new(),
            cursor: 0,
            shown: None,
            over: false,
            playing: false,
            speed: Speed::One,
            owed: 0.0,
            catching: None,
        }
    }

    /// Ticks recorded so far.
    pub fn len(&self) -> usize {
        self.ticks.len()
    }

    pub fn is_empty(&self) -> bool {
        self.ticks.is_empty()
    }

    /// Ticks shown (the instant is after this many).
    pub fn cursor(&self) -> usize {
        self.cursor
    }

    /// Every tick recorded, and those up to the instant shown.
    pub fn ticks(&self) -> &[S::Tick] {
        &self.ticks
    }

    pub fn ticks_shown(&self) -> &[S::Tick] {
        &self.ticks[..self.cursor]
    }

    /// The simulated time shown, s.
    pub fn time(&self) -> f64 {
        self.times[self.cursor]
    }

    /// The time after `k` ticks, s (the last recorded, past the end).
    pub fn time_at(&self, k: usize) -> f64 {
        self.times[k.min(self.ticks.len())]
    }

    /// Whether the run has ended (a goal reached, its time up).
    pub fn over(&self) -> bool {
        self.over
    }

    /// Whether the recording is full ([`MAX_TICKS`]).
    pub fn full(&self) -> bool {
        self.ticks.len() >= MAX_TICKS
    }

    /// Whether the instant shown is the live end of the run.
    pub fn at_end(&self) -> bool {
        self.cursor == self.ticks.len()
    }

    /// The events sprung so far, with the time of each.
    pub fn events(&self) -> Vec<(f64, S::Event)> {
        self.events
            .iter()
            .map(|(k, e)| (self.times[*k], e.clone()))
            .collect()
    }

    /// The run as it was at the instant shown.
    pub fn state(&mut self) -> &S {
        if self.at_end() {
            return &self.live;
        }
        let k = self.cursor;
        if self.shown.as_ref().is_none_or(|(at, _)| *at != k) {
            self.shown = Some((k, self.replayed(k)));
        }
        match &self.shown {
            Some((_, run)) => run,
            None => &self.live,
        }
    }

    /// The run at the instant shown, for a look that cannot change the
    /// player (a widget's description): borrowed when it is at hand (the
    /// live end, or the instant last drawn), replayed otherwise.
    pub fn peek(&self) -> std::borrow::Cow<'_, S> {
        use std::borrow::Cow;
        if self.at_end() {
            return Cow::Borrowed(&self.live);
        }
        match &self.shown {
            Some((at, run)) if *at == self.cursor => Cow::Borrowed(run),
            _ => Cow::Owned(self.replayed(self.cursor)),
        }
    }

    /// The run after `k` ticks, from the copy at or before `k`.
    fn replayed(&self, k: usize) -> S {
        let i = (k / self.spacing).min(self.checkpoints.len() - 1);
        let mut run = self.checkpoints[i].clone();
        for tick in i * self.spacing..k {
            run.step();
            for (_, e) in self.events.iter().filter(|(at, _)| *at == tick + 1) {
                run.spring(e);
            }
        }
        run
    }

    /// One tick forwards: through the recording, or a new one at the end.
    /// False when the run is over.
    pub fn step_forward(&mut self) -> bool {
        if !self.at_end() {
            self.cursor += 1;
            return true;
        }
        if self.over || self.full() {
            return false;
        }
        let Some(tick) = self.live.step() else {
            self.over = true;
            return false;
        };
        self.ticks.push(tick);
        self.times.push(self.live.time());
        self.cursor = self.ticks.len();
        if self.cursor.is_multiple_of(self.spacing) {
            self.checkpoints.push(self.live.clone());
            self.thin();
        }
        true
    }

    /// Keep at most [`MAX_CHECKPOINTS`] copies: drop every other one.
    fn thin(&mut self) {
        if self.checkpoints.len() <= MAX_CHECKPOINTS {
            return;
        }
        let kept: Vec<S> = self.checkpoints.iter().step_by(2).cloned().collect();
        self.checkpoints = kept;
        self.spacing *= 2;
    }

    /// One tick back; false at the start.
    pub fn step_back(&mut self) -> bool {
        self.playing = false;
        if self.cursor == 0 {
            return false;
        }
        self.cursor -= 1;
        true
    }

    /// Show the instant after `k` ticks, running the run on if `k` is past
    /// the end (as far as it goes).
    pub fn seek(&mut self, k: usize) {
        while self.ticks.len() < k && self.step_forward() {}
        self.cursor = k.min(self.ticks.len());
    }

    /// Show the first instant at or after `t` seconds (running on as needed).
    pub fn seek_time(&mut self, t: f64) {
        while self.times.last().is_some_and(|last| *last < t - 1e-9) && self.step_forward() {}
        let k = self.times.partition_point(|x| *x < t - 1e-9);
        self.cursor = k.min(self.ticks.len());
    }

    /// Back to the start and play (the recording stays: the run is the same).
    pub fn restart(&mut self) {
        self.cursor = 0;
        self.owed = 0.0;
        self.playing = true;
    }

    /// Spring `event` at the instant shown: what came after is dropped and
    /// the run goes on from here with the event.
    pub fn spring(&mut self, event: S::Event) {
        let k = self.cursor;
        let mut run = self.state().clone();
        run.spring(&event);
        self.ticks.truncate(k);
        self.times.truncate(k + 1);
        self.events.retain(|(at, _)| *at <= k);
        self.events.push((k, event));
        self.checkpoints.truncate(k / self.spacing + 1);
        if k.is_multiple_of(self.spacing)
            && let Some(last) = self.checkpoints.last_mut()
        {
            *last = run.clone();
        }
        self.live = run;
        self.shown = None;
        self.over = false;
    }

    /// What a link carries of the run: the instant shown and the events
    /// (while a replay is under way, the instant and events it lands on).
    pub fn moment(&self) -> crate::link::Moment<S::Event> {
        let mut events = self.events();
        let instant = match &self.catching {
            Some(c) => {
                events.extend(c.events.iter().cloned());
                c.instant
            }
            None => self.time(),
        };
        crate::link::Moment { instant, events }
    }

    /// Replay a link's events (each at its time) and land on `instant`,
    /// paused. What does not fit in this frame's budget runs over the
    /// next frames ([`Player::catching_up`]).
    pub fn replay(&mut self, events: &[(f64, S::Event)], instant: f64) {
        self.start_replay(events, instant);
        self.catch_up(FRAME_BUDGET);
    }

    fn start_replay(&mut self, events: &[(f64, S::Event)], instant: f64) {
        self.playing = false;
        self.catching = Some(Catching {
            events: events.iter().cloned().collect(),
            instant,
        });
    }

    /// Whether a link's replay is still running on.
    pub fn catching_up(&self) -> bool {
        self.catching.is_some()
    }

    /// Run a replay on for at most `budget` of wall time (at least a
    /// chunk of ticks).
    fn catch_up(&mut self, budget: std::time::Duration) {
        let started = web_time::Instant::now();
        while let Some(mut c) = self.catching.take() {
            let target = c.events.front().map_or(c.instant, |(t, _)| *t);
            if self.run_toward(target, TICKS_PER_LOOK) {
                match c.events.pop_front() {
                    Some((t, event)) => {
                        self.seek_time(t);
                        self.spring(event);
                    }
                    None => {
                        self.seek_time(c.instant);
                        return;
                    }
                }
            }
            self.catching = Some(c);
            if started.elapsed() > budget {
                return;
            }
        }
    }

    /// Record up to `most` more ticks toward time `t`; whether the record
    /// reaches it (or the run is over).
    fn run_toward(&mut self, t: f64, most: usize) -> bool {
        for _ in 0..most {
            if !self.times.last().is_some_and(|last| *last < t - 1e-9) || !self.step_forward() {
                return true;
            }
        }
        false
    }

    /// Run on as the wall clock says (`seconds` since the last frame at
    /// [`Player::speed`]), at most `most` ticks; whether anything moved.
    pub fn advance(&mut self, seconds: f64, most: usize) -> bool {
        if self.catching.is_some() {
            self.catch_up(FRAME_BUDGET);
            return true;
        }
        if !self.playing {
            return false;
        }
        let dt = self.live.dt().max(1e-9);
        self.owed = (self.owed + seconds * self.speed.factor() / dt).min(most as f64);
        let mut moved = false;
        while self.owed >= 1.0 {
            self.owed -= 1.0;
            if !self.step_forward() {
                self.playing = false;
                self.owed = 0.0;
                break;
            }
            moved = true;
        }
        moved
    }
}

#[cfg(test)]
mod tests;
