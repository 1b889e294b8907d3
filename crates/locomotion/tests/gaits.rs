//! McGhee and Frank: a quadruped creeping gait can only be statically
//! stable with a duty factor of at least 3/4, whatever its phases; and the
//! stance counts of any gait average the number of legs times β.

use kinolab_locomotion::gait::min_margin;
use kinolab_locomotion::{Gait, Leg};
use proptest::prelude::*;

fn quadruped(beta: f64, phases: [f64; 4]) -> Gait {
    let feet = [(0.3, 0.2), (0.3, -0.2), (-0.3, 0.2), (-0.3, -0.2)];
    Gait {
        name: "random".into(),
        duty_factor: beta,
        stride: 0.2,
        com: [0.0, 0.0],
        legs: feet
            .iter()
            .zip(phases)
            .enumerate()
            .map(|(i, (&(x, y), phase))| Leg {
                name: format!("leg{i}"),
                x,
                y,
                phase,
            })
            .collect(),
    }
}

proptest! {
    #[test]
    fn below_three_quarters_no_quadruped_gait_is_static(
        beta in 0.30f64..0.74,
        phases in prop::array::uniform4(0.0f64..1.0),
    ) {
        let g = quadruped(beta, phases);
        let m = min_margin(&g.sample(800));
        prop_assert!(m.is_none_or(|m| m <= 1e-12), "β {beta}, φ {phases:?}: {m:?}");
    }

    #[test]
    fn stance_counts_average_legs_times_beta(
        beta in 0.05f64..0.95,
        phases in prop::array::uniform4(0.0f64..1.0),
    ) {
        let g = quadruped(beta, phases);
        let n = 2000;
        let total: usize = g.sample(n).iter().map(|s| s.stance.len()).sum();
        let mean = total as f64 / n as f64;
        prop_assert!((mean - 4.0 * beta).abs() <= 4.0 / n as f64 + 1e-12, "{mean} vs {}", 4.0 * beta);
    }
}
