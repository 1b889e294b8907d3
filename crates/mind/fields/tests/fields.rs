#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Field values against closed forms, Jacobians against finite differences,
//! minima against hand-derived positions, descents and remedies.

use kinolab_fields::catalogue::preset;
use kinolab_fields::descend::{Outcome, Steps, Unicycle, descend, follow, heading_command};
use kinolab_fields::minima::{Kind, Search, classify, minima};
use kinolab_fields::primitive::{Primitive, Profile, Sense, Source, Spin};
use kinolab_fields::remedy::{Remedy, Wavefront, escape};
use kinolab_fields::{Field, Vec2};
use kinolab_world::{Pose, Rect};
use proptest::prelude::*;

fn prim(source: Source, gain: f64, profile: Profile, range: Option<f64>) -> Primitive {
    Primitive::new(source, gain, profile, range).unwrap()
}

fn close(a: Vec2, b: [f64; 2]) -> bool {
    (a - Vec2::new(b[0], b[1])).norm() < 1e-12
}

const ORIGIN: Vec2 = Vec2::new(0.0, 0.0);

#[test]
fn every_primitive_and_profile_matches_its_closed_form() {
    let p = Vec2::new(3.0, 4.0); // 5 m from the origin, direction (0.6, 0.8)
    let attract =
        |profile, range| prim(Source::Attractive { centre: ORIGIN }, 2.0, profile, range).vector(p);
    assert!(close(attract(Profile::Constant, None), [-1.2, -1.6]));
    assert!(
        close(attract(Profile::Constant, Some(4.0)), [0.0, 0.0]),
        "beyond the range"
    );
    assert!(
        close(attract(Profile::Linear, Some(10.0)), [-0.6, -0.8]),
        "min(1, d/D) = 0.5"
    );
    assert!(
        close(attract(Profile::Linear, Some(2.0)), [-1.2, -1.6]),
        "no cut-off beyond D"
    );
    assert!(
        close(attract(Profile::Potential, None), [-6.0, -8.0]),
        "m (c − p)"
    );

    let disc = Source::Repulsive {
        centre: ORIGIN,
        radius: 1.0,
    }; // d = 4
    let repel = |profile, range| prim(disc, 2.0, profile, Some(range)).vector(p);
    assert!(close(repel(Profile::Constant, 5.0), [1.2, 1.6]));
    assert!(close(repel(Profile::Constant, 3.0), [0.0, 0.0]));
    assert!(
        close(repel(Profile::Linear, 8.0), [0.6, 0.8]),
        "1 − d/D = 0.5"
    );
    let e = 2.0 * (-2.0f64).exp();
    assert!(close(
        repel(Profile::Exponential { lambda: 2.0 }, 10.0),
        [0.6 * e, 0.8 * e]
    ));
    // Khatib: (1/d − 1/D)/d² = (1/4 − 1/8)/16.
    assert!(close(repel(Profile::Potential, 8.0), [0.009375, 0.0125]));

    let turn = |spin| {
        prim(
            Source::Tangential {
                centre: ORIGIN,
                radius: 1.0,
                spin,
            },
            2.0,
            Profile::Linear,
            Some(8.0),
        )
        .vector(p)
    };
    assert!(close(turn(Spin::Ccw), [-0.8, 0.6]));
    assert!(close(turn(Spin::Cw), [0.8, -0.6]));

    let segment = |sense, q: Vec2| {
        prim(
            Source::Perpendicular {
                from: Vec2::new(-1.0, 0.0),
                to: Vec2::new(1.0, 0.0),
                sense,
            },
            1.0,
            Profile::Linear,
            Some(0.6),
        )
        .vector(q)
    };
    assert!(close(segment(Sense::Away, Vec2::new(0.5, 0.3)), [0.0, 0.5]));
    assert!(close(
        segment(Sense::Toward, Vec2::new(0.5, 0.3)),
        [0.0, -0.5]
    ));
    // Past the end the nearest point is the end itself: 0.5 m away.
    assert!(close(
        segment(Sense::Away, Vec2::new(1.3, 0.4)),
        [0.1, 0.4 / 3.0]
    ));

    let uniform = prim(
        Source::Uniform {
            direction: 90f64.to_radians(),
        },
        0.2,
        Profile::Constant,
        None,
    );
    assert!((uniform.vector(p) - Vec2::new(0.0, 0.2)).norm() < 1e-15);
    // Inside a disc the distance is 0: full strength, straight out; at the
    // centre the direction is undefined and the field is 0.
    let inside = prim(disc, 2.0, Profile::Linear, Some(1.0));
    assert!(close(inside.vector(Vec2::new(0.5, 0.0)), [2.0, 0.0]));
    assert!(close(inside.vector(ORIGIN), [0.0, 0.0]));
}

#[test]
fn the_field_is_the_sum_of_its_primitives() {
    let f = preset("goal-behind-a-rock").unwrap().field().unwrap();
    let p = Vec2::new(1.1, -0.4);
    let sum: Vec2 = f.primitives.iter().map(|q| q.vector(p)).sum();
    assert_eq!(f.vector(p), sum);
}

