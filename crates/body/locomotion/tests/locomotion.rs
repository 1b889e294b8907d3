#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
use kinolab_locomotion::{
    MAX_LEGS_EXACT, STANDARD_GRAVITY, cost_of_transport, leg_events, leg_events_f64,
    static_stability,
};
use proptest::prelude::*;

#[test]
fn leg_event_counts_match_the_reference_sheet() {
    assert_eq!(leg_events(1).unwrap(), 1);
    assert_eq!(leg_events(2).unwrap(), 6);
    assert_eq!(leg_events(3).unwrap(), 120);
    assert_eq!(leg_events(4).unwrap(), 5040);
    assert_eq!(leg_events(6).unwrap(), 39_916_800);
    assert_eq!(
        leg_events(MAX_LEGS_EXACT).unwrap(),
        8_683_317_618_811_886_495_518_194_401_280_000_000
    );
    assert_eq!(leg_events_f64(6).unwrap(), 39_916_800.0);
}

#[test]
fn bad_leg_counts_name_the_field() {
    assert_eq!(
        leg_events(0).unwrap_err().to_string(),
        "legs: a walker needs at least one leg"
    );
    assert_eq!(leg_events(MAX_LEGS_EXACT + 1).unwrap_err().field, "legs");
    assert_eq!(leg_events_f64(0).unwrap_err().field, "legs");
    assert!(leg_events_f64(100).unwrap().is_infinite());
}

#[test]
fn square_stance_has_margin_to_the_nearest_edge() {
    let feet = [[1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0], [1.0, -1.0]];
    let s = static_stability([0.0, 0.0], &feet).unwrap();
    assert!(s.stable);
    assert!((s.margin - 1.0).abs() < 1e-12);
    assert_eq!(s.polygon.len(), 4);
    let off_centre = static_stability([0.5, 0.2], &feet).unwrap();
    assert!((off_centre.margin - 0.5).abs() < 1e-12);
    assert!(
        (off_centre.nearest[0] - 1.0).abs() < 1e-12 && (off_centre.nearest[1] - 0.2).abs() < 1e-12
    );
}

#[test]
fn centre_of_mass_outside_tips_over() {
    let feet = [[1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0], [1.0, -1.0]];
    let s = static_stability([3.0, 0.0], &feet).unwrap();
    assert!(!s.stable);
    assert!((s.margin + 2.0).abs() < 1e-12);
}

#[test]
fn lifting_a_foot_shrinks_the_margin() {
    // Square stance, lift the front-right foot: the diagonal edge passes
    // through the centre, so a centred body is exactly on the edge.
    let three = [[-1.0, 1.0], [-1.0, -1.0], [1.0, -1.0]];
    let s = static_stability([0.0, 0.0], &three).unwrap();
    assert!(s.margin.abs() < 1e-12);
    assert!(!s.stable, "on the edge is not strictly stable");
    // Shift the body away from the lifted foot first.
    let shifted = static_stability([-0.3, -0.3], &three).unwrap();
    assert!(shifted.stable);
    assert!((shifted.margin - 0.6 / 2f64.sqrt()).abs() < 1e-12);
}

#[test]
fn feet_in_a_line_or_one_foot_are_never_statically_stable() {
    let line = static_stability([0.0, 0.0], &[[-1.0, 0.0], [1.0, 0.0], [0.2, 0.0]]).unwrap();
    assert!(!line.stable);
    assert_eq!(line.polygon.len(), 2);
    assert_eq!(line.margin, 0.0);
    let one = static_stability([0.0, 0.5], &[[0.0, 0.0]]).unwrap();
    assert!(!one.stable);
    assert!((one.margin + 0.5).abs() < 1e-12);
}

#[test]
fn bad_stances_are_errors() {
    assert_eq!(static_stability([0.0, 0.0], &[]).unwrap_err().field, "feet");
    assert_eq!(
        static_stability([f64::NAN, 0.0], &[[0.0, 0.0]])
            .unwrap_err()
            .field,
        "com"
    );
    assert_eq!(
        static_stability([0.0, 0.0], &[[f64::INFINITY, 0.0]])
            .unwrap_err()
            .field,
        "feet"
    );
}

#[test]
fn cost_of_transport_is_energy_per_weight_and_distance() {
    assert!((cost_of_transport(100.0, 10.0, 10.0, 10.0).unwrap() - 0.1).abs() < 1e-15);
    let walking = cost_of_transport(2_000.0, 80.0, 1_000.0, STANDARD_GRAVITY).unwrap();
    assert!((walking - 2_000.0 / (80.0 * 9.806_65 * 1_000.0)).abs() < 1e-15);
    assert_eq!(
        cost_of_transport(1.0, 0.0, 1.0, 9.8).unwrap_err().field,
        "mass"
    );
    assert_eq!(
        cost_of_transport(1.0, 1.0, -1.0, 9.8).unwrap_err().field,
        "distance"
    );
    assert_eq!(
        cost_of_transport(f64::NAN, 1.0, 1.0, 9.8)
            .unwrap_err()
            .field,
        "energy"
    );
}

/// Distance from `p` to segment `a`–`b`, by hand, to check parry's answer.
fn segment_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 == 0.0 {
        0.0
    } else {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    };
    let (qx, qy) = (a[0] + t * dx, a[1] + t * dy);
    ((p[0] - qx).powi(2) + (p[1] - qy).powi(2)).sqrt()
}

fn cross(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
}

/// The static stability margin by brute force, without computing a hull:
/// every pair of feet whose line has all feet on one side bounds the
/// support polygon; the CoM is inside when it is on the feet's side of
/// every such line; the margin is ± its distance to the nearest of them.
fn brute_force_margin(com: [f64; 2], feet: &[[f64; 2]]) -> f64 {
    let mut nearest = f64::INFINITY;
    let mut inside = true;
    for (i, &a) in feet.iter().enumerate() {
        for &b in &feet[i + 1..] {
            if a == b {
                continue;
            }
            let sides: Vec<f64> = feet.iter().map(|&p| cross(a, b, p)).collect();
            let tol = 1e-12;
            let all_left = sides.iter().all(|&v| v >= -tol);
            let all_right = sides.iter().all(|&v| v <= tol);
            if !(all_left || all_right) {
                continue;
            }
            let c = cross(a, b, com);
            if (all_left && c < 0.0) || (all_right && c > 0.0) {
                inside = false;
            }
            nearest = nearest.min(segment_distance(com, a, b));
        }
    }
    if inside { nearest } else { -nearest }
}

proptest! {
    #[test]
    fn margin_matches_a_brute_force_over_foot_pairs(
        feet in prop::collection::vec((-2.0f64..2.0, -2.0f64..2.0), 3..8),
        com in (-3.0f64..3.0, -3.0f64..3.0),
    ) {
        let feet: Vec<[f64; 2]> = feet.into_iter().map(|(x, y)| [x, y]).collect();
        let com = [com.0, com.1];
        // Only feet that enclose an area (three not in a line).
        let area = feet.iter().enumerate().any(|(i, &a)| {
            feet[i + 1..].iter().enumerate().any(|(j, &b)| {
                feet[i + j + 2..].iter().any(|&c| cross(a, b, c).abs() > 1e-6)
            })
        });
        prop_assume!(area);
        let s = static_stability(com, &feet).unwrap();
        let expected = brute_force_margin(com, &feet);
        prop_assert!((s.margin - expected).abs() < 1e-9, "{} vs {}", s.margin, expected);
        prop_assert_eq!(s.stable, expected > 0.0);
    }
}
