//! Each pattern's semantics, run through the runtime.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use kinolab_components::system::{EXAMPLES, example};
use kinolab_components::{Record, Report, Status, System};

fn notes<'a>(report: &'a Report, from: &str) -> Vec<(&'a str, f64)> {
    report
        .trace
        .iter()
        .filter(|r| r.kind == "note" && r.from == from)
        .map(|r| (r.summary.as_str(), r.sent))
        .collect()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-9
}

#[test]
fn every_example_parses_and_runs_to_its_end() {
    for (id, _) in EXAMPLES {
        let system = example(id).unwrap();
        let report = system.run(None).unwrap();
        assert!(report.complete, "{id}");
        assert!(report.counts.messages > 0, "{id}");
    }
}

#[test]
fn answers_are_matched_to_their_requests_in_any_order() {
    let report = example("out-of-order").unwrap().run(None).unwrap();
    let got = notes(&report, "client");
    // 0.1 + 0.02 latency + 0.2 work + 0.02 back = 0.34 for the quick one;
    // the slow one takes 1.0: 1.14. The synchronous ask (request 3, work
    // 1.0 again) leaves at 1.14 and is back at 2.18.
    assert_eq!(got[0].0, "quick answered: 16");
    assert!(close(got[0].1, 0.34), "{got:?}");
    assert_eq!(got[1].0, "slow answered: 9");
    assert!(close(got[1].1, 1.14), "{got:?}");
    assert_eq!(got[2].0, "ask 5 answered: 25");
    assert!(close(got[2].1, 2.18), "{got:?}");
    // Answers travel in the opposite order to their requests.
    let answers: Vec<&Record> = report.trace.iter().filter(|r| r.kind == "answer").collect();
    assert_eq!(answers[0].summary, "Number 16.0");
}

fn reads(report: &Report, component: &str) -> String {
    report
        .components
        .iter()
        .find(|c| c.name == component)
        .map(|c| c.status.clone())
        .unwrap()
}

#[test]
fn push_newest_skips_for_a_slow_subscriber_and_prescale_asks_for_less() {
    let report = example("newest-vs-timed").unwrap().run(None).unwrap();
    let port = |name: &str| {
        let (c, p) = name.split_once('.').unwrap();
        report
            .components
            .iter()
            .find(|x| x.name == c)
            .unwrap()
            .ports
            .iter()
            .find(|x| x.name == p)
            .unwrap()
            .stats
    };
    let slow = port("slow.value");
    // Ten values a second for five seconds; a quarter second of work per
    // value read: most arrive while the subscriber is busy and are skipped.
    assert!(slow.received >= 49, "{slow:?}");
    assert!(slow.skipped > slow.received / 2, "{slow:?}");
    // Prescale 3: two ticks in three are held back at the server, none
    // skipped at the client (0.3 s between updates > 0.25 s of work).
    let third = port("every-third.value");
    assert_eq!(third.skipped, 0, "{third:?}");
    assert!(
        third.withheld >= 2 * third.received - 2 && third.withheld <= 2 * third.received + 2,
        "{third:?}"
    );
    // The late subscriber's first value is the current one at 2 s.
    assert!(
        reads(&report, "late").starts_with("read "),
        "{}",
        reads(&report, "late")
    );
    let first_late = report
        .trace
        .iter()
        .find(|r| r.kind == "update" && r.to == "late")
        .unwrap();
    assert!(
        first_late.sent >= 2.0 && first_late.sent < 2.02,
        "{first_late:?}"
    );
    assert_eq!(first_late.summary, "Count 20.0");
}

