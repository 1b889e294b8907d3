#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! The new widgets' exercises, driven the way a learner drives them, and
//! graded right and wrong by the core.

use egui_kittest::kittest::{NodeT as _, Queryable};

mod common;

use common::{KITTEST_STEP, harness as harness_at, widget};

fn harness(
    widget: Box<dyn kinolab_widgets::widget::LabWidget>,
) -> egui_kittest::Harness<'static, common::Host> {
    harness_at(widget, KITTEST_STEP)
}

#[test]
fn the_stand_off_exercise_wants_the_robot_kept_back() {
    let mut h = harness(widget(
        "field-sandbox",
        &[("preset", "wall-ahead"), ("task", "stand-off")],
    ));
    h.run_steps(3);
    // As the preset comes, the wall stops the robot only 0.13 m away.
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("gets within 0.13 m of the wall");
    // A longer reach: rest where 1 = 1.5 (1 − d/1), d = 0.33 m.
    h.get_by_label_contains("2. perpendicular").click();
    h.run_steps(2);
    h.get_all_by_label("range D (m)")
        .next()
        .unwrap()
        .set_value_accesskit(1.0);
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("Solved. The robot stops 0.33 m from the wall");
}

#[test]
fn the_layer_exercise_is_run_on_three_worlds() {
    let mut h = harness(widget(
        "behaviour-arena",
        &[("coordinator", "subsumption"), ("task", "layers")],
    ));
    h.run_steps(2);
    h.get_by_label("Check on all three worlds").click();
    h.run_steps(2);
    h.get_by_label_contains("did not reach the goal");
    // go to level 0 (two steps down), then a suppress node driven by avoid on go's wire.
    for _ in 0..2 {
        let go = h.get_by_label_contains(": go").rect();
        h.get_all_by_label("down")
            .find(|b| (b.rect().center().y - go.center().y).abs() < 4.0)
            .unwrap()
            .click();
        h.run_steps(2);
    }
    h.get_by_label("level 0: go");
    h.get_by_label("place a node").click();
    h.run_steps(2);
    h.get_by_label("by avoid").click();
    h.run_steps(2);
    h.get_by_label("of go").click();
    h.run_steps(2);
    h.get_by_label("Check on all three worlds").click();
    h.run_steps(2);
    h.get_by_label_contains("Solved. All three worlds reached with no collision");
}

#[test]
fn the_static_phases_exercise_wants_a_crawl_order() {
    let mut h = harness(widget(
        "gait-studio",
        &[
            ("gait", "quadruped-crawl"),
            ("duty_factor", "0.8"),
            ("task", "static-phases"),
        ],
    ));
    h.run_steps(3);
    // Every leg starts lifting at τ = 0: nothing stands then.
    h.get_by_label("Check my phases").click();
    h.run_steps(2);
    h.get_by_label_contains("Not yet: at τ =");
    // The crawl's order: LH, LF, RH, RF a quarter of a cycle apart.
    for (leg, phase) in [("φ LF", 0.25), ("φ RF", 0.75), ("φ LH", 0.0), ("φ RH", 0.5)] {
        h.get_all_by_label(leg)
            .next()
            .unwrap()
            .set_value_accesskit(phase);
        h.run_steps(1);
    }
    h.run_steps(2);
    h.get_by_label("Check my phases").click();
    h.run_steps(2);
    h.get_by_label_contains("Solved. Statically stable through the whole cycle");
}

#[test]
fn the_person_exercise_wants_fresh_plans() {
    let mut h = harness(widget(
        "architecture-arena",
        &[("task", "survive-the-person"), ("planning_cost", "12")],
    ));
    h.run_steps(3);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("touched something");
    h.get_all_by_label("planning cost (ms/cell)")
        .next()
        .unwrap()
        .set_value_accesskit(2.0);
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("without touching the walker");
}

type Host = egui_kittest::Harness<'static, common::Host>;

/// Press Tab until the first node labelled `label` has the keyboard focus.
fn tab_to(h: &mut Host, label: &str) {
    for _ in 0..200 {
        let focused = h
            .get_all_by_label(label)
            .any(|n| n.accesskit_node().is_focused());
        if focused {
            return;
        }
        h.key_press(egui::Key::Tab);
        h.run_steps(1);
    }
    panic!("Tab never reaches {label:?}");
}

