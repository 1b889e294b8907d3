//! `cargo xtask bench --anchors`: the mechanism kernels beside Pinocchio,
//! the reference rigid-body library, on the same arms (a 6-joint Puma and
//! a 7-joint Panda, with their masses), in the same run: kinematics and the
//! dynamics (RNEA, gravity, CRBA, ABA).
//!
//! Pinocchio comes from its PyPI wheel (`pin`, which ships the C++ headers
//! and libraries) installed in a virtual environment under `target/`, and
//! Eigen's headers from Debian's `libeigen3-dev`. When either cannot be
//! had, the comparison says so and times our kernels alone. Runs alternate
//! (ours, then Pinocchio, three pairs) so that the machine's drift falls on
//! both sides alike; each pair gives a ratio.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

use crate::setup::{Result, output, path_env, root, run};

/// The arm, our kernel, and the Pinocchio call it is measured against
/// (its `time` key in the anchor's output, and its name).
const PAIRS: [(&str, &str, &str, &str); 12] = [
    (
        "puma",
        "mech_fk_puma_tool",
        "fk",
        "forwardKinematics + updateFramePlacement",
    ),
    (
        "puma",
        "mech_jacobian_puma",
        "jacobian",
        "computeJointJacobian",
    ),
    (
        "puma",
        "mech_jacobian_puma",
        "jacobian_frame",
        "computeFrameJacobian (LOCAL_WORLD_ALIGNED)",
    ),
    ("puma", "mech_rnea_puma", "rnea", "rnea"),
    (
        "puma",
        "mech_gravity_puma",
        "gravity",
        "computeGeneralizedGravity",
    ),
    ("puma", "mech_crba_puma", "crba", "crba"),
    ("puma", "mech_aba_puma", "aba", "aba"),
    (
        "panda",
        "mech_fk_panda_dh_flange",
        "fk",
        "forwardKinematics + updateFramePlacement",
    ),
    ("panda", "mech_rnea_panda", "rnea", "rnea"),
    (
        "panda",
        "mech_gravity_panda",
        "gravity",
        "computeGeneralizedGravity",
    ),
    ("panda", "mech_crba_panda", "crba", "crba"),
    ("panda", "mech_aba_panda", "aba", "aba"),
];

/// The arms the anchor is run on.
const ARMS: [&str; 2] = ["puma", "panda"];

const ROUNDS: usize = 3;
const PIN_VERSION: &str = "4.1.0";

