#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Learners' behaviours and coordinators run in the same runs as the
//! library's: a script that implements a built-in behaviour gives the
//! same run, a script coordinator can choose among the library's
//! behaviours, the same script and seed give the same run, and an error
//! stops the run at its step with the learner's message.

use kinolab_behaviours::coordinate::Coordinator;
use kinolab_behaviours::library::{Behaviour, Named};
use kinolab_behaviours::run::{Setup, run};

/// go_to_goal (gain 0.4, slowing within 0.5 m), as a learner writes it.
const GO: &str = r#"
fn behave(p) {
    if p.goal == () || p.goal.distance <= 0.05 { return (); }
    let speed = 0.4 * if p.goal.distance / 0.5 < 1.0 { p.goal.distance / 0.5 } else { 1.0 };
    #{ x: cos(p.goal.bearing) * speed, y: sin(p.goal.bearing) * speed }
}"#;

fn setup(behaviours: Vec<Named>, coordinator: Coordinator) -> Setup {
    let world = kinolab_world::catalogue::world("two-rooms").unwrap();
    let mut s = Setup::new(world, behaviours, coordinator);
    s.duration = 20.0;
    s.seed = 4;
    s
}

fn sum() -> Coordinator {
    Coordinator::Sum {
        gains: Default::default(),
    }
}

fn script(name: &str, source: &str) -> Named {
    Named::new(
        name,
        Behaviour::Script {
            source: source.to_owned(),
        },
    )
}

#[test]
fn a_script_that_goes_to_the_goal_is_the_library_behaviour() {
    let built_in = vec![Named::new(
        "go",
        Behaviour::GoToGoal {
            gain: 0.4,
            slow_within: 0.5,
        },
    )];
    let a = run(&setup(built_in, sum())).unwrap();
    let b = run(&setup(vec![script("go", GO)], sum())).unwrap();
    assert_eq!(a.samples.len(), b.samples.len());
    for (x, y) in a.samples.iter().zip(&b.samples) {
        assert!(
            (x.motion.x - y.motion.x).abs() <= 1e-12,
            "t = {}",
            x.motion.t
        );
        assert!(
            (x.motion.y - y.motion.y).abs() <= 1e-12,
            "t = {}",
            x.motion.t
        );
    }
    assert_eq!(a.metrics, b.metrics);
    assert!(b.error.is_none());
}

#[test]
fn a_script_coordinator_chooses_among_library_behaviours() {
    let library = || {
        vec![
            Named::new(
                "go",
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
    };
    // Avoid wins whenever it answers: a two-layer subsumption without hold.
    let chooser =
        r#"fn coordinate(outputs, p) { if outputs.avoid != () { "avoid" } else { "go" } }"#;
    let report = run(&setup(
        library(),
        Coordinator::Script {
            source: chooser.into(),
        },
    ))
    .unwrap();
    assert!(report.error.is_none(), "{:?}", report.error);
    let who: Vec<&str> = report
        .control
        .iter()
        .filter_map(|s| s.behaviour.as_deref())
        .collect();
    assert!(who.contains(&"go") && who.contains(&"avoid"), "{who:?}");
    // The same script and seed: the same run.
    let again = run(&setup(
        library(),
        Coordinator::Script {
            source: chooser.into(),
        },
    ))
    .unwrap();
    assert_eq!(report.samples, again.samples);
}

#[test]
fn an_error_stops_the_run_with_the_learners_message() {
    let endless = "fn behave(p) {\n  if p.t > 2.0 { loop { } }\n  [0.2, 0.0]\n}";
    let report = run(&setup(vec![script("mine", endless)], sum())).unwrap();
    let e = report.error.expect("the loop never ends");
    assert!(
        e.message.contains("more than 100 000 steps at t = 2.05 s"),
        "{e}"
    );
    assert!((e.t.unwrap() - 2.05).abs() < 1e-9, "{e}");
    let end = report.samples.last().unwrap().motion.t;
    assert!(end <= 2.15, "the run stopped at {end}");
    let shape = run(&setup(
        vec![script("mine", "fn behave(p) { \"left\" }")],
        sum(),
    ))
    .unwrap();
    let e = shape.error.unwrap();
    assert!(
        e.message.contains("must return [v, omega], #{x, y} or ()"),
        "{e}"
    );
}

#[test]
fn a_broken_script_is_bad_input_naming_the_behaviour() {
    let e = setup(vec![script("mine", "fn behave(p) { [1.0,, 2.0] }")], sum())
        .check()
        .unwrap_err();
    assert!(e.field.starts_with("behaviours[0]"), "{e}");
    assert!(e.to_string().contains("line 1, column"), "{e}");
}
