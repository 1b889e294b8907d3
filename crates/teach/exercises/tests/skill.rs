#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! No grader passes code that lacks the skill its exercise teaches: random
//! constant commands (code that reads nothing) fail every exercise, and a
//! random linear control law passes only when the theory says it should.

use kinolab_exercises::find;
use proptest::prelude::*;

fn passes(id: &str, source: &str) -> bool {
    find(id).unwrap().check(source, true).passed
}

/// A number with four decimals, as a learner would type it.
fn typed(x: f64) -> String {
    format!("{x:.4}")
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 12, ..ProptestConfig::default() })]

    #[test]
    fn a_constant_command_fails_every_exercise(
        a in -1.0..1.0_f64,
        b in -2.5..2.5_f64,
        named in 0..3_usize,
        stance in proptest::bool::ANY,
    ) {
        let (a, b) = (typed(a), typed(b));
        let command = format!("[{a}, {b}]");
        let cases = [
            ("control-park", format!("fn control(rho, alpha, beta) {{ {command} }}")),
            ("control-slow-loop", format!("fn control(rho, alpha, beta) {{ {command} }}")),
            ("behaviour-explore", format!("fn behave(p) {{ {command} }}")),
            ("behaviour-explore", format!("fn behave(p) {{ #{{ x: {a}, y: {b} }} }}")),
            (
                "behaviour-coordinate",
                format!("fn coordinate(outputs, p) {{ {} }}", ["\"seek\"", "\"avoid\"", &command][named]),
            ),
            ("field-pull", format!("fn field(x, y) {{ {command} }}")),
            ("field-escape", format!("fn field(x, y) {{ {command} }}")),
            (
                "legs-walk",
                format!("fn foot(leg, phase) {{ #{{ stance: {stance}, at: [leg.x + {a} * 0.03, leg.y, leg.z + {b} * 0.01] }} }}"),
            ),
            (
                "legs-careful",
                format!("fn foot(leg, phase) {{ #{{ stance: {stance}, at: [leg.x + {a} * 0.03, leg.y, leg.z] }} }}"),
            ),
            (
                "sequencer-replan",
                format!("fn next(state) {{ #{{ replan: {stance}, target: () }} }}"),
            ),
            (
                "arm-hold",
                format!("fn control(q, qd, target, payload) {{ [{a} * 40.0, {b} * 10.0] }}"),
            ),
        ];
        for (id, source) in cases {
            prop_assert!(!passes(id, &source), "{id} passed {source}");
        }
    }

    #[test]
    fn a_linear_law_parks_only_when_it_is_stable_and_suits_the_loop(
        k_rho in -1.0..4.0_f64,
        k_alpha in -2.0..10.0_f64,
        k_beta in -3.0..1.0_f64,
    ) {
        let law = format!(
            "fn control(rho, alpha, beta) {{ [{} * rho, {} * alpha + {} * beta] }}",
            typed(k_rho), typed(k_alpha), typed(k_beta)
        );
        let stable = k_rho > 0.0 && k_beta < 0.0 && k_alpha > k_rho;
        // The plain law ignores the speed limit wherever it starts far off.
        prop_assert!(!passes("control-park", &law), "{law}");
        // Twice a second, the heading error shrinks each period by the
        // factor 1 − T (k_alpha − k_rho) of the held command: a law that
        // arrives is stable and keeps T (k_alpha − k_rho) below 2.
        if passes("control-slow-loop", &law) {
            prop_assert!(stable && 0.5 * (k_alpha - k_rho) < 2.0, "{law}");
        }
    }

    #[test]
    fn a_linear_field_pulls_to_the_goal_only_when_it_is_attractive_and_never_out_of_the_u(
        a in -1.0..3.0_f64,
        b in -1.0..3.0_f64,
        c in -0.5..0.5_f64,
    ) {
        let pull = format!(
            "fn field(x, y) {{ [{} * (4.0 - x) + {} * y, {} * (0.0 - y)] }}",
            typed(a), typed(c), typed(b)
        );
        if passes("field-pull", &pull) {
            prop_assert!(a > 0.0 && b > 0.0, "{pull}");
        }
        // The U traps whatever a linear field does: the wall's own push
        // must be outdone somewhere in particular, not everywhere.
        let escape = format!(
            "fn field(x, y) {{ [{} * (6.0 - x) + {} * y, {} * (0.0 - y)] }}",
            typed(a), typed(c), typed(b)
        );
        prop_assert!(!passes("field-escape", &escape), "{escape}");
    }
}
