use serde::{Deserialize, Serialize};

use super::*;

/// A toy run: a number that grows by its speed each tick, for 1000 ticks
/// of 0.05 s; a kick changes the speed. Its state after any ticks and
/// kicks is known in closed form.
#[derive(Debug, Clone, PartialEq)]
struct Counter {
    tick: usize,
    value: f64,
    speed: f64,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Kick(f64);

impl Simulation for Counter {
    type Tick = f64;
    type Event = Kick;

    fn step(&mut self) -> Option<f64> {
        if self.tick >= 1000 {
            return None;
        }
        self.tick += 1;
        self.value += self.speed;
        Some(self.value)
    }

    fn time(&self) -> f64 {
        self.tick as f64 * 0.05
    }

    fn dt(&self) -> f64 {
        0.05
    }

    fn spring(&mut self, event: &Kick) {
        self.speed = event.0;
    }
}

fn counter() -> Counter {
    Counter {
        tick: 0,
        value: 0.0,
        speed: 1.0,
    }
}

#[test]
fn any_instant_shows_the_state_the_run_had_there() {
    let mut p = Player::new(counter());
    p.seek(700);
    assert_eq!(p.len(), 700);
    for k in [0, 1, 15, 16, 17, 333, 699, 700] {
        p.seek(k);
        assert_eq!(p.state().value, k as f64, "after {k} ticks");
        assert_eq!(p.state().tick, k);
        assert!((p.time() - k as f64 * 0.05).abs() < 1e-12);
    }
}

#[test]
fn stepping_back_and_forth_lands_on_the_same_states() {
    let mut p = Player::new(counter());
    p.seek(100);
    let forward: Vec<Counter> = (0..=100)
        .map(|k| {
            p.seek(k);
            p.state().clone()
        })
        .collect();
    p.seek(100);
    for k in (0..100).rev() {
        assert!(p.step_back());
        assert_eq!(p.state(), &forward[k], "back to {k}");
    }
    assert!(!p.step_back(), "nothing before the start");
    for (k, state) in forward.iter().enumerate().skip(1) {
        assert!(p.step_forward());
        assert_eq!(p.state(), state, "on to {k}");
    }
    assert_eq!(p.len(), 100, "stepping through the recording adds nothing");
}

#[test]
fn a_sprung_event_changes_what_follows_and_replays_the_same() {
    let mut p = Player::new(counter());
    p.seek(300);
    p.seek(40);
    p.spring(Kick(3.0));
    assert_eq!(p.len(), 40, "what came after the kick is dropped");
    p.seek(100);
    assert_eq!(p.state().value, 40.0 + 3.0 * 60.0);
    p.seek(32);
    assert_eq!(p.state().value, 32.0, "before the kick");
    p.seek(41);
    assert_eq!(p.state().value, 43.0);
    // A link: the events at their times and the instant.
    let events = p.events();
    assert_eq!(events, vec![(40.0 * 0.05, Kick(3.0))]);
    let mut again = Player::new(counter());
    again.replay(&events, 4.5);
    assert_eq!(again.cursor(), 90);
    assert_eq!(again.state().value, 40.0 + 3.0 * 50.0);
}

#[test]
fn a_kick_on_a_copy_boundary_is_kept_in_the_copy() {
    let mut p = Player::new(counter());
    p.seek(64);
    p.seek(32);
    p.spring(Kick(-1.0));
    p.seek(80);
    p.seek(33);
    assert_eq!(p.state().value, 31.0);
    p.seek(0);
    p.spring(Kick(2.0));
    p.seek(10);
    assert_eq!(p.state().value, 20.0);
    p.seek(5);
    assert_eq!(p.state().value, 10.0);
}

#[test]
fn memory_stays_bounded_as_the_run_grows() {
    let mut p = Player::new(counter());
    p.seek(1000);
    assert!(p.over() || p.len() == 1000);
    assert!(p.checkpoints.len() <= MAX_CHECKPOINTS);
    assert_eq!(p.spacing, 16, "1000 ticks fit in 64 copies of 16");
    // The whole run is still reachable exactly.
    p.seek(999);
    assert_eq!(p.state().value, 999.0);
    assert!(!p.step_forward() || p.cursor() == 1000);
}

#[test]
fn copies_thin_out_on_long_runs() {
    #[derive(Debug, Clone)]
    struct Endless(usize);
    impl Simulation for Endless {
        type Tick = ();
        type Event = Kick;
        fn step(&mut self) -> Option<()> {
            self.0 += 1;
            Some(())
        }
        fn time(&self) -> f64 {
            self.0 as f64
        }
        fn dt(&self) -> f64 {
            1.0
        }
        fn spring(&mut self, _: &Kick) {}
    }
    let mut p = Player::new(Endless(0));
    p.seek(5000);
    assert!(
        p.checkpoints.len() <= MAX_CHECKPOINTS,
        "{}",
        p.checkpoints.len()
    );
    assert_eq!(p.spacing, 128);
    p.seek(4321);
    assert_eq!(p.state().0, 4321);
}

#[test]
fn playing_follows_the_wall_clock_at_each_speed() {
    let mut p = Player::new(counter());
    p.playing = true;
    assert!(p.advance(0.5, 1000));
    assert_eq!(p.cursor(), 10, "0.5 s at 1× is ten 0.05 s ticks");
    p.speed = Speed::Four;
    p.advance(0.5, 1000);
    assert_eq!(p.cursor(), 50);
    p.speed = Speed::Quarter;
    p.advance(0.1, 1000);
    assert_eq!(p.cursor(), 50, "a quarter of two ticks is not yet one");
    p.advance(0.1, 1000);
    assert_eq!(p.cursor(), 51);
    p.speed = Speed::Four;
    p.advance(100.0, 30);
    assert_eq!(p.cursor(), 81, "at most `most` ticks a frame");
    p.playing = false;
    assert!(!p.advance(1.0, 1000));
    p.restart();
    assert_eq!((p.cursor(), p.playing), (0, true));
    p.advance(0.05, 10);
    assert_eq!(p.cursor(), 4, "4× replays the recording from the start");
}

#[test]
fn the_run_ends_and_stays_ended() {
    let mut p = Player::new(counter());
    p.seek(2000);
    assert_eq!(p.len(), 1000);
    assert!(p.over());
    p.playing = true;
    p.advance(1.0, 100);
    assert!(!p.playing, "playing stops at the end");
    p.seek_time(12.34);
    assert_eq!(p.cursor(), 247);
}

/// A link's replay spread over many frames lands where one all at once
/// does, and meanwhile the link still says where it is going.
#[test]
fn a_replay_in_pieces_lands_where_one_at_once_does() {
    let events = [(10.0, Kick(2.0)), (20.0, Kick(-1.0))];
    let mut whole = Player::new(counter());
    whole.replay(&events, 40.0);
    assert!(!whole.catching_up());
    let mut pieces = Player::new(counter());
    pieces.start_replay(&events, 40.0);
    let mut frames = 0;
    while pieces.catching_up() {
        assert_eq!(pieces.moment().instant, 40.0);
        assert_eq!(pieces.moment().events, events.to_vec());
        pieces.catch_up(std::time::Duration::ZERO);
        frames += 1;
    }
    assert!(frames > 5, "{frames} pieces");
    assert_eq!(pieces.moment(), whole.moment());
    assert_eq!(pieces.state().value, whole.state().value);
    // 200 ticks at 1, 200 at 2, 400 at -1.
    assert_eq!(whole.state().value, 200.0 + 400.0 - 400.0);
}

#[test]
fn a_peek_sees_the_instant_shown_without_moving_anything() {
    let mut p = Player::new(counter());
    p.seek(300);
    p.spring(Kick(2.0));
    p.seek(500);
    for k in [0, 17, 300, 301, 444, 500] {
        p.seek(k);
        // Before the instant is drawn (replayed), then after (borrowed).
        let peeked = p.peek().into_owned();
        assert_eq!(peeked, *p.state(), "after {k} ticks");
        assert!(matches!(p.peek(), std::borrow::Cow::Borrowed(_)));
        assert_eq!(p.cursor(), k);
    }
}
