//! Wiring at run time: refusals with reasons, disconnect cancelling what
//! is pending, and (property) no message reaching a port that is not
//! connected to its sender.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use kinolab_components::kinds::build;
use kinolab_components::{Action, Latency, Runtime, Status, System};
use proptest::prelude::*;

fn runtime(parts: &[(&str, &str, serde_json::Value)]) -> Runtime {
    let mut rt = Runtime::new(1, Latency::default()).unwrap();
    for (name, kind, params) in parts {
        rt.add(name, build(kind, params).unwrap(), 0.0).unwrap();
    }
    rt
}

#[test]
fn a_master_is_refused_a_mismatch_of_pattern_or_type_with_the_reason() {
    let robot = System::from_json(kinolab_components::system::EXAMPLES[3].1).unwrap();
    let mut rt = robot.build().unwrap();
    let master = Some(6); // the sequencer
    let e = rt
        .connect("motion.source", "laser.scan", "sequencer", master)
        .unwrap_err();
    assert_eq!(e.reason, "types");
    assert!(
        e.message.contains("Path") && e.message.contains("Scan"),
        "{e}"
    );
    let e = rt
        .connect("motion.source", "planner.goal", "sequencer", master)
        .unwrap_err();
    assert_eq!(e.reason, "pattern");
    let e = rt
        .connect("motion.velocity", "base.velocity", "sequencer", master)
        .unwrap_err();
    assert_eq!(e.reason, "not-wireable");
    let e = rt
        .connect("motion.source", "planner.route", "mapper", Some(2))
        .unwrap_err();
    assert_eq!(e.reason, "not-master");
    // The refusal is in the trace and in the port's "why".
    assert!(
        rt.trace()
            .iter()
            .any(|r| r.status == Status::Refused && r.summary.contains("Scan"))
    );
    rt.connect("motion.source", "planner.route", "sequencer", master)
        .unwrap();
    assert_eq!(
        rt.component("motion").unwrap().ports[0]
            .connected_to
            .as_deref(),
        Some("planner.route")
    );
}

#[test]
fn disconnecting_cancels_pending_requests_and_drops_late_answers() {
    let mut rt = runtime(&[
        ("solver", "server", serde_json::json!({ "work": [2.0] })),
        (
            "client",
            "client",
            serde_json::json!({ "steps": [{ "request": "a", "value": 2 }, { "wait": "a" }, { "ask": 3 }] }),
        ),
    ]);
    rt.connect("client.ask", "solver.compute", "deployer", None)
        .unwrap();
    rt.schedule(
        1.0,
        Action::Disconnect {
            port: "client.ask".into(),
        },
    );
    assert!(rt.run_until(5.0));
    let notes: Vec<(String, f64)> = rt
        .trace()
        .iter()
        .filter(|r| r.kind == "note")
        .map(|r| (r.summary.clone(), r.sent))
        .collect();
    assert_eq!(notes[0], ("a returned disconnected".to_owned(), 1.0));
    // The synchronous ask after it has no connection: it never leaves.
    assert_eq!(notes[1], ("ask 3 returned not-connected".to_owned(), 1.0));
    // The solver finishes near 2.01 but its request was cancelled with the
    // connection: no answer goes anywhere.
    assert!(rt.trace().iter().all(|r| r.kind != "answer"));
    assert_eq!(rt.component("solver").unwrap().services[0].pending, 0);
    assert_eq!(rt.why_nothing("client.ask").reason, "not-connected");
}

#[test]
fn prescale_and_never_connected_ports_explain_themselves() {
    let mut rt = runtime(&[
        (
            "timed",
            "publisher",
            serde_json::json!({ "pattern": "push-timed", "period": 0.1 }),
        ),
        (
            "rare",
            "subscriber",
            serde_json::json!({ "pattern": "push-timed", "prescale": 1000 }),
        ),
        ("alone", "subscriber", serde_json::json!({})),
    ]);
    rt.connect("rare.value", "timed.value", "deployer", None)
        .unwrap();
    rt.run_until(0.55);
    // The first tick goes out, the next four are held back.
    let rare = rt.component("rare").unwrap().ports[0].stats;
    assert_eq!((rare.received, rare.withheld), (1, 4));
    assert_eq!(rt.why_nothing("alone.value").reason, "not-connected");
    assert_eq!(rt.why_nothing("rare.value").reason, "received");
    assert_eq!(rt.why_nothing("nobody.value").reason, "no-such-port");
}

