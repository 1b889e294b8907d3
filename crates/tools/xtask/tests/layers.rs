#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Crates sit in role folders, in layers: no crate uses a crate of a group
//! below its own in `crates/README.md`'s table (development-only use of
//! `tools` is allowed), and the table names every crate where it is.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command;

use serde_json::Value;

fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../../.."))
}

/// The groups in layer order, each with the crates the table lists.
fn layers() -> Vec<(String, Vec<String>)> {
    let text = std::fs::read_to_string(root().join("crates/README.md")).unwrap();
    text.lines()
        .filter_map(|line| {
            let cells: Vec<&str> = line.split('|').map(str::trim).collect();
            let layer: usize = cells.get(1)?.parse().ok()?;
            let group = cells.get(2)?.trim_matches('`').to_owned();
            let crates = cells
                .get(3)?
                .split(',')
                .map(|c| c.trim().to_owned())
                .collect();
            Some((layer, group, crates))
        })
        .enumerate()
        .map(|(i, (layer, group, crates))| {
            assert_eq!(layer, i + 1, "the table's layers must count 1, 2, 3…");
            (group, crates)
        })
        .collect()
}

/// A workspace dependency: its name and kind (`None` for a normal one,
/// `dev`, `build`).
type Dependency = (String, Option<String>);

/// Every workspace crate: its name, its folder under `crates/` and its
/// workspace dependencies.
fn members() -> Vec<(String, String, Vec<Dependency>)> {
    let out = Command::new(env!("CARGO"))
        .args(["metadata", "--format-version", "1", "--no-deps"])
        .current_dir(root())
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let meta: Value = serde_json::from_slice(&out.stdout).unwrap();
    let crates = root().canonicalize().unwrap().join("crates");
    meta["packages"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            let manifest = Path::new(p["manifest_path"].as_str().unwrap());
            let folder = manifest
                .parent()
                .unwrap()
                .strip_prefix(&crates)
                .unwrap()
                .display()
                .to_string();
            let deps = p["dependencies"]
                .as_array()
                .unwrap()
                .iter()
                .filter(|d| d["path"].is_string())
                .map(|d| {
                    let kind = d["kind"].as_str().map(str::to_owned);
                    (d["name"].as_str().unwrap().to_owned(), kind)
                })
                .collect();
            (p["name"].as_str().unwrap().to_owned(), folder, deps)
        })
        .collect()
}

#[test]
fn no_crate_uses_a_group_below_its_own() {
    let layers = layers();
    assert!(layers.len() >= 8, "{layers:?}");
    let members = members();
    let mut layer_of = BTreeMap::new();
    for (name, folder, _) in &members {
        let (group, short) = folder.split_once('/').unwrap_or(("", folder));
        let layer = layers
            .iter()
            .position(|(g, crates)| g == group && crates.iter().any(|c| c == short))
            .unwrap_or_else(|| {
                panic!("`{name}` ({folder}) is not in the table of crates/README.md")
            });
        layer_of.insert(name.clone(), (layer, group.to_owned()));
    }
    for (name, _, deps) in &members {
        let (layer, group) = &layer_of[name];
        for (dep, kind) in deps {
            let (dep_layer, dep_group) = &layer_of[dep];
            let for_tests = kind.as_deref() == Some("dev") && dep_group == "tools";
            assert!(
                dep_layer <= layer || for_tests,
                "`{name}` ({group}) uses `{dep}` ({dep_group}), a group below it"
            );
        }
    }
}

#[test]
fn every_crate_the_table_lists_exists() {
    for (group, crates) in layers() {
        for short in crates {
            let manifest = root()
                .join("crates")
                .join(&group)
                .join(&short)
                .join("Cargo.toml");
            assert!(
                manifest.is_file(),
                "crates/{group}/{short} is in the table but not on disk"
            );
        }
    }
}
