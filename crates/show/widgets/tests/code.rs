#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! The code panel as a learner uses it: type code, see a syntax error at
//! its line, run it, step back through the run, submit it, unlock a hint
//! after a failure, and find the code again in the widget's link.

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable};

mod common;

use common::{Host, KITTEST_STEP, shown_time, widget};

fn harness(exercise: &str) -> Harness<'static, Host> {
    common::harness(widget("code", &[("exercise", exercise)]), KITTEST_STEP)
}

/// Replace the editor's text with `code`, as typed.
fn type_code(h: &mut Harness<'_, Host>, code: &str) {
    let editor = h.get_by_label("Your code");
    editor.focus();
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.key_press(egui::Key::Delete);
    h.run();
    h.get_by_label("Your code").type_text(code);
    h.run();
}

fn labels(h: &Harness<'_, Host>) -> Vec<String> {
    h.get_all(egui_kittest::kittest::by())
        .filter_map(|n| n.accesskit_node().label().or(n.accesskit_node().value()))
        .collect()
}

fn has(h: &Harness<'_, Host>, start: &str) -> bool {
    labels(h).iter().any(|l| l.starts_with(start))
}

/// The textbook law scaled into the parking exercise's speed limit.
const MODEL: &str = "fn control(rho, alpha, beta) {\nlet v = 3.0 * rho; let w = 8.0 * alpha - 1.5 * beta;\nlet k = max(1.0, max(abs(v) / 0.5, abs(w) / 2.0));\n[v / k, w / k]\n}";

#[test]
fn type_see_the_error_run_step_back_and_submit() {
    let mut h = harness("control-park");
    h.run_steps(2);
    // A syntax error shows at its line, and nothing can run.
    type_code(&mut h, "fn control(rho, alpha, beta) {\n[rho,\n");
    h.run_steps(2);
    assert!(has(&h, "Line "), "{:?}", labels(&h));
    assert!(h.get_by_label("Run").accesskit_node().is_disabled());

    // The model law runs, passes the worlds shown and steps.
    type_code(&mut h, MODEL);
    h.run_steps(2);
    assert!(!has(&h, "Line "));
    h.get_by_label("Run").click();
    h.run_steps(2);
    assert!(has(&h, "Passed on the worlds shown"), "{:?}", labels(&h));
    assert!(has(&h, "Your function was given"));
    h.get_by_label("Play").click();
    h.run_steps(20);
    h.get_by_label("Pause").click();
    h.run_steps(2);
    let played = shown_time(&h);
    assert!(played > 0.0);
    h.get_by_label("Back").click();
    h.run_steps(2);
    assert!(shown_time(&h) < played);
    // What the law answered at that instant is on screen.
    assert!(has(&h, "and answered"));

    h.get_by_label("Submit").click();
    h.run_steps(2);
    assert!(has(&h, "Passed on every world"), "{:?}", labels(&h));
}

#[test]
fn a_failed_submission_unlocks_a_hint_and_opens_the_failing_world() {
    let mut h = harness("control-park");
    h.run_steps(2);
    type_code(
        &mut h,
        "fn control(rho, alpha, beta) {\nlet v = 3.0 * rho; let w = 8.0 * alpha;\nlet k = max(1.0, max(abs(v) / 0.5, abs(w) / 2.0));\n[v / k, w / k]\n}",
    );
    assert!(!has(&h, "· "));
    h.get_by_label("Submit").click();
    h.run_steps(2);
    assert!(has(&h, "Not yet:"));
    assert!(has(&h, "arrived facing"), "{:?}", labels(&h));
    assert!(has(&h, "· Start from the law"), "the first hint");
    // Of the held-back worlds, only how many passed.
    assert!(has(&h, "Held back: 1 of 3 passed."), "{:?}", labels(&h));
    assert!(
        !has(&h, "facing away") && !has(&h, "straight behind"),
        "{:?}",
        labels(&h)
    );
    assert!(
        has(&h, "Stepping through: from the left"),
        "{:?}",
        labels(&h)
    );
}

#[test]
fn an_endless_loop_stops_the_run_with_its_line_and_the_panel_goes_on() {
    let mut h = harness("control-park");
    h.run_steps(2);
    type_code(&mut h, "fn control(rho, alpha, beta) {\nloop { }\n}");
    h.get_by_label("Run").click();
    h.run_steps(3);
    assert!(has(&h, "your code stopped: line 2"), "{:?}", labels(&h));
    // The learner's code is kept, and the panel still works.
    type_code(&mut h, MODEL);
    h.get_by_label("Run").click();
    h.run_steps(2);
    assert!(has(&h, "Passed on the worlds shown"));
}

#[test]
fn the_code_travels_in_the_link() {
    let mut h = harness("field-pull");
    h.run_steps(2);
    let code = "fn field(x, y) { [4.0 - x, 0.0 - y] }";
    type_code(&mut h, code);
    let link = h.state().widget.state().expect("changed code makes a link");
    let mut again = widget("code", &[("exercise", "field-pull")]);
    again.restore(&link).unwrap();
    let run = again.saved_run().unwrap();
    assert_eq!(run.text, code);
    assert_eq!(run.args[..2], ["script", "check"]);
    // A link from another widget, or damaged code, is refused.
    let mut other = widget("code", &[]);
    assert!(other.restore("bAAAA").is_err());
}

#[test]
fn every_exercise_opens_with_its_starter_and_runs_only_when_asked() {
    for e in kinolab_exercises::all() {
        let mut h = harness(e.id);
        h.run_steps(3);
        assert!(
            has(&h, "Press Run to try your code"),
            "{}: {:?}",
            e.id,
            labels(&h)
        );
        assert!(!has(&h, "t = 0"), "{}: nothing ran", e.id);
        let run = h.state_mut().widget.saved_run().unwrap();
        assert_eq!(run.text, e.starter, "{}", e.id);
        assert!(
            h.state().widget.state().is_none(),
            "{}: the starter is no change",
            e.id
        );
        h.get_by_label("Run").click();
        h.run_steps(3);
        let first = &(e.worlds)()[0].name;
        assert!(has(&h, &format!("Stepping through: {first}")), "{}", e.id);
        assert!(has(&h, "t = 0"), "{}: {:?}", e.id, labels(&h));
    }
}
