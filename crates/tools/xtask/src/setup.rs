//! Install what the build needs, once: later runs find it and skip.

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::versions;

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
        .join("../../..")
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
    versions::wasm_bindgen(&lock)
}

fn has_version(program: &str, wanted: &str) -> bool {
    output(program, &["--version"]).is_some_and(|v| v.contains(wanted))
}

/// Install whatever is missing, saying what and why.
pub fn ensure(needs: Needs) -> Result {
    let installed = output("rustup", &["target", "list", "--installed"]).unwrap_or_default();
    if !installed
        .lines()
        .any(|l| l.trim() == "wasm32-unknown-unknown")
    {
        run(Command::new("rustup").args(["target", "add", "wasm32-unknown-unknown"]))?;
    }
    cargo_tool("trunk", "trunk", versions::TRUNK, true)?;
    // Not --locked: the registry snapshot lags the CLI's own lock file.
    cargo_tool(
        "wasm-bindgen",
        "wasm-bindgen-cli",
        &locked_wasm_bindgen()?,
        false,
    )?;
    cargo_tool("wasm-pack", "wasm-pack", versions::WASM_PACK, true)?;
    npm_tools()?;
    if needs.browser {
        browser()?;
    }
    Ok(())
}

/// `program` at `version`, installed with cargo when missing or different.
fn cargo_tool(program: &str, krate: &str, version: &str, locked: bool) -> Result {
    if has_version(program, &format!("{program} {version}")) {
        return Ok(());
    }
    eprintln!("Installing {krate} {version} (about 5–10 minutes, once)…");
    let mut cmd = Command::new("cargo");
    cmd.args(["install", krate, "--version", version]);
    if locked {
        cmd.arg("--locked");
    }
    run(&mut cmd)
}

/// wasm-opt (binaryen), the Chromium driver and Zopfli, from the npm
/// registry.
fn npm_tools() -> Result {
    let tools = [
        ("binaryen", versions::BINARYEN),
        ("playwright-core", versions::PLAYWRIGHT_CORE),
        ("@gfx/zopfli", versions::ZOPFLI),
    ];
    let has = |name: &str, version: &str| {
        let manifest = root()
            .join("web/node_modules")
            .join(name)
            .join("package.json");
        std::fs::read_to_string(manifest)
            .is_ok_and(|t| t.contains(&format!("\"version\": \"{version}\"")))
    };
    if tools.iter().all(|(name, version)| has(name, version)) {
        return Ok(());
    }
    let wanted: Vec<String> = tools.iter().map(|(n, v)| format!("{n}@{v}")).collect();
    eprintln!(
        "Installing {} from npm into web/node_modules…",
        wanted.join(", ")
    );
    let mut npm = Command::new("npm");
    npm.args([
        "install",
        "--prefix",
        "web",
        "--no-save",
        "--no-audit",
        "--no-fund",
    ]);
    run(npm.args(&wanted))
}

/// Debian's Chromium and ChromeDriver, when missing (needs apt and root).
fn browser() -> Result {
    if output("chromium", &["--version"]).is_some()
        && output("chromedriver", &["--version"]).is_some()
    {
        return Ok(());
    }
    if output("apt-get", &["--version"]).is_none() {
        return Err("Chromium and ChromeDriver are needed for the browser tests: install them with your package manager".into());
    }
    eprintln!("Installing Debian's chromium and chromium-driver with apt-get (needs root)…");
    run(Command::new("apt-get").arg("update"))?;
    run(Command::new("apt-get")
        .args(["install", "-y", "chromium", "chromium-driver"])
        .env("DEBIAN_FRONTEND", "noninteractive"))
}
