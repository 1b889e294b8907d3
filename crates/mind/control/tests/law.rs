#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! A learner's control law runs in the same simulation as the built-in
//! one: the built-in law written as a script gives the same run to 1e-12,
//! the same script and seed give the same run, an error stops the run at
//! its tick, and every call is kept.

use kinolab_control::file::from_json;

/// The textbook gains as a script.
const POLAR: &str = "fn control(rho, alpha, beta) { [3.0 * rho, 8.0 * alpha + -1.5 * beta] }";

fn run_file(controller: &str, extra: &str) -> String {
    format!(
        r#"{{ "controller": {controller}, "start": {{ "x": -1.0, "y": 0.5, "theta_deg": 30 }},
             "goal": {{ "x": 0.0, "y": 0.0, "theta_deg": 0 }}, "dt": 0.001, "duration": 8,
             "output_every": 10, "control_rate": 100 {extra} }}"#
    )
}

fn script(source: &str) -> String {
    serde_json::json!({ "kind": "script", "source": source }).to_string()
}

#[test]
fn the_built_in_law_as_a_script_is_the_same_run() {
    let noise = r#", "noise": { "seed": 7, "slip": 0.1, "push_speed": 0.02, "push_turn_deg": 2 }"#;
    for extra in ["", noise, r#", "max_wheel_speed": 8"#] {
        let built_in = from_json(&run_file(
            r#"{ "kind": "polar", "k_rho": 3, "k_alpha": 8, "k_beta": -1.5 }"#,
            extra,
        ))
        .unwrap();
        let learner = from_json(&run_file(&script(POLAR), extra)).unwrap();
        let (a, b) = (
            built_in.run.simulate().unwrap(),
            learner.run.simulate().unwrap(),
        );
        assert_eq!(a.samples.len(), b.samples.len());
        for (x, y) in a.samples.iter().zip(&b.samples) {
            for (p, q) in [
                (x.pose.x, y.pose.x),
                (x.pose.y, y.pose.y),
                (x.pose.theta, y.pose.theta),
                (x.v, y.v),
            ] {
                assert!((p - q).abs() <= 1e-12, "{extra} t = {}: {p} vs {q}", x.t);
            }
        }
        assert_eq!(a.reached, b.reached);
        assert_eq!(b.calls.len(), 801, "at 0, 0.01, …, 8 s");
        assert!(b.error.is_none());
    }
}

#[test]
fn the_same_script_and_seed_give_the_same_run() {
    let noise = r#", "noise": { "seed": 3, "slip": 0.2, "push_speed": 0.05, "push_turn_deg": 5 }"#;
    let file = run_file(&script(POLAR), noise);
    let a = from_json(&file).unwrap().run.simulate().unwrap();
    let b = from_json(&file).unwrap().run.simulate().unwrap();
    assert_eq!(a, b);
}

#[test]
fn an_error_stops_the_run_at_its_tick() {
    let source = "fn control(rho, alpha, beta) {\n  if rho < 0.5 { return [1.0 / 0.0, 0.0]; }\n  [rho, alpha]\n}";
    let t = from_json(&run_file(&script(source), ""))
        .unwrap()
        .run
        .simulate()
        .unwrap();
    let e = t.error.expect("the law returned an infinity");
    let stopped = e.t.unwrap();
    assert!(stopped > 0.1 && stopped < 8.0, "{e}");
    assert!(e.message.contains("returned inf for v"), "{e}");
    assert!(t.samples.last().unwrap().t <= stopped + 1e-9);
    assert_eq!(
        t.calls.last().unwrap().t,
        stopped - 0.01,
        "the last good call"
    );
}

#[test]
fn a_law_keeps_notes_and_prints_each_tick() {
    let source = r#"fn control(rho, alpha, beta) {
        if this.ticks == () { this.ticks = 0; }
        this.ticks += 1;
        print(`tick ${this.ticks}`);
        plot("rho", rho);
        [if this.ticks < 50 { 0.0 } else { rho }, alpha]
    }"#;
    let t = from_json(&run_file(&script(source), ""))
        .unwrap()
        .run
        .simulate()
        .unwrap();
    assert_eq!(t.calls[0].v, 0.0);
    assert_eq!(
        t.calls[49].v, t.calls[49].rho,
        "moves from the fiftieth tick"
    );
    assert_eq!(t.calls[9].output.prints, vec!["tick 10"]);
    assert_eq!(
        t.calls[9].output.plots,
        vec![("rho".to_owned(), t.calls[9].rho)]
    );
}

#[test]
fn a_broken_script_is_bad_input_naming_its_line() {
    let e = from_json(&run_file(
        &script("fn control(rho, alpha, beta) {\n  [rho,, 0.0]\n}"),
        "",
    ))
    .unwrap_err();
    assert_eq!(e.field, "controller.source");
    assert!(e.message.starts_with("line 2, column"), "{e}");
}
