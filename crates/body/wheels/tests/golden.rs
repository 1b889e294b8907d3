//! Golden values: the reference sheet's table, Siegwart's worked example,
//! the catalogue's ICRs and the errors bad layouts must give.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use kinolab_wheels::catalogue::{CATALOGUE, robot};
use kinolab_wheels::{Chassis, Icr, Vector3, Wheel, WheelKind, integrate, to_inertial};
use std::f64::consts::FRAC_PI_2;

/// (id, δm, δs, δM, DOF, holonomic) — δ columns from the reference sheet's
/// golden table; DOF from which poses each robot can reach.
const GOLDEN: &[(&str, usize, usize, usize, usize, bool)] = &[
    ("unicycle", 2, 0, 2, 3, false),
    ("differential-drive", 2, 0, 2, 3, false),
    ("two-axles", 1, 0, 1, 1, true),
    ("bicycle", 1, 1, 2, 3, false),
    ("tricycle", 1, 1, 2, 3, false),
    ("ackermann-car", 1, 1, 2, 3, false),
    ("three-swedish", 3, 0, 3, 3, true),
    ("uranus-mecanum", 3, 0, 3, 3, true),
    ("nomad-xr4000", 3, 0, 3, 3, true),
    ("omni-steer", 2, 1, 3, 3, false),
    ("two-steer", 1, 2, 3, 3, false),
    ("synchro-drive", 1, 1, 2, 2, false),
    ("rocker-bogie", 1, 1, 2, 3, false),
    ("every-wheel-kind", 1, 1, 2, 3, false),
];

#[test]
fn every_catalogue_robot_matches_the_golden_table() {
    assert_eq!(
        GOLDEN.len(),
        CATALOGUE.len(),
        "every entry has golden values"
    );
    for &(id, dm, ds, dmm, dof, holonomic) in GOLDEN {
        let a = robot(id).unwrap().analyze();
        assert_eq!(
            (
                a.mobility,
                a.steerability,
                a.maneuverability,
                a.dof,
                a.holonomic
            ),
            (dm, ds, dmm, dof, holonomic),
            "{id}"
        );
        // δm against nalgebra's SVD of the stacked sliding rows.
        let c1 = robot(id).unwrap().c1();
        let svd_rank = if c1.nrows() == 0 { 0 } else { c1.rank(1e-9) };
        assert_eq!(a.mobility, 3 - svd_rank, "{id}");
    }
}

#[test]
fn a_stuck_car_keeps_its_steering_input() {
    // The Ackermann car with both linked front wheels set parallel, 20°
    // to the left: their zero-motion lines never meet the rear axle's line
    // at one point, so the car cannot move (rank C₁ = 3, δm = 0), yet its one
    // steering input still moves the rows of C₁s: δs = 1, δM = 1.
    let car = robot("ackermann-car").unwrap();
    let mut wheels = car.wheels().to_vec();
    for w in &mut wheels[2..4] {
        // Rolling 20° left of straight ahead: α + β = 110°.
        w.beta = 110f64.to_radians() - w.alpha;
    }
    let stuck = Chassis::new("stuck", wheels).unwrap();
    let a = stuck.analyze();
    assert_eq!(
        (a.rank_c1, a.mobility, a.steerability, a.maneuverability),
        (3, 0, 1, 1)
    );
    assert_eq!(a.icr, Icr::None);
    assert!(stuck.disagreement().is_some());
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-9
}

#[test]
fn siegwart_differential_drive_example() {
    // Right wheel (α = −π/2, β = π) spins at 4, left wheel at 2; r = l = 1.
    let chassis = Chassis::from_compact("siegwart", "f,-90,180,1,1;f,90,0,1,1").unwrap();
    let fk = chassis.forward(&[Some(4.0), Some(2.0)]).unwrap();
    assert!(close(fk.twist[0], 3.0) && close(fk.twist[1], 0.0) && close(fk.twist[2], 1.0));
    assert!(fk.consistent && fk.determined && fk.residual < 1e-12);
    let inertial = to_inertial(FRAC_PI_2, Vector3::from(fk.twist));
    assert!(close(inertial.x, 0.0) && close(inertial.y, 3.0) && close(inertial.z, 1.0));
    // And back: the twist asks for exactly those spins.
    let ik = chassis.inverse(Vector3::new(3.0, 0.0, 1.0)).unwrap();
    assert!(ik.feasible);
    assert!(close(ik.wheels[0].spin, 4.0) && close(ik.wheels[1].spin, 2.0));
}

