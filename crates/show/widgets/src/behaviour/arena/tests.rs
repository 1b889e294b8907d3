use super::*;
use crate::registry::{create, spec};

fn arena(params: &[(&str, &str)]) -> Arena {
    let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
    Arena::new(p.settings().unwrap_or_else(|e| panic!("{e}"))).unwrap_or_else(|e| panic!("{e}"))
}

fn player(a: &mut Arena) -> &mut Player<Run> {
    a.player.as_mut().unwrap_or_else(|| panic!("no run"))
}

#[test]
fn every_set_runs_under_every_coordinator() {
    for set in ["goal-and-avoid", "explore", "light"] {
        for c in sets::COORDINATORS {
            let world = if set == "light" {
                "lights"
            } else {
                "scattered"
            };
            let mut a = arena(&[("world", world), ("set", set), ("coordinator", c.name())]);
            assert!(a.problem.is_none(), "{set}/{c:?}: {:?}", a.problem);
            player(&mut a).seek(100);
            assert!(!player(&mut a).is_empty());
        }
    }
}

#[test]
fn scrubbing_back_and_resuming_replays_the_same_run() {
    let mut a = arena(&[("coordinator", "voting")]);
    let p = player(&mut a);
    p.seek(200);
    let end = p.state().runner.sim.pose;
    let original = p.ticks().to_vec();
    p.seek(80);
    assert_eq!(p.state().runner.sim.pose, original[79].pose);
    p.seek(200);
    assert_eq!(p.state().runner.sim.pose, end);
    assert_eq!(p.ticks(), &original[..]);
}

#[test]
fn scrubbing_back_a_minute_is_quick() {
    let mut a = arena(&[("coordinator", "voting")]);
    let p = player(&mut a);
    p.seek_time(60.0);
    let began = std::time::Instant::now();
    for k in (0..p.len()).rev().step_by(97) {
        p.seek(k);
        let _ = p.state();
    }
    // 13 scrubs in well under a second natively, even in a debug build.
    assert!(began.elapsed().as_secs_f64() < 2.0, "{:?}", began.elapsed());
}

#[test]
fn a_link_of_the_first_format_still_opens() {
    // world, set, coordinator, seed, moved (index, [x, y]), goal, layers
    let old = (
        "two-rooms",
        "explore",
        "voting",
        7_u64,
        vec![(1_u32, [2.5_f64, 1.5_f64])],
        Some([8.0_f64, 5.0_f64]),
        None::<()>,
    );
    let text = link::encode(&old).unwrap_or_default();
    let mut a = arena(&[]);
    assert_eq!(a.restore(&text), Ok(()));
    let s = &a.settings;
    assert_eq!(
        (s.world.as_str(), s.set, s.coordinator, s.seed),
        ("two-rooms", Set::Explore, CoordinatorKind::Voting, 7)
    );
    assert_eq!(
        (s.moved.clone(), s.goal),
        (vec![[1.0, 2.5, 1.5]], Some([8.0, 5.0]))
    );
    // The layer exercise's design, in the old shape.
    let layers = Some((
        vec!["go", "avoid", "wander"],
        Some((true, "avoid", "go", 0.75_f64)),
        2_u64,
    ));
    let old = (
        "scattered",
        "goal-and-avoid",
        "subsumption",
        1_u64,
        Vec::<(u32, [f64; 2])>::new(),
        None::<[f64; 2]>,
        layers,
    );
    let mut a = arena(&[("coordinator", "subsumption"), ("task", "layers")]);
    assert_eq!(a.restore(&link::encode(&old).unwrap_or_default()), Ok(()));
    let s = &a.settings;
    assert_eq!(s.layers.as_deref(), Some("go, avoid, wander"));
    assert_eq!(
        (s.node.as_deref(), s.hold, s.task_world),
        (Some("avoid suppresses go"), 0.75, 3)
    );
    // An unknown coordinator, or a seed past the schema's range: refused,
    // the lesson's settings kept.
    let mut a = arena(&[("seed", "5")]);
    let bad = (
        "scattered",
        "explore",
        "anarchy",
        1_u64,
        Vec::<(u32, [f64; 2])>::new(),
        None::<[f64; 2]>,
        None::<()>,
    );
    assert!(a.restore(&link::encode(&bad).unwrap_or_default()).is_err());
    let bad = (
        "scattered",
        "explore",
        "sum",
        9_000_000_u64,
        Vec::<(u32, [f64; 2])>::new(),
        None::<[f64; 2]>,
        None::<()>,
    );
    assert!(a.restore(&link::encode(&bad).unwrap_or_default()).is_err());
    assert_eq!(a.settings.seed, 5);
    assert!(create(&spec(NAME, &[])).is_ok());
}

