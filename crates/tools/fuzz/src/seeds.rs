//! Valid inputs of every kind, the starting points the generators damage:
//! the catalogues' robots, models, fields and worlds, the contract's
//! examples, and the example run files, all written out as files.

use std::path::{Path, PathBuf};

/// Valid files of each format.
#[derive(Debug, Clone, Default)]
pub struct Seeds {
    pub robots: Vec<String>,
    pub models: Vec<String>,
    pub control_runs: Vec<String>,
    pub fields: Vec<String>,
    pub worlds: Vec<String>,
    pub behaviour_runs: Vec<String>,
    pub lessons: Vec<String>,
    pub gaits: Vec<String>,
    pub cpgs: Vec<String>,
    pub systems: Vec<String>,
    pub pushes: Vec<String>,
    pub beaches: Vec<String>,
    /// Learners' scripts: the exercises' model and wrong solutions.
    pub scripts: Vec<String>,
    /// Catalogue ids, for `catalogue:<id>` arguments.
    pub robot_ids: Vec<String>,
    pub model_ids: Vec<String>,
    pub field_ids: Vec<String>,
    pub gait_ids: Vec<String>,
    pub world_ids: Vec<String>,
}

/// The workspace's root (for the example files kept in crates).
pub fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../..")
}

fn files_in(folder: &Path, suffix: &str) -> Vec<String> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(folder)
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    paths.sort();
    paths
        .iter()
        .filter(|p| p.to_string_lossy().ends_with(suffix))
        .filter_map(|p| std::fs::read_to_string(p).ok())
        .collect()
}

impl Seeds {
    /// Every seed the project has.
    pub fn load() -> Self {
        let root = workspace();
        let robot_ids: Vec<String> = kinolab_wheels::catalogue::CATALOGUE
            .iter()
            .map(|e| e.id.to_owned())
            .collect();
        let mut robots: Vec<String> = robot_ids
            .iter()
            .filter_map(|id| kinolab_wheels::catalogue::robot(id).ok())
            .map(|c| c.to_json())
            .collect();
        robots.push(kinolab_wheels::catalogue::EVERY_WHEEL_KIND.to_owned());
        let model_ids: Vec<String> = kinolab_mechanism::catalogue::CATALOGUE
            .iter()
            .map(|(id, _, _)| (*id).to_owned())
            .collect();
        let mut models: Vec<String> = model_ids
            .iter()
            .filter_map(|id| kinolab_mechanism::catalogue::mechanism(id).ok())
            .map(|m| kinolab_mechanism::file::to_json(&m))
            .collect();
        models.push(kinolab_mechanism::file::CONTRACT_EXAMPLE.to_owned());
        let control_runs = vec![
            kinolab_control::file::CONTRACT_EXAMPLE.to_owned(),
            OPEN_LOOP_RUN.to_owned(),
        ];
        let field_ids = kinolab_fields::catalogue::PRESETS
            .iter()
            .map(|p| p.id.to_owned())
            .collect();
        Self {
            robots,
            models,
            control_runs,
            fields: files_in(&root.join("crates/mind/fields/presets"), ".field.json"),
            worlds: kinolab_world::catalogue::WORLDS
                .iter()
                .map(|(_, text)| (*text).to_owned())
                .chain([CONTRACT_WORLD.to_owned()])
                .collect(),
            behaviour_runs: files_in(&root.join("crates/mind/behaviours/runs"), ".run.json"),
            gaits: kinolab_locomotion::named_ids()
                .filter_map(kinolab_locomotion::named)
                .map(|g| gait_json(&g))
                .collect(),
            cpgs: vec![CPG.to_owned(), CPG_LAB.to_owned()],
            pushes: PUSHES.iter().map(|p| (*p).to_owned()).collect(),
            beaches: BEACHES.iter().map(|b| (*b).to_owned()).collect(),
            scripts: files_in(
                &root.join("crates/teach/exercises/tests/solutions"),
                ".rhai",
            ),
            systems: files_in(&root.join("crates/talk/components/systems"), ".system.json"),
            gait_ids: kinolab_locomotion::named_ids().map(str::to_owned).collect(),
            world_ids: kinolab_world::catalogue::WORLDS
                .iter()
                .map(|(id, _)| (*id).to_owned())
                .collect(),
            lessons: files_in(&root.join("lessons/05-behaviours"), ".md")
                .into_iter()
                .filter(|t| t.contains("objectives:"))
                .chain([LESSON.to_owned()])
                .collect(),
            robot_ids,
            model_ids,
            field_ids,
        }
    }
}

