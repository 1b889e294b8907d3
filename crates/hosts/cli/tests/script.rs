#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! `kinolab script`: the exercise list as the contract writes it, a
//! learner's script checked (exit 0 whether or not it passed), a class
//! graded as JSON and CSV, and script runs given by path.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

fn kinolab(args: &[&str], dir: &Path) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_kinolab"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// A fresh folder holding the exercises' solutions.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("kinolab-script-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let solutions = kinolab_fuzz::seeds::workspace().join("crates/teach/exercises/tests/solutions");
    for entry in std::fs::read_dir(solutions).unwrap().flatten() {
        std::fs::copy(entry.path(), dir.join(entry.file_name())).unwrap();
    }
    dir
}

#[test]
fn exercises_are_listed_as_the_contract_says() {
    let dir = folder("list");
    let (code, out, _) = kinolab(&["script", "exercises"], &dir);
    assert_eq!(code, 0);
    let list: Vec<Value> = serde_json::from_str(&out).unwrap();
    assert!(list.len() >= 8);
    let control = list.iter().find(|e| e["id"] == "control-park").unwrap();
    assert_eq!(control["hook"], "control");
    assert_eq!(control["signature"], "control(rho, alpha, beta)");
    assert_eq!(control["returns"], "[v, omega]");
    assert_eq!(control["visible"], 2);
    assert_eq!(control["held_back"], 3);
    let hooks: std::collections::BTreeSet<&str> =
        list.iter().map(|e| e["hook"].as_str().unwrap()).collect();
    let all = [
        "behaviour",
        "control",
        "coordinator",
        "field",
        "legs",
        "sequencer",
    ];
    assert_eq!(hooks, all.into_iter().collect());
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_check_answers_whether_or_not_the_script_passed() {
    let dir = folder("check");
    let (code, out, err) = kinolab(
        &[
            "script",
            "check",
            "control-park.rhai",
            "--exercise",
            "control-park",
        ],
        &dir,
    );
    assert_eq!(code, 0, "{err}");
    let check: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(check["exercise"], "control-park");
    assert_eq!(check["passed"], true);
    // The visible worlds in full; of the held-back ones, only the tally.
    assert_eq!(check["worlds"].as_array().unwrap().len(), 2);
    assert!(
        check["worlds"]
            .as_array()
            .unwrap()
            .iter()
            .all(|w| w["visible"] == true)
    );
    assert_eq!(
        check["held_back"],
        serde_json::json!({ "passed": 3, "of": 3 })
    );
    assert!(check["worlds"][0]["metrics"]["distance"].as_f64().unwrap() < 0.01);
    // `--all`: every world in full, for the instructor.
    let (code, out, _) = kinolab(
        &[
            "script",
            "check",
            "control-park.rhai",
            "--exercise",
            "control-park",
            "--all",
        ],
        &dir,
    );
    assert_eq!(code, 0);
    let all: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(all["worlds"].as_array().unwrap().len(), 5);
    assert!(all.get("held_back").is_none(), "{all}");

    let (code, out, _) = kinolab(
        &[
            "script",
            "check",
            "control-park.no-beta.rhai",
            "--exercise",
            "control-park",
        ],
        &dir,
    );
    assert_eq!(code, 0);
    let check: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(check["passed"], false);
    // It happens to arrive facing the right way from straight behind.
    assert_eq!(
        check["held_back"],
        serde_json::json!({ "passed": 1, "of": 3 })
    );
    let reasons: Vec<&str> = check["worlds"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|w| w["reason"].as_str())
        .collect();
    assert!(
        reasons.iter().any(|r| r.starts_with("arrived facing")),
        "{reasons:?}"
    );

    // An endless loop: exit 0, the error with its line, column and time.
    std::fs::write(
        dir.join("loop.rhai"),
        "fn control(rho, alpha, beta) {\n    loop { }\n}\n",
    )
    .unwrap();
    let (code, out, _) = kinolab(
        &["script", "check", "loop.rhai", "--exercise", "control-park"],
        &dir,
    );
    assert_eq!(code, 0);
    let check: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(check["passed"], false);
    assert_eq!(check["error"]["line"], 2, "{check}");
    assert_eq!(check["error"]["t"], 0.0);
    assert!(
        check["error"]["message"]
            .as_str()
            .unwrap()
            .contains("100 000 steps")
    );

    // A syntax error: nothing runs, the error names its line.
    std::fs::write(
        dir.join("broken.rhai"),
        "fn control(rho, alpha, beta) {\n    [rho,\n",
    )
    .unwrap();
    let (code, out, _) = kinolab(
        &[
            "script",
            "check",
            "broken.rhai",
            "--exercise",
            "control-park",
        ],
        &dir,
    );
    assert_eq!(code, 0);
    let check: Value = serde_json::from_str(&out).unwrap();
    assert_eq!(check["worlds"].as_array().unwrap().len(), 0);
    assert!(check["error"]["line"].as_u64().is_some(), "{check}");

    // Bad input: exit 2, one line naming what is wrong.
    let (code, _, err) = kinolab(
        &[
            "script",
            "check",
            "missing.rhai",
            "--exercise",
            "control-park",
        ],
        &dir,
    );
    assert_eq!(code, 2);
    assert!(err.contains("missing.rhai"), "{err}");
    let (code, _, err) = kinolab(
        &[
            "script",
            "check",
            "control-park.rhai",
            "--exercise",
            "parking",
        ],
        &dir,
    );
    assert_eq!(code, 2);
    assert!(
        err.contains("--exercise: no exercise called `parking`"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_class_is_graded_one_row_per_file_as_json_or_csv() {
    let dir = folder("grade");
    // A missing, an empty and a Latin-1 file stay rows of their own.
    std::fs::write(dir.join("empty.rhai"), "").unwrap();
    let mut latin1 = b"// caf\xe9\n".to_vec();
    latin1.extend(std::fs::read(dir.join("field-pull.rhai")).unwrap());
    std::fs::write(dir.join("latin1.rhai"), latin1).unwrap();
    std::fs::write(dir.join("broken.rhai"), "fn field(x, y) {\n  [x,\n").unwrap();
    let files = [
        "field-pull.rhai",
        "field-pull.push.rhai",
        "field-pull.x-only.rhai",
        "missing.rhai",
        "empty.rhai",
        "latin1.rhai",
        "broken.rhai",
    ];
    let mut args = vec!["script", "grade", "--exercise", "field-pull"];
    args.extend(files);
    let (code, out, err) = kinolab(&args, &dir);
    assert_eq!(code, 0, "{err}");
    let rows: Vec<Value> = serde_json::from_str(&out).unwrap();
    let passed: Vec<bool> = rows
        .iter()
        .map(|r| r["passed"].as_bool().unwrap())
        .collect();
    assert_eq!(passed, [true, false, false, false, false, true, false]);
    let names: Vec<&str> = rows.iter().map(|r| r["file"].as_str().unwrap()).collect();
    assert_eq!(names, files, "one row per file, in the order given");
    assert_eq!(rows[0]["visible"], serde_json::json!([2, 2]));
    assert_eq!(rows[0]["held_back"], serde_json::json!([3, 3]));
    assert_eq!(rows[0]["first_failure"], Value::Null);
    assert!(
        rows[2]["first_failure"]
            .as_str()
            .unwrap()
            .contains("stuck at (4.00")
    );
    assert_eq!(rows[3]["error_kind"], "unreadable");
    assert!(
        rows[3]["first_failure"]
            .as_str()
            .unwrap()
            .contains("cannot read"),
        "{}",
        rows[3]
    );
    assert_eq!(rows[4]["first_failure"], "the file is empty");
    assert!(
        rows[5]["notice"].as_str().unwrap().contains("not UTF-8"),
        "{}",
        rows[5]
    );
    // A script that does not compile ran on no world, of all of them.
    assert_eq!(rows[6]["error_kind"], "syntax");
    assert_eq!(rows[6]["visible"], serde_json::json!([0, 2]));
    assert_eq!(rows[6]["held_back"], serde_json::json!([0, 3]));

    args.push("--csv");
    let (code, out, _) = kinolab(&args, &dir);
    assert_eq!(code, 0);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines[0],
        "file,passed,visible,held_back,error_kind,first_failure"
    );
    assert_eq!(lines[1], "\"field-pull.rhai\",true,2/2,3/3,,\"\"");
    assert!(
        lines[3].starts_with("\"field-pull.x-only.rhai\",false,"),
        "{}",
        lines[3]
    );
    assert!(
        lines[7].starts_with("\"broken.rhai\",false,0/2,0/3,syntax,"),
        "{}",
        lines[7]
    );
    assert_eq!(lines.len(), 8);
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn held_back_worlds_stay_held_back() {
    let dir = folder("held");
    // A script that throws what it is given, in the held-back worlds only
    // (their starts are not the visible ones').
    std::fs::write(
        dir.join("spy.rhai"),
        "fn field(x, y) {\n  if x > 5.0 || y < -1.0 { throw `at ${x}, ${y}`; }\n  [4.0 - x, -y]\n}\n",
    )
    .unwrap();
    let (code, out, _) = kinolab(
        &["script", "check", "spy.rhai", "--exercise", "field-pull"],
        &dir,
    );
    assert_eq!(code, 0);
    assert!(
        !out.contains("beyond the goal") && !out.contains("6.00"),
        "{out}"
    );
    let check: Value = serde_json::from_str(&out).unwrap();
    let message = check["error"]["message"].as_str().unwrap();
    assert!(message.starts_with("in a world held back"), "{message}");
    assert!(!message.contains("at 6"), "{message}");
    assert_eq!(check["error"]["kind"], "runtime");
    // The instructor sees all of it.
    let (_, out, _) = kinolab(
        &[
            "script",
            "check",
            "spy.rhai",
            "--exercise",
            "field-pull",
            "--all",
        ],
        &dir,
    );
    assert!(out.contains("from beyond the goal"), "{out}");
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_script_saved_by_another_editor_is_read_as_written() {
    let dir = folder("editors");
    let model = std::fs::read(dir.join("control-park.rhai")).unwrap();
    // A byte-order mark and Windows line ends.
    let mut bom = b"\xef\xbb\xbf".to_vec();
    bom.extend(
        String::from_utf8(model.clone())
            .unwrap()
            .replace('\n', "\r\n")
            .bytes(),
    );
    std::fs::write(dir.join("bom.rhai"), bom).unwrap();
    // Latin-1, with an accent in a comment.
    let mut latin1 = b"// na\xefve\n".to_vec();
    latin1.extend(&model);
    std::fs::write(dir.join("latin1.rhai"), latin1).unwrap();
    for (file, notice) in [("bom.rhai", false), ("latin1.rhai", true)] {
        let (code, out, err) = kinolab(
            &["script", "check", file, "--exercise", "control-park"],
            &dir,
        );
        assert_eq!(code, 0, "{file}: {err}");
        let check: Value = serde_json::from_str(&out).unwrap();
        assert_eq!(check["passed"], true, "{file}: {check}");
        assert_eq!(err.contains("not UTF-8"), notice, "{file}: {err}");
    }
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_run_file_may_name_its_script_by_path() {
    let dir = folder("path");
    let run = |controller: Value| {
        serde_json::json!({
            "controller": controller,
            "start": { "x": -1.0, "y": 0.5, "theta_deg": 0.0 },
            "goal": { "x": 0.0, "y": 0.0, "theta_deg": 0.0 },
        })
        .to_string()
    };
    let source = std::fs::read_to_string(dir.join("control-park.rhai")).unwrap();
    std::fs::write(
        dir.join("by-path.run.json"),
        run(serde_json::json!({"kind": "script", "path": "control-park.rhai"})),
    )
    .unwrap();
    std::fs::write(
        dir.join("inline.run.json"),
        run(serde_json::json!({"kind": "script", "source": source})),
    )
    .unwrap();
    let (code, by_path, err) = kinolab(&["simulate", "by-path.run.json"], &dir);
    assert_eq!(code, 0, "{err}");
    let (_, inline, _) = kinolab(&["simulate", "inline.run.json"], &dir);
    assert_eq!(by_path, inline);
    let report: Value = serde_json::from_str(&by_path).unwrap();
    assert_eq!(report["reached"], true);

    std::fs::write(
        dir.join("lost.run.json"),
        run(serde_json::json!({"kind": "script", "path": "nowhere.rhai"})),
    )
    .unwrap();
    let (code, _, err) = kinolab(&["simulate", "lost.run.json"], &dir);
    assert_eq!(code, 2);
    assert!(
        err.contains("lost.run.json")
            && err.contains("controller.path")
            && err.contains("nowhere.rhai"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(dir);
}

/// A lesson file's address part: its name without the number and `.md`.
fn address_part(name: &str) -> &str {
    let name = name.strip_suffix(".md").unwrap_or(name);
    name.split_once('-')
        .filter(|(n, _)| n.chars().all(|c| c.is_ascii_digit()))
        .map_or(name, |(_, rest)| rest)
}

#[test]
fn every_exercise_sits_in_the_lesson_it_names() {
    let dir = folder("lessons");
    let (_, out, _) = kinolab(&["script", "exercises"], &dir);
    let exercises: Vec<Value> = serde_json::from_str(&out).unwrap();
    let _ = std::fs::remove_dir_all(dir);
    let lessons = kinolab_fuzz::seeds::workspace().join("lessons");
    let mut found = std::collections::BTreeMap::new();
    for unit in std::fs::read_dir(&lessons).unwrap().flatten() {
        let Ok(files) = std::fs::read_dir(unit.path()) else {
            continue;
        };
        let unit_name = unit.file_name().to_string_lossy().into_owned();
        for file in files.flatten() {
            let name = file.file_name().to_string_lossy().into_owned();
            let text = std::fs::read_to_string(file.path()).unwrap();
            let address = format!("{}/{}", address_part(&unit_name), address_part(&name));
            for block in text.split("```exercise\n").skip(1) {
                let id = block.lines().next().unwrap().trim().to_owned();
                assert!(
                    found.insert(id.clone(), address.clone()).is_none(),
                    "{id} twice"
                );
            }
        }
    }
    assert_eq!(found.len(), exercises.len(), "{found:?}");
    for e in &exercises {
        let id = e["id"].as_str().unwrap();
        assert_eq!(
            found.get(id),
            Some(&e["lesson"].as_str().unwrap().to_owned()),
            "{id}"
        );
    }
}
