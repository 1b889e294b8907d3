//! Graded tasks, checked by running systems: wiring the robot system so it
//! reaches its goal, and matching requirements with patterns.

use kinolab_common::Feedback;
use serde::Serialize;
use serde_json::{Value, json};

use crate::FieldError;
use crate::system::{ConnectionFile, Report, System, example};

/// The connections the wiring task leaves for the learner to make.
pub const WIRE_TASK: [&str; 3] = ["planner.map", "motion.velocity", "sequencer.goal"];

/// The robot system without the task's connections.
pub fn wire_task_system() -> Result<System, FieldError> {
    let mut system = example("robot")?;
    system
        .connections
        .retain(|c| !WIRE_TASK.contains(&c.port.as_str()));
    Ok(system)
}

/// "Wire it so the map reaches the planner and the planner drives the
/// base": run the robot system with the learner's `(port, service)` pairs
/// added and see whether the robot gets there.
pub fn wire_robot(connections: &[(String, String)]) -> Feedback {
    let mut system = match wire_task_system() {
        Ok(s) => s,
        Err(e) => return Feedback::not_yet(e.to_string()),
    };
    for (port, service) in connections {
        system.connections.retain(|c| &c.port != port);
        system.connections.push(ConnectionFile {
            port: port.clone(),
            service: service.clone(),
            latency: None,
        });
    }
    let report = match system.run(None) {
        Ok(r) => r,
        Err(e) => return Feedback::not_yet(format!("That wiring cannot be made: {}", e.message)),
    };
    if let Some(t) = reached(&report) {
        return Feedback::met(format!(
            "The robot reached the goal at {t:.1} s, {} messages after the start.",
            report.counts.messages
        ));
    }
    let quiet: Vec<String> = report
        .quiet_ports
        .iter()
        .filter(|q| WIRE_TASK.contains(&q.port.as_str()) || q.port == "motion.source")
        .map(|q| format!("{}: {}", q.port, q.why.message))
        .collect();
    let unwired: Vec<&str> = WIRE_TASK
        .iter()
        .copied()
        .filter(|p| !system.connections.iter().any(|c| c.port == *p))
        .collect();
    let mut message = String::from("The robot did not reach the goal in 40 s.");
    if !unwired.is_empty() {
        message += &format!(" Still unwired: {}.", unwired.join(", "));
    }
    if !quiet.is_empty() {
        message += &format!(" Ports that got nothing: {}.", quiet.join("; "));
    }
    Feedback::not_yet(message)
}

/// When the sequencer saw the goal reached.
pub fn reached(report: &Report) -> Option<f64> {
    report
        .trace
        .iter()
        .find(|r| {
            r.kind == "note" && r.from == "sequencer" && r.summary.starts_with("goal reached")
        })
        .map(|r| r.sent)
}

/// A requirement of the "which pattern?" task.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Requirement {
    pub id: &'static str,
    pub text: &'static str,
    /// The pattern the task expects (and any other that also passes).
    pub best: &'static str,
}

pub const REQUIREMENTS: [Requirement; 5] = [
    Requirement {
        id: "bumper",
        text: "tell the behaviour when the bumper is hit",
        best: "event",
    },
    Requirement {
        id: "scan",
        text: "a laser scan for three consumers, 10 times a second",
        best: "push-timed",
    },
    Requirement {
        id: "path",
        text: "\"give me a path to X\"",
        best: "query",
    },
    Requirement {
        id: "velocity",
        text: "a velocity command to the base",
        best: "send",
    },
    Requirement {
        id: "source",
        text: "switch where the motion component takes its path from",
        best: "wiring",
    },
];

/// What a learner may choose for a requirement: a communication pattern,
/// or wiring (changing connections while the system runs).
pub const CHOICES: [&str; 6] = {
    let names = crate::Pattern::NAMES;
    [names[0], names[1], names[2], names[3], names[4], "wiring"]
};

/// What trying one pattern for one requirement showed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Trial {
    pub works: bool,
    /// Messages the trial system exchanged, when it was run.
    pub messages: Option<u64>,
    pub note: String,
}

fn run(file: Value) -> Result<Report, FieldError> {
    System::from_json(&file.to_string())?.run(None)
}

/// The numbers carried to `component` by messages of `kinds`.
fn values_to(report: &Report, component: &str, kinds: &[&str]) -> Vec<(f64, f64)> {
    report
        .trace
        .iter()
        .filter(|r| r.to == component && kinds.contains(&r.kind) && r.delivered.is_some())
        .filter_map(|r| {
            let value = r.summary.rsplit(' ').next()?.parse().ok()?;
            Some((r.delivered.unwrap_or(r.sent), value))
        })
        .collect()
}

