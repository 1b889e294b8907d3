//! The library entry points the command line, the JS API and the lab's
//! "paste a file" panels share: on any generated file they return a value
//! or a `FieldError`, never panic, and what they compute is finite or is
//! refused by the report check, never printed as `null`.

use kinolab_fuzz::case::FileSpec;
use kinolab_fuzz::generate;
use kinolab_fuzz::seeds::Seeds;

/// The text of every file of the generated cases of `command`.
fn files(seeds: &Seeds, command: &str, wanted: usize) -> Vec<String> {
    let mut out = Vec::new();
    for i in 0..50_000u64 {
        let case = generate::case(seeds, 77, i);
        if case.command != command {
            continue;
        }
        for (_, spec) in &case.files {
            if let FileSpec::Text(t) = spec {
                out.push(t.clone());
            }
        }
        if out.len() >= wanted {
            break;
        }
    }
    out
}

#[test]
fn robot_files_parse_and_analyse_or_are_refused() {
    let seeds = Seeds::load();
    let texts = files(&seeds, "analyze", 300);
    assert!(texts.len() >= 200);
    let mut parsed = 0;
    for text in &texts {
        if let Ok(chassis) = kinolab_wheels::Chassis::from_json(text) {
            parsed += 1;
            let report = kinolab_wheels::report::analysis(&chassis);
            // Either finite numbers or an error naming the bad one.
            let _ = kinolab_common::display::tidy_report(&report);
        }
    }
    assert!(parsed > 30, "{parsed} of {}", texts.len());
}

#[test]
fn model_files_parse_and_pose_or_are_refused() {
    let seeds = Seeds::load();
    let texts = files(&seeds, "fk", 200);
    let mut parsed = 0;
    for text in &texts {
        if let Ok(model) = kinolab_mechanism::file::from_json(text) {
            parsed += 1;
            if let (Ok(q), Ok(tool)) = (model.home_state(), model.frame("tool")) {
                let pose = model.pose(&q, &tool).unwrap();
                assert!(pose.translation.vector.iter().all(|v| v.is_finite()));
            }
        }
    }
    assert!(parsed > 20, "{parsed} of {}", texts.len());
}

#[test]
fn run_field_and_world_files_parse_or_are_refused() {
    let seeds = Seeds::load();
    for text in files(&seeds, "simulate", 200) {
        if let Ok(spec) = kinolab_control::file::from_json(&text)
            && let Ok(t) = spec.run.simulate()
        {
            let report = kinolab_control::report::simulation(&spec, &t);
            assert!(kinolab_common::display::tidy_report(&report).is_ok());
        }
    }
    for text in files(&seeds, "field", 200) {
        let _ = kinolab_fields::Field::from_json(&text);
    }
    for text in files(&seeds, "run", 150) {
        if let Ok(setup) = kinolab_behaviours::run::Setup::from_json(&text) {
            let _ = kinolab_behaviours::run::run(&setup);
        }
    }
}
