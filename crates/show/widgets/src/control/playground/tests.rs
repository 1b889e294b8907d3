use super::settings::pose;
use super::*;
use crate::registry::{create as build, spec};

fn widget(params: &[(&str, &str)]) -> Playground {
    let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
    Playground::new(p.settings().unwrap_or_else(|e| panic!("{e}")))
        .unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn lesson_parameters_reach_the_settings() {
    let block = spec(
        "controller-playground",
        &[
            ("view", "many"),
            ("gains", "3, 9, -2"),
            ("slip", "0.1"),
            ("start", "-1, 0.5, 90"),
        ],
    );
    assert!(build(&block).is_ok());
    let Ok(p) = kinolab_schema::validate(&block) else {
        panic!()
    };
    let Ok(set) = p.settings::<Settings>() else {
        panic!()
    };
    let s = pose(set.start);
    assert!((s.theta - std::f64::consts::FRAC_PI_2).abs() < 1e-15 && s.x == -1.0);
    for (k, v) in [
        ("view", "sideways"),
        ("plan", "jump 2"),
        ("task", "dance"),
        ("slip", "2"),
        ("start", "1,2"),
    ] {
        assert!(
            build(&spec("controller-playground", &[(k, v)])).is_err(),
            "{k}: {v}"
        );
    }
}

#[test]
fn a_link_of_the_first_format_still_opens() {
    let old = link::encode(&(
        1_u8,
        [-1.25_f64, 0.5, 0.5],
        [0.3_f64, -0.2, -1.0],
        [2.5_f64, 9.0, -2.0],
        1_u8,
        0.1_f64,
        0.05_f64,
        42_u64,
        20.0_f64,
        15.0_f64,
        "line 1; arc 0.5 90".to_owned(),
        36_u16,
        45.0_f64,
    ))
    .unwrap_or_default();
    let mut w = widget(&[]);
    assert_eq!(w.restore(&old), Ok(()));
    assert_eq!(w.set.view, View::Many);
    assert_eq!(w.set.gains, [2.5, 9.0, -2.0]);
    assert_eq!((w.set.starts, w.set.start_heading), (36, 45.0));
    assert_eq!(w.set.goal[2], (-1.0_f64).to_degrees());
    // A slip past the schema's range: refused, the lesson's settings kept.
    let bad = link::encode(&(
        0_u8,
        [-1.25_f64, 0.5, 0.5],
        [0.3_f64, -0.2, -1.0],
        [2.5_f64, 9.0, -2.0],
        0_u8,
        0.9_f64,
        0.0_f64,
        1_u64,
        0.0_f64,
        0.0_f64,
        "line 1".to_owned(),
        24_u16,
        0.0_f64,
    ))
    .unwrap_or_default();
    let mut w = widget(&[("slip", "0.2")]);
    assert!(w.restore(&bad).is_err());
    assert_eq!(w.set.slip, 0.2);
}

#[test]
fn the_instant_and_the_learners_settings_travel_in_the_link() {
    let mut w = widget(&[("task", "spot-unstable")]);
    w.set.gains = [2.0, 7.0, -1.0];
    w.set.goal = [0.5, 0.25, 45.0];
    w.refresh();
    if let Some(ex) = &mut w.exercise {
        ex.marks[1] = true;
    }
    w.seek(1.25);
    let text = w.state().unwrap_or_default();
    let mut again = widget(&[("task", "spot-unstable")]);
    assert_eq!(again.restore(&text), Ok(()));
    assert_eq!(again.set, w.set);
    assert_eq!(again.settings(), w.settings());
    assert_eq!(
        again.exercise.as_ref().map(|e| e.marks.clone()),
        Some(vec![false, true, false, false])
    );
    assert!((again.time() - 1.25).abs() < 1e-9);
    assert_eq!(again.saved_run(), w.saved_run());
}

#[test]
fn the_saved_run_shows_the_samples_to_the_instant() {
    let mut w = widget(&[]);
    w.seek(0.5);
    let Some(run) = w.saved_run() else {
        panic!("one run saves its file")
    };
    assert_eq!(run.args, ["simulate", "playground.run.json"]);
    let samples = run.shows[0].1.as_array().map_or(0, Vec::len);
    assert_eq!(samples, 51);
    // The open-vs-closed tab saves its open-loop run; many starts none.
    w.show(View::OpenVsClosed);
    w.refresh();
    assert_eq!(
        w.saved_run().map(|r| r.file),
        Some("open-loop.run.json".into())
    );
    w.show(View::Many);
    w.refresh();
    assert_eq!(w.saved_run(), None);
}