fn reasoned(note: &str) -> Trial {
    Trial {
        works: false,
        messages: None,
        note: note.to_owned(),
    }
}

/// Try `choice` for requirement `id`.
pub fn trial(id: &str, choice: &str) -> Result<Trial, FieldError> {
    if !CHOICES.contains(&choice) {
        return Err(FieldError::new("choice", format!("no pattern `{choice}`")));
    }
    match id {
        "bumper" => bumper(choice),
        "scan" => scan(choice),
        "path" => path(choice),
        "velocity" => velocity(choice),
        "source" => source(choice),
        other => Err(FieldError::new(
            "requirement",
            format!("no requirement `{other}`"),
        )),
    }
}

/// Press episodes: a bumper held for 0.15 s every 2 s or so, four in 10 s.
const PRESSES: usize = 4;

fn bumper_system(consumer: Value, port: &str, service: &str, pattern: &str) -> Value {
    json!({
        "seed": 1, "until": 10.0,
        "components": [
            { "name": "bumper", "kind": "publisher", "params": { "pattern": pattern, "every": [2.0, 0.15], "wrap": 1, "period": 0.1 } },
            consumer,
        ],
        "connections": [{ "port": port, "service": service }],
    })
}

/// Polling steps: ask every `period` s for `until` s.
fn polls(period: f64, until: f64) -> Vec<Value> {
    let n = (until / period).floor() as usize;
    (1..n)
        .flat_map(|k| [json!({ "at": k as f64 * period }), json!({ "ask": 0 })])
        .collect()
}

fn bumper(choice: &str) -> Result<Trial, FieldError> {
    let (file, consumer, kinds) = match choice {
        "event" => (
            bumper_system(
                json!({ "name": "behaviour", "kind": "watcher", "params": { "above": 0.5, "mode": "continuous", "at": 0.0 } }),
                "behaviour.alarm",
                "bumper.above",
                "push-newest",
            ),
            "behaviour",
            ["notify"],
        ),
        "push-newest" | "push-timed" => (
            bumper_system(
                json!({ "name": "behaviour", "kind": "subscriber", "params": { "pattern": choice } }),
                "behaviour.value",
                "bumper.value",
                choice,
            ),
            "behaviour",
            ["update"],
        ),
        "query" => (
            bumper_system(
                json!({ "name": "behaviour", "kind": "client", "params": { "object": "Read", "answer": "Count", "steps": polls(0.25, 10.0) } }),
                "behaviour.ask",
                "bumper.read",
                "push-newest",
            ),
            "behaviour",
            ["answer"],
        ),
        "send" => {
            return Ok(reasoned(
                "send goes from a client to a server and carries commands: the bumper's owner would have to know every component that cares and command each one",
            ));
        }
        _ => {
            return Ok(reasoned(
                "wiring changes who talks to whom; it carries no data",
            ));
        }
    };
    let report = run(file)?;
    let seen = values_to(&report, consumer, &kinds);
    // Presses seen: each notification is one; read values count by their
    // rising edges.
    let mut presses = 0;
    let mut last = 0.0;
    for &(_, v) in &seen {
        if v > 0.5 && (last < 0.5 || kinds == ["notify"]) {
            presses += 1;
        }
        last = v;
    }
    let idle = seen.iter().filter(|(_, v)| *v < 0.5).count();
    let works = presses == PRESSES && idle == 0;
    let note = format!(
        "saw {presses} of {PRESSES} presses; woken {idle} times with nothing pressed; {} messages",
        report.counts.messages
    );
    Ok(Trial {
        works,
        messages: Some(report.counts.messages),
        note,
    })
}

