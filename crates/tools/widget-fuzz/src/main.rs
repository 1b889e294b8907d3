//! `kinolab-widget-fuzz [--cases N] [--seed S]`: the long run over every
//! widget (`cargo xtask fuzz` runs it with 100 000 cases in a release
//! build, with the 50 ms frame limit).

use std::process::ExitCode;

use kinolab_widget_fuzz::{FRAME_LIMIT, campaign, widgets};

// A report for the terminal.
#[allow(clippy::print_stdout)]
fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let option = |name: &str, default: u64| -> Result<u64, String> {
        match args.iter().position(|a| a == name) {
            None => Ok(default),
            Some(i) => args
                .get(i + 1)
                .and_then(|v| v.parse().ok())
                .ok_or_else(|| format!("{name} needs a whole number")),
        }
    };
    let (cases, seed) = match (option("--cases", 100_000), option("--seed", 1)) {
        (Ok(c), Ok(s)) => (c, s),
        (Err(e), _) | (_, Err(e)) => {
            eprintln!("kinolab-widget-fuzz: {e}");
            return ExitCode::from(2);
        }
    };
    // Panics are caught and reported as failures; keep their noise off the terminal.
    std::panic::set_hook(Box::new(|_| {}));
    let tally = campaign(
        seed,
        usize::try_from(cases).unwrap_or(usize::MAX),
        Some(FRAME_LIMIT),
    );
    println!(
        "widget fuzz: {} cases over {} widgets (seed {seed}): {} links taken, {} refused, {} failures; slowest {:.1} ms ({})",
        tally.cases,
        widgets().len(),
        tally.accepted,
        tally.cases - tally.accepted - tally.failures.len(),
        tally.failures.len(),
        tally.slowest.as_secs_f64() * 1e3,
        tally.slowest_widget,
    );
    for f in tally.failures.iter().take(40) {
        let shown: String = f.state.chars().take(120).collect();
        println!(
            "FAIL {} ({:?}): {} — state `{shown}`",
            f.widget, f.damage, f.why
        );
    }
    if tally.failures.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
