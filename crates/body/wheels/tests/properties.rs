//! Property tests over random layouts and twists: inverse kinematics obeys
//! every row, forward kinematics undoes it, and the general model agrees
//! with each closed form.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use kinolab_wheels::closed_form::{ackermann_outer, differential_drive, tricycle};
use kinolab_wheels::{Chassis, Icr, SlidingExtra, Vector3, Wheel, WheelKind, integrate};
use proptest::prelude::*;

fn kind() -> impl Strategy<Value = WheelKind> {
    prop_oneof![
        Just(WheelKind::Fixed),
        Just(WheelKind::Steered),
        (0.01f64..0.1).prop_map(|offset| WheelKind::Castor { offset }),
        (-1.2f64..1.2).prop_map(|gamma| WheelKind::Swedish { gamma }),
        Just(WheelKind::Spherical),
    ]
}

fn wheel() -> impl Strategy<Value = Wheel> {
    (
        kind(),
        -1.0f64..1.0,
        -1.0f64..1.0,
        -3.2f64..3.2,
        0.02f64..0.5,
    )
        .prop_map(|(k, x, y, heading, r)| Wheel::at(k, x, y, heading, r))
}

fn layout() -> impl Strategy<Value = Chassis> {
    prop::collection::vec(wheel(), 1..7).prop_filter_map("wheels too close", |wheels| {
        Chassis::new("random", wheels).ok()
    })
}

