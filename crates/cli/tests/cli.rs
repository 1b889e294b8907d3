#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! The command line, tested through its JSON and its error lines.

use std::process::Command;

use serde_json::Value;

fn kinolab(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_kinolab"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn json(args: &[&str]) -> Value {
    let (code, stdout, stderr) = kinolab(args);
    assert_eq!(code, 0, "stderr: {stderr}");
    serde_json::from_str(&stdout)
        .unwrap_or_else(|e| panic!("not one JSON document ({e}): {stdout}"))
}

#[test]
fn version_and_help() {
    let (code, stdout, _) = kinolab(&["--version"]);
    assert_eq!(code, 0);
    assert_eq!(
        stdout.trim(),
        format!("kinolab {}", env!("CARGO_PKG_VERSION"))
    );
    let (code, stdout, _) = kinolab(&["--help"]);
    assert_eq!(code, 0);
    assert!(
        stdout.contains("leg-events") && stdout.contains("stability") && stdout.contains("lessons")
    );
}

#[test]
fn leg_events_golden_values() {
    assert_eq!(json(&["leg-events", "2"])["events"], "6");
    assert_eq!(json(&["leg-events", "6"])["events"], "39916800");
}

#[test]
fn stability_of_a_square_stance() {
    let v = json(&[
        "stability",
        "--com",
        "0.5,0.2",
        "--feet",
        "1,1;-1,1;-1,-1;1,-1",
    ]);
    assert_eq!(v["stable"], true);
    assert!((v["margin"].as_f64().unwrap() - 0.5).abs() < 1e-12);
    let v = json(&[
        "stability",
        "--com",
        "-3,0",
        "--feet",
        "1,1;-1,1;-1,-1;1,-1",
    ]);
    assert_eq!(v["stable"], false);
    assert!((v["margin"].as_f64().unwrap() + 2.0).abs() < 1e-12);
}

#[test]
fn embedded_lessons_check_out() {
    let v = json(&["lessons"]);
    assert_eq!(v["ok"], true);
    assert_eq!(v["units"][0]["unit"], "automation");
    assert!(v["units"][0]["lessons"][0]["quizzes"].as_u64().unwrap() >= 3);
}

#[test]
fn a_broken_lesson_folder_names_file_and_line() {
    let dir = std::env::temp_dir().join(format!("kinolab-cli-test-{}", std::process::id()));
    let unit = dir.join("01-demo");
    std::fs::create_dir_all(&unit).unwrap();
    std::fs::write(unit.join("unit.md"), "---\ntitle: Demo\n---\n").unwrap();
    std::fs::write(unit.join("01-a.md"), "---\ntitle: A\nminutes: x\n---\n").unwrap();
    let (code, stdout, stderr) = kinolab(&["lessons", dir.to_str().unwrap()]);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(code, 2);
    assert!(stdout.is_empty());
    assert_eq!(
        stderr.trim(),
        "kinolab: 01-demo/01-a.md:3: `minutes` must be a whole number, found `x`"
    );
}

#[test]
fn bad_input_is_one_line_naming_the_field() {
    for (args, expected) in [
        (
            vec!["leg-events", "0"],
            "kinolab: legs: a walker needs at least one leg",
        ),
        (
            vec!["stability", "--com", "0,nan", "--feet", "1,1"],
            "kinolab: --com: `nan` is not a finite number",
        ),
        (
            vec!["stability", "--com", "0", "--feet", "1,1"],
            "kinolab: --com: expected two numbers X,Y, got 1",
        ),
        (
            vec!["stability", "--com", "0,0", "--feet", ""],
            "kinolab: --feet: no foot is on the ground",
        ),
    ] {
        let (code, stdout, stderr) = kinolab(&args);
        assert_eq!(code, 2, "{args:?}");
        assert!(stdout.is_empty());
        assert_eq!(stderr.trim(), expected);
        assert_eq!(stderr.lines().count(), 1);
    }
    let (code, _, stderr) = kinolab(&["no-such-command"]);
    assert_eq!(code, 2);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(!stderr.contains("panicked"));
}
