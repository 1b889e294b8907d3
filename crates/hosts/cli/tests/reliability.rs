//! The command keeps its contract on any input: every case of the
//! regression folder (`tests/fuzz/regressions`, inputs that once broke it)
//! and a bounded number of generated cases, run against this build's
//! binary. `cargo xtask fuzz` runs the long campaign.

use std::path::PathBuf;
use std::time::Duration;

use kinolab_fuzz::campaign::{self, Plan};
use kinolab_fuzz::run::Limits;

fn plan(cases: u64, seed: u64) -> Plan {
    Plan {
        binary: PathBuf::from(env!("CARGO_BIN_EXE_kinolab")),
        cases,
        seed,
        workers: 2,
        // A debug build is slower than the release one the long run uses.
        limits: Limits {
            time: Duration::from_secs(60),
            ..Limits::default()
        },
        save: None,
        progress: false,
    }
}

fn failures(report: &campaign::Report) -> String {
    report
        .failures
        .iter()
        .take(10)
        .map(|f| format!("{} {:?}: {}\n", f.case.command, f.case.args, f.why))
        .collect()
}

#[test]
fn every_regression_case_keeps_the_contract() {
    let folder = kinolab_fuzz::seeds::workspace().join("tests/fuzz/regressions");
    let regressions = kinolab_fuzz::case::load_folder(&folder).unwrap();
    assert!(regressions.len() >= 30, "{} cases", regressions.len());
    let report = campaign::run(&plan(0, 0), &regressions);
    assert_eq!(report.tally.total(), regressions.len() as u64);
    assert!(report.failures.is_empty(), "{}", failures(&report));
}

#[test]
fn generated_cases_keep_the_contract() {
    let report = campaign::run(&plan(3000, 20_261_201), &[]);
    assert_eq!(report.tally.total(), 3000);
    assert!(report.failures.is_empty(), "{}", failures(&report));
    // The generators reach both sides of the contract.
    let table = report.tally.table();
    assert!(report.tally.count("answer") > 400, "{table}");
    assert!(report.tally.count("refused") > 400, "{table}");
}