#[test]
fn the_person_exercise_is_solved_with_the_keyboard_alone() {
    let mut h = harness(widget(
        "architecture-arena",
        &[("task", "survive-the-person"), ("planning_cost", "12")],
    ));
    h.run_steps(3);
    // The slider's arrows lower the planning cost to 2 ms per cell.
    let cost = "planning cost (ms/cell)";
    tab_to(&mut h, cost);
    let value = |h: &Host| {
        h.get_all_by_label(cost)
            .next()
            .and_then(|n| n.accesskit_node().numeric_value())
            .unwrap()
    };
    for _ in 0..200 {
        if value(&h) <= 2.0 {
            break;
        }
        h.key_press(egui::Key::ArrowLeft);
        h.run_steps(1);
    }
    assert!(value(&h) <= 2.0, "the arrows stop at {}", value(&h));
    tab_to(&mut h, "Check");
    h.key_press(egui::Key::Enter);
    h.run_steps(2);
    h.get_by_label_contains("without touching the walker");
}

#[test]
fn the_pick_exercise_runs_every_pick() {
    let mut h = harness(widget(
        "architecture-arena",
        &[("task", "pick-architecture")],
    ));
    h.run_steps(3);
    // Reactive everywhere: the glass mission keeps it at the window.
    h.get_by_label("Check by running").click();
    h.run_steps(2);
    h.get_by_label_contains("reactive on \"the goal is behind a glass wall\"");
    // The third row's hybrid.
    h.get_all_by_label("hybrid").nth(2).unwrap().click();
    h.run_steps(2);
    h.get_by_label("Check by running").click();
    h.run_steps(2);
    h.get_by_label_contains("Every pick reached its goal");
}

#[test]
fn the_routes_exercise_wants_a_hybrid_wiring() {
    let mut h = harness(widget("sensing-routes", &[("task", "wire-hybrid")]));
    h.run_steps(3);
    h.get_by_label("reactive").click();
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("This wiring is reactive");
    // The "Start from" button (the legend below names the routes too).
    h.get_all_by_label("hybrid").next().unwrap().click();
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("Hybrid: some sensors reach behaviours directly");
}

#[test]
fn the_push_exercise_wants_the_capture_limit() {
    let mut h = harness(widget(
        "zmp-cart-table",
        &[("task", "largest-push"), ("push", "0.3")],
    ));
    h.run_steps(3);
    // A push draws the run and its plot (every label must have its glyphs).
    h.get_by_label("Push").click();
    // The push plays on the player at 1×: its 4 s at a tenth of a second a step.
    h.run_steps(45);
    h.get_by_label_contains("Caught: the capture point stayed on the foot");
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("Push more");
    // ω = √(9.80665 / 0.8) ≈ 3.501 1/s; the toe 0.15 m ahead: 0.525 m/s.
    for (push, verdict) in [(0.6, "passes the toe"), (0.52, "Solved")] {
        h.get_all_by_label("push (m/s)")
            .next()
            .unwrap()
            .set_value_accesskit(push);
        h.run_steps(2);
        h.get_by_label("Check").click();
        h.run_steps(2);
        h.get_by_label_contains(verdict);
    }
}

#[test]
fn the_trot_exercise_wants_the_trots_offsets() {
    let mut h = harness(widget(
        "cpg-lab",
        &[("gait", "quadruped-pace"), ("task", "lock-trot")],
    ));
    h.run_steps(3);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("not the trot's");
    h.get_by_label("trot").click();
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("Solved. From every start");
}

#[test]
fn the_speed_picks_the_cpgs_gait_through_the_froude_number() {
    let mut h = harness(widget("cpg-lab", &[("speed", "1.2")]));
    h.run_steps(3);
    // l = 0.5 m: Fr = 1.2² / (9.80665 · 0.5) ≈ 0.29, a walk; f = 0.75 · 1.2 / 0.5.
    h.get_by_label_contains("Fr = v²/(g l) = 0.29 → crawl, f = βv/L = 1.80 Hz");
    // Past √(0.5 g l) ≈ 1.57 m/s the trot takes over, at a lower frequency.
    h.get_all_by_label("speed v (m/s)")
        .next()
        .unwrap()
        .set_value_accesskit(2.0);
    h.run_steps(2);
    h.get_by_label_contains("Fr = v²/(g l) = 0.82 → trot, f = βv/L = 2.00 Hz");
    h.get_all_by_label("speed v (m/s)")
        .next()
        .unwrap()
        .set_value_accesskit(4.0);
    h.run_steps(2);
    h.get_by_label_contains("→ gallop, f = βv/L = 2.40 Hz");
}