fn any_primitive() -> impl Strategy<Value = Primitive> {
    let centre = (-2.0f64..2.0, -2.0f64..2.0).prop_map(|(x, y)| Vec2::new(x, y));
    let profile = prop_oneof![
        Just(Profile::Constant),
        Just(Profile::Linear),
        (0.2f64..2.0).prop_map(|lambda| Profile::Exponential { lambda }),
        Just(Profile::Potential),
    ];
    (
        0usize..5,
        centre.clone(),
        centre,
        0.0f64..0.8,
        profile,
        0.1f64..3.0,
        0.5f64..4.0,
        0.0f64..6.3,
        any::<bool>(),
    )
        .prop_filter_map(
            "a valid primitive",
            |(kind, c, d, radius, profile, gain, range, angle, flag)| {
                let source = match kind {
                    0 => Source::Uniform { direction: angle },
                    1 => Source::Attractive { centre: c },
                    2 => Source::Repulsive { centre: c, radius },
                    3 => Source::Tangential {
                        centre: c,
                        radius,
                        spin: if flag { Spin::Ccw } else { Spin::Cw },
                    },
                    _ => Source::Perpendicular {
                        from: c,
                        to: d,
                        sense: if flag { Sense::Away } else { Sense::Toward },
                    },
                };
                let profile = if kind == 0 {
                    Profile::Constant
                } else {
                    profile
                };
                Primitive::new(source, gain, profile, Some(range)).ok()
            },
        )
}

proptest! {
    /// The exact Jacobian agrees with central differences wherever the
    /// field is smooth (with a margin for the stencil).
    #[test]
    fn jacobians_match_finite_differences(
        prims in proptest::collection::vec(any_primitive(), 1..6),
        x in -3.0f64..3.0, y in -3.0f64..3.0,
    ) {
        let field = Field::new("random", None, prims);
        let p = Vec2::new(x, y);
        prop_assume!(field.primitives.iter().all(|q| q.smooth_at(p, 1e-3)));
        // Keep away from the near-infinite Khatib field next to an obstacle.
        prop_assume!(field.vector(p).norm() < 1e4);
        let (_, j) = field.linearise(p);
        let h = 1e-6;
        for (col, dp) in [Vec2::new(h, 0.0), Vec2::new(0.0, h)].into_iter().enumerate() {
            let numeric = (field.vector(p + dp) - field.vector(p - dp)) / (2.0 * h);
            let exact = j.column(col);
            let scale = 1.0 + exact.norm();
            prop_assert!((numeric - exact).norm() < 1e-5 * scale, "column {col}: {numeric:?} vs {exact:?}");
        }
    }
}

fn area(r: [f64; 4]) -> Rect {
    Rect::new("box", r).unwrap()
}

#[test]
fn a_wall_across_the_axis_traps_where_the_pull_equals_the_push() {
    // Pull 1 towards (5, 0); a wall at x = 3 pushes back 2 (1 − d/1).
    // They balance at d = 0.5: the robot rests at (2.5, 0).
    let field = Field::new(
        "wall",
        Some(Vec2::new(5.0, 0.0)),
        vec![
            prim(
                Source::Attractive {
                    centre: Vec2::new(5.0, 0.0),
                },
                1.0,
                Profile::Constant,
                None,
            ),
            prim(
                Source::Perpendicular {
                    from: Vec2::new(3.0, -10.0),
                    to: Vec2::new(3.0, 10.0),
                    sense: Sense::Away,
                },
                2.0,
                Profile::Linear,
                Some(1.0),
            ),
        ],
    );
    let found = minima(&field, &area([0.0, -3.0, 6.0, 3.0]), Search::default()).unwrap();
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(
        (found[0].x - 2.5).abs() < 1e-9 && found[0].y.abs() < 1e-9,
        "{found:?}"
    );
    assert!(
        !found[0].goal,
        "the constant pull is not smooth at its centre, so the goal is not listed"
    );
}

#[test]
fn a_rock_on_the_axis_makes_a_saddle_not_a_trap() {
    let field = preset("rock-on-the-axis").unwrap().field().unwrap();
    // On the axis the pull (1) meets the push 2 (1 − d) at d = 0.5: x = 1.2.
    let saddle = Vec2::new(1.2, 0.0);
    let (f, j) = field.linearise(saddle);
    assert!(f.norm() < 1e-12);
    assert_eq!(classify(&j), Kind::Saddle);
    let found = minima(&field, &area([-0.5, -2.0, 5.0, 2.0]), Search::default()).unwrap();
    assert_eq!(found.len(), 1, "{found:?}");
    assert!((found[0].x - 4.0).abs() < 1e-9 && found[0].y.abs() < 1e-9 && found[0].goal);
    // Exactly on the axis a point robot stalls at the saddle; a hair off
    // it, it rolls round the rock and arrives.
    let on = descend(&field, Vec2::new(0.0, 0.0), Steps::default()).unwrap();
    assert_eq!(on.outcome, Outcome::Trapped);
    assert!((Vec2::new(on.end[0], on.end[1]) - saddle).norm() < 0.02);
    let off = descend(&field, Vec2::new(0.0, 0.05), Steps::default()).unwrap();
    assert_eq!(off.outcome, Outcome::Reached);
}