/// A twist the layout allows at its current steering: a random mix of the
/// null space of C₁.
fn admissible_twist(chassis: &Chassis, mix: [f64; 3]) -> Option<Vector3<f64>> {
    let a = chassis.analyze();
    let basis = a.admissible.basis();
    if basis.is_empty() {
        return None;
    }
    Some(basis.iter().zip(mix).map(|(b, m)| b * m).sum())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn inverse_kinematics_satisfies_every_row(chassis in layout(), mix in prop::array::uniform3(-2.0f64..2.0)) {
        let Some(twist) = admissible_twist(&chassis, mix) else { return Ok(()) };
        let ik = chassis.inverse(twist).unwrap();
        prop_assert!(ik.feasible, "{:?}", ik.violations);
        let scale = 1e-9 * (1.0 + twist.norm());
        for (w, cmd) in chassis.wheels().iter().zip(&ik.wheels) {
            let mut steered = w.clone();
            steered.beta = cmd.steer;
            let rows = steered.rows();
            prop_assert!((rows.rolling.dot(&twist) - rows.spin_gain * cmd.spin).abs() < scale);
            let sliding = rows.sliding.dot(&twist);
            let left = match rows.sliding_extra {
                SlidingExtra::None => sliding,
                SlidingExtra::SteerRate { offset } => sliding + offset * cmd.steer_rate,
                SlidingExtra::Rollers { spin_gain } => {
                    sliding - spin_gain * cmd.spin - cmd.roller_speed.unwrap()
                }
                SlidingExtra::Free => 0.0,
            };
            prop_assert!(left.abs() < scale, "{:?}: {left}", w.kind);
            if w.kind == WheelKind::Steered {
                prop_assert!((cmd.steer - w.beta).abs() <= std::f64::consts::FRAC_PI_2 + 1e-12,
                    "nearest solution");
            }
        }
    }

    #[test]
    fn forward_of_inverse_returns_the_twist(chassis in layout(), mix in prop::array::uniform3(-2.0f64..2.0)) {
        let Some(twist) = admissible_twist(&chassis, mix) else { return Ok(()) };
        let ik = chassis.inverse(twist).unwrap();
        // Forward kinematics reads steered wheels at their file angle: set them.
        let wheels: Vec<Wheel> = chassis.wheels().iter().zip(&ik.wheels).map(|(w, c)| {
            let mut w = w.clone();
            if w.kind == WheelKind::Steered { w.beta = c.steer; }
            w
        }).collect();
        let steered = Chassis::new("steered", wheels).unwrap();
        let spins: Vec<Option<f64>> = ik.wheels.iter().map(|c| Some(c.spin)).collect();
        let fk = steered.forward(&spins).unwrap();
        prop_assert!(fk.consistent, "residual {}", fk.residual);
        if fk.determined {
            let got = Vector3::from(fk.twist);
            prop_assert!((got - twist).norm() < 1e-7 * (1.0 + twist.norm()), "{got} vs {twist}");
        }
    }

    #[test]
    fn degrees_agree_with_an_independent_null_space(chassis in layout()) {
        let a = chassis.analyze();
        // δm against nalgebra's SVD of the stacked sliding rows.
        let c1 = chassis.c1();
        let svd_rank = if c1.nrows() == 0 { 0 } else { c1.rank(1e-9) };
        prop_assert_eq!(a.rank_c1, svd_rank);
        prop_assert_eq!(a.mobility, 3 - svd_rank);
        // Every admissible twist satisfies every sliding row.
        for v in a.admissible.basis() {
            let residual = (&c1 * nalgebra::DVector::from_column_slice(v.as_slice())).norm();
            prop_assert!(residual < 1e-9, "{residual}");
        }
        // No steered wheel, no steerability; a steered one that counts adds one.
        let steered = chassis.wheels().iter().any(|w| w.kind == WheelKind::Steered);
        if !steered {
            prop_assert_eq!(a.steerability, 0);
        }
        // A holonomic robot can make every motion at once: IK is feasible
        // for a sideways slide and a turn on the spot.
        if a.holonomic && a.dof == 3 {
            for twist in [Vector3::new(0.0, 1.0, 0.0), Vector3::new(0.0, 0.0, 1.0)] {
                prop_assert!(chassis.inverse(twist).unwrap().feasible);
            }
        }
        // The ICR kind follows the rank.
        let kind_ok = match a.icr {
            Icr::Anywhere => a.rank_c1 == 0,
            Icr::Line { .. } => a.rank_c1 == 1,
            Icr::Point { .. } | Icr::Infinity { .. } => a.rank_c1 == 2,
            Icr::None => a.rank_c1 == 3,
        };
        prop_assert!(kind_ok);
        prop_assert_eq!(chassis.disagreement().is_some(), a.rank_c1 == 3);
    }

    #[test]
    fn differential_drive_matches_its_closed_form(track in 0.1f64..2.0, r in 0.02f64..0.5,
                                                  left in -5.0f64..5.0, right in -5.0f64..5.0) {
        let w = track / 2.0;
        let chassis = Chassis::new("dd", vec![
            Wheel::at(WheelKind::Fixed, 0.0, w, 0.0, r),
            Wheel::at(WheelKind::Fixed, 0.0, -w, 0.0, r),
        ]).unwrap();
        let fk = chassis.forward(&[Some(left), Some(right)]).unwrap();
        let closed = differential_drive(track, left * r, right * r).unwrap();
        prop_assert!((fk.twist[0] - closed.v).abs() < 1e-9);
        prop_assert!(fk.twist[1].abs() < 1e-9);
        prop_assert!((fk.twist[2] - closed.omega).abs() < 1e-9);
        if let (Some(radius), Icr::Point { x, y }) = (closed.radius, kinolab_wheels::twist_icr(&Vector3::from(fk.twist))) {
            prop_assert!(x.abs() < 1e-6 * (1.0 + radius.abs()));
            prop_assert!((y - radius).abs() < 1e-6 * (1.0 + radius.abs()));
        }
    }

    #[test]
    fn tricycle_matches_its_closed_form(wheelbase in 0.2f64..2.0, steer in -1.3f64..1.3, speed in -3.0f64..3.0) {
        prop_assume!(steer.abs() > 1e-3);
        let r = 0.1;
        let chassis = Chassis::new("trike", vec![
            Wheel::at(WheelKind::Fixed, 0.0, 0.25, 0.0, r),
            Wheel::at(WheelKind::Fixed, 0.0, -0.25, 0.0, r),
            Wheel::at(WheelKind::Steered, wheelbase, 0.0, steer, r),
        ]).unwrap();
        let closed = tricycle(wheelbase, steer, speed).unwrap();
        match chassis.analyze().icr {
            Icr::Point { x, y } => {
                prop_assert!(x.abs() < 1e-9);
                prop_assert!((y - closed.turn_radius.unwrap()).abs() < 1e-9 * (1.0 + y.abs()));
            }
            other => prop_assert!(false, "{other:?}"),
        }
        // The closed-form twist: the front wheel rolls at `speed`, steered at `steer`.
        let twist = Vector3::new(closed.rear_speed, 0.0, closed.omega);
        let ik = chassis.inverse(twist).unwrap();
        prop_assert!(ik.feasible);
        prop_assert!((ik.wheels[2].spin * r - speed).abs() < 1e-9);
        prop_assert!((ik.wheels[2].steer - chassis.wheels()[2].beta).abs() < 1e-9);
    }

    #[test]
    fn ackermann_linkage_keeps_the_car_mobile(turn in -2.0f64..2.0, steer_to in 0.05f64..0.7) {
        let car = kinolab_wheels::catalogue::robot("ackermann-car").unwrap();
        // Steer the left front wheel; the linkage moves the right one.
        let base = car.wheels()[2].beta;
        let car = car.steer(2, base + turn.signum() * steer_to).unwrap();
        let a = car.analyze();
        prop_assert_eq!(a.mobility, 1);
        // Each front wheel's heading from straight ahead, from its rolling
        // direction: wheelbase L = 1, track w = 0.6.
        let heading = |i: usize| {
            let [tx, ty] = car.wheels()[i].rolling_direction();
            ty.atan2(tx)
        };
        let (left, right) = (heading(2), heading(3));
        // The ICR lies on the rear axle (x = 0), where the left wheel's
        // axle meets it: y = 0.3 + L / tan(left).
        let expected = 0.3 + 1.0 / left.tan();
        let Icr::Point { x, y } = a.icr else {
            return Err(TestCaseError::fail(format!("a steered car has an ICR point, got {:?}", a.icr)));
        };
        prop_assert!(x.abs() < 1e-9 && (y - expected).abs() < 1e-9 * (1.0 + expected.abs()), "{y} vs {expected}");
        // The Ackermann condition: cot s_right − cot s_left = w / L, and the
        // closed form gives the outer wheel's angle from the inner one's.
        // Nearly straight, an angle error δ moves cot by δ(1 + cot²): scale
        // the tolerance with it.
        let (cot_left, cot_right) = (1.0 / left.tan(), 1.0 / right.tan());
        let tolerance = 1e-12 * (1.0 + cot_left.powi(2).max(cot_right.powi(2)));
        prop_assert!((cot_right - cot_left - 0.6).abs() < tolerance);
        let (inner, outer) = if left.abs() > right.abs() { (left, right) } else { (right, left) };
        let closed = ackermann_outer(1.0, 0.6, inner.abs()).unwrap();
        prop_assert!((closed - outer.abs()).abs() < 1e-9, "{} vs {}", closed, outer);
    }

    #[test]
    fn integration_is_exact_for_constant_twists(v in -2.0f64..2.0, vy in -1.0f64..1.0, w in -3.0f64..3.0,
                                                t1 in 0.0f64..2.0, t2 in 0.0f64..2.0) {
        let twist = Vector3::new(v, vy, w);
        let start = [0.3, -0.2, 0.7];
        let whole = integrate(start, twist, t1 + t2);
        let split = integrate(integrate(start, twist, t1), twist, t2);
        for k in 0..3 { prop_assert!((whole[k] - split[k]).abs() < 1e-9); }
        // Against many tiny steps (midpoint rule), which converges to the arc.
        let n = 2000;
        let mut pose = start;
        for _ in 0..n {
            let h = (t1 + t2) / n as f64;
            let mid = pose[2] + w * h / 2.0;
            pose = [pose[0] + h * (v * mid.cos() - vy * mid.sin()),
                    pose[1] + h * (v * mid.sin() + vy * mid.cos()),
                    pose[2] + w * h];
        }
        for k in 0..3 { prop_assert!((whole[k] - pose[k]).abs() < 1e-5); }
    }
}

