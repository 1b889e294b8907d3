//! Kinolab's task runner, called through `cargo xtask <task>`.
//!
//! - `serve [--dev]`: install what is missing, build, serve the lab on
//!   http://127.0.0.1:8080.
//! - `test`: install what is missing (Chromium too), then formatting,
//!   clippy, native tests, wasm tests in headless Chromium, and the
//!   end-to-end browser test. This is what CI runs.
//! - `check`: a quick check of a change: formatting, then clippy and the
//!   native tests of the crates it touches and their dependents.
//! - `dist`: build the static site into `dist/`.
//! - `bench`: native (criterion) and wasm (headless Chromium) benchmarks
//!   side by side, wasm size, and time to first frame; `bench --anchors`
//!   the mechanism kernels beside Pinocchio, pair by pair.
//! - `fuzz [--cases N] [--seed S]`: the long reliability run of the
//!   `kinolab` command (100 000 generated cases by default), its table of
//!   counts per command and class; failing cases join the regression folder.
//!
//! Every tool is installed from a package registry by name; nothing
//! downloads binaries at run time (trunk runs with `--offline`).

mod anchors;
mod changes;
mod setup;
mod tasks;
mod versions;

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let task = args.first().map(String::as_str).unwrap_or("help");
    let rest = &args[args.len().min(1)..];
    let result = match task {
        "serve" => tasks::serve(rest),
        "test" => tasks::test(),
        "check" => tasks::check(),
        "dist" => tasks::dist(),
        "bench" => tasks::bench(rest),
        "fuzz" => tasks::fuzz(rest),
        "setup" => setup::ensure(setup::Needs { browser: true }),
        _ => {
            eprintln!(
                "usage: cargo xtask <serve [--dev] | test | check | dist | bench [--quick | --anchors] | fuzz [--cases N] | setup>"
            );
            return ExitCode::from(2);
        }
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("xtask {task}: {e}");
            ExitCode::FAILURE
        }
    }
}