/// A gait as a gait file.
fn gait_json(g: &kinolab_locomotion::Gait) -> String {
    let legs: Vec<serde_json::Value> = g
        .legs
        .iter()
        .map(|l| serde_json::json!({ "name": l.name, "x": l.x, "y": l.y, "phase": l.phase }))
        .collect();
    serde_json::json!({
        "name": g.name, "duty_factor": g.duty_factor, "stride": g.stride,
        "com": g.com, "legs": legs,
    })
    .to_string()
}

/// The contract's world example.
const CONTRACT_WORLD: &str = r#"{ "name": "two-rooms", "bounds": [0.0, 0.0, 10.0, 6.0],
  "robot_radius": 0.2, "obstacles": [
    { "kind": "circle", "x": 3.0, "y": 3.0, "radius": 0.5 },
    { "kind": "polygon", "points": [[5, 0], [5.2, 0], [5.2, 4], [5, 4]] },
    { "kind": "wall", "from": [7, 2], "to": [7, 6], "thickness": 0.1 } ] }"#;

/// Push-recovery runs: a push the foot holds, one it does not.
const PUSHES: [&str; 2] = [
    r#"{ "height": 0.8, "heel": -0.05, "toe": 0.15, "push": 0.2 }"#,
    r#"{ "height": 0.9, "heel": -0.1, "toe": 0.2, "x0": 0.02, "push": 0.6, "duration": 2, "dt": 0.01 }"#,
];

/// Ants on beaches.
const BEACHES: [&str; 2] = [
    r#"{ "seed": 3, "pebbles": 400, "size": 12 }"#,
    r#"{ "seed": 11, "size": 1 }"#,
];

/// The contract's CPG example.
const CPG: &str = r#"{ "frequency": 1.0, "legs": ["LF", "RF", "LH", "RH"],
  "target_phases": [0.25, 0.75, 0.0, 0.5], "weight": 2.0,
  "initial_deg": [0, 10, 20, 30], "dt": 0.001, "duration": 10.0 }"#;

/// A run of the lab's CPG widget: Van der Pol oscillators, a weight per
/// pair, kicks and a change of gait on the move.
const CPG_LAB: &str = r#"{ "frequency": 1.0, "legs": ["LF", "RF", "LH", "RH"],
  "target_phases": [0.0, 0.5, 0.5, 0.0], "weight": 1.0,
  "weights": [[0, 1, 1, 1], [1, 0, 1, 1], [1, 1, 0, 1], [1.5, 1, 0.5, 0]],
  "model": "van_der_pol", "initial_deg": [12, 250, 99, 301],
  "dt": 0.001953125, "duration": 3.5,
  "kicks": [ { "at": 1.0, "leg": 0, "by_deg": 90 }, { "at": 1.0, "leg": 3, "by_deg": 200.5 } ],
  "changes": [ { "at": 2.0, "frequency": 1.8, "target_phases": [0.25, 0.75, 0.0, 0.5],
                 "weights": [[0, 2, 2, 2], [2, 0, 2, 2], [2, 2, 0, 2], [2, 2, 2, 0]] } ] }"#;

/// An open-loop run file (a plan instead of a controller).
const OPEN_LOOP_RUN: &str = r#"{
  "robot": "catalogue:differential-drive",
  "controller": { "kind": "open_loop", "segments": [
    { "kind": "line", "length": 1 }, { "kind": "arc", "radius": 0.5, "angle_deg": 90 },
    { "kind": "turn", "angle_deg": -45 } ] },
  "start": { "x": 0, "y": 0, "theta_deg": 0 },
  "dt": 0.001,
  "duration": 8
}"#;

/// A small lesson using most of the format.
const LESSON: &str = "---\ntitle: A small lesson\nminutes: 3\nobjectives:\n  - Read a lesson\n---\n\n# A small lesson\n\n\
Some *text* with **strong** words and $x^2$.\n\n> A quote\n> - with a list\n\n\
| a | b |\n|---|---|\n| 1 | 2 |\n\n```quiz\nkind: single\nquestion: Which?\n\
- [x] This one\n  because it is right\n- [ ] That one\n  because it is wrong\n```\n";
