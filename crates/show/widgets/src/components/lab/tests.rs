use super::*;
use crate::registry::spec;

fn lab(params: &[(&str, &str)]) -> ComponentLab {
    let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
    let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
    let mut lab = ComponentLab::new(settings);
    lab.rebuild(&Moment::default());
    lab
}

fn player(lab: &mut ComponentLab) -> &mut Player<LabRun> {
    lab.player
        .as_mut()
        .unwrap_or_else(|| panic!("no run: {:?}", lab.problem))
}

fn connect(port: &str, service: &str) -> Action {
    Action::Connect {
        port: port.into(),
        service: service.into(),
    }
}

#[test]
fn a_link_of_the_first_format_still_opens() {
    // The old set-up: system, latency, jitter, loss, period, prescale, and
    // the learner's changes (none: the old format could not read them back).
    let old = (
        "newest-vs-timed",
        0.05_f64,
        0.0_f64,
        0.1_f64,
        0.2_f64,
        2_u32,
        0_u8,
    );
    let text = link::encode(&old).unwrap_or_default();
    let mut w = lab(&[]);
    assert_eq!(w.restore(&text), Ok(()));
    assert_eq!(w.settings.system, "newest-vs-timed");
    assert_eq!(
        (
            w.settings.latency,
            w.settings.loss,
            w.settings.period,
            w.settings.prescale
        ),
        (Some(0.05), Some(0.1), 0.2, 2)
    );
    // Out of the schema's range: refused, the lesson's settings kept.
    let bad = ("events", 0.05_f64, 0.0_f64, 0.9_f64, 0.2_f64, 2_u32, 0_u8);
    let mut w = lab(&[("system", "out-of-order")]);
    assert!(w.restore(&link::encode(&bad).unwrap_or_default()).is_err());
    assert_eq!(w.settings.system, "out-of-order");
}

#[test]
fn a_wiring_made_while_it_runs_is_replayed_on_scrub_and_in_the_link() {
    let mut w = lab(&[("task", "wire-robot")]);
    w.seek(2.0);
    w.act(connect("planner.map", "mapper.map"));
    w.seek(3.0);
    w.act(connect("motion.velocity", "base.velocity"));
    w.seek(4.0);
    let at_four = player(&mut w).state().rt.trace().to_vec();
    // Back before the second change and on again: the same history.
    w.seek(2.5);
    player(&mut w).seek(0);
    w.seek(4.0);
    assert_eq!(player(&mut w).state().rt.trace(), at_four.as_slice());
    assert_eq!(player(&mut w).events().len(), 2);
    // The link carries the changes and the instant.
    let text = w.state().unwrap_or_default();
    let mut again = lab(&[("task", "wire-robot")]);
    assert_eq!(again.restore(&text), Ok(()));
    assert_eq!(player(&mut again).state().rt.trace(), at_four.as_slice());
    assert_eq!(again.saved_run(), w.saved_run());
}

#[test]
fn the_saved_file_runs_to_what_the_lab_shows() {
    let mut w = lab(&[("system", "robot"), ("loss", "0.2")]);
    w.seek(6.0);
    w.act(Action::Cancel {
        port: "planner.map".into(),
    });
    w.seek(8.5);
    let Some(saved) = w.saved_run() else {
        panic!("no run")
    };
    assert_eq!(saved.args[3], "8.5");
    let file = System::from_json(&saved.text).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(file.script.len(), 1);
    assert_eq!(file.latency.loss, 0.2);
    let report = file.run(Some(8.5)).unwrap_or_else(|e| panic!("{e}"));
    let shown = player(&mut w).state().rt.trace().to_vec();
    assert_eq!(report.trace, shown);
    assert!(report.trace.iter().any(|r| r.kind == "cancel"));
    // The trace as a table: a header and a row per record.
    assert_eq!(trace_csv(&shown).lines().count(), shown.len() + 1);
}

#[test]
fn a_refused_wiring_is_not_made_and_says_why() {
    let mut w = lab(&[("system", "robot")]);
    w.seek(1.0);
    w.act(connect("motion.source", "laser.scan"));
    assert!(
        w.refusal
            .as_deref()
            .is_some_and(|r| r.starts_with("Refused")),
        "{:?}",
        w.refusal
    );
    assert!(player(&mut w).events().is_empty());
}

#[test]
fn the_wiring_task_is_solved_by_wiring_while_it_runs() {
    let mut w = lab(&[("task", "wire-robot")]);
    w.seek(0.5);
    for (port, service) in [
        ("planner.map", "mapper.map"),
        ("motion.velocity", "base.velocity"),
        ("sequencer.goal", "planner.goal"),
    ] {
        w.act(connect(port, service));
    }
    let pairs: Vec<(String, String)> = player(&mut w)
        .events()
        .into_iter()
        .filter_map(|(_, a)| match a {
            Action::Connect { port, service } => Some((port, service)),
            _ => None,
        })
        .collect();
    assert!(kinolab_components::exercise::wire_robot(&pairs).met);
}