pub fn anchors() -> Result {
    let dir = root().join("target/anchor");
    fs::create_dir_all(&dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let anchor = match build_anchor(&dir) {
        Ok(path) => Some(path),
        Err(why) => {
            eprintln!(
                "\nThe Pinocchio anchor is not available: {why}\nTiming Kinolab's kernels alone.\n"
            );
            None
        }
    };
    let mut described = Vec::new();
    for arm in ARMS {
        let description = output(
            "cargo",
            &[
                "run",
                "-q",
                "--release",
                "-p",
                "kinolab-bench",
                "--example",
                "arm_model",
                "--",
                arm,
            ],
        )
        .ok_or(format!(
            "cannot describe the {arm} (cargo run --example arm_model failed)"
        ))?;
        let model = dir.join(format!("{arm}.txt"));
        fs::write(&model, &description)
            .map_err(|e| format!("cannot write {}: {e}", model.display()))?;
        described.push((arm, model, description));
    }
    let mut rows = Vec::new();
    for round in 1..=ROUNDS {
        let ours = criterion_round()?;
        for (arm, model, description) in &described {
            let theirs = match &anchor {
                Some(exe) => anchor_round(exe, model, description)?,
                None => Vec::new(),
            };
            for (which, kernel, call, name) in PAIRS.iter().filter(|p| p.0 == *arm) {
                let mine = ours.iter().find(|(k, _)| k == kernel).map(|(_, t)| *t);
                let pin = theirs.iter().find(|(k, _)| k == call).map(|(_, t)| *t);
                rows.push((round, *which, *kernel, *name, mine, pin));
            }
        }
    }
    let report = table(&rows);
    eprintln!("\n{report}\n");
    let path = root().join("target/anchor-report.md");
    fs::write(&path, &report).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// Pinocchio's headers, library and Eigen, or why not; then the anchor,
/// compiled unless it is newer than its source.
fn build_anchor(dir: &Path) -> Result<PathBuf> {
    let eigen = Path::new("/usr/include/eigen3");
    if !eigen.exists() {
        // Debian's package, when this user may install it.
        let _ = Command::new("apt-get")
            .args(["install", "-y", "-q", "libeigen3-dev"])
            .status();
    }
    if !eigen.exists() {
        return Err("Eigen's headers are missing (Debian package libeigen3-dev)".into());
    }
    let venv = dir.join("venv");
    let prefix = cmeel_prefix(&venv);
    if !prefix.join("include/pinocchio").exists() {
        let python = std::env::var("PYTHON").unwrap_or_else(|_| "python3".into());
        run(Command::new(&python).args(["-m", "venv"]).arg(&venv))?;
        run(Command::new(venv.join("bin/pip")).args([
            "install",
            "-q",
            &format!("pin=={PIN_VERSION}"),
        ]))
        .map_err(|e| format!("cannot install the `pin` wheel from PyPI: {e}"))?;
    }
    let prefix = cmeel_prefix(&venv);
    let source = root().join("crates/tools/bench/anchor/pinocchio_arm.cpp");
    let exe = dir.join("pinocchio_arm");
    if is_newer(&exe, &source) {
        return Ok(exe);
    }
    eprintln!("compiling the Pinocchio anchor (about a minute)");
    let include = prefix.join("include");
    let lib = prefix.join("lib");
    run(Command::new("g++")
        .args(["-std=c++17", "-O3", "-DNDEBUG"])
        // The limits Pinocchio's own CMake configuration sets.
        .args([
            "-DBOOST_MPL_LIMIT_LIST_SIZE=30",
            "-DBOOST_MPL_LIMIT_VECTOR_SIZE=30",
            "-DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS",
            "-DBOOST_FUSION_INVOKE_MAX_ARITY=12",
        ])
        .arg(format!("-I{}", include.display()))
        .arg(format!("-I{}", eigen.display()))
        .arg(&source)
        .arg("-o")
        .arg(&exe)
        .arg(format!("-L{}", lib.display()))
        .arg("-lpinocchio_default")
        .arg(format!("-Wl,-rpath,{}", lib.display())))
    .map_err(|e| format!("cannot compile the anchor: {e}"))?;
    Ok(exe)
}

/// Where the `pin` wheel (a cmeel package) puts its C++ files.
fn cmeel_prefix(venv: &Path) -> PathBuf {
    let lib = venv.join("lib");
    let python = fs::read_dir(&lib)
        .ok()
        .and_then(|mut entries| {
            entries.find_map(|e| {
                let name = e.ok()?.file_name().to_string_lossy().into_owned();
                name.starts_with("python").then_some(name)
            })
        })
        .unwrap_or_else(|| "python3".into());
    lib.join(python).join("site-packages/cmeel.prefix")
}

fn is_newer(a: &Path, than: &Path) -> bool {
    let modified = |p: &Path| fs::metadata(p).and_then(|m| m.modified()).ok();
    matches!((modified(a), modified(than)), (Some(a), Some(b)) if a >= b)
}

/// One criterion run of our kernels; their medians in ns.
fn criterion_round() -> Result<Vec<(String, f64)>> {
    let mut kernels: Vec<&str> = PAIRS.iter().map(|p| p.1).collect();
    kernels.dedup();
    let filter = format!("^({})$", kernels.join("|"));
    run(Command::new("cargo")
        .env("PATH", path_env())
        .args([
            "bench",
            "-q",
            "-p",
            "kinolab-bench",
            "--bench",
            "kernels",
            "--",
        ])
        .args(["--warm-up-time", "1", "--measurement-time", "3"])
        .arg(&filter))?;
    let mut out = Vec::new();
    for kernel in kernels {
        let path = root().join(format!("target/criterion/{kernel}/new/estimates.json"));
        let text = fs::read_to_string(&path)
            .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        let median = median_of(&text).ok_or(format!("no median in {}", path.display()))?;
        out.push((kernel.to_string(), median));
    }
    Ok(out)
}

/// criterion's `"median": {…, "point_estimate": X, …}`.
fn median_of(estimates: &str) -> Option<f64> {
    let after = &estimates[estimates.find("\"median\"")?..];
    let value = &after[after.find("\"point_estimate\":")? + "\"point_estimate\":".len()..];
    let end = value.find([',', '}'])?;
    value[..end].trim().parse().ok()
}

/// One run of the anchor; checks it computed what we compute, returns its
/// medians in ns.
fn anchor_round(exe: &Path, model: &Path, description: &str) -> Result<Vec<(String, f64)>> {
    let out = Command::new(exe)
        .arg(model)
        .output()
        .map_err(|e| format!("cannot run {}: {e}", exe.display()))?;
    let text = String::from_utf8_lossy(&out.stdout);
    for check in ["tool", "jacobian_norm", "tau", "mass_diagonal", "forward"] {
        let ours = field(description, &format!("# ours {check}"));
        let theirs = field(&text, &format!("check {check}"));
        let same = match (ours, theirs) {
            (Some(a), Some(b)) if a.len() == b.len() => {
                let scale = b.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
                a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-9 * scale)
            }
            _ => false,
        };
        if !same {
            return Err(format!("the anchor's {check} differs from ours:\n{text}"));
        }
    }
    Ok(text
        .lines()
        .filter_map(|l| {
            let mut parts = l.strip_prefix("time ")?.split_whitespace();
            Some((parts.next()?.to_string(), parts.next()?.parse().ok()?))
        })
        .collect())
}

fn field(text: &str, prefix: &str) -> Option<Vec<f64>> {
    let line = text.lines().find_map(|l| l.strip_prefix(prefix))?;
    line.split_whitespace().map(|v| v.parse().ok()).collect()
}

type Row<'a> = (usize, &'a str, &'a str, &'a str, Option<f64>, Option<f64>);

