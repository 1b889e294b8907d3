#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! A learner's leg sequencer walks the lab's hexapod: the tripod written
//! as a script puts every foot where the built-in tripod does, a cycle's
//! progress is the stride, and a broken sequencer says why.

use kinolab_locomotion::walker::{Walker, progress};

/// The tripod gait (β = 0.5, stride 0.06 m, lift 0.03 m) as a learner
/// writes it.
const TRIPOD: &str = r#"
fn foot(leg, phase) {
    let lift_off = if leg.index % 2 == 0 { 0.0 } else { 0.5 };
    let s = phase - lift_off;
    if s < 0.0 { s += 1.0; }
    if s >= 0.5 {
        let through = (s - 0.5) / 0.5;
        #{ stance: true, at: [leg.x + 0.06 / 2.0 - 0.06 * through, leg.y, leg.z] }
    } else {
        let u = s / 0.5;
        #{ stance: false, at: [leg.x - 0.06 / 2.0 + 0.06 * u, leg.y, leg.z + 0.03 * sin(PI() * u)] }
    }
}"#;

fn tripod() -> Walker {
    let mut gait = kinolab_locomotion::named("hexapod-tripod").unwrap();
    gait.stride = 0.06;
    Walker::new(gait, 0.03).unwrap()
}

#[test]
fn the_tripod_as_a_script_walks_like_the_tripod() {
    let built_in = tripod().cycle(24).unwrap();
    let learner = tripod().with_sequencer(TRIPOD).unwrap().cycle(24).unwrap();
    for (a, b) in built_in.iter().zip(&learner) {
        assert_eq!(a.stance, b.stance, "τ = {}", a.tau);
        for (p, q) in a.targets.iter().zip(&b.targets) {
            for k in 0..3 {
                assert!((p[k] - q[k]).abs() < 1e-12, "τ = {}: {p:?} {q:?}", a.tau);
            }
        }
        assert_eq!(a.margin.is_some(), b.margin.is_some());
    }
    // A tripod moves L/β a cycle (each tripod slides L while standing for
    // half the cycle); the sampled count misses the two switch-overs.
    let fine = tripod().with_sequencer(TRIPOD).unwrap().cycle(48).unwrap();
    let moved = progress(&fine);
    assert!((moved - 0.12).abs() < 0.05 * 0.12, "L/β a cycle: {moved}");
    assert!(learner.iter().all(|s| s.margin.is_some_and(|m| m > 0.0)));
}

#[test]
fn a_sequencer_that_lifts_every_foot_is_never_stable() {
    let hop = "fn foot(leg, phase) { #{ stance: false, at: [leg.x, leg.y, leg.z + 0.02] } }";
    let steps = tripod().with_sequencer(hop).unwrap().cycle(8).unwrap();
    assert!(steps.iter().all(|s| s.margin.is_none()));
    assert_eq!(progress(&steps), 0.0);
}

#[test]
fn a_broken_sequencer_says_why() {
    let e = tripod().with_sequencer("fn foot(leg) { () }").unwrap_err();
    assert_eq!(e.field, "sequencer");
    let e = tripod()
        .with_sequencer("fn foot(leg, phase) { [leg.x, leg.y] }")
        .unwrap()
        .cycle(4)
        .unwrap_err();
    assert!(e.message.contains("`foot` must return #{ stance"), "{e}");
    assert!(e.message.contains("at phase 0.000"), "{e}");
}