#[test]
fn events_fire_once_or_every_time_and_cancel_releases_the_waiting_client() {
    let report = example("events").unwrap().run(None).unwrap();
    let fired = |who: &str| {
        notes(&report, who)
            .iter()
            .filter(|(n, _)| n.starts_with("alarm"))
            .count()
    };
    // A sawtooth 0..9, a step every 0.1 s: above 5 from 6 on, once a second.
    assert_eq!(fired("once"), 1);
    assert_eq!(fired("every-time"), 4);
    assert_eq!(fired("never"), 0);
    let quiet = report
        .quiet_ports
        .iter()
        .find(|q| q.port == "never.alarm")
        .unwrap();
    assert_eq!(quiet.why.reason, "event-not-activated");
    // The client's first ask is released by the cancel at 1 s; its second
    // returns at once, unsent.
    let got = notes(&report, "client");
    assert_eq!(got[0], ("ask 2 returned cancelled", 1.0));
    assert_eq!(got[1], ("ask 3 returned cancelled", 1.0));
    let requests = report.trace.iter().filter(|r| r.kind == "request").count();
    assert_eq!(requests, 1);
}

#[test]
fn the_same_seed_gives_the_same_trace() {
    let mut system = example("robot").unwrap();
    system.until = 8.0;
    system.latency.loss = 0.05;
    let a = system.run(None).unwrap();
    let b = system.run(None).unwrap();
    assert_eq!(a.trace, b.trace);
    system.seed = 2;
    let c = system.run(None).unwrap();
    assert_ne!(a.trace, c.trace);
}

fn reached(report: &Report) -> Option<f64> {
    notes(report, "sequencer")
        .iter()
        .find(|(n, _)| n.starts_with("goal reached"))
        .map(|(_, t)| *t)
}

#[test]
fn the_robot_reaches_its_goal_after_the_rewire_and_not_before() {
    let system = example("robot").unwrap();
    let report = system.run(None).unwrap();
    let at = reached(&report).expect("the robot should reach the goal");
    assert!(at > 5.0, "{at}");
    let [x, y, _] = report.robot.unwrap();
    assert!((x - 9.0).hypot(y - 5.0) < 0.3, "{x} {y}");
    // The rewire is in the trace, by the sequencer, at 5 s.
    assert!(report.trace.iter().any(|r| r.kind == "connect"
        && r.from == "sequencer"
        && r.status == Status::Done
        && r.service == "planner.route"
        && close(r.sent, 5.0)));
    // Without the rewire the idle joystick keeps the robot at its start.
    let mut idle = system.clone();
    idle.components[6].params = serde_json::json!({ "rewire_at": null });
    let report = idle.run(None).unwrap();
    assert!(reached(&report).is_none());
    let [x, y, _] = report.robot.unwrap();
    assert!((x - 1.0).hypot(y - 1.0) < 1e-9);
}

#[test]
fn bad_system_files_name_the_field() {
    let e = System::from_json(r#"{"components": []}"#).unwrap_err();
    assert_eq!(e.field, "components");
    let e = System::from_json(
        r#"{"components": [{"name": "a", "kind": "server", "params": {"work": [-1]}}]}"#,
    )
    .and_then(|s| s.build())
    .unwrap_err();
    assert_eq!(e.field, "components[0].params.work[0]");
    let e = System::from_json(r#"{"components": [{"name": "a", "kind": "teleporter"}]}"#)
        .and_then(|s| s.build())
        .unwrap_err();
    assert_eq!(e.field, "components[0].kind");
    let e = System::from_json(r#"{"until": 1e9, "components": [{"name": "a", "kind": "sink"}]}"#)
        .unwrap_err();
    assert_eq!(e.field, "until");
    // A refused initial connection names it, with the reason.
    let e = System::from_json(
        r#"{"components": [{"name": "a", "kind": "sink"}, {"name": "b", "kind": "client", "params": {"steps": []}}],
            "connections": [{"port": "b.ask", "service": "a.in"}]}"#,
    )
    .and_then(|s| s.build())
    .unwrap_err();
    assert_eq!(e.field, "connections[0]");
    assert!(
        e.message.contains("query") && e.message.contains("send"),
        "{}",
        e.message
    );
}
