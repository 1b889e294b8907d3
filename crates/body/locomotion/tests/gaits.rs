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

fn crawl_network(initial_deg: Vec<f64>) -> kinolab_locomotion::Cpg {
    kinolab_locomotion::Cpg {
        frequency: 1.0,
        legs: ["LF", "RF", "LH", "RH"].map(String::from).to_vec(),
        target_phases: vec![0.25, 0.75, 0.0, 0.5],
        weight: 2.0,
        weights: None,
        model: Default::default(),
        initial_deg,
        dt: 0.005,
        duration: 20.0,
        kicks: Vec::new(),
        changes: Vec::new(),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// From almost every start, positive all-to-all coupling locks the
    /// oscillators onto the crawl's lags.
    #[test]
    fn the_cpg_locks_from_random_starts(initial in prop::collection::vec(-720.0f64..720.0, 4)) {
        let s = crawl_network(initial.clone()).run().unwrap();
        prop_assert!(s.locked, "{initial:?} → {:?}", s.lag);
    }

    /// The margin is positive exactly when the CoM is strictly inside the
    /// feet's convex hull (three feet in general position).
    #[test]
    fn the_margin_sign_is_point_in_triangle(
        a in prop::array::uniform2(-1.0f64..1.0),
        b in prop::array::uniform2(-1.0f64..1.0),
        c in prop::array::uniform2(-1.0f64..1.0),
        com in prop::array::uniform2(-1.0f64..1.0),
    ) {
        let cross = |o: [f64; 2], p: [f64; 2], q: [f64; 2]| {
            (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])
        };
        let area = cross(a, b, c);
        prop_assume!(area.abs() > 1e-3);
        let sides = [cross(a, b, com), cross(b, c, com), cross(c, a, com)];
        let inside = sides.iter().all(|s| s * area > 1e-9);
        let outside = sides.iter().any(|s| s * area < -1e-9);
        prop_assume!(inside || outside);
        let m = kinolab_locomotion::static_stability(com, &[a, b, c]).unwrap().margin;
        prop_assert_eq!(m > 0.0, inside, "margin {}", m);
    }
}