/// A random system of publishers, subscribers, servers and clients, with
/// random latencies, loss and a random script of (re)wiring.
fn random_system(seed: u64, plan: &[(u8, u8, u8)]) -> System {
    let mut components = vec![
        serde_json::json!({ "name": "p0", "kind": "publisher", "params": { "pattern": "push-newest", "every": [0.07, 0.2] } }),
        serde_json::json!({ "name": "p1", "kind": "publisher", "params": { "pattern": "push-newest", "every": [0.13] } }),
        serde_json::json!({ "name": "s0", "kind": "server", "params": { "work": [0.05, 0.4] } }),
        serde_json::json!({ "name": "s1", "kind": "server", "params": { "work": [0.3] } }),
    ];
    for k in 0..3 {
        components.push(serde_json::json!({ "name": format!("sub{k}"), "kind": "subscriber", "params": { "work": 0.05 * k as f64 } }));
        let steps: Vec<serde_json::Value> = (0..6)
            .flat_map(|i| {
                [
                    serde_json::json!({ "request": format!("r{i}"), "value": i }),
                    serde_json::json!({ "at": 0.3 * (i + 1) as f64 }),
                ]
            })
            .chain([serde_json::json!({ "wait": "r5" })])
            .collect();
        components.push(serde_json::json!({ "name": format!("cl{k}"), "kind": "client", "params": { "steps": steps } }));
    }
    let script: Vec<serde_json::Value> = plan
        .iter()
        .enumerate()
        .map(|(i, &(who, to, what))| {
            let at = 0.1 * i as f64;
            let k = who % 3;
            match what % 3 {
                0 => serde_json::json!({ "at": at, "do": "connect", "port": format!("sub{k}.value"), "service": format!("p{}.value", to % 2) }),
                1 => serde_json::json!({ "at": at, "do": "connect", "port": format!("cl{k}.ask"), "service": format!("s{}.compute", to % 2) }),
                _ => serde_json::json!({ "at": at, "do": "disconnect", "port": if to % 2 == 0 { format!("sub{k}.value") } else { format!("cl{k}.ask") } }),
            }
        })
        .collect();
    let file = serde_json::json!({
        "seed": seed,
        "until": 3.0,
        "latency": { "fixed": 0.01, "jitter": 0.08, "loss": 0.1 },
        "components": components,
        "script": script,
    });
    System::from_json(&file.to_string()).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn nothing_arrives_before_it_left_or_at_a_port_wired_elsewhere(
        seed in 0u64..1000,
        plan in proptest::collection::vec((0u8..6, 0u8..6, 0u8..6), 1..25),
    ) {
        let report = random_system(seed, &plan).run(None).unwrap();
        prop_assert!(report.complete);
        // Connection intervals per port, from the wiring records.
        let mut wired: std::collections::BTreeMap<String, Vec<(String, f64, f64)>> = Default::default();
        for r in report.trace.iter().filter(|r| r.pattern == "wiring" && r.status == Status::Done) {
            let spans = wired.entry(r.port.clone()).or_default();
            if let Some(last) = spans.last_mut().filter(|s| s.2.is_infinite()) {
                last.2 = r.sent;
            }
            if r.kind == "connect" {
                spans.push((r.service.clone(), r.sent, f64::INFINITY));
            }
        }
        for r in report.trace.iter().filter(|r| r.status == Status::Delivered && !matches!(r.pattern, "wiring" | "state" | "note")) {
            let at = r.delivered.unwrap();
            prop_assert!(at >= r.sent, "{r:?}");
            let spans = wired.get(&r.port).cloned().unwrap_or_default();
            let ok = spans.iter().any(|(service, from, to)| *service == r.service && *from <= r.sent && at <= *to);
            prop_assert!(ok, "{r:?} outside {spans:?}");
        }
    }
}

/// A copied runtime runs on exactly as the original (the lab's player
/// keeps copies to scrub back), and stepping the clock in small steps
/// gives what one long run gives (the command line's `--until`).
#[test]
fn a_copied_runtime_and_a_stepped_one_run_as_the_original() {
    for (id, text) in kinolab_components::system::EXAMPLES {
        let system = System::from_json(text).unwrap();
        let mut stepped = system.build().unwrap();
        for k in 1..=40 {
            stepped.run_until(f64::from(k) * 0.05);
        }
        let mut copy = stepped.clone();
        stepped.run_until(3.0);
        copy.run_until(3.0);
        let whole = system.run(Some(3.0)).unwrap();
        assert_eq!(
            stepped.report("", 3.0, true),
            copy.report("", 3.0, true),
            "{id}"
        );
        assert_eq!(whole.trace, stepped.trace(), "{id}");
        assert_eq!(whole.components, stepped.view(), "{id}");
    }
}

/// A change scheduled for later does not alter what happens before it:
/// jitter and loss are drawn per message, not per thing scheduled.
#[test]
fn a_later_script_item_leaves_the_past_alone() {
    let plan = [(0, 0, 0), (1, 1, 1), (2, 0, 1)];
    let mut later = random_system(7, &plan);
    let before = later.run(Some(2.5)).unwrap();
    later.script.push(
        serde_json::from_value(
            serde_json::json!({ "at": 2.5, "do": "disconnect", "port": "sub0.value" }),
        )
        .unwrap(),
    );
    let after = later.run(Some(2.5)).unwrap();
    let past = |r: &kinolab_components::Record| r.sent < 2.5;
    let a: Vec<_> = before.trace.iter().filter(|r| past(r)).collect();
    let b: Vec<_> = after.trace.iter().filter(|r| past(r)).collect();
    assert!(
        a.iter().any(|r| r.status == Status::Lost),
        "the system loses messages"
    );
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(
            (x.sent, &x.summary, x.status),
            (y.sent, &y.summary, y.status)
        );
    }
}
