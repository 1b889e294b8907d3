#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Every simulating widget's "Save run" file, given to the command it
//! names, prints exactly the numbers the widget shows: widget state →
//! file → `kinolab` → the same samples.

use std::process::Command;

use kinolab_widgets::link::{self, Moment};
use kinolab_widgets::registry::{SIMULATING, create, spec};
use kinolab_widgets::widget::LabWidget;
use serde_json::{Value, json};

/// `shown` is what the command printed there: the same value, or for a
/// list, the list the command printed begins with it (the widget shows
/// the run up to its instant; the command runs it to the end).
fn prints(printed: &Value, shown: &Value) -> bool {
    match (printed, shown) {
        (Value::Array(all), Value::Array(part)) => {
            all.len() >= part.len() && all.iter().zip(part).all(|(a, b)| a == b)
        }
        _ => printed == shown,
    }
}

#[test]
fn every_saved_run_reproduces_the_widgets_numbers() {
    let dir = std::env::temp_dir().join(format!("kinolab-widget-runs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let failed: Vec<&str> = SIMULATING
        .iter()
        .copied()
        .filter(|name| std::panic::catch_unwind(|| reproduces(name, &dir)).is_err())
        .collect();
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failed.is_empty(), "failed: {failed:?}");
}

/// `name`'s saved run, through the command line.
fn reproduces(name: &str, dir: &std::path::Path) {
    let mut widget = create(&spec(name, &[])).unwrap();
    widget.seek(1.5);
    prints_what_it_shows(name, widget.as_mut(), dir);
}

/// `widget`'s saved run, through the command line, prints what it shows.
fn prints_what_it_shows(name: &str, widget: &mut dyn LabWidget, dir: &std::path::Path) {
    {
        let run = widget
            .saved_run()
            .unwrap_or_else(|| panic!("{name} has no run to save"));
        std::fs::write(dir.join(&run.file), &run.text).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_kinolab"))
            .args(&run.args)
            .current_dir(dir)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{name}: `{}`: {}",
            run.command(),
            String::from_utf8_lossy(&out.stderr)
        );
        let printed: Value = serde_json::from_slice(&out.stdout).unwrap();
        for (pointer, shown) in &run.shows {
            let at = printed
                .pointer(pointer)
                .unwrap_or_else(|| panic!("{name}: `{}` prints no {pointer}", run.command()));
            assert!(
                prints(at, shown),
                "{name}: {pointer} differs from what the widget shows"
            );
        }
    }
}

/// A widget opened from a link holding `settings` and `moment` (as a
/// learner's link would hold them).
fn opened(name: &str, settings: &Value, moment: &Moment<&str>) -> Box<dyn LabWidget> {
    let text = link::write(name, settings, &json!({}), moment).unwrap();
    let mut widget = create(&spec(name, &[])).unwrap();
    widget.restore(&text).unwrap();
    widget
}

#[test]
fn surprises_sprung_in_any_arena_world_reproduce_on_the_command_line() {
    let dir = std::env::temp_dir().join(format!("kinolab-arena-runs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for world in ["office", "two-rooms", "u-trap", "crossing"] {
        for (surprise, focus) in [("door", "hierarchical"), ("noise", "hybrid")] {
            let settings = json!({"world": world, "surprise": surprise, "focus": focus});
            let moment = Moment {
                instant: 14.0,
                events: vec![(2.0, "person"), (4.5, "door"), (7.25, "moved-goal")],
            };
            let mut widget = opened("architecture-arena", &settings, &moment);
            let run = widget.saved_run().unwrap();
            assert_eq!(run.args.iter().filter(|a| *a == "--perturb").count(), 4);
            prints_what_it_shows(&format!("{world}, {surprise}"), widget.as_mut(), &dir);
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_planner_with_its_own_radius_start_and_goal_reproduces() {
    let dir = std::env::temp_dir().join(format!("kinolab-plan-runs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for settings in [
        json!({"world": "corridor", "radius": 0.3, "algorithm": "dijkstra"}),
        json!({"world": "scattered", "cell": 0.15, "radius": 0.35, "start": [1.0, 1.5]}),
    ] {
        let mut widget = opened("grid-planner", &settings, &Moment::default());
        prints_what_it_shows(&settings.to_string(), widget.as_mut(), &dir);
    }
    let _ = std::fs::remove_dir_all(&dir);
}
