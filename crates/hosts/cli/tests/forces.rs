#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! `kinolab dynamics` and `kinolab statics` as the contract gives them:
//! real robots' files against Pinocchio's goldens (made by
//! `crates/body/mechanism/tests/urdf/dynamics_goldens.py`), the answers'
//! shapes, and bad input in one line with exit 2.

use std::process::Command;

use serde_json::Value;

fn workspace() -> std::path::PathBuf {
    kinolab_fuzz::seeds::workspace()
}

fn kinolab(args: &[&str]) -> (i32, Value, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_kinolab"))
        .args(args)
        .current_dir(workspace())
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    let value = serde_json::from_str(&text).unwrap_or(Value::Null);
    (
        out.status.code().unwrap_or(-1),
        value,
        String::from_utf8(out.stderr).unwrap(),
    )
}

fn list(v: &Value) -> String {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap().to_string())
        .collect::<Vec<_>>()
        .join(",")
}

fn close(a: &Value, b: &Value) -> bool {
    let flat = |v: &Value| -> Vec<f64> {
        match v {
            Value::Array(items) if items.iter().all(Value::is_array) => items
                .iter()
                .flat_map(|r| r.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()))
                .collect(),
            Value::Array(items) => items.iter().map(|x| x.as_f64().unwrap()).collect(),
            _ => Vec::new(),
        }
    };
    let (a, b) = (flat(a), flat(b));
    let scale = b.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
    a.len() == b.len() && a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= 1e-8 * scale)
}

#[test]
fn real_robots_through_the_command_line_match_pinocchio() {
    for name in ["panda", "ur5", "solo12"] {
        let file = format!("crates/body/mechanism/robots/{name}.urdf");
        let goldens: Value = serde_json::from_str(
            &std::fs::read_to_string(workspace().join(format!(
                "crates/body/mechanism/tests/urdf/{name}.dynamics.json"
            )))
            .unwrap(),
        )
        .unwrap();
        for s in goldens["states"].as_array().unwrap() {
            let (q, qd) = (list(&s["q"]), list(&s["qd"]));
            let (code, inverse, err) = kinolab(&[
                "dynamics",
                &file,
                "--q",
                &q,
                "--qd",
                &qd,
                "--qdd",
                &list(&s["qdd"]),
            ]);
            assert_eq!(code, 0, "{err}");
            assert_eq!(inverse["order"], goldens["order"]);
            for (ours, theirs) in [
                ("tau", "tau"),
                ("gravity", "gravity"),
                ("mass_matrix", "mass_matrix"),
            ] {
                assert!(
                    close(&inverse[ours], &s[theirs]),
                    "{name} {ours}: {} vs {}",
                    inverse[ours],
                    s[theirs]
                );
            }
            let (code, forward, err) = kinolab(&[
                "dynamics",
                &file,
                "--q",
                &q,
                "--qd",
                &qd,
                "--tau",
                &list(&s["forward_tau"]),
            ]);
            assert_eq!(code, 0, "{err}");
            assert!(close(&forward["qdd"], &s["forward_qdd"]), "{name} forward");
            assert_eq!(forward.as_object().unwrap().len(), 2, "{{ order, qdd }}");
        }
    }
    // The Panda's zero pose is outside the elbow's range: computed, and named.
    let panda = "crates/body/mechanism/robots/panda.urdf";
    let (code, zero, err) = kinolab(&[
        "dynamics",
        panda,
        "--set",
        "panda_joint1=0",
        "--qdd",
        "0,0,0,0,0,0,0,0",
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(zero["outside_limits"][0]["joint"], "panda_joint4", "{zero}");
    assert_eq!(
        zero["tau"], zero["gravity"],
        "at rest the torques are gravity's"
    );
}

#[test]
fn statics_holds_the_arm_and_says_how_far_the_tool_sags() {
    let (code, held, err) = kinolab(&[
        "statics",
        "catalogue:puma560",
        "--q",
        "0,0,0,0,0,0",
        "--load",
        "tool:0,0,-50",
        "--stiffness",
        "5000",
    ]);
    assert_eq!(code, 0, "{err}");
    for key in [
        "order",
        "gravity",
        "load",
        "total",
        "mass",
        "com",
        "deflection",
        "sag",
        "frame",
    ] {
        assert!(held.get(key).is_some(), "{key}: {held}");
    }
    assert!((held["mass"].as_f64().unwrap() - 23.45).abs() < 1e-9);
    // The shoulder (q2) carries the arm held out and the 5 kg at the tool;
    // the springs let the tool drop.
    let total = held["total"].as_array().unwrap();
    let load = held["load"].as_array().unwrap();
    assert!(total[1].as_f64().unwrap().abs() > load[1].as_f64().unwrap().abs() - 1e-9);
    assert!(held["sag"][2].as_f64().unwrap() < -0.001, "{held}");
    // By name: one stiffness for each joint.
    let (code, _, err) = kinolab(&[
        "statics",
        "catalogue:puma560",
        "--q",
        "0,0,0,0,0,0",
        "--stiffness",
        "q1=100",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("no stiffness for joint `q2`"), "{err}");
}

#[test]
fn bad_input_is_one_line_and_exit_two() {
    let cases: [(&[&str], &str); 5] = [
        (
            &[
                "dynamics",
                "catalogue:puma560",
                "--q",
                "0,0",
                "--qdd",
                "0,0,0,0,0,0",
            ],
            "has 6 joints",
        ),
        (
            &[
                "dynamics",
                "catalogue:puma560",
                "--set",
                "elbow=1",
                "--qdd",
                "0,0,0,0,0,0",
            ],
            "`elbow` is not a joint",
        ),
        (
            &[
                "dynamics",
                "catalogue:planar-2r",
                "--q",
                "0,0",
                "--tau",
                "1,1",
            ],
            "no mass anywhere",
        ),
        (
            &[
                "statics",
                "catalogue:puma560",
                "--q",
                "0,0,0,0,0,0",
                "--load",
                "hand:0,0,1",
            ],
            "hand",
        ),
        (
            &[
                "statics",
                "catalogue:puma560",
                "--q",
                "0,0,0,0,0,0",
                "--stiffness",
                "-3",
            ],
            "stiffness",
        ),
    ];
    for (args, words) in cases {
        let (code, _, err) = kinolab(args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains(words), "{args:?}: {err}");
    }
}
