//! The widgets' player at work: scrubbing 60 s back through a recorded
//! behaviour-arena run and architecture-arena run (the replay from the
//! nearest copy before the instant), and the player's own cost per frame
//! at 60 frames a second, over a run that costs nothing to step.

use std::cell::RefCell;

use kinolab_architectures::exercise::office;
use kinolab_architectures::{Architecture, Arena};
use kinolab_behaviours::run::Runner;
use kinolab_widgets::player::{Player, Simulation};

/// How much run is recorded before scrubbing back, s.
const RECORDED: f64 = 120.0;
/// How far back the scrub goes, s.
const BACK: f64 = 60.0;

/// The behaviour arena's run, as its widget wraps it.
#[derive(Debug, Clone)]
pub struct Behaving(Runner);

impl Simulation for Behaving {
    type Tick = f64;
    type Event = ();
    fn step(&mut self) -> Option<f64> {
        (!self.0.done()).then(|| self.0.step().pose.x)
    }
    fn time(&self) -> f64 {
        self.0.sim.time
    }
    fn dt(&self) -> f64 {
        self.0.sim.dt
    }
    fn spring(&mut self, (): &()) {}
}

/// The architecture arena's three robots, as its widget wraps them.
#[derive(Debug, Clone)]
pub struct Racing(Arena);

impl Simulation for Racing {
    type Tick = f64;
    type Event = ();
    fn step(&mut self) -> Option<f64> {
        if self.0.done() {
            return None;
        }
        self.0.step();
        Some(self.0.time())
    }
    fn time(&self) -> f64 {
        self.0.time()
    }
    fn dt(&self) -> f64 {
        self.0.entrants.first().map_or(0.05, |e| e.sim.dt)
    }
    fn spring(&mut self, (): &()) {}
}

/// A player with `RECORDED` seconds of `run` (or all of it) behind it.
fn recorded<S: Simulation>(run: S) -> Player<S> {
    let mut player = Player::new(run);
    player.seek_time(RECORDED);
    player
}

/// Scrub from the end to `BACK` seconds before it (or to the start of a
/// shorter run) and show that instant. Each call lands `turn` ticks later
/// (0 to 63, round and round), so each replays from its copy afresh (the
/// player keeps only the last instant it showed) over every distance from
/// a copy there is.
fn scrub<S: Simulation>(player: &mut Player<S>, turn: &mut usize) -> f64 {
    let end = player.time_at(player.len());
    player.seek(player.len());
    player.seek_time(end - BACK);
    let k = player.cursor() + *turn;
    *turn = (*turn + 1) % 64;
    player.seek(k.min(player.len().saturating_sub(1)));
    player.state().time()
}

thread_local! {
    static BEHAVING: RefCell<Option<(Player<Behaving>, usize)>> = const { RefCell::new(None) };
    static RACING: RefCell<Option<(Player<Racing>, usize)>> = const { RefCell::new(None) };
    static IDLE: RefCell<Option<Player<Idle>>> = const { RefCell::new(None) };
}

/// Scrub back 60 s in the behaviour arena (16 rays, 50 obstacles).
pub fn scrub_behaviour_arena() -> f64 {
    BEHAVING.with(|cell| {
        let mut slot = cell.borrow_mut();
        if slot.is_none() {
            let setup = crate::behaviour::setup(crate::behaviour::cluttered());
            *slot = Runner::new(&setup).ok().map(|r| (recorded(Behaving(r)), 0));
        }
        slot.as_mut()
            .map_or(f64::NAN, |(player, turn)| scrub(player, turn))
    })
}

/// Scrub back 60 s in the architecture arena (the office, a person
/// stepping in, three robots).
pub fn scrub_architecture_arena() -> f64 {
    RACING.with(|cell| {
        let mut slot = cell.borrow_mut();
        if slot.is_none() {
            *slot = office(Some("person"))
                .ok()
                .and_then(|s| Arena::new(&s, &Architecture::ALL).ok())
                .map(|a| (recorded(Racing(a)), 0));
        }
        slot.as_mut()
            .map_or(f64::NAN, |(player, turn)| scrub(player, turn))
    })
}

/// A run whose step costs nothing: what is left is the player's own work.
#[derive(Debug, Clone)]
pub struct Idle(u64);

impl Simulation for Idle {
    type Tick = u64;
    type Event = ();
    fn step(&mut self) -> Option<u64> {
        self.0 += 1;
        Some(self.0)
    }
    fn time(&self) -> f64 {
        self.0 as f64 * 0.01
    }
    fn dt(&self) -> f64 {
        0.01
    }
    fn spring(&mut self, (): &()) {}
}

/// One frame at 60 Hz playing at 1× (about two ticks at 100 Hz), then the
/// instant shown: the player's bookkeeping alone. Starts over when the
/// recording is full.
pub fn player_frame() -> f64 {
    IDLE.with(|cell| {
        let mut slot = cell.borrow_mut();
        let player = slot.get_or_insert_with(|| Player::new(Idle(0)));
        if player.full() {
            *player = Player::new(Idle(0));
        }
        player.playing = true;
        player.advance(1.0 / 60.0, 100);
        player.state().0 as f64
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn a_scrub_lands_sixty_seconds_back_and_shows_that_instant() {
        for (name, kernel) in [
            ("behaviour", scrub_behaviour_arena as fn() -> f64),
            ("architecture", scrub_architecture_arena),
        ] {
            let a = kernel();
            let b = kernel();
            // Two calls land one tick apart, 60 s before the end of the
            // recording (or at the start of a shorter run).
            assert!(b > a, "{name}: {a} {b}");
            assert!(b - a < 0.2, "{name}: {a} {b}");
            assert!(
                name == "architecture" || (a - 60.0).abs() < 0.2,
                "{name}: {a}"
            );
        }
        let t0 = player_frame();
        let t1 = player_frame();
        assert!(t1 > t0);
    }
}