fn scan(choice: &str) -> Result<Trial, FieldError> {
    let consumers = ["mapper", "avoider", "logger"];
    let (pattern, consumer, service) = match choice {
        "push-newest" | "push-timed" => (
            choice,
            json!({ "kind": "subscriber", "params": { "pattern": choice, "work": 0.02 } }),
            "laser.value",
        ),
        "query" => (
            "push-newest",
            json!({ "kind": "client", "params": { "object": "Read", "answer": "Count", "steps": polls(0.1, 10.0) } }),
            "laser.read",
        ),
        "event" => {
            return Ok(reasoned(
                "an event says that a condition became true; a stream of scans is not a condition",
            ));
        }
        "send" => {
            return Ok(reasoned(
                "with send the laser would command each consumer by name: a fourth consumer means changing the laser",
            ));
        }
        _ => {
            return Ok(reasoned(
                "wiring changes who talks to whom; it carries no scans",
            ));
        }
    };
    let mut components = vec![
        json!({ "name": "laser", "kind": "publisher", "params": { "pattern": pattern, "every": [0.1], "period": 0.1 } }),
    ];
    let mut connections = Vec::new();
    for name in consumers {
        let mut c = consumer.clone();
        c["name"] = json!(name);
        components.push(c);
        let port = if choice == "query" { "ask" } else { "value" };
        connections.push(json!({ "port": format!("{name}.{port}"), "service": service }));
    }
    let report = run(
        json!({ "seed": 1, "until": 10.0, "components": components, "connections": connections }),
    )?;
    let kinds = if choice == "query" {
        ["answer"]
    } else {
        ["update"]
    };
    let fewest = consumers
        .iter()
        .map(|c| {
            let mut v: Vec<i64> = values_to(&report, c, &kinds)
                .iter()
                .map(|(_, x)| *x as i64)
                .collect();
            v.dedup();
            v.len()
        })
        .min()
        .unwrap_or(0);
    let budget = 3 * 100 + 30;
    let works = fewest >= 95 && report.counts.messages <= budget;
    Ok(Trial {
        works,
        messages: Some(report.counts.messages),
        note: format!(
            "each consumer got at least {fewest} of about 100 scans; {} messages (one per scan per consumer would be about 300)",
            report.counts.messages
        ),
    })
}

fn path(choice: &str) -> Result<Trial, FieldError> {
    match choice {
        "query" => {
            let report = run(json!({
                "seed": 1, "until": 3.0,
                "components": [
                    { "name": "planner", "kind": "server", "params": { "work": [0.3] } },
                    { "name": "motion", "kind": "client", "params": { "steps": [{ "ask": 4 }, { "ask": 7 }] } },
                ],
                "connections": [{ "port": "motion.ask", "service": "planner.compute" }],
            }))?;
            let answers = values_to(&report, "motion", &["answer"]).len();
            Ok(Trial {
                works: answers == 2,
                messages: Some(report.counts.messages),
                note: format!("2 requests, {answers} answers, each matched to its request"),
            })
        }
        "send" => {
            let report = run(json!({
                "seed": 1, "until": 3.0,
                "components": [
                    { "name": "planner", "kind": "sink" },
                    { "name": "motion", "kind": "sender", "params": { "period": 1.0 } },
                ],
                "connections": [{ "port": "motion.out", "service": "planner.in" }],
            }))?;
            Ok(Trial {
                works: false,
                messages: Some(report.counts.messages),
                note: format!(
                    "the planner got {} goals, and no path ever came back: send is one-way",
                    report.counts.delivered
                ),
            })
        }
        "push-newest" | "push-timed" => Ok(reasoned(
            "a publisher pushes what it has to every subscriber; a client cannot say where it wants to go",
        )),
        "event" => Ok(reasoned(
            "an event notifies that a condition became true; it does not compute an answer",
        )),
        _ => Ok(reasoned(
            "wiring changes who talks to whom; it computes nothing",
        )),
    }
}

fn velocity(choice: &str) -> Result<Trial, FieldError> {
    match choice {
        "send" | "query" => {
            let (client, port, server) = if choice == "send" {
                (
                    json!({ "name": "controller", "kind": "sender", "params": { "period": 0.1 } }),
                    "controller.out",
                    json!({ "name": "base", "kind": "sink" }),
                )
            } else {
                (
                    json!({ "name": "controller", "kind": "client", "params": { "steps": polls(0.1, 5.0) } }),
                    "controller.ask",
                    json!({ "name": "base", "kind": "server", "params": { "work": [0.0] } }),
                )
            };
            let service = if choice == "send" {
                "base.in"
            } else {
                "base.compute"
            };
            let report = run(json!({
                "seed": 1, "until": 5.0,
                "latency": { "fixed": 0.02 },
                "components": [server, client],
                "connections": [{ "port": port, "service": service }],
            }))?;
            let commands = report
                .trace
                .iter()
                .filter(|r| r.to == "base" && matches!(r.kind, "command" | "request"))
                .count();
            let works = choice == "send";
            let note = if works {
                format!("{commands} commands, one message each, and the controller never waits")
            } else {
                format!(
                    "{commands} commands took {} messages, and the controller waited 0.04 s on each for an answer it does not need",
                    report.counts.messages
                )
            };
            Ok(Trial {
                works,
                messages: Some(report.counts.messages),
                note,
            })
        }
        "push-newest" | "push-timed" => Ok(reasoned(
            "the base would have to subscribe to one particular controller: the roles are upside down, and switching controllers means rewiring the base",
        )),
        "event" => Ok(reasoned(
            "an event waits for a condition; a command should act now",
        )),
        _ => Ok(reasoned(
            "wiring changes who talks to whom; it carries no command",
        )),
    }
}