#[test]
fn a_dragged_obstacle_and_goal_travel_in_the_link_and_the_run_file() {
    let mut a = arena(&[("world", "scattered")]);
    let mut settings = a.settings.clone();
    settings.moved = vec![[0.0, 4.0, 1.0]];
    settings.goal = Some([6.5, 4.0]);
    a.change(settings);
    assert!(a.problem.is_none(), "{:?}", a.problem);
    a.seek(4.0);
    let text = a.state().unwrap_or_default();
    let mut again = arena(&[("world", "scattered")]);
    assert_eq!(again.restore(&text), Ok(()));
    assert_eq!(again.settings, a.settings);
    let run = a.saved_run().unwrap_or_else(|| panic!("no run"));
    assert_eq!(again.saved_run().as_ref(), Some(&run));
    // The file is exactly the run shown.
    let setup = Setup::from_json(&run.text).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(setup.world.goal, Some(Vec2::new(6.5, 4.0)));
    let report = kinolab_behaviours::run::run(&setup).unwrap_or_else(|e| panic!("{e}"));
    let k = player(&mut a).cursor();
    let printed = kinolab_common::display::tidy_report(&report.samples[..=k].to_vec())
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(run.shows[0].1, printed);
    // An obstacle the world does not have cannot be moved.
    let mut settings = a.settings.clone();
    settings.moved = vec![[99.0, 3.0, 2.0]];
    assert!(settings.setup().is_err());
}

#[test]
fn an_inhibiting_top_node_hands_the_robot_to_wander_not_to_avoid() {
    // Who drove, and for how long (s), in the scattered world.
    let drive = |top: &str| {
        let a = arena(&[("coordinator", "subsumption"), ("top-node", top)]);
        let setup = a.setup.clone().unwrap_or_else(|| panic!("no setup"));
        let r = kinolab_behaviours::run::run(&setup).unwrap_or_else(|e| panic!("{e}"));
        let mut who = std::collections::BTreeMap::<String, f64>::new();
        for s in &r.control {
            *who.entry(s.behaviour.clone().unwrap_or_default())
                .or_default() += s.to - s.from;
        }
        (r.metrics, who)
    };
    let (suppress, by_suppress) = drive("suppress");
    assert!(suppress.reached && suppress.collisions == 0, "{suppress:?}");
    assert!(
        by_suppress.get("avoid").copied().unwrap_or(0.0) > 1.0,
        "{by_suppress:?}"
    );
    assert!(!by_suppress.contains_key("wander"), "{by_suppress:?}");
    // Inhibit silences go's wire and passes nothing on: avoid never drives,
    // go's own node on wander lets go, and wander steers into things.
    let (inhibit, by_inhibit) = drive("inhibit");
    assert!(!by_inhibit.contains_key("avoid"), "{by_inhibit:?}");
    assert!(
        by_inhibit.get("wander").copied().unwrap_or(0.0) > 5.0,
        "{by_inhibit:?}"
    );
    assert!(inhibit.collisions > 0, "{inhibit:?}");
}

#[test]
fn the_top_node_is_for_the_arenas_own_stacks() {
    let spec = spec(
        NAME,
        &[
            ("coordinator", "subsumption"),
            ("task", "layers"),
            ("top-node", "inhibit"),
        ],
    );
    let err = kinolab_schema::validate(&spec).err().unwrap_or_default();
    assert!(err.contains("top-node"), "{err}");
}