#[test]
fn catalogue_icrs_are_where_the_geometry_puts_them() {
    let icr = |id: &str| robot(id).unwrap().analyze().icr;
    match icr("differential-drive") {
        Icr::Line { point, direction } => {
            assert!(close(point[0], 0.0) && close(point[1], 0.0));
            assert!(close(direction[0], 0.0) && close(direction[1], 1.0));
        }
        other => panic!("{other:?}"),
    }
    for (id, x, y) in [
        ("bicycle", 0.0, 3.0),
        ("ackermann-car", 0.0, 2.5),
        ("two-axles", 0.0, 0.5),
    ] {
        match icr(id) {
            Icr::Point { x: px, y: py } => assert!(close(px, x) && close(py, y), "{id}: {px} {py}"),
            other => panic!("{id}: {other:?}"),
        }
    }
    match icr("tricycle") {
        Icr::Infinity { direction } => {
            assert!(close(direction[0], 1.0) && close(direction[1], 0.0))
        }
        other => panic!("{other:?}"),
    }
    match icr("synchro-drive") {
        Icr::Infinity { direction } => {
            let h = 30f64.to_radians();
            assert!(close(direction[0], h.cos()) && close(direction[1], h.sin()));
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(icr("three-swedish"), Icr::Anywhere);
}

#[test]
fn a_stuck_layout_names_the_wheel_that_disagrees() {
    // A turntable (three fixed wheels whose axles meet at P) with a fourth
    // fixed wheel whose axle misses P by 0.5 sin 60°.
    let chassis = Chassis::from_compact(
        "stuck",
        "f,90,0,0.3,0.1;f,210,0,0.3,0.1;f,0,60,0.5,0.1;f,330,0,0.3,0.1",
    )
    .unwrap();
    let a = chassis.analyze();
    assert_eq!((a.rank_c1, a.mobility, a.icr), (3, 0, Icr::None));
    let d = chassis.disagreement().unwrap();
    assert_eq!(d.agree, vec![0, 1, 3]);
    assert_eq!(d.disagree.len(), 1);
    assert_eq!(d.disagree[0].0, 2);
    assert!(close(d.disagree[0].1, 0.5 * 60f64.to_radians().sin()));
    match d.consensus {
        Icr::Point { x, y } => assert!(close(x, 0.0) && close(y, 0.0)),
        other => panic!("{other:?}"),
    }
    // The lesson's cart: four straight wheels and a crooked fifth.
    let cart = Chassis::from_compact(
        "cart",
        "f,45,45,0.5,0.1;f,-45,135,0.5,0.1;f,135,-45,0.5,0.1;f,-135,-135,0.5,0.1;f,0,20,0.5,0.1",
    )
    .unwrap();
    let d = cart.disagreement().unwrap();
    assert_eq!(d.agree, vec![0, 1, 2, 3]);
    assert_eq!(
        d.disagree.iter().map(|(i, _)| *i).collect::<Vec<_>>(),
        vec![4]
    );
    // Without the fourth wheel the turntable spins about P.
    let turntable =
        Chassis::from_compact("t", "f,90,0,0.3,0.1;f,210,0,0.3,0.1;f,330,0,0.3,0.1").unwrap();
    assert!(turntable.disagreement().is_none());
    // Three fixed wheels whose axles pairwise cross at three different points.
    let triangle = Chassis::new(
        "triangle",
        vec![
            Wheel::at(WheelKind::Fixed, 0.0, 0.3, 0.0, 0.1),
            Wheel::at(WheelKind::Fixed, 0.4, 0.0, 1.0, 0.1),
            Wheel::at(WheelKind::Fixed, -0.4, -0.2, 2.0, 0.1),
        ],
    )
    .unwrap();
    let d = triangle.disagreement().unwrap();
    assert_eq!(d.agree.len(), 2);
    assert_eq!(d.disagree.len(), 1);
    assert!(d.disagree[0].1 > 0.01);
    assert!(robot("tricycle").unwrap().disagreement().is_none());
}

#[test]
fn parallel_axles_give_a_clean_translation_not_nan() {
    // Two fixed wheels, one in front of the other, axles both along y.
    let chassis = Chassis::from_compact("inline", "f,0,90,0.5,0.1;f,180,-90,0.5,0.1").unwrap();
    let a = chassis.analyze();
    assert_eq!(a.mobility, 1);
    assert_eq!(
        a.icr,
        Icr::Infinity {
            direction: [1.0, 0.0]
        }
    );
    let ik = chassis.inverse(Vector3::new(0.0, 0.0, 1.0)).unwrap();
    assert!(!ik.feasible);
    assert_eq!(ik.violations.len(), 2);
    assert!(ik.wheels.iter().all(|w| w.spin.is_finite()));
}

#[test]
fn bad_layouts_name_the_field() {
    let err = |code: &str| Chassis::from_compact("x", code).unwrap_err().to_string();
    assert_eq!(
        err("f,90,0,0.25,0"),
        "wheels[0].radius: must be greater than 0, got 0"
    );
    assert!(
        err("f,90,0,0.25,0.1;f,90,0,0.25,0.1")
            .starts_with("wheels[1]: sits on the same spot as wheels[0]")
    );
    assert!(err("f,nan,0,0.25,0.1").contains("alpha_deg must be a number"));
    assert!(err("f,90,0,-1,0.1").starts_with("wheels[0].l: a distance cannot be negative"));
    assert!(err("c,90,0,0.2,0.1,d=0").starts_with("wheels[0].offset:"));
    assert!(err("w,90,0,0.2,0.1,g=90").starts_with("wheels[0].gamma_deg:"));
    assert!(err("f,90,0,0.2,0.1,s=belt").starts_with("wheels[0].steer_group: only steered wheels"));
    assert!(err("").starts_with("wheels: a robot needs at least one wheel"));
    assert!(err("q,1,2,3,4").contains("unknown kind \"q\""));
    let nan = Wheel::new(WheelKind::Fixed, f64::NAN, 0.0, 0.2, 0.1);
    assert_eq!(
        Chassis::new("x", vec![nan]).unwrap_err().to_string(),
        "wheels[0].alpha_deg: must be a finite number, got NaN"
    );
}

#[test]
fn robot_files_read_write_and_explain_errors() {
    let every = robot("every-wheel-kind").unwrap();
    assert_eq!(every.wheels().len(), 6);
    let again = Chassis::from_json(&every.to_json()).unwrap();
    assert_eq!(again.to_compact(), every.to_compact());
    for entry in CATALOGUE {
        let chassis = robot(entry.id).unwrap();
        let back = Chassis::from_compact(chassis.name(), &chassis.to_compact()).unwrap();
        assert_eq!(
            back.analyze().maneuverability,
            chassis.analyze().maneuverability
        );
        let back = Chassis::from_json(&chassis.to_json()).unwrap();
        assert_eq!(
            back.steering_inputs(),
            chassis.steering_inputs(),
            "{}",
            entry.id
        );
    }
    let bad = |text: &str| Chassis::from_json(text).unwrap_err();
    let e = bad(
        r#"{"wheels":[{"kind":"fixed","alpha_deg":0,"beta_deg":0,"l":0.2,"radius":0.1,"colour":1}]}"#,
    );
    assert_eq!(e.field, "wheels[0].colour");
    assert!(e.message.contains("unknown field `colour`"), "{e}");
    let e =
        bad(r#"{"wheels":[{"kind":"castor","alpha_deg":0,"beta_deg":0,"l":0.2,"radius":0.1}]}"#);
    assert_eq!(
        e.to_string(),
        "wheels[0].offset: missing: a castor needs its offset d (metres)"
    );
    let e =
        bad(r#"{"wheels":[{"kind":"fixed","alpha_deg":0,"beta_deg":0,"l":0.2,"radius":-0.1}]}"#);
    assert_eq!(
        e.to_string(),
        "wheels[0].radius: must be greater than 0, got -0.1"
    );
    let e =
        bad(r#"{"wheels":[{"kind":"fixed","alpha_deg":"x","beta_deg":0,"l":0.2,"radius":0.1}]}"#);
    assert_eq!(e.field, "wheels[0].alpha_deg");
    let e = bad(r#"{"wheels":[{"kind":"fixed","alpha_deg":0,"l":0.2,"radius":0.1,"offset":0.1}]}"#);
    assert!(
        e.field == "wheels[0].offset" || e.field == "wheels[0].beta_deg",
        "{e}"
    );
    assert!(bad("{").to_string().contains("EOF"));
    assert!(
        robot("hovercraft")
            .unwrap_err()
            .to_string()
            .contains("known: unicycle")
    );
}

#[test]
fn pose_integration_follows_the_arc() {
    // Quarter circle of radius 1 to the left: v = 1, ω = 1 for π/2 s.
    let end = integrate([0.0, 0.0, 0.0], Vector3::new(1.0, 0.0, 1.0), FRAC_PI_2);
    assert!(close(end[0], 1.0) && close(end[1], 1.0) && close(end[2], FRAC_PI_2));
    // Sideways in the robot frame while facing +y moves along −x.
    let end = integrate([1.0, 2.0, FRAC_PI_2], Vector3::new(0.0, 1.0, 0.0), 2.0);
    assert!(close(end[0], -1.0) && close(end[1], 2.0));
}