fn table(rows: &[Row<'_>]) -> String {
    let ns = |t: Option<f64>| t.map_or("—".to_string(), |t| format!("{t:.1} ns"));
    let mut lines = vec![
        "| pair | arm | Kinolab kernel | Kinolab | Pinocchio 4.1 call | Pinocchio | ratio |"
            .to_string(),
        "|---:|---|---|---:|---|---:|---:|".to_string(),
    ];
    for &(round, arm, kernel, call, mine, pin) in rows {
        let ratio = match (mine, pin) {
            (Some(a), Some(b)) if b > 0.0 => format!("{:.2}×", a / b),
            _ => "—".to_string(),
        };
        lines.push(format!(
            "| {round} | {arm} | {kernel} | {} | {call} | {} | {ratio} |",
            ns(mine),
            ns(pin)
        ));
    }
    lines.push(String::new());
    for (arm, kernel, _, call) in PAIRS {
        let mut ratios: Vec<f64> = rows
            .iter()
            .filter(|r| r.1 == arm && r.2 == kernel && r.3 == call)
            .filter_map(|r| Some(r.4? / r.5?))
            .collect();
        ratios.sort_by(f64::total_cmp);
        if let Some(mid) = ratios.get(ratios.len() / 2) {
            lines.push(format!(
                "- {arm}, {kernel} / {call}: median {mid:.2}× over {} pairs ({:.2}–{:.2}×)",
                ratios.len(),
                ratios[0],
                ratios[ratios.len() - 1]
            ));
        }
    }
    lines.join("\n")
}
