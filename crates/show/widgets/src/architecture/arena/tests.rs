use kinolab_architectures::Surprise;

use super::settings::{Picks, Scripted};
use super::*;
use crate::registry::{create, spec};

fn widget(params: &[(&str, &str)]) -> ArchitectureArena {
    let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
    ArchitectureArena::new(p.settings().unwrap_or_else(|e| panic!("{e}")))
}

fn time(w: &ArchitectureArena) -> f64 {
    w.player.as_ref().map_or(f64::NAN, Player::time)
}

fn sprung(w: &mut ArchitectureArena) -> Vec<Surprise> {
    w.player
        .as_mut()
        .map(|p| p.state().sprung.clone())
        .unwrap_or_default()
}

#[test]
fn a_link_of_the_first_format_still_opens() {
    let old = link::encode(&("two-rooms", "noise", 5.0_f64, [0_u8, 1, 2])).unwrap_or_default();
    let mut w = widget(&[]);
    assert_eq!(w.restore(&old), Ok(()));
    assert_eq!(w.settings.world, WorldId::TwoRooms);
    assert_eq!(w.settings.surprise, Scripted::Noise);
    assert_eq!(w.settings.planning_cost, 5.0);
    assert_eq!(w.settings.picks, Picks(Architecture::ALL));
    // Out of the schema's range, or no such pick: refused, the lesson's
    // settings kept.
    for bad in [
        link::encode(&("office", "none", 50.0_f64, [1_u8, 1, 1])),
        link::encode(&("office", "none", 2.0_f64, [1_u8, 7, 1])),
        link::encode(&("mars", "none", 2.0_f64, [1_u8, 1, 1])),
    ] {
        let mut w = widget(&[("planning_cost", "12")]);
        assert!(w.restore(&bad.unwrap_or_default()).is_err());
        assert_eq!(w.settings.planning_cost, 12.0);
        assert_eq!(w.settings.world, WorldId::Office);
    }
    assert!(create(&spec(NAME, &[])).is_ok());
}

#[test]
fn surprises_spring_in_every_world_and_travel_in_the_link() {
    for world in WorldId::ALL {
        let mut w = widget(&[("world", world.id()), ("focus", "hybrid")]);
        w.seek(2.0);
        for (k, kind) in Spring::ALL.into_iter().enumerate() {
            w.spring(kind);
            assert_eq!(w.notice, None, "{kind:?} in {}", world.id());
            assert_eq!(sprung(&mut w).len(), k + 1, "{kind:?} in {}", world.id());
            w.seek(2.0 + k as f64);
        }
        w.seek(6.5);
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()), "{}", world.id());
        assert_eq!(again.settings, w.settings);
        assert!((time(&again) - time(&w)).abs() < 1e-9);
        assert_eq!(sprung(&mut again), sprung(&mut w), "placed again alike");
        assert_eq!(again.saved_run(), w.saved_run());
    }
}

#[test]
fn scrubbing_back_shows_the_run_as_it_was() {
    let mut w = widget(&[("surprise", "person")]);
    w.seek(3.0);
    let then = w.samples();
    w.seek(9.0);
    w.spring(Spring::Door);
    w.seek(12.0);
    w.seek(3.0);
    assert_eq!(w.samples(), then);
    assert!(sprung(&mut w).is_empty(), "sprung later, not yet");
    w.seek(12.0);
    assert_eq!(sprung(&mut w).len(), 1);
}

#[test]
fn scripted_surprises_are_placed_in_every_world() {
    for world in WorldId::ALL {
        for surprise in Scripted::ALL {
            let w = widget(&[("world", world.id()), ("surprise", surprise.id())]);
            let glass_elsewhere = surprise == Scripted::Glass && world != WorldId::Office;
            assert_eq!(
                w.problem.is_some(),
                glass_elsewhere,
                "{} in {}: {:?}",
                surprise.id(),
                world.id(),
                w.problem
            );
        }
    }
}

#[test]
fn the_saved_run_names_the_robot_in_focus_and_every_surprise() {
    let mut w = widget(&[("surprise", "door"), ("focus", "reactive")]);
    w.seek(1.0);
    w.spring(Spring::MovedGoal);
    w.seek(2.0);
    let run = w.saved_run().unwrap_or_else(|| panic!("no run"));
    let command = run.command();
    assert!(
        command.starts_with(
            "kinolab arena office.world.json --architecture reactive --perturb door:5,1,5,2@6 --perturb goal:9,5@"
        ),
        "{command}"
    );
    assert!(
        command.ends_with("--planning-cost 2 --duration 120"),
        "{command}"
    );
    // The start, and a sample a tick to 2 s.
    let shown = &run.shows[0].1;
    assert_eq!(shown.as_array().map(Vec::len), Some(41));
}
