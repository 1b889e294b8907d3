//! Test inputs drawn from proptest strategies: random joint values within
//! each joint's limits, couplings applied. `sample` draws a fixed, seeded
//! set for tests that count (an IK survey); the strategies plug into
//! `proptest!` for the rest.

#![allow(dead_code)] // each test file uses what it needs

use std::f64::consts::PI;

use kinolab_mechanism::Model;
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::TestRunner;

/// Joint values within the limits (±π for unlimited joints), couplings applied.
pub fn states(m: &Model) -> impl Strategy<Value = Vec<f64>> + use<> {
    let m = m.clone();
    let ranges: Vec<(f64, f64)> = (0..m.dof())
        .map(|i| {
            let [lo, hi] = m
                .variable_joint(i)
                .and_then(|j| j.limits)
                .unwrap_or([-PI, PI]);
            (lo, hi)
        })
        .collect();
    ranges
        .into_iter()
        .map(|(lo, hi)| lo..=hi)
        .collect::<Vec<_>>()
        .prop_map(move |mut q| {
            m.apply_couplings(&mut q);
            q
        })
}

/// `count` values of `strategy`, the same ones on every run.
pub fn sample<S: Strategy>(strategy: &S, count: usize) -> Vec<S::Value> {
    let mut runner = TestRunner::deterministic();
    (0..count)
        .map(|_| match strategy.new_tree(&mut runner) {
            Ok(tree) => tree.current(),
            Err(e) => panic!("cannot draw a test input: {e}"),
        })
        .collect()
}
