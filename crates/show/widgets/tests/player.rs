#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Every widget that simulates has the one player: play, pause, a tick
//! back and on, and a link that carries the instant, driven as a learner
//! drives them; the restored widget shows what the original showed.

use egui_kittest::kittest::Queryable;

use kinolab_widgets::registry::SIMULATING;

mod common;

use common::{KITTEST_STEP as FRAME, harness, shown_time, widget};

/// Run `check` for every simulating widget; fail naming every widget
/// that failed (so each can be worked on apart).
fn for_each(check: fn(&str)) {
    let failed: Vec<&str> = SIMULATING
        .iter()
        .copied()
        .filter(|name| std::panic::catch_unwind(|| check(name)).is_err())
        .collect();
    assert!(failed.is_empty(), "failed: {failed:?}");
}

#[test]
fn every_simulating_widget_plays_steps_and_scrubs_with_one_player() {
    for_each(plays_steps_and_scrubs);
}

fn plays_steps_and_scrubs(name: &str) {
    {
        let mut h = harness(widget(name, &[]), FRAME);
        h.run_steps(2);
        assert_eq!(shown_time(&h), 0.0, "{name} starts paused at 0");
        h.get_by_label("Play").click();
        h.run_steps(30);
        h.get_by_label("Pause").click();
        h.run_steps(2);
        let played = shown_time(&h);
        assert!(played > 0.0, "{name} played");
        h.get_by_label("Back").click();
        h.run_steps(2);
        let back = shown_time(&h);
        assert!(back < played, "{name}: back from {played} to {back}");
        h.get_by_label("Step").click();
        h.run_steps(2);
        assert_eq!(
            shown_time(&h),
            played,
            "{name}: a tick on lands where it was"
        );
        // The link carries the instant: a fresh widget opens there and
        // shows the same run.
        let link = h
            .state()
            .widget
            .state()
            .expect("a played widget has a state");
        let mut again = widget(name, &[]);
        again.restore(&link).unwrap();
        let shown = h.state_mut().widget.saved_run();
        assert_eq!(again.saved_run(), shown, "{name}");
        let mut h2 = harness(again, FRAME);
        h2.run_steps(2);
        assert_eq!(shown_time(&h2), played, "{name} reopened at its instant");
    }
}

#[test]
fn every_simulating_widget_saves_a_run_the_command_line_reads() {
    for_each(saves_a_run);
}

fn saves_a_run(name: &str) {
    {
        let mut w = widget(name, &[]);
        w.seek(0.5);
        let run = w
            .saved_run()
            .unwrap_or_else(|| panic!("{name} saves no run"));
        assert!(run.args.contains(&run.file), "{name}: {:?}", run.args);
        assert!(
            serde_json::from_str::<serde_json::Value>(&run.text).is_ok(),
            "{name}"
        );
        assert!(!run.shows.is_empty(), "{name}");
    }
}
