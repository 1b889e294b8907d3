#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! A learner leaves a simulation playing at 4× for ten simulated minutes
//! (a lecture, a coffee): the memory it holds must level off. Each widget
//! is driven as a learner drives it (Play, then 4×) at ten frames a
//! second, and this test binary's allocator counts the bytes alive after
//! every simulated minute. Every run in the lab has an end, and the
//! player's recording a cap (said on screen when reached): once a run is
//! over, nothing may grow.

use std::alloc::System;

use egui_kittest::kittest::Queryable;
// A counting allocator, so the test sees the bytes alive (stats_alloc:
// small, MIT, and it keeps the unsafe allocator code out of this crate).
use stats_alloc::{INSTRUMENTED_SYSTEM, StatsAlloc};

#[global_allocator]
static COUNTING: &StatsAlloc<System> = &INSTRUMENTED_SYSTEM;

/// Bytes alive now.
fn alive() -> f64 {
    let s = COUNTING.stats();
    // A reallocation counts its growth as allocated, its shrinking as freed.
    s.bytes_allocated as f64 - s.bytes_deallocated as f64
}

mod common;

use common::{harness, shown_time, widget};

/// Frames of a tenth of a second: at 4× each runs 0.4 simulated seconds.
const FRAME: f32 = 0.1;
const FRAMES_PER_MINUTE: usize = (60.0 / (4.0 * FRAME)) as usize;

/// The bytes alive after each simulated minute of ten, from the frame
/// the widget started playing at 4×.
fn curve(name: &str) -> (Vec<f64>, f64) {
    let mut h = harness(widget(name, &[]), FRAME);
    h.run_steps(2);
    h.get_by_label("4×").click();
    h.get_by_label("Play").click();
    h.run_steps(2);
    let mut curve = vec![alive()];
    for _ in 0..10 {
        h.run_steps(FRAMES_PER_MINUTE);
        curve.push(alive());
    }
    (curve, shown_time(&h))
}

fn report(name: &str, curve: &[f64], ran: f64) -> String {
    let kb: Vec<String> = curve.iter().map(|b| format!("{:.0}", b / 1024.0)).collect();
    format!(
        "{name} (its run ends at {ran} s): KiB alive each simulated minute: {}",
        kb.join(" ")
    )
}

#[test]
fn ten_simulated_minutes_at_four_times_level_off() {
    let mut failed = Vec::new();
    for name in [
        "behaviour-arena",
        "architecture-arena",
        "component-lab",
        "controller-playground",
    ] {
        let (curve, ran) = curve(name);
        assert!(ran > 5.0, "{name} did not play: it shows {ran} s");
        let line = report(name, &curve, ran);
        eprintln!("{line}");
        // Every run in the lab has an end (and the player's recording a
        // cap): after the first five minutes nothing may grow (64 KiB of
        // slack for egui's caches), and a run may hold at most 32 MiB.
        let settled = curve[10] - curve[5];
        if settled > 64.0 * 1024.0 || curve[10] - curve[0] > 32.0 * 1048576.0 {
            failed.push(line);
        }
    }
    assert!(
        failed.is_empty(),
        "memory kept growing:\n{}",
        failed.join("\n")
    );
}
