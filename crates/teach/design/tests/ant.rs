//! Simon's ant: the path's complexity belongs to the beach at the ant's
//! scale; a body a thousand times larger goes straight.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use kinolab_design::ant::{Beach, DEFAULT_PEBBLES, walk};
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    #[test]
    fn the_ant_winds_where_the_giant_goes_straight(seed in 0u64..10_000) {
        let beach = Beach::new(seed, DEFAULT_PEBBLES).unwrap();
        let ant = walk(&beach, 1.0).unwrap();
        let giant = walk(&beach, 1000.0).unwrap();
        prop_assert!(ant.reached && giant.reached);
        prop_assert!(ant.tortuosity > giant.tortuosity, "{} vs {}", ant.tortuosity, giant.tortuosity);
        prop_assert!((giant.tortuosity - 1.0).abs() < 1e-9);
        prop_assert!(ant.turns > giant.turns);
    }
}

#[test]
fn tortuosity_falls_as_the_body_grows_on_average() {
    let mean = |size: f64| {
        let t: f64 = (0..24)
            .map(|seed| {
                walk(&Beach::new(seed, DEFAULT_PEBBLES).unwrap(), size)
                    .unwrap()
                    .tortuosity
            })
            .sum();
        t / 24.0
    };
    let (ant, dog) = (mean(1.0), mean(10f64.powf(2.5)));
    assert!(ant > dog + 0.05, "{ant} {dog}");
    assert!((dog - 1.0).abs() < 1e-9, "{dog}");
    // Fewer and fewer pebbles matter as the body grows.
    let beach = Beach::new(7, DEFAULT_PEBBLES).unwrap();
    let counts: Vec<usize> = kinolab_design::ant::sizes()
        .map(|s| walk(&beach, s).unwrap().obstacles)
        .collect();
    assert!(counts.windows(2).all(|w| w[0] >= w[1]), "{counts:?}");
    assert!(
        counts[0] > 500 && *counts.last().unwrap() == 0,
        "{counts:?}"
    );
}

#[test]
fn swapping_the_beach_keeps_the_ant_and_changes_the_path() {
    // The rule is the same on every beach; only the path differs.
    let a = walk(&Beach::new(3, DEFAULT_PEBBLES).unwrap(), 1.0).unwrap();
    let b = walk(&Beach::new(4, DEFAULT_PEBBLES).unwrap(), 1.0).unwrap();
    assert_ne!(a.path, b.path);
    assert_ne!(a.tortuosity, b.tortuosity);
}
