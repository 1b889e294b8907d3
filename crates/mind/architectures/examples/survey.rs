//! Every office surprise against every architecture: the scoreboard.
#![allow(clippy::print_stdout)]
use kinolab_architectures::exercise::office;
use kinolab_architectures::{Architecture, Arena};

fn main() -> Result<(), kinolab_architectures::FieldError> {
    let cost: f64 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(2.0);
    for id in [
        None,
        Some("door"),
        Some("person"),
        Some("wrong-map"),
        Some("noise"),
        Some("moved-goal"),
        Some("glass"),
    ] {
        let mut setup = office(id)?;
        setup.planning_cost = cost / 1e3;
        let mut arena = Arena::new(&setup, &Architecture::ALL)?;
        let t = std::time::Instant::now();
        while !arena.done() {
            arena.step();
        }
        println!(
            "{:?} ({:.0} ms)",
            id.unwrap_or("none"),
            t.elapsed().as_secs_f64() * 1e3
        );
        for e in &arena.entrants {
            let s = &e.scores;
            println!(
                "  {:>12}: reached {} t {:?} len {:.1} clear {:.2} coll {} replans {} age {:.2?}/{:.2?} exp/plan {:.0} eval/cyc {:.1}  [{}]",
                e.architecture.name(),
                s.reached,
                s.time.map(|t| (t * 10.0).round() / 10.0),
                s.path_length,
                s.min_clearance,
                s.collisions,
                s.replans,
                s.model_age_mean,
                s.model_age_max,
                s.expanded_per_plan,
                s.evaluations_per_cycle,
                e.activity
            );
        }
    }
    Ok(())
}
