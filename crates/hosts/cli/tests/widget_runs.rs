#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Every simulating widget's "Save run" file, given to the command it
//! names, prints exactly the numbers the widget shows: widget state →
//! file → `kinolab` → the same samples.

use std::process::Command;

use kinolab_widgets::registry::{SIMULATING, create, spec};
use serde_json::Value;

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
    {
        let mut widget = create(&spec(name, &[])).unwrap();
        widget.seek(1.5);
        let run = widget
            .saved_run()
            .unwrap_or_else(|| panic!("{name} has no run to save"));
        std::fs::write(dir.join(&run.file), &run.text).unwrap();
        let out = Command::new(env!("CARGO_BIN_EXE_kinolab"))
            .args(&run.args)
            .current_dir(&dir)
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
