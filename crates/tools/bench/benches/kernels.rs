//! Native timings of every kernel (criterion), and the inverse-kinematics
//! survey: success rate and mean time over 10 000 random reachable targets
//! per arm (written to `target/ik-survey.md` for the report).

use std::time::Instant;

use criterion::Criterion;
use kinolab_bench::KERNELS;
use kinolab_bench::mechanism::{Arm, panda, puma, solve_all, targets};

fn kernels(c: &mut Criterion) {
    for kernel in KERNELS {
        c.bench_function(kernel.name, |b| b.iter(kernel.run));
    }
    #[cfg(feature = "compare-k")]
    for kernel in kinolab_bench::REFERENCE_KERNELS {
        c.bench_function(kernel.name, |b| b.iter(kernel.run));
    }
}

/// One survey line: success and mean time per target.
fn survey(name: &str, arm: &Arm, solve: impl Fn(&[kinolab_mechanism::Pose]) -> usize) -> String {
    let goals = targets(arm, 10_000, 2026);
    let started = Instant::now();
    let ok = solve(&goals);
    let mean = started.elapsed().as_secs_f64() / goals.len() as f64;
    format!(
        "| {name} | {} | {:.2} % | {:.1} µs |",
        goals.len(),
        100.0 * ok as f64 / goals.len() as f64,
        mean * 1e6
    )
}

fn main() {
    let mut lines = vec![
        "| IK survey (from the zero pose unless noted; 1e-6 m / 1e-6 rad) | targets | converged | mean time |"
            .to_string(),
        "|---|---:|---:|---:|".to_string(),
    ];
    if let (Some(puma), Some(panda)) = (puma(), panda()) {
        lines.push(survey("Kinolab, Puma 560", puma, |t| solve_all(puma, t)));
        lines.push(survey("Kinolab, Panda", panda, |t| solve_all(panda, t)));
        #[cfg(feature = "compare-k")]
        if let Some(chain) =
            kinolab_bench::reference::chain_of(&puma.model, &kinolab_mechanism::Pose::identity())
        {
            use kinolab_bench::reference::{K_SEED, solve_all_k};
            lines.push(survey(
                "Kinolab, Puma 560, from k's start pose",
                puma,
                |t| kinolab_bench::mechanism::solve_all_from(puma, t, &K_SEED),
            ));
            lines.push(survey(
                "k 0.32, Puma 560, from the same start (Jacobian solver, 100 steps)",
                puma,
                |t| solve_all_k(&chain, t),
            ));
        }
    }
    let text = lines.join("\n");
    eprintln!("{text}");
    let _ = std::fs::write(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../target/ik-survey.md"),
        text + "\n",
    );
    let mut c = Criterion::default().configure_from_args();
    kernels(&mut c);
    c.final_summary();
}