#[test]
fn moving_a_slider_keeps_the_changes_and_the_instant() {
    let mut w = lab(&[("system", "events")]);
    w.seek(1.0);
    w.act(Action::Cancel {
        port: "client.ask".into(),
    });
    w.seek(2.0);
    w.settings.latency = Some(0.3);
    let moment = w.moment();
    w.rebuild(&moment);
    let p = player(&mut w);
    assert_eq!(p.events().len(), 1);
    assert!((p.time() - 2.0).abs() < 1e-9);
    assert_eq!(p.state().system.latency.fixed, 0.3);
}

type Harness = egui_kittest::Harness<'static, (ComponentLab, bool)>;

/// The robot system's lab at 1 s, drawn, with the anchors of `port` and
/// `service`.
fn robot_lab_at_one_second(port: &str, service: &str) -> (Harness, egui::Pos2, egui::Pos2) {
    // The lab's fonts take effect a frame after they are installed.
    let mut h = egui_kittest::Harness::builder()
        .with_size(egui::vec2(1200.0, 2400.0))
        .build_ui_state(
            |ui, (w, ready): &mut (ComponentLab, bool)| {
                if *ready {
                    w.ui(ui);
                } else {
                    crate::theme::install(ui.ctx());
                    *ready = true;
                }
            },
            (lab(&[("system", "robot")]), false),
        );
    h.state_mut().0.seek(1.0);
    h.run_steps(3);
    let anchors = &h.state().0.look.anchors;
    let (Some(from), Some(to)) = (anchors.port(port), anchors.service(service)) else {
        panic!("the diagram has no such port or service")
    };
    (h, from, to)
}

fn button(pos: egui::Pos2, pressed: bool) -> egui::Event {
    egui::Event::PointerButton {
        pos,
        button: egui::PointerButton::Primary,
        pressed,
        modifiers: egui::Modifiers::NONE,
    }
}

/// The wiring the learner made, at 1 s: motion.source to planner.route.
fn assert_wired_at_one_second(h: &mut Harness) {
    let events = player(&mut h.state_mut().0).events();
    assert_eq!(events.len(), 1, "{events:?}");
    assert_eq!(events[0].1, connect("motion.source", "planner.route"));
    assert!((events[0].0 - 1.0).abs() < 1e-9);
    let view = player(&mut h.state_mut().0).state().rt.component("motion");
    let source = view.and_then(|c| c.ports.into_iter().find(|p| p.name == "source"));
    assert_eq!(
        source.and_then(|p| p.connected_to).as_deref(),
        Some("planner.route")
    );
}

#[test]
fn a_port_dragged_onto_a_service_is_wired_while_it_runs() {
    let (mut h, from, to) = robot_lab_at_one_second("motion.source", "planner.route");
    let steps = [
        egui::Event::PointerMoved(from),
        button(from, true),
        egui::Event::PointerMoved(from + (to - from) * 0.5),
        egui::Event::PointerMoved(to),
        button(to, false),
    ];
    for event in steps {
        h.input_mut().events.push(event);
        h.run_steps(1);
    }
    assert_wired_at_one_second(&mut h);
}

#[test]
fn a_fast_drag_from_the_edge_of_a_port_wires_it() {
    // Pressed 8 points off the port's centre, then straight to the service
    // and released within one frame: no slow start for egui to see.
    let (mut h, from, to) = robot_lab_at_one_second("motion.source", "planner.route");
    let press = from + egui::vec2(8.0, 0.0);
    h.input_mut().events.push(egui::Event::PointerMoved(press));
    h.run_steps(1);
    for event in [
        button(press, true),
        egui::Event::PointerMoved(to),
        button(to, false),
    ] {
        h.input_mut().events.push(event);
    }
    h.run_steps(2);
    assert_wired_at_one_second(&mut h);
}

#[test]
fn a_finger_drag_wires_a_port_and_a_miss_says_where_to_drop() {
    use egui_kittest::kittest::Queryable as _;
    let (mut h, from, to) = robot_lab_at_one_second("motion.source", "planner.route");
    // A finger lands 16 points left of the port (within reach on a touch
    // screen), then drops halfway: nothing wired, and the lab says why.
    let press = from + egui::vec2(-16.0, 0.0);
    let halfway = from + (to - from) * 0.5 + egui::vec2(0.0, 60.0);
    fn drag(h: &mut Harness, id: u64, press: egui::Pos2, end: egui::Pos2) {
        for (phase, pos, down) in [
            (egui::TouchPhase::Start, press, Some(true)),
            (egui::TouchPhase::Move, end, None),
            (egui::TouchPhase::End, end, Some(false)),
        ] {
            h.input_mut().events.push(egui::Event::Touch {
                device_id: egui::TouchDeviceId(1),
                id: egui::TouchId(id),
                phase,
                pos,
                force: None,
            });
            h.input_mut().events.push(egui::Event::PointerMoved(pos));
            if let Some(pressed) = down {
                h.input_mut().events.push(button(pos, pressed));
            }
            h.run_steps(1);
        }
        h.run_steps(1);
    }
    drag(&mut h, 1, press, halfway);
    assert!(player(&mut h.state_mut().0).events().is_empty());
    h.get_by_label_contains("Nothing was wired: drop motion.source on a service");
    // The same finger, now dropped on the service, wires it.
    drag(&mut h, 2, press, to);
    assert_wired_at_one_second(&mut h);
    assert!(h.query_by_label_contains("Nothing was wired").is_none());
}