#[test]
fn synchro_belt_turns_every_wheel_by_the_same_angle() {
    let synchro = kinolab_wheels::catalogue::robot("synchro-drive").unwrap();
    let before: Vec<f64> = synchro.wheels().iter().map(|w| w.beta).collect();
    let turned = synchro.steer(1, before[1] + 0.4).unwrap();
    for (b, w) in before.iter().zip(turned.wheels()) {
        assert!((kinolab_common::angle::wrap(w.beta - b) - 0.4).abs() < 1e-12);
    }
    let a = turned.analyze();
    assert_eq!((a.mobility, a.steerability), (1, 1));
    // A belt-driven robot cannot turn its chassis: IK refuses θ̇ ≠ 0.
    let ik = turned.inverse(Vector3::new(0.0, 0.0, 1.0)).unwrap();
    assert!(!ik.feasible);
    assert_eq!(ik.violations[0].constraint, "steer_group");
    assert!(turned.steer(0, f64::NAN).is_err());
}

#[test]
fn uranus_and_three_swedish_are_fully_determined_by_their_spins() {
    for id in ["uranus-mecanum", "three-swedish"] {
        let robot = kinolab_wheels::catalogue::robot(id).unwrap();
        let twist = Vector3::new(0.3, -0.2, 0.5);
        let ik = robot.inverse(twist).unwrap();
        let spins: Vec<Option<f64>> = ik.wheels.iter().map(|c| Some(c.spin)).collect();
        let fk = robot.forward(&spins).unwrap();
        assert!(fk.determined, "{id}");
        assert!((Vector3::from(fk.twist) - twist).norm() < 1e-12, "{id}");
        // With four wheels for three unknowns a wrong spin shows up as a
        // residual; with three wheels every set of spins is some twist.
        let mut bad = spins.clone();
        bad[0] = Some(bad[0].unwrap() + 1.0);
        let fk = robot.forward(&bad).unwrap();
        if id == "uranus-mecanum" {
            assert!(!fk.consistent && fk.residual > 1e-3, "{id}");
        } else {
            assert!(fk.consistent && fk.residual < 1e-12, "{id}");
        }
    }
}

