//! Many cases on a few workers: the regression folder, then generated
//! cases, tallied; every failure reported (and optionally kept).

use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicU64, Ordering};

use crate::case::{self, Case};
use crate::contract::{self, Verdict};
use crate::run::{self, Limits};
use crate::seeds::Seeds;
use crate::tally::Tally;

/// What a campaign runs.
#[derive(Debug, Clone)]
pub struct Plan {
    pub binary: PathBuf,
    /// Generated cases (after the regression folder's).
    pub cases: u64,
    pub seed: u64,
    pub workers: usize,
    pub limits: Limits,
    /// Where failing generated cases are saved, if anywhere.
    pub save: Option<PathBuf>,
    /// Say on stderr how far the campaign has come, every 10 000 cases.
    pub progress: bool,
}

/// A case that broke the contract (or a regression's own expectation).
#[derive(Debug, Clone)]
pub struct Failure {
    pub case: Case,
    pub why: String,
}

/// The tally and the failures.
#[derive(Debug, Default)]
pub struct Report {
    pub tally: Tally,
    pub failures: Vec<Failure>,
    /// The first few refusal lines of each command, to read.
    pub refusals: std::collections::BTreeMap<String, Vec<String>>,
}

/// Run every case of `regressions`, then `plan.cases` generated ones.
pub fn run(plan: &Plan, regressions: &[(PathBuf, Case)]) -> Report {
    let seeds = Seeds::load();
    let fixed: Vec<Case> = regressions.iter().map(|(_, c)| c.clone()).collect();
    let next = AtomicU64::new(0);
    let total = fixed.len() as u64 + plan.cases;
    let report = Mutex::new(Report::default());
    std::thread::scope(|scope| {
        for _ in 0..plan.workers.max(1) {
            let (next, report, fixed, seeds) = (&next, &report, &fixed, &seeds);
            scope.spawn(move || {
                let folder = run::scratch();
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    if i >= total {
                        break;
                    }
                    if plan.progress && i > 0 && i % 10_000 == 0 {
                        eprintln!("kinolab-fuzz: {i} of {total} cases");
                    }
                    let (case, regression) = match fixed.get(i as usize) {
                        Some(c) => (c.clone(), true),
                        None => (crate::generate::case(seeds, plan.seed, i), false),
                    };
                    let (verdict, elapsed, why, line) =
                        one(&plan.binary, &case, &folder, &plan.limits);
                    let mut r = report.lock().unwrap_or_else(|e| e.into_inner());
                    r.tally.add(&case.command, &verdict, elapsed);
                    if verdict == Verdict::Refused {
                        let seen = r.refusals.entry(case.command.clone()).or_default();
                        if seen.len() < 8 {
                            seen.push(line);
                        }
                    }
                    if let Some(why) = why {
                        if !regression && let Some(dir) = &plan.save {
                            let _ = case::save(dir, &case);
                        }
                        r.failures.push(Failure { case, why });
                    }
                }
            });
        }
    });
    report.into_inner().unwrap_or_else(|e| e.into_inner())
}

/// One case: its verdict, time, what went wrong if anything did, and the
/// error line.
fn one(
    binary: &Path,
    case: &Case,
    folder: &Path,
    limits: &Limits,
) -> (Verdict, std::time::Duration, Option<String>, String) {
    match run::run(binary, case, folder, limits) {
        Err(e) => (
            Verdict::Crash(format!("could not run: {e}")),
            std::time::Duration::ZERO,
            Some(format!("could not run: {e}")),
            String::new(),
        ),
        Ok(outcome) => {
            let verdict = contract::judge(case, &outcome);
            let why = if verdict.kept() {
                contract::unmet(case, &outcome)
            } else {
                Some(format!("{verdict:?}"))
            };
            let line = String::from_utf8_lossy(&outcome.stderr)
                .trim_end()
                .to_owned();
            (verdict, outcome.elapsed, why, line)
        }
    }
}
