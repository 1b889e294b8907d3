#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! The stepper's record of a run: the graded run itself, tick by tick.

use kinolab_exercises::trace::MAX_TICKS;
use kinolab_exercises::{all, find};

fn solution(name: &str) -> String {
    let path = format!("{}/tests/solutions/{name}.rhai", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The numbers in a tick's text, in order.
fn numbers(text: &str) -> Vec<f64> {
    text.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e'))
        .filter_map(|piece| piece.parse().ok())
        .collect()
}

#[test]
fn every_model_solution_is_recorded_as_it_was_graded() {
    for exercise in all() {
        let source = solution(exercise.id);
        let graded = exercise.check(&source, true);
        for (world, outcome) in (exercise.worlds)().iter().zip(&graded.worlds) {
            let trace = exercise.trace(&source, world);
            let at = format!("{} / {}", exercise.id, world.name);
            assert_eq!(&trace.outcome, outcome, "{at}");
            assert!(!trace.ticks.is_empty(), "{at}: no ticks");
            assert!(trace.ticks.len() <= MAX_TICKS, "{at}");
            assert!(
                trace.ticks.windows(2).all(|w| w[0].t <= w[1].t),
                "{at}: ticks out of order"
            );
            // Same code, same world: the same record, tick for tick.
            let again = exercise.trace(&source, world);
            assert_eq!(again.ticks, trace.ticks, "{at}");
            assert_eq!(again.path, trace.path, "{at}");
        }
    }
}

#[test]
fn each_control_tick_shows_the_law_answering_what_it_was_given() {
    let exercise = find("control-park").unwrap();
    let source = solution("control-park");
    let world = &(exercise.worlds)()[0];
    let trace = exercise.trace(&source, world);
    for tick in &trace.ticks {
        let given: Vec<f64> = tick.given.iter().map(|(_, v)| numbers(v)[0]).collect();
        let [rho, alpha, beta] = given[..] else {
            panic!("{:?}", tick.given)
        };
        let answered = numbers(&tick.returned);
        // The model scales the textbook law into the speed limit. The
        // texts carry three decimals: the law, recomputed from them,
        // agrees within what the rounding allows.
        let (v, omega) = (3.0 * rho, 8.0 * alpha - 1.5 * beta);
        let over = (v.abs() / 0.5).max(omega.abs() / 2.0).max(1.0);
        assert!((answered[0] - v / over).abs() < 0.01, "{tick:?}");
        assert!((answered[1] - omega / over).abs() < 0.02, "{tick:?}");
    }
    // The robot ends near the goal at the origin.
    let [x, y] = *trace.path.last().unwrap();
    assert!(x.hypot(y) < 0.1, "ended at ({x}, {y})");
}

#[test]
fn what_the_code_prints_and_plots_is_kept_with_its_tick() {
    let exercise = find("control-park").unwrap();
    let source = "fn control(rho, alpha, beta) {\n  plot(\"rho\", rho);\n  if rho < 0.5 { print(\"close\"); }\n  [3.0 * rho, 8.0 * alpha - 1.5 * beta]\n}";
    let world = &(exercise.worlds)()[0];
    let trace = exercise.trace(source, world);
    for tick in &trace.ticks {
        let rho = numbers(&tick.given[0].1)[0];
        assert_eq!(tick.output.plots.len(), 1, "{tick:?}");
        let (name, plotted) = &tick.output.plots[0];
        assert_eq!(name, "rho");
        assert!((plotted - rho).abs() < 1e-3);
        assert_eq!(
            tick.output.prints.len(),
            usize::from(*plotted < 0.5),
            "{tick:?}"
        );
    }
}

#[test]
fn a_trace_recorded_in_pieces_is_the_trace_recorded_at_once() {
    for id in ["sequencer-replan", "behaviour-explore"] {
        let exercise = find(id).unwrap();
        let source = solution(id);
        let world = &(exercise.worlds)()[0];
        let whole = exercise.trace(&source, world);
        let mut tracing = exercise.tracing(&source, world);
        let mut progress = vec![tracing.progress()];
        while !tracing.advance(7) {
            progress.push(tracing.progress());
        }
        assert!(progress.len() > 10, "{id}: a long run takes several pieces");
        assert_eq!(progress[0], 0.0, "{id}");
        assert!(
            progress.windows(2).all(|w| w[0] <= w[1]),
            "{id}: {progress:?}"
        );
        let pieces = tracing.finish();
        assert_eq!(pieces.ticks, whole.ticks, "{id}");
        assert_eq!(pieces.path, whole.path, "{id}");
        assert_eq!(pieces.outcome, whole.outcome, "{id}");
        assert_eq!(pieces.outcome, exercise.run(&source, world), "{id}");
    }
}
