//! The tasks themselves.

use std::process::Command;

use crate::setup::{Needs, Result, ensure, path_env, run};

fn cargo(args: &[&str]) -> Command {
    let mut cmd = Command::new("cargo");
    cmd.args(args).env("PATH", path_env());
    cmd
}

fn tool(program: &str, args: &[&str]) -> Command {
    let mut cmd = Command::new(program);
    cmd.args(args).env("PATH", path_env());
    cmd
}

/// Build the JavaScript package (crates/js) into web/pkg.
fn js_package(release: bool) -> Result {
    let profile = if release { "--release" } else { "--dev" };
    run(&mut tool(
        "wasm-pack",
        &[
            "build",
            "crates/hosts/js",
            "--target",
            "web",
            profile,
            "--mode",
            "no-install",
            "--out-dir",
            "../../../web/pkg",
            "--out-name",
            "kinolab_js",
        ],
    ))?;
    if release {
        let wasm = "web/pkg/kinolab_js_bg.wasm";
        run(&mut tool(
            "wasm-opt",
            &[
                "-O2",
                "--enable-bulk-memory",
                "--enable-nontrapping-float-to-int",
                "--enable-sign-ext",
                "--enable-mutable-globals",
                "--enable-simd",
                wasm,
                "-o",
                wasm,
            ],
        ))?;
    }
    Ok(())
}

/// Build the static site into dist/.
pub fn dist() -> Result {
    ensure(Needs { browser: false })?;
    js_package(true)?;
    run(&mut tool("trunk", &["build", "--release", "--offline"]))?;
    // Brotli and gzip copies beside each file, for hosts that serve them.
    run(&mut tool("node", &["web/precompress.mjs", "dist"]))
}

/// Build and serve the lab on http://127.0.0.1:8080.
pub fn serve(args: &[String]) -> Result {
    ensure(Needs { browser: false })?;
    let release = !args.iter().any(|a| a == "--dev");
    js_package(release)?;
    eprintln!("\nKinolab will be served at http://127.0.0.1:8080 (Ctrl+C stops it)\n");
    let mut trunk_args = vec!["serve", "--offline"];
    if release {
        trunk_args.push("--release");
    }
    run(&mut tool("trunk", &trunk_args))
}

/// Everything that proves the lab works: what CI runs.
pub fn test() -> Result {
    let started = std::time::Instant::now();
    ensure(Needs { browser: true })?;
    run(&mut cargo(&["fmt", "--all", "--", "--check"]))?;
    run(&mut cargo(&[
        "clippy",
        "--workspace",
        "--all-targets",
        "--",
        "-D",
        "warnings",
    ]))?;
    // One package at a time, as each is built: the lab reads its course
    // prepared (no Markdown), the JS package reads Markdown.
    for package in ["kinolab-app", "kinolab-js"] {
        run(&mut cargo(&[
            "clippy",
            "-p",
            package,
            "--target",
            "wasm32-unknown-unknown",
            "--",
            "-D",
            "warnings",
        ]))?;
    }
    native_tests(None)?;
    run(cargo(&[
        "test",
        "-p",
        "kinolab-js",
        "--target",
        "wasm32-unknown-unknown",
    ])
    .env("CHROMEDRIVER", chromedriver()))?;
    // The end-to-end test checks behaviour, not size: a quick optimised
    // build without link-time optimisation or wasm-opt. `cargo xtask dist`
    // and `cargo xtask bench` make (and measure) the release build.
    js_package(false)?;
    run(&mut tool(
        "trunk",
        &[
            "build",
            "--offline",
            "--cargo-profile",
            "e2e",
            "--dist",
            E2E_SITE,
        ],
    ))?;
    run(&mut tool(
        "node",
        &["tests/e2e/lab.mjs", E2E_SITE, "target/e2e"],
    ))?;
    eprintln!(
        "\nAll checks passed in {:.0} s.",
        started.elapsed().as_secs_f64()
    );
    Ok(())
}

/// Where the end-to-end test's site is built.
const E2E_SITE: &str = "target/e2e-site";

/// Native tests of `crates` (every crate when `None`). The app's shell is
/// tested without its window stack, which only eframe needs.
fn native_tests(crates: Option<&[String]>) -> Result {
    let mut args: Vec<&str> = vec!["test"];
    match crates {
        None => args.extend(["--workspace", "--exclude", "kinolab-app"]),
        Some(list) => {
            for name in list.iter().filter(|c| *c != "kinolab-app") {
                args.extend(["-p", name]);
            }
        }
    }
    if args.len() > 1 {
        run(&mut cargo(&args))?;
    }
    if crates.is_none_or(|list| list.iter().any(|c| c == "kinolab-app")) {
        run(&mut cargo(&[
            "test",
            "-p",
            "kinolab-app",
            "--no-default-features",
        ]))?;
    }
    Ok(())
}