#[test]
fn unknown_spins_leave_rows_out() {
    let dd = kinolab_wheels::catalogue::robot("differential-drive").unwrap();
    let fk = dd.forward(&[Some(2.0), Some(4.0), None]).unwrap();
    assert!(fk.determined && fk.consistent);
    assert!((fk.twist[0] - 0.3).abs() < 1e-12 && (fk.twist[2] - 0.4).abs() < 1e-12);
    // One wheel only: the turn rate is not pinned down.
    let fk = dd.forward(&[Some(2.0), None, None]).unwrap();
    assert!(!fk.determined && fk.consistent);
    assert!(
        dd.forward(&[Some(1.0)])
            .unwrap_err()
            .to_string()
            .contains("expected one spin per wheel (3), got 1")
    );
    assert!(dd.forward(&[Some(f64::NAN), None, None]).is_err());
}

/// Found by the property above in CI: a castor and a fixed wheel whose rows
/// are nearly parallel. The normal equations square that conditioning and
/// lost seven digits; the solve must still give back the spins.
#[test]
fn nearly_parallel_rows_still_give_back_the_spins() {
    let castor = Wheel {
        kind: WheelKind::Castor { offset: 0.01 },
        alpha: -1.0693707825313818,
        beta: -1.6479499601882095,
        l: 1.0377034187341978,
        radius: 0.02,
        steer_group: None,
    };
    let fixed = Wheel {
        kind: WheelKind::Fixed,
        alpha: 1.8369065445615596,
        beta: -0.26611021776666277,
        l: 0.5079785183973703,
        radius: 0.02,
        steer_group: None,
    };
    let chassis = Chassis::new("random", vec![castor, fixed]).unwrap();
    let twist = admissible_twist(&chassis, [0.0, -1.8547002651107571, 0.0]).unwrap();
    let ik = chassis.inverse(twist).unwrap();
    let spins: Vec<Option<f64>> = ik.wheels.iter().map(|c| Some(c.spin)).collect();
    let fk = chassis.forward(&spins).unwrap();
    assert!(fk.consistent, "residual {}", fk.residual);
    if fk.determined {
        let got = Vector3::from(fk.twist);
        assert!(
            (got - twist).norm() < 1e-7 * (1.0 + twist.norm()),
            "{got} vs {twist}"
        );
    }
}
