//! A learner's code at work: the parking law as a script against the same
//! law built in (one run of 10 s with the law called at 100 Hz), compiling
//! a 100-line script, and one behaviour-arena step whose behaviour is a
//! script reading 16 rays.

use std::cell::RefCell;
use std::hint::black_box;

use kinolab_behaviours::coordinate::Coordinator;
use kinolab_behaviours::library::{Behaviour, Named};
use kinolab_behaviours::run::Runner;

/// The textbook law, written as a learner writes it.
pub const LAW: &str =
    "fn control(rho, alpha, beta) {\n    [3.0 * rho, 8.0 * alpha - 1.5 * beta]\n}";

/// A behaviour that reads every ray: drive on while the way ahead is
/// clear, else turn towards the side with more room.
pub const EXPLORE: &str = r"fn behave(p) {
    let ahead = 10.0;
    let left = 0.0;
    let right = 0.0;
    for r in p.rays {
        if r.angle.abs() < 0.5 && r.range < ahead { ahead = r.range; }
        if r.angle > 0.0 { left += r.range; } else { right += r.range; }
    }
    if ahead < 0.55 {
        return [0.0, if left > right { 1.2 } else { -1.2 }];
    }
    [0.3, 0.0]
}";

/// A run file: 10 s from the contract's start, the law at 100 Hz.
fn run_file(controller: &str) -> String {
    format!(
        r#"{{"controller": {controller}, "start": {{"x": -1.0, "y": 0.5, "theta_deg": 0}},
        "goal": {{"x": 0.0, "y": 0.0, "theta_deg": 0}}, "dt": 0.001, "duration": 10.0,
        "control_rate": 100, "tolerance": {{"position": 1e-9, "heading_deg": 1e-6}}}}"#
    )
}

fn simulate(file: &str) -> f64 {
    kinolab_control::file::from_json(black_box(file))
        .ok()
        .and_then(|spec| spec.run.simulate().ok())
        .map_or(f64::NAN, |run| run.path_length)
}

/// 10 s at 100 Hz with the learner's law: 1 000 calls into the script.
pub fn law_run_script() -> f64 {
    thread_local! {
        static FILE: String = run_file(
            &serde_json::json!({ "kind": "script", "source": LAW }).to_string(),
        );
    }
    FILE.with(|f| simulate(f))
}

/// The same run with the law built in.
pub fn law_run_builtin() -> f64 {
    thread_local! {
        static FILE: String = run_file(
            r#"{"kind": "polar", "k_rho": 3.0, "k_alpha": 8.0, "k_beta": -1.5}"#,
        );
    }
    FILE.with(|f| simulate(f))
}

/// A 100-line script: the parking law and 24 helpers of four lines each.
pub fn hundred_lines() -> String {
    let mut text = String::from("// Helpers, then the law.\n");
    for i in 0..24 {
        text.push_str(&format!(
            "fn helper{i}(x) {{\n    let y = x * {i}.5 + sin(x);\n    if y > 1.0 {{ y - 1.0 }} else {{ y }}\n}}\n"
        ));
    }
    text.push_str(LAW);
    text
}

/// Compile [`hundred_lines`], as the editor does after each keystroke.
pub fn compile_100_lines() -> f64 {
    thread_local! {
        static TEXT: String = hundred_lines();
    }
    TEXT.with(|t| {
        kinolab_script::Script::compile(black_box(t), kinolab_control::law::SIGNATURE)
            .map_or(f64::NAN, |s| s.signature().params.len() as f64)
    })
}

thread_local! {
    static EXPLORER: RefCell<Option<Runner>> = const { RefCell::new(None) };
}

/// One step of the cluttered world's robot, its one behaviour a script
/// that reads all 16 rays.
pub fn behaviour_step() -> f64 {
    EXPLORER.with(|cell| {
        let mut slot = cell.borrow_mut();
        if slot.as_ref().is_none_or(Runner::done) {
            let mut s = crate::behaviour::setup(crate::behaviour::cluttered());
            s.behaviours = vec![Named::new(
                "explore",
                Behaviour::Script {
                    source: EXPLORE.to_owned(),
                },
            )];
            s.coordinator = Coordinator::Sum {
                gains: Default::default(),
            };
            *slot = Runner::new(&s).ok();
        }
        slot.as_mut().map_or(f64::NAN, |r| r.step().pose.x)
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn the_scripted_and_built_in_laws_drive_the_same_path() {
        let (script, builtin) = (law_run_script(), law_run_builtin());
        assert!(script.is_finite() && script > 1.0, "{script}");
        assert!((script - builtin).abs() < 1e-9, "{script} vs {builtin}");
    }

    #[test]
    fn the_long_script_has_a_hundred_lines_and_compiles() {
        assert_eq!(hundred_lines().lines().count(), 100);
        assert_eq!(compile_100_lines(), 3.0);
        let x0 = behaviour_step();
        let x1 = behaviour_step();
        assert!(x0.is_finite() && x1.is_finite());
    }
}