/// A quick check of a change: formatting, then clippy and the native tests
/// of the crates it touches and the crates that depend on them.
pub fn check() -> Result {
    let started = std::time::Instant::now();
    run(&mut cargo(&["fmt", "--all", "--", "--check"]))?;
    let crates = crate::changes::touched_crates()?;
    if crates.is_empty() {
        eprintln!("No crate changed since the last commit: formatting checked.");
        return Ok(());
    }
    eprintln!("Checking {}", crates.join(", "));
    let mut selection: Vec<&str> = Vec::new();
    for name in &crates {
        selection.extend(["-p", name]);
    }
    let mut clippy = vec!["clippy"];
    clippy.extend(&selection);
    clippy.extend(["--all-targets", "--", "-D", "warnings"]);
    run(&mut cargo(&clippy))?;
    native_tests(Some(&crates))?;
    eprintln!("\nChecked in {:.0} s.", started.elapsed().as_secs_f64());
    Ok(())
}

fn chromedriver() -> String {
    std::env::var("CHROMEDRIVER").unwrap_or_else(|_| "/usr/bin/chromedriver".to_owned())
}

/// Benchmarks: criterion natively, the same kernels as wasm in headless
/// Chromium, then size and start-up figures.
pub fn bench(args: &[String]) -> Result {
    if args.iter().any(|a| a == "--anchors") {
        return crate::anchors::anchors();
    }
    ensure(Needs { browser: true })?;
    if args.iter().any(|a| a == "--smooth") {
        dist()?;
        return smooth();
    }
    let quick = args.iter().any(|a| a == "--quick");
    let mut criterion = cargo(&[
        "bench",
        "-p",
        "kinolab-bench",
        "--features",
        "compare-k",
        "--bench",
        "kernels",
        "--",
    ]);
    if quick {
        criterion.args(["--warm-up-time", "0.5", "--measurement-time", "1"]);
    }
    run(&mut criterion)?;
    run(&mut cargo(&[
        "build",
        "-p",
        "kinolab-bench",
        "--lib",
        "--target",
        "wasm32-unknown-unknown",
        "--profile",
        "bench",
    ]))?;
    run(&mut tool(
        "wasm-bindgen",
        &[
            "--target",
            "web",
            "--out-dir",
            "target/bench-web",
            // Cargo keeps the bench profile's artifacts in the release folder.
            "target/wasm32-unknown-unknown/release/kinolab_bench.wasm",
        ],
    ))?;
    // The release build, fresh: its size is part of the report.
    dist()?;
    run(&mut tool(
        "node",
        &[
            "tests/e2e/bench.mjs",
            "target/criterion",
            "target/bench-web",
        ],
    ))?;
    smooth()
}

/// The release lab on a CPU slowed four times: every widget's frames at
/// two sizes, lessons at rest, the heap, the first frame and the size.
fn smooth() -> Result {
    run(&mut tool(
        "node",
        &["tests/e2e/smooth.mjs", "dist", "target/smooth-report.md"],
    ))
}

/// The long reliability run: the release `kinolab` binary on the
/// regression folder and `--cases N` generated cases (100 000 unless
/// given), with the table of counts per command and class. Failing cases
/// are saved into `tests/fuzz/regressions/` so CI replays them forever.
/// Then every widget fed as many generated and damaged links, each taken
/// and drawn within 50 ms.
pub fn fuzz(args: &[String]) -> Result {
    run(&mut cargo(&[
        "build",
        "--release",
        "-p",
        "kinolab-cli",
        "-p",
        "kinolab-fuzz",
        "-p",
        "kinolab-widget-fuzz",
    ]))?;
    let root = crate::setup::root();
    let release = root.join("target/release");
    let mut cmd = tool(
        &release.join("kinolab-fuzz").to_string_lossy(),
        &[
            "--binary",
            &release.join("kinolab").to_string_lossy(),
            "--save",
            &root.join("tests/fuzz/regressions").to_string_lossy(),
        ],
    );
    cmd.args(args);
    if !args.iter().any(|a| a == "--cases") {
        cmd.args(["--cases", "100000"]);
    }
    run(&mut cmd)?;
    let passed: Vec<&str> = args.iter().map(String::as_str).collect();
    let mut widgets = tool(
        &release.join("kinolab-widget-fuzz").to_string_lossy(),
        &passed,
    );
    if !args.iter().any(|a| a == "--cases") {
        widgets.args(["--cases", "100000"]);
    }
    run(&mut widgets)
}
