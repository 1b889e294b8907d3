//! `kinolab-fuzz`: the long reliability run (`cargo xtask fuzz` calls it).
//!
//! ```text
//! kinolab-fuzz --binary target/release/kinolab [--cases 100000] [--seed 1]
//!              [--workers 2] [--save tests/fuzz/regressions] [--time 10]
//!              [--show-refusals]
//! ```
//! Runs the regression folder, then the generated cases, prints the table
//! of counts per command and class, and exits non-zero when any case broke
//! the contract.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};

use kinolab_fuzz::campaign::{self, Plan};
use kinolab_fuzz::run::Limits;

fn value<T: std::str::FromStr>(args: &[String], name: &str, default: T) -> Result<T, String> {
    match args.iter().position(|a| a == name) {
        None => Ok(default),
        Some(i) => args
            .get(i + 1)
            .and_then(|v| v.parse().ok())
            .ok_or_else(|| format!("{name} needs a value")),
    }
}

fn plan(args: &[String]) -> Result<Plan, String> {
    let binary: String = value(args, "--binary", String::new())?;
    if binary.is_empty() {
        return Err("--binary PATH is required".into());
    }
    let save: String = value(args, "--save", String::new())?;
    let binary = std::fs::canonicalize(&binary).map_err(|e| format!("{binary}: {e}"))?;
    Ok(Plan {
        binary,
        cases: value(args, "--cases", 100_000)?,
        seed: value(args, "--seed", 1)?,
        workers: value(args, "--workers", 2)?,
        limits: Limits {
            time: Duration::from_secs_f64(value(args, "--time", 10.0)?),
            ..Limits::default()
        },
        save: (!save.is_empty()).then(|| PathBuf::from(save)),
        progress: true,
    })
}

#[allow(clippy::print_stdout)]
fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let plan = match plan(&args) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("kinolab-fuzz: {e}");
            return ExitCode::from(2);
        }
    };
    let folder = kinolab_fuzz::seeds::workspace().join("tests/fuzz/regressions");
    let regressions = match kinolab_fuzz::case::load_folder(&folder) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("kinolab-fuzz: {e}");
            return ExitCode::from(2);
        }
    };
    let started = Instant::now();
    let report = campaign::run(&plan, &regressions);
    println!(
        "{} cases ({} from the regression folder, {} generated, seed {}) in {:.0} s\n",
        report.tally.total(),
        regressions.len(),
        plan.cases,
        plan.seed,
        started.elapsed().as_secs_f64()
    );
    println!("{}", report.tally.table());
    if args.iter().any(|a| a == "--show-refusals") {
        for (command, lines) in &report.refusals {
            for line in lines {
                println!("{command}: {line}");
            }
        }
    }
    for f in report.failures.iter().take(30) {
        let args: Vec<String> = f
            .case
            .args
            .iter()
            .map(|a| a.chars().take(80).collect())
            .collect();
        println!("FAIL {} {:?}: {}", f.case.command, args, f.why);
    }
    if report.failures.is_empty() {
        ExitCode::SUCCESS
    } else {
        println!("{} cases broke the contract", report.failures.len());
        ExitCode::FAILURE
    }
}