fn source(choice: &str) -> Result<Trial, FieldError> {
    if choice != "wiring" {
        return Ok(reasoned(
            "only wiring changes who talks to whom while the system runs; every other pattern carries data over a connection that stays as it is",
        ));
    }
    let report = example("robot")?.run(None)?;
    let t = reached(&report);
    Ok(Trial {
        works: t.is_some(),
        messages: Some(report.counts.messages),
        note: match t {
            Some(t) => format!(
                "the sequencer rewired motion.source at 5 s and the robot reached the goal at {t:.1} s"
            ),
            None => "the robot did not reach the goal".to_owned(),
        },
    })
}

/// Grade the learner's `(requirement, pattern)` choices by running each.
pub fn which_pattern(choices: &[(&str, &str)]) -> Feedback {
    let mut wrong = Vec::new();
    for r in REQUIREMENTS {
        let Some((_, choice)) = choices.iter().find(|(id, _)| *id == r.id) else {
            wrong.push(format!("{}: no pattern chosen", r.text));
            continue;
        };
        match trial(r.id, choice) {
            Ok(t) if t.works => {}
            Ok(t) => wrong.push(format!("{} with {choice}: {}", r.text, t.note)),
            Err(e) => wrong.push(e.to_string()),
        }
    }
    if wrong.is_empty() {
        Feedback::met("Every requirement works with the pattern you chose.")
    } else {
        Feedback::not_yet(format!(
            "{} of 5 do not work yet. {}",
            wrong.len(),
            wrong.join(" · ")
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_requirement_passes_with_its_pattern_and_fails_with_most_others() {
        for r in REQUIREMENTS {
            let works: Vec<&str> = CHOICES
                .iter()
                .copied()
                .filter(|c| trial(r.id, c).unwrap().works)
                .collect();
            assert!(works.contains(&r.best), "{}: {works:?}", r.id);
            let expected: &[&str] = match r.id {
                // A steady stream: push newest delivers it as well.
                "scan" => &["push-newest", "push-timed"],
                other => &[REQUIREMENTS.iter().find(|x| x.id == other).unwrap().best],
            };
            assert_eq!(works, expected, "{}", r.id);
        }
    }

    #[test]
    fn the_trials_measure_what_goes_wrong() {
        let polled = trial("bumper", "query").unwrap();
        assert!(polled.note.contains("woken"), "{}", polled.note);
        let newest = trial("bumper", "push-newest").unwrap();
        // Started, then four presses and four releases: five idle wake-ups.
        assert!(
            newest.note.starts_with("saw 4 of 4 presses; woken 5 times"),
            "{}",
            newest.note
        );
        let scan = trial("scan", "query").unwrap();
        assert!(scan.messages.unwrap() > 550, "{scan:?}");
        assert!(trial("path", "teleport").is_err());
        let graded = which_pattern(&[
            ("bumper", "event"),
            ("scan", "push-newest"),
            ("path", "query"),
            ("velocity", "send"),
            ("source", "wiring"),
        ]);
        assert!(graded.met, "{}", graded.message);
        let graded = which_pattern(&[
            ("bumper", "push-newest"),
            ("scan", "push-timed"),
            ("path", "query"),
            ("velocity", "send"),
            ("source", "wiring"),
        ]);
        assert!(
            !graded.met && graded.message.starts_with("1 of 5"),
            "{}",
            graded.message
        );
    }

    #[test]
    fn the_wiring_task_passes_only_when_the_map_reaches_the_planner_and_the_planner_drives_the_base()
     {
        let pairs = |n: usize| -> Vec<(String, String)> {
            [
                ("planner.map", "mapper.map"),
                ("motion.velocity", "base.velocity"),
                ("sequencer.goal", "planner.goal"),
            ]
            .iter()
            .take(n)
            .map(|(p, s)| ((*p).to_owned(), (*s).to_owned()))
            .collect()
        };
        let done = wire_robot(&pairs(3));
        assert!(done.met, "{}", done.message);
        let missing = wire_robot(&pairs(2));
        assert!(!missing.met);
        assert!(
            missing.message.contains("Still unwired: sequencer.goal"),
            "{}",
            missing.message
        );
        let wrong = wire_robot(&[("planner.map".into(), "laser.scan".into())]);
        assert!(
            !wrong.met && wrong.message.contains("cannot be made"),
            "{}",
            wrong.message
        );
    }
}