#[test]
fn the_which_pattern_task_runs_each_choice() {
    let mut h = harness(widget("which-pattern", &[("task", "match")]));
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("5 of 5 do not work yet");
}

#[test]
fn the_wiring_task_is_checked_by_running_the_robot() {
    let mut h = harness(widget("component-lab", &[("task", "wire-robot")]));
    h.run_steps(3);
    h.get_by_label_contains("Click a port");
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("Still unwired: planner.map, motion.velocity, sequencer.goal");
}

#[test]
fn the_robot_is_wired_with_the_keyboard_alone() {
    let mut h = harness(widget("component-lab", &[("task", "wire-robot")]));
    h.run_steps(3);
    // Each wiring: open the port list, choose the port, open the service
    // list, choose the service; Tab moves, Enter opens and chooses.
    for (port, service) in [
        ("planner.map", "mapper.map"),
        ("motion.velocity", "base.velocity"),
    ] {
        for item in ["port", port, "wire it to", service] {
            tab_to(&mut h, item);
            h.key_press(egui::Key::Enter);
            h.run_steps(2);
        }
    }
    tab_to(&mut h, "Check");
    h.key_press(egui::Key::Enter);
    h.run_steps(2);
    h.get_by_label_contains("Still unwired: sequencer.goal");
}

#[test]
fn the_component_lab_plays_on_its_own() {
    let mut h = harness(widget("component-lab", &[("system", "robot")]));
    h.run_steps(2);
    // It waits for the learner, then plays on its own.
    h.get_by_label("Play").click();
    h.run_steps(10);
    h.get_by_label("Pause");
}

#[test]
fn the_car_is_fixed_by_its_body_not_its_behaviours() {
    let mut h = harness(widget("three-slots", &[("task", "fix-the-car")]));
    h.run_steps(3);
    h.get_by_label_contains("Did not reach the goal: a car cannot turn tighter");
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("Change exactly one slot (you changed 0)");
    h.get_by_label("wander-when-stuck").click();
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("Still no: a car cannot turn tighter");
    h.get_by_label("go-and-avoid").click();
    h.get_by_label("omni").click();
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("Solved. The omni with go-and-avoid reached the goal");
}

#[test]
fn a_giant_walks_straight_across_the_beach() {
    let mut h = harness(widget(
        "ant-beach",
        &[("task", "nearly-straight"), ("size", "1")],
    ));
    h.run_steps(3);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("pebbles still matter");
    h.get_all_by_label("body size (ant lengths)")
        .next()
        .unwrap()
        .set_value_accesskit(90.0);
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("Solved. At size 90 the path is 1.000 times the straight line");
}

#[test]
fn the_churn_counts_match_the_two_designs() {
    let mut h = harness(widget("technology-churn", &[("swap", "SickLaser")]));
    h.run_steps(2);
    h.get_by_label_contains("stable design: replacing SickLaser edits 1 class: Configuration");
    h.get_by_label_contains("naive design: replacing SickLaser edits 4 classes");
}

#[test]
fn the_morphology_builder_dissolves_pairs_and_swaps_commands() {
    let mut h = harness(widget("morphology-builder", &[("mechanism", "planar-3r")]));
    h.run_steps(2);
    h.get_by_label_contains("T(from → to): (");
    h.get_by_label_contains("computed by closed-form planar FK");
    h.get_by_label_contains("use the plugged-in commands")
        .click();
    h.run_steps(2);
    h.get_by_label_contains("computed by the generic tree walk");
    h.get_by_label("Pairs: delete the port a pair hangs on")
        .click();
    h.run_steps(2);
    h.get_all_by_label("delete the port")
        .next()
        .unwrap()
        .click();
    h.run_steps(2);
    h.get_by_label_contains("No transform: a dissolved pair lies on the path");
}
