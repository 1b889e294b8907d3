//! Install what the build needs, once: later runs find it and skip.

use std::path::{Path, PathBuf};
use std::process::Command;

/// Which optional pieces a task needs.
#[derive(Debug, Clone, Copy)]
pub struct Needs {
    /// Chromium and ChromeDriver, for browser tests and benchmarks.
    pub browser: bool,
}

pub type Result<T = ()> = std::result::Result<T, String>;

/// The workspace root (the folder above `crates/`).
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .unwrap_or_else(|_| PathBuf::from("."))
}

/// Run a command in the workspace root, echoing it; fail on a non-zero exit.
pub fn run(cmd: &mut Command) -> Result {
    eprintln!("$ {}", describe(cmd));
    let status = cmd
        .current_dir(root())
        .status()
        .map_err(|e| format!("cannot start {}: {e}", describe(cmd)))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("`{}` failed ({status})", describe(cmd)))
    }
}

fn describe(cmd: &Command) -> String {
    std::iter::once(cmd.get_program().to_string_lossy().into_owned())
        .chain(cmd.get_args().map(|a| a.to_string_lossy().into_owned()))
        .collect::<Vec<_>>()
        .join(" ")
}

/// A command's stdout, or `None` if it cannot run or fails.
pub fn output(program: &str, args: &[&str]) -> Option<String> {
    let out = Command::new(program)
        .args(args)
        .current_dir(root())
        .output()
        .ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).into_owned())
}

/// PATH with the npm tools (wasm-opt) and cargo's bin folder in front.
pub fn path_env() -> String {
    let mut parts = vec![root().join("web/node_modules/.bin").display().to_string()];
    if let Ok(home) = std::env::var("CARGO_HOME") {
        parts.push(format!("{home}/bin"));
    } else if let Ok(home) = std::env::var("HOME") {
        parts.push(format!("{home}/.cargo/bin"));
    }
    parts.push(std::env::var("PATH").unwrap_or_default());
    parts.join(":")
}

/// The wasm-bindgen version pinned in Cargo.lock.
pub fn locked_wasm_bindgen() -> Result<String> {
    let lock = std::fs::read_to_string(root().join("Cargo.lock"))
        .map_err(|e| format!("Cargo.lock: {e}"))?;
    let mut lines = lock.lines();
    while let Some(line) = lines.next() {
        if line == "name = \"wasm-bindgen\""
            && let Some(version) = lines.next().and_then(|l| l.strip_prefix("version = \""))
        {
            return Ok(version.trim_end_matches('"').to_owned());
        }
    }
    Err("Cargo.lock has no wasm-bindgen entry".into())
}

fn has_version(program: &str, wanted: &str) -> bool {
    output(program, &["--version"]).is_some_and(|v| v.contains(wanted))
}

/// Install whatever is missing.
pub fn ensure(needs: Needs) -> Result {
    let installed = output("rustup", &["target", "list", "--installed"]).unwrap_or_default();
    if !installed
        .lines()
        .any(|l| l.trim() == "wasm32-unknown-unknown")
    {
        run(Command::new("rustup").args(["target", "add", "wasm32-unknown-unknown"]))?;
    }
    if !has_version("trunk", "trunk 0.21.") {
        run(Command::new("cargo").args(["install", "trunk", "--version", "0.21.14", "--locked"]))?;
    }
    let bindgen = locked_wasm_bindgen()?;
    if !has_version("wasm-bindgen", &format!("wasm-bindgen {bindgen}")) {
        // Not --locked: the registry snapshot lags the CLI's own lock file.
        run(Command::new("cargo").args(["install", "wasm-bindgen-cli", "--version", &bindgen]))?;
    }
    if output("wasm-pack", &["--version"]).is_none() {
        run(Command::new("cargo").args(["install", "wasm-pack"]))?;
    }
    let wasm_opt = root().join("web/node_modules/.bin/wasm-opt");
    let driver = root().join("web/node_modules/playwright-core/package.json");
    if !wasm_opt.exists() || !driver.exists() {
        run(Command::new("npm").args(["ci", "--prefix", "web", "--no-audit", "--no-fund"]))?;
    }
    if needs.browser
        && (output("chromium", &["--version"]).is_none()
            || output("chromedriver", &["--version"]).is_none())
    {
        if output("apt-get", &["--version"]).is_some() {
            run(Command::new("apt-get").arg("update"))?;
            run(Command::new("apt-get")
                .args(["install", "-y", "chromium", "chromium-driver"])
                .env("DEBIAN_FRONTEND", "noninteractive"))?;
        } else {
            return Err("Chromium and ChromeDriver are needed for the browser tests: install them with your package manager".into());
        }
    }
    Ok(())
}