#[test]
fn a_goal_beside_an_obstacle_is_never_reached() {
    // (4 − x) = 2 (1 − (4.3 − x)/0.8) gives x = 12.75 / 3.5.
    let field = preset("goal-by-an-obstacle").unwrap().field().unwrap();
    let found = minima(&field, &area([0.0, -1.5, 6.0, 1.5]), Search::default()).unwrap();
    assert_eq!(found.len(), 1, "{found:?}");
    assert!((found[0].x - 12.75 / 3.5).abs() < 1e-9 && found[0].y.abs() < 1e-9 && !found[0].goal);
}

#[test]
fn the_u_traps_and_the_remedies_escape() {
    let field = preset("u-shaped-wall").unwrap().field().unwrap();
    let found = minima(&field, &area([0.0, -2.5, 7.0, 2.5]), Search::default()).unwrap();
    // Inside the U the back wall's push 2 (1 − d/0.5) meets the pull 1 at d = 0.25.
    assert_eq!(found.len(), 2, "{found:?}");
    assert!((found[0].x - 3.75).abs() < 1e-9 && !found[0].goal);
    assert!((found[1].x - 6.0).abs() < 1e-9 && found[1].goal);
    let start = Vec2::new(0.5, 0.3);
    let steps = Steps::default();
    assert_eq!(
        descend(&field, start, steps).unwrap().outcome,
        Outcome::Trapped
    );
    let follow_wall = escape(&field, start, steps, &Remedy::WallFollowing).unwrap();
    assert_eq!(
        follow_wall.outcome,
        Outcome::Reached,
        "ended at {:?}",
        follow_wall.end
    );
    let wave = Wavefront::new(&field, &area([0.0, -2.5, 7.0, 2.5]), 0.1, 0.15).unwrap();
    let d = wave.descend(start);
    assert_eq!(d.outcome, Outcome::Reached);
    let end = Vec2::new(d.end[0], d.end[1]);
    assert!((end - Vec2::new(6.0, 0.0)).norm() < 0.1);
}

#[test]
fn noise_and_templates_leave_the_saddle() {
    let field = preset("rock-on-the-axis").unwrap().field().unwrap();
    let start = Vec2::new(0.0, 0.0);
    for remedy in [
        Remedy::Noise {
            magnitude: 0.3,
            seed: 4,
        },
        Remedy::Templates { gain: 1.0 },
    ] {
        let d = escape(&field, start, Steps::default(), &remedy).unwrap();
        assert_eq!(d.outcome, Outcome::Reached, "{remedy:?}");
    }
    // Same seed, same path.
    let noisy = Remedy::Noise {
        magnitude: 0.3,
        seed: 4,
    };
    assert_eq!(
        escape(&field, start, Steps::default(), &noisy),
        escape(&field, start, Steps::default(), &noisy)
    );
}

#[test]
fn the_heading_controller_follows_the_sheet() {
    // Field along +y, robot facing +x: error 90°, so it turns at k·π/2 and
    // does not drive (cos 90° = 0).
    let (v, w) = heading_command(Vec2::new(0.0, 2.0), 0.0, 3.0, 0.5);
    assert!(v.abs() < 1e-15 && (w - 1.5 * std::f64::consts::PI).abs() < 1e-12);
    // Aligned: full speed, capped by v_max or by ‖F‖.
    assert_eq!(
        heading_command(Vec2::new(2.0, 0.0), 0.0, 3.0, 0.5),
        (0.5, 0.0)
    );
    assert_eq!(
        heading_command(Vec2::new(0.2, 0.0), 0.0, 3.0, 0.5),
        (0.2, 0.0)
    );
    let field = Field::new(
        "pull",
        Some(Vec2::new(2.0, 1.0)),
        vec![prim(
            Source::Attractive {
                centre: Vec2::new(2.0, 1.0),
            },
            1.0,
            Profile::Linear,
            Some(0.5),
        )],
    );
    let trail = follow(
        &field,
        Pose::new(0.0, 0.0, std::f64::consts::PI),
        &Unicycle::default(),
    )
    .unwrap();
    assert_eq!(trail.outcome, Outcome::Reached);
}

#[test]
fn bad_descents_are_refused() {
    let field = preset("rock-on-the-axis").unwrap().field().unwrap();
    let e = descend(
        &field,
        Vec2::zeros(),
        Steps {
            step: 0.0,
            max_steps: 10,
        },
    )
    .unwrap_err();
    assert_eq!(e.field, "step");
    let e = descend(
        &field,
        Vec2::zeros(),
        Steps {
            step: 0.1,
            max_steps: 0,
        },
    )
    .unwrap_err();
    assert_eq!(e.field, "max_steps");
    let e = minima(&field, &Rect::from([1.0, 0.0, 0.0, 1.0]), Search::default()).unwrap_err();
    assert_eq!(e.field, "box");
}
