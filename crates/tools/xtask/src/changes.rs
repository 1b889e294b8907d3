//! Which crates a change touches: the crates whose files changed since the
//! last commit (or are new), and every workspace crate that depends on
//! them. Lessons are compiled into `kinolab-lessons`.

use std::collections::BTreeSet;

use crate::setup::{Result, output, root};

/// A workspace crate: its folder (`group/crate`), package name and
/// workspace dependencies.
struct Member {
    folder: String,
    name: String,
    uses: Vec<String>,
}

/// The crate folders, `crates/<group>/<crate>`.
fn crate_folders() -> Result<Vec<(String, std::path::PathBuf)>> {
    let dir = root().join("crates");
    let read =
        |d: &std::path::Path| std::fs::read_dir(d).map_err(|e| format!("{}: {e}", d.display()));
    let mut out = Vec::new();
    for group in read(&dir)?.flatten().filter(|e| e.path().is_dir()) {
        for entry in read(&group.path())?.flatten() {
            let folder = format!(
                "{}/{}",
                group.file_name().to_string_lossy(),
                entry.file_name().to_string_lossy()
            );
            out.push((folder, entry.path()));
        }
    }
    Ok(out)
}

fn members() -> Result<Vec<Member>> {
    let mut out = Vec::new();
    for (folder, path) in crate_folders()? {
        let manifest = path.join("Cargo.toml");
        let Ok(text) = std::fs::read_to_string(&manifest) else {
            continue;
        };
        let name = text
            .lines()
            .find_map(|l| l.strip_prefix("name = \""))
            .map(|n| n.trim_end_matches('"').to_owned())
            .unwrap_or_default();
        let uses = text
            .lines()
            .filter_map(|l| l.split_once(" = ").map(|(k, _)| k.trim()))
            .filter(|k| k.starts_with("kinolab-"))
            .map(str::to_owned)
            .collect();
        out.push(Member { folder, name, uses });
    }
    Ok(out)
}

/// Files changed since the last commit, and new files git does not ignore.
fn changed_files() -> Vec<String> {
    let tracked = output("git", &["diff", "--name-only", "HEAD"]).unwrap_or_default();
    let new = output("git", &["ls-files", "--others", "--exclude-standard"]).unwrap_or_default();
    tracked
        .lines()
        .chain(new.lines())
        .map(str::to_owned)
        .collect()
}

/// The crates to check, by package name, in a stable order.
pub fn touched_crates() -> Result<Vec<String>> {
    let members = members()?;
    let mut touched = BTreeSet::new();
    for file in changed_files() {
        if file == "Cargo.toml" || file == "Cargo.lock" {
            return Ok(members.into_iter().map(|m| m.name).collect());
        }
        let folder = match file.strip_prefix("crates/") {
            Some(rest) => rest.splitn(3, '/').take(2).collect::<Vec<_>>().join("/"),
            None if file.starts_with("lessons/") => "teach/lessons".to_owned(),
            None => continue,
        };
        if let Some(m) = members.iter().find(|m| m.folder == folder) {
            touched.insert(m.name.clone());
        }
    }
    // Add dependents until nothing changes.
    loop {
        let before = touched.len();
        for m in &members {
            if m.uses.iter().any(|u| touched.contains(u)) {
                touched.insert(m.name.clone());
            }
        }
        if touched.len() == before {
            break;
        }
    }
    touched.remove("xtask");
    Ok(touched.into_iter().collect())
}
